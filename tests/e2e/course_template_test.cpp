// The course is data: a stage is a folder with a stage.json, and adding one
// needs no C++ change. These tests work on a copy of the tree (RAYLAB_ROOT).
#include "test_support.h"

#include <gtest/gtest.h>

using namespace raylab::test;

namespace {

// A copy of the parts of the tree that `raylab` and `raylab-labgen` read.
void copyTree(const fs::path& to) {
    for (const char* part : {"framework/shaders", "solution", "assets"}) {
        fs::create_directories((to / part).parent_path());
        fs::copy(sourceDir() / part, to / part, fs::copy_options::recursive);
    }
}

CommandResult inTree(const fs::path& root, const std::string& command) {
    return runCommand("RAYLAB_ROOT=" + quote(root.string()) + " " + command);
}

std::string raylabCmd() { return quote(raylabExe().string()); }

// A stage between 04 and 05: its own sky.glsl with a TODO, the rest from 04.
void insertStage(const fs::path& root) {
    const fs::path dir = root / "solution/04b-sky";
    fs::create_directories(dir);
    std::string json = readFile(root / "solution/04-recursion/stage.json");
    auto swap = [&](const std::string& from, const std::string& to) {
        auto at = json.find(from);
        ASSERT_NE(at, std::string::npos) << from;
        json.replace(at, from.size(), to);
    };
    swap("\"id\": \"04-recursion\"", "\"id\": \"04b-sky\"");
    swap("\"builds_on\": \"03-shadows\"", "\"builds_on\": \"04-recursion\"");
    swap("\"title\": \"", "\"title\": \"an inserted stage: the sky, written by the student; ");
    // Its TODO is the sky; the Fresnel functions and trace stay 04's to check.
    swap("\"function_checks\": [\"fresnelDielectric\", \"fresnelConductor\", \"refractGlass\", "
         "\"trace\"]",
         "\"function_checks\": []");
    swap("\"weights\": {\"glass-closeup\": 2, \"trace\": 2}",
         "\"weights\": {\"glass-closeup\": 2}");
    writeFile(dir / "stage.json", json);
    writeFile(dir / "sky.glsl", "// The colour of a ray that hits nothing.\n"
                                "vec3 skyColor(vec3 dir)\n{\n"
                                "    // TODO(04b.a): return the scene's background colour.\n"
                                "    //@solution\n    return uBackground;\n    //@stub\n    //@ "
                                "labTodo();\n    //@ return vec3(0.0);\n    //@end\n}\n");
    replaceInFile(root / "solution/05-primitives/stage.json", "\"builds_on\": \"04-recursion\"",
                  "\"builds_on\": \"04b-sky\"");
}

}  // namespace

TEST(CourseTemplate, AStageInsertedAsDataIsListedGeneratedAndChecked) {
    ScratchDir root;
    copyTree(root.path());
    insertStage(root.path());

    CommandResult labgen = inTree(root.path(), quote(RAYLAB_LABGEN_EXE) + " --labs " +
                                                   quote((root / "labs").string()));
    ASSERT_EQ(labgen.exitCode, 0) << labgen.all();
    EXPECT_TRUE(fs::is_regular_file(root / "labs/04b-sky/sky.glsl"));
    EXPECT_TRUE(fs::is_regular_file(root / "labs/04b-sky/trace.glsl"))
        << "inherited from 04-recursion, solved";
    EXPECT_NE(readFile(root / "labs/04b-sky/sky.glsl").find("labTodo();"), std::string::npos);
    EXPECT_EQ(readFile(root / "labs/05-primitives/sky.glsl").find("labTodo();"), std::string::npos)
        << "solved in later labs";

    CommandResult stages = inTree(root.path(), raylabCmd() + " stages");
    ASSERT_EQ(stages.exitCode, 0) << stages.all();
    const auto at04 = stages.out.find("04-recursion"), at04b = stages.out.find("04b-sky"),
               at05 = stages.out.find("05-primitives");
    ASSERT_NE(at04b, std::string::npos) << stages.out;
    EXPECT_LT(at04, at04b) << stages.out;
    EXPECT_LT(at04b, at05) << stages.out;

    CommandResult solved =
        inTree(root.path(), raylabCmd() + " check --stage 04b-sky --solution --size 160x120");
    EXPECT_EQ(solved.exitCode, 0) << solved.all();
    EXPECT_NE(solved.out.find("6 passed, 0 failed"), std::string::npos) << solved.out;
    // The later stage now builds on the inserted one and still assembles.
    CommandResult later =
        inTree(root.path(), raylabCmd() + " check --stage 05 --solution --size 160x120");
    EXPECT_EQ(later.exitCode, 0) << later.all();
    // The untouched lab of the new stage is unfinished: its check fails.
    CommandResult lab = inTree(root.path(), raylabCmd() + " check --stage 04b-sky --size 160x120");
    EXPECT_EQ(lab.exitCode, 1) << lab.all();
    EXPECT_NE(lab.all().find("04b-sky/sky.glsl"), std::string::npos)
        << "the open TODO is named: " << lab.all();
}

