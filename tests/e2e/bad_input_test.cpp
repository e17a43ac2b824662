// Bad input: a one-line cause, a non-zero exit, and no output file left behind.
#include "test_support.h"

#include <gtest/gtest.h>

using namespace raylab::test;

namespace {

struct BadCase {
    const char* name;
    std::string args;      // after "render --out OUT"
    const char* expected;  // part of the error line
};

void expectCleanFailure(const ScratchDir& dir, const BadCase& c) {
    SCOPED_TRACE(c.name);
    fs::path out = dir / (std::string(c.name) + ".png");
    CommandResult r = runRaylab("render --out " + quote(out) + " " + c.args);
    EXPECT_EQ(r.exitCode, 2) << r.all();
    std::string last = r.err.substr(
        r.err.rfind("raylab: error:") == std::string::npos ? 0 : r.err.rfind("raylab: error:"));
    EXPECT_EQ(last.rfind("raylab: error: ", 0), 0u) << r.err;
    EXPECT_EQ(std::count(last.begin(), last.end(), '\n'), 1)
        << "the cause must be one line: " << last;
    EXPECT_NE(last.find(c.expected), std::string::npos)
        << "expected '" << c.expected << "' in: " << last;
    EXPECT_FALSE(fs::exists(out)) << "no output file on failure";
    for (const auto& e : fs::directory_iterator(dir.path()))
        EXPECT_EQ(e.path().filename().string().find(".tmp"), std::string::npos)
            << "leftover " << e.path();
}

}  // namespace

TEST(BadInput, EachIsAOneLineErrorWithNoOutputFile) {
    ScratchDir dir;
    writeFile(dir / "broken.json", "{ \"background\": [0, 0, 0], ");
    std::string manyLights = "{\"background\": [0, 0, 0], \"camera\": {\"position\": [0, 0, 5], "
                             "\"yaw\": 0, \"pitch\": 0}, \"lights\": [";
    for (int i = 0; i < 9; ++i)
        manyLights += std::string(i ? "," : "") + "{\"position\": [0, 0, 0], \"color\": [1, 1, 1]}";
    writeFile(dir / "many-lights.json", manyLights + "], \"spheres\": []}");
    std::string boxes = "{\"background\": [0, 0, 0], \"camera\": {\"position\": [0, 0, 5], "
                        "\"yaw\": 0, \"pitch\": 0}, \"boxes\": [";
    for (int i = 0; i < 3; ++i)
        boxes += std::string(i ? "," : "") +
                 "{\"center\": [0, 0, 0], \"size\": [1, 1, 1], \"color\": [1, 1, 1]}";
    writeFile(dir / "many-triangles.json", boxes + "], \"spheres\": []}");
    const BadCase cases[] = {
        {"unknown-stage", "--stage 42", "unknown stage '42'"},
        {"unknown-stage-name", "--stage 01-raytrace", "unknown stage '01-raytrace'"},
        {"missing-lab", "--stage 01 --lab /nonexistent/lab",
         "lab folder /nonexistent/lab does not exist"},
        {"lab-without-stage", "--stage 01 --lab " + quote(dir.path()), "has no 01-raycast/"},
        {"missing-scene", "--stage 01 --solution --scene /nonexistent/s.json",
         "scene file /nonexistent/s.json does not exist"},
        {"malformed-scene", "--stage 01 --solution --scene " + quote(dir / "broken.json"),
         "JSON syntax error"},
        {"kind-not-yet",
         "--stage 04 --solution --scene " + quote(sourceDir() / "assets/scenes/stage05.json"),
         "stage05.json: planes: stage 04-recursion has no planes"},
        {"too-many-triangles",
         "--stage 05 --solution --scene " + quote(dir / "many-triangles.json"),
         "triangles: 36 triangles, but stage 05-primitives supports at most 32"},
        {"color-mode", "--stage 08 --solution --color-mode XYZ",
         "--color-mode must be RGB, BRB, BRR, RBB or GGR"},
        {"too-many-lights", "--stage 02 --solution --scene " + quote(dir / "many-lights.json"),
         "lights: 9 lights, but stage 02-shading supports at most 4"},
        {"size-format", "--stage 01 --solution --size 800by600",
         "--size '800by600': expected WIDTHxHEIGHT"},
        {"size-absurd", "--stage 01 --solution --size 100000x100000", "--size"},
        {"size-zero", "--stage 01 --solution --size 0x10", "each side must be between 1 and"},
        {"camera-format", "--stage 01 --solution --camera 1,2,3",
         "--camera '1,2,3': expected x,y,z,yaw,pitch"},
        {"camera-nan", "--stage 01 --solution --camera nan,0,0,0,0", "--camera"},
        {"depth-zero", "--stage 04 --solution --depth 0", "--depth must be between 1 and 8"},
        {"depth-nine", "--stage 04 --solution --depth 9", "--depth must be between 1 and 8"},
        {"backend", "--stage 01 --solution --backend vulkan", "unknown backend 'vulkan'"},
        {"both-lab-and-solution", "--stage 01 --solution --lab", "exclude each other"},
    };
    for (const BadCase& c : cases) expectCleanFailure(dir, c);
}

TEST(BadInput, OutputFolderMustExistAndNameMustBePng) {
    ScratchDir dir;
    CommandResult r =
        runRaylab("render --stage 01 --solution --out " + quote(dir / "no/such/dir/x.png"));
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("does not exist"), std::string::npos) << r.err;
    r = runRaylab("render --stage 01 --solution --out " + quote(dir / "x.jpg"));
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("must end in .png"), std::string::npos) << r.err;
    EXPECT_TRUE(fs::is_empty(dir.path()));
}

TEST(BadInput, UnknownSubcommandOrOptionIsAnError) {
    EXPECT_EQ(runRaylab("fly").exitCode, 2);
    CommandResult r = runRaylab("render --stage 01 --teleport");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("raylab: error:"), std::string::npos) << r.err;
}

TEST(BadInput, AFailedRenderKeepsAnExistingOutputFileIntact) {
    ScratchDir dir;
    writeFile(dir / "keep.png", "previous content");
    CommandResult r =
        runRaylab("render --stage 01 --solution --size 0x0 --out " + quote(dir / "keep.png"));
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_EQ(readFile(dir / "keep.png"), "previous content");
}
