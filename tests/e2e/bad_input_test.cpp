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
    const std::string textures = (sourceDir() / "assets/textures").string();
    writeFile(dir / "fur-no-obj.json",
              "{\"background\": [0, 0, 0], \"camera\": {\"position\": [0, 0, 3], \"yaw\": 0, "
              "\"pitch\": 0}, \"mesh\": {\"obj\": \"nowhere.obj\"}, \"light\": {\"direction\": "
              "[0, 1, 0]}, \"fur\": {\"color_map\": \"" +
                  textures + "/fur_color.png\", \"pattern\": \"" + textures +
                  "/fur_pattern.png\", \"fin_map\": \"" + textures + "/fur_fin.png\"}}");
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
        {"scene-scale", "--stage 01 --solution --scene-scale 0",
         "--scene-scale '0': expected a factor between 1e-6 and 1e8"},
        {"scene-offset", "--stage 01 --solution --scene-offset 1,2",
         "--scene-offset '1,2': expected x,y,z"},
        {"scene-scale-fur", "--stage f1 --solution --scene-scale 2",
         "--scene-scale and --scene-offset are for the ray-tracing stages"},
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
        // The fur track.
        {"fur-shells", "--stage f2 --solution --shells 999", "--shells must be between 1 and 256"},
        {"fur-length", "--stage f2 --solution --fur-length 0", "--fur-length must be a factor"},
        {"fur-technique", "--stage f4 --solution --technique knitting",
         "--technique must be shells_and_fins or fur_shader (not 'knitting')"},
        {"fur-stage-with-a-ray-tracing-scene",
         "--stage f1 --solution --scene " + quote(sourceDir() / "assets/scenes/lite.json"),
         "lite.json: scene: a ray-tracing scene (it has spheres or materials, no mesh)"},
        {"ray-tracing-stage-with-a-fur-scene",
         "--stage 01 --solution --scene " + quote(sourceDir() / "assets/scenes/fur/sphere.json"),
         "sphere.json: scene: a fur scene (it has a mesh or fur)"},
        {"fur-obj-missing", "--stage f3 --solution --scene " + quote(dir / "fur-no-obj.json"),
         "mesh.obj: file"},
        {"fur-debug-view", "--stage f1 --solution --view depth",
         "stage f1-mesh is on the fur track: --view depth draws ray-tracing stages only"},
        {"fur-reference", "--stage f2 --solution --reference",
         "stage f2-shells is on the fur track: the reference tracer (--reference) draws "
         "ray-tracing stages only"},
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