// A bad stage.json is one line naming the file and the key, and exit 2.
TEST(CourseTemplate, BadStageFilesNameFileAndKey) {
    struct Case {
        std::string from, to, message;
    };
    const std::vector<Case> cases = {
        {"\"track\": \"raytrace\",", "",
         "solution/03-shadows/stage.json: stage: missing \"track\""},
        {"\"builds_on\": \"02-shading\"", "\"builds_on\": \"02-shadingg\"",
         "solution/03-shadows/stage.json: builds_on: no stage '02-shadingg'"},
        {"\"features\": [\"shading\", \"shadows\"]", "\"features\": [\"shading\", \"shadow\"]",
         "solution/03-shadows/stage.json: features[1]: unknown feature 'shadow'"},
        {"\"spheres\": 16", "\"spheres\": -1",
         "solution/03-shadows/stage.json: limits.spheres: expected a whole number"},
        {"\"yaw\": 115.0", "\"yaw\": \"115\"",
         "solution/03-shadows/stage.json: check_views[2].camera.yaw: expected a number"},
        {"\"shadows\": false", "\"shadow\": false",
         "solution/03-shadows/stage.json: check_views[5].shadow: unknown key"},
        {"\"id\": \"03-shadows\"", "\"id\": \"03-shadow\"",
         "solution/03-shadows/stage.json: id: '03-shadow' is not the folder's name"},
        {"\"builds_on\": \"02-shading\"", "\"builds_on\": \"03-shadows\"",
         "solution/03-shadows/stage.json: builds_on: a stage cannot build on itself"},
        {"\"scene\": \"stage02.json\",", "\"scene\": \"stage02.json\"",
         "solution/03-shadows/stage.json: line 7, column 11: JSON syntax error"},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.message);
        ScratchDir root;
        copyTree(root.path());
        replaceInFile(root / "solution/03-shadows/stage.json", c.from, c.to);
        CommandResult r = inTree(root.path(), raylabCmd() + " stages");
        EXPECT_EQ(r.exitCode, 2) << r.all();
        EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "one line: " << r.err;
        EXPECT_TRUE(r.out.empty()) << r.out;
    }
}

// A function check a stage names must exist.
TEST(CourseTemplate, UnknownFunctionCheckIsAnError) {
    ScratchDir root;
    copyTree(root.path());
    replaceInFile(root / "solution/01-raycast/stage.json", "\"intersectSphere\"",
                  "\"intersectSpheres\"");
    CommandResult r =
        inTree(root.path(), raylabCmd() + " check --stage 01 --solution --size 80x60");
    EXPECT_EQ(r.exitCode, 2) << r.all();
    EXPECT_NE(r.err.find("solution/01-raycast/stage.json: function_checks[0]: no function check "
                         "'intersectSpheres'"),
              std::string::npos)
        << r.err;
}

// The ray tracer has no geometry stage: a stage that names one is refused, not ignored.
TEST(CourseTemplate, AGeometryShaderOnTheRayTracerIsRefused) {
    ScratchDir root;
    copyTree(root.path());
    replaceInFile(root / "solution/02-shading/stage.json", "\"vertex\": \"canvas.vert\",",
                  "\"vertex\": \"canvas.vert\", \"geometry\": \"fins.geom\",");
    CommandResult r =
        inTree(root.path(), raylabCmd() + " render --stage 02 --solution --size 80x60 --out " +
                                quote((root / "x.png").string()));
    EXPECT_EQ(r.exitCode, 2) << r.all();
    EXPECT_NE(r.err.find("solution/02-shading/stage.json: program.geometry: the ray tracer's "
                         "renderer takes no geometry shader"),
              std::string::npos)
        << r.err;
    EXPECT_FALSE(fs::exists(root / "x.png"));
}
