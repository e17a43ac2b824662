// `raylab compare` (the graders' comparison as a command) and `raylab shader`
// (the assembled program the web build must reproduce).
#include "test_support.h"

#include <gtest/gtest.h>
#include <zip.h>

#include <cstdlib>
#include <cstring>

#include <algorithm>
#include <functional>

#include <nlohmann/json.hpp>

using namespace raylab::test;

TEST(CompareCommand, AgreesWithItselfAndDiffersFromAnotherView) {
    const fs::path ref = sourceDir() / "tests/reference/01-raycast";
    CommandResult same =
        runRaylab("compare " + quote(ref / "front.png") + " " + quote(ref / "front.png"));
    EXPECT_EQ(same.exitCode, 0) << same.all();
    EXPECT_NE(same.out.find("agrees (0.00% of pixels differ"), std::string::npos) << same.out;

    ScratchDir dir;
    CommandResult other =
        runRaylab("compare " + quote(ref / "front.png") + " " + quote(ref / "inside.png") +
                  " --heat-map " + quote(dir / "heat.png"));
    EXPECT_EQ(other.exitCode, 1) << other.all();
    EXPECT_NE(other.out.find("DIFFERS"), std::string::npos) << other.out;
    EXPECT_TRUE(fs::exists(dir / "heat.png"));
}

TEST(CompareCommand, PicturesOfTwoSizesAreAOneLineError) {
    CommandResult r = runRaylab("compare " + quote(sourceDir() / "labs/01-raycast/expected.png") +
                                " " + quote(sourceDir() / "tests/reference/01-raycast/front.png"));
    EXPECT_EQ(r.exitCode, 2) << r.all();
    EXPECT_NE(r.err.find("is 480x360 but"), std::string::npos) << r.err;
    CommandResult missing = runRaylab("compare nowhere.png nowhere.png");
    EXPECT_EQ(missing.exitCode, 2) << missing.all();
}

TEST(ShaderCommand, PrintsTheSpecialisedProgramAndItsOrigins) {
    CommandResult r = runRaylab("shader --stage 08 --solution");
    ASSERT_EQ(r.exitCode, 0) << r.all();
    EXPECT_EQ(r.out.rfind("#version 330 core\n", 0), 0u);
    EXPECT_NE(r.out.find("#define SCENE_BAKED"), std::string::npos);
    EXPECT_NE(r.out.find("assets/scenes/lite.json"), std::string::npos);

    CommandResult es = runRaylab("shader --stage 01 --solution --es --origins");
    ASSERT_EQ(es.exitCode, 0) << es.all();
    EXPECT_EQ(es.out.rfind("<raylab>:1\t#version 300 es\n", 0), 0u) << es.out.substr(0, 80);
    EXPECT_NE(es.out.find("solution/01-raycast/intersect_sphere.glsl:"), std::string::npos);

    CommandResult generic = runRaylab("shader --stage 08 --solution --generic");
    ASSERT_EQ(generic.exitCode, 0) << generic.all();
    EXPECT_EQ(generic.out.find("#define SCENE_BAKED"), std::string::npos);
    EXPECT_EQ(generic.out.find("The scene, compiled in"), std::string::npos);
}

// --scene takes the demo scenes' names, as `raylab demo` does; the demo's
// program for pro has its levers, the glass cube's shell slots among them.
TEST(ShaderCommand, TakesTheDemoScenesByName) {
    CommandResult r = runRaylab("shader --stage 08 --solution --demo --scene pro");
    ASSERT_EQ(r.exitCode, 0) << r.all();
    EXPECT_NE(r.out.find("assets/scenes/pro.json"), std::string::npos);
    EXPECT_NE(r.out.find("#define RAYLAB_SHELL_SLOTS"), std::string::npos);
    CommandResult lite = runRaylab("shader --stage 08 --solution --demo --scene lite");
    ASSERT_EQ(lite.exitCode, 0) << lite.all();
    EXPECT_EQ(lite.out.find("#define RAYLAB_SHELL_SLOTS"), std::string::npos) << "lite has no box";
    CommandResult missing = runRaylab("shader --stage 08 --solution --scene pro-typo");
    EXPECT_EQ(missing.exitCode, 2) << missing.all();
    EXPECT_NE(missing.err.find("does not exist"), std::string::npos) << missing.err;
}

// A fur stage's programs: the shells' fragment shader by default, the fins'
// geometry shader with every uniform it reads (the guide of f3 sends students
// here for uEye and uFurLength), the strands' with this driver's budget; a
// program or shader the stage lacks is a one-line error.
TEST(ShaderCommand, PrintsAFurStagesPrograms) {
    CommandResult shells = runRaylab("shader --stage f2 --solution");
    EXPECT_EQ(shells.exitCode, 0) << shells.all();
    EXPECT_NE(shells.out.find("#define RAYLAB_FRAGMENT_SHADER"), std::string::npos);
    CommandResult fins = runRaylab("shader --stage f3 --program fins --geometry --origins");
    EXPECT_EQ(fins.exitCode, 0) << fins.all();
    EXPECT_NE(fins.out.find("#define RAYLAB_GEOMETRY_SHADER"), std::string::npos);
    EXPECT_NE(fins.out.find("vec3 uEye;"), std::string::npos) << fins.out;
    EXPECT_NE(fins.out.find("uFurLength"), std::string::npos);
    EXPECT_NE(fins.out.find("f3-fins/fin.geom:"), std::string::npos) << "lines name their file";
    CommandResult strands = runRaylab("shader --stage f4 --program strands --geometry");
    EXPECT_EQ(strands.exitCode, 0) << strands.all();
    EXPECT_NE(strands.out.find("#define STRANDS_PER_TRIANGLE "), std::string::npos);
    const struct {
        const char* args;
        const char* says;
    } refused[] = {
        {"shader --stage f3 --program hair", "has the programs shells, fins"},
        {"shader --stage f3 --geometry", "has no geometry shader"},
        {"shader --stage f3 --program fins --geometry --es", "WebGL 2 has no geometry shaders"},
        {"shader --stage 02 --program fins", "are for the fur stages"},
        {"shader --stage f2 --demo --solution", "for the ray-tracing stages"},
    };
    for (const auto& r : refused) {
        CommandResult c = runRaylab(r.args);
        EXPECT_EQ(c.exitCode, 2) << r.args << "\n" << c.all();
        EXPECT_NE(c.err.find(r.says), std::string::npos) << r.args << "\n" << c.err;
    }
}

namespace {

// PrairieLearn's /grade folder in DIR/NAME, with the files of FROM (a
// folder) as the student's upload; raylab prairielearn run against it.
nlohmann::json gradeForPrairieLearn(const ScratchDir& dir, const std::string& name,
                                    const std::function<void(const fs::path&)>& upload,
                                    const std::string& moreArgs = "") {
    const fs::path root = dir / name;
    fs::create_directories(root / "student");
    upload(root / "student");
    CommandResult r = runCommand("GRADE_ROOT=" + quote(root) + " " + quote(raylabExe()) +
                                 " prairielearn --stages 01" + moreArgs);
    EXPECT_EQ(r.exitCode, 0) << name << ": " << r.all();
    const fs::path results = root / "results" / "results.json";
    EXPECT_TRUE(fs::exists(results)) << name;
    EXPECT_LT(fs::file_size(results), 1024u * 1024u) << name << ": PrairieLearn's limit is 1 MB";
    nlohmann::json j = nlohmann::json::parse(readFile(results));
    // PrairieLearn's documented fields, with their types.
    EXPECT_TRUE(j["gradable"].is_boolean()) << name;
    EXPECT_TRUE(j["score"].is_number()) << name;
    EXPECT_GE(j["score"].get<double>(), 0.0);
    EXPECT_LE(j["score"].get<double>(), 1.0);
    EXPECT_TRUE(j["message"].is_string()) << name;
    for (const auto& t : j.value("tests", nlohmann::json::array())) {
        EXPECT_TRUE(t["name"].is_string());
        EXPECT_TRUE(t["points"].is_number());
        EXPECT_TRUE(t["max_points"].is_number());
        EXPECT_LE(t["points"].get<double>(), t["max_points"].get<double>() + 1e-9);
        for (const auto& image : t.value("images", nlohmann::json::array()))
            EXPECT_EQ(image["url"].get<std::string>().rfind("data:image/png;base64,", 0), 0u);
    }
    return j;
}

void copyShaders(const fs::path& from, const fs::path& to) {
    for (const auto& e : fs::directory_iterator(from))
        if (e.path().extension() == ".glsl" || e.path().extension() == ".frag")
            fs::copy_file(e.path(), to / e.path().filename());
}

}  // namespace

TEST(PrairieLearn, GradesSolvedUntouchedBrokenAndEmptySubmissions) {
    ScratchDir dir;
    const fs::path solution = sourceDir() / "solution" / "01-raycast";
    nlohmann::json solved = gradeForPrairieLearn(dir, "solved", [&](const fs::path& s) {
        copyShaders(solution, s);  // loose files: they replace the lab's own
    });
    EXPECT_TRUE(solved["gradable"].get<bool>());
    EXPECT_DOUBLE_EQ(solved["score"].get<double>(), 1.0);

    nlohmann::json untouched = gradeForPrairieLearn(dir, "untouched", [&](const fs::path& s) {
        copyShaders(sourceDir() / "labs" / "01-raycast", s);
    });
    EXPECT_LT(untouched["score"].get<double>(), 0.2);
    int heatMaps = 0;
    for (const auto& t : untouched["tests"]) heatMaps += t.contains("images") ? 1 : 0;
    EXPECT_GT(heatMaps, 0) << "failed views carry their difference heat map";
    // The seeded views count, as one test without details until the due date;
    // --seeded-views shown (the control) lists each with its own test.
    auto seededTests = [](const nlohmann::json& j) {
        int n = 0;
        for (const auto& t : j["tests"])
            n += t["name"].get<std::string>().find("seeded-") != std::string::npos;
        return n;
    };
    int folded = 0;
    for (const auto& t : untouched["tests"])
        if (t["name"].get<std::string>().find("further views") != std::string::npos) {
            ++folded;
            EXPECT_FALSE(t.contains("images"));
            EXPECT_NE(t["message"].get<std::string>().find("after the due date"),
                      std::string::npos);
        }
    EXPECT_EQ(folded, 1);
    EXPECT_EQ(seededTests(untouched), 0);
    nlohmann::json shown = gradeForPrairieLearn(
        dir, "shown",
        [&](const fs::path& s) { copyShaders(sourceDir() / "labs" / "01-raycast", s); },
        " --seeded-views shown");
    EXPECT_GT(seededTests(shown), 0);
    EXPECT_DOUBLE_EQ(shown["score"].get<double>(), untouched["score"].get<double>())
        << "hiding changes what is shown, not the score";

    nlohmann::json broken = gradeForPrairieLearn(dir, "broken", [&](const fs::path& s) {
        copyShaders(solution, s);
        std::string text = readFile(s / "intersect_sphere.glsl");
        text.replace(text.find("    return"), 0, "    float = 1.0;\n");
        writeFile(s / "intersect_sphere.glsl", text);
    });
    EXPECT_DOUBLE_EQ(broken["score"].get<double>(), 0.0);
    EXPECT_NE(broken.dump().find("01-raycast/intersect_sphere.glsl:"), std::string::npos)
        << broken.dump();
    EXPECT_EQ(broken.dump().find("raylab-work"), std::string::npos) << "the student's paths only";

    nlohmann::json empty = gradeForPrairieLearn(dir, "empty", [](const fs::path&) {});
    EXPECT_FALSE(empty["gradable"].get<bool>()) << "no attempt is used up";
    EXPECT_EQ(empty["format_errors"][0].get<std::string>(), "nothing was submitted");

    // The labs folder as uploaded folders: one extra top folder around the stage folders.
    nlohmann::json folders = gradeForPrairieLearn(
        dir, "folders", [&](const fs::path& s) { writeSolvedLabs(s / "my-labs"); });
    EXPECT_DOUBLE_EQ(folders["score"].get<double>(), 1.0);

    // The open level: the open lab as handed out earns nothing; loose files
    // lie over the open lab (a file not uploaded is its open stub).
    ASSERT_EQ(runLabgen("--level open --labs " + quote(dir / "open-labs")).exitCode, 0);
    nlohmann::json openUntouched = gradeForPrairieLearn(
        dir, "open-untouched",
        [&](const fs::path& s) { copyShaders(dir / "open-labs" / "01-raycast", s); },
        " --level open");
    EXPECT_DOUBLE_EQ(openUntouched["score"].get<double>(), 0.0) << openUntouched.dump(1);
    nlohmann::json openHalf = gradeForPrairieLearn(
        dir, "open-half",
        [&](const fs::path& s) {
            fs::copy_file(solution / "intersect_sphere.glsl", s / "intersect_sphere.glsl");
        },
        " --level open");
    EXPECT_NE(openHalf.dump().find("findClosest"), std::string::npos);
    bool findClosestFailed = false;
    for (const auto& t : openHalf["tests"])
        if (t["name"].get<std::string>().find("findClosest") != std::string::npos)
            findClosestFailed = t["points"].get<double>() == 0.0;
    EXPECT_TRUE(findClosestFailed) << "find_closest.glsl is the open stub: " << openHalf.dump(1);
}

namespace {

// A zip of ENTRIES (name -> content) written with libzip, names as given
// (so that a hostile one such as "../x" can be made).
// An entry whose name starts with "@link:" is a symbolic link to its text.
void writeZip(const fs::path& file,
              const std::vector<std::pair<std::string, std::string>>& entries) {
    int err = 0;
    zip_t* z = zip_open(file.c_str(), ZIP_CREATE | ZIP_TRUNCATE, &err);
    ASSERT_NE(z, nullptr);
    for (const auto& [entry, text] : entries) {
        const bool link = entry.rfind("@link:", 0) == 0;
        const std::string name = link ? entry.substr(6) : entry;
        char* copy = static_cast<char*>(malloc(text.size() + 1));
        memcpy(copy, text.data(), text.size());
        zip_source_t* src = zip_source_buffer(z, copy, text.size(), 1);
        const zip_int64_t index = zip_file_add(z, name.c_str(), src, ZIP_FL_ENC_UTF_8);
        ASSERT_GE(index, 0) << name;
        if (link) {
            ASSERT_EQ(zip_file_set_external_attributes(z, zip_uint64_t(index), 0, ZIP_OPSYS_UNIX,
                                                       zip_uint32_t(0120777) << 16),
                      0);
        }
    }
    ASSERT_EQ(zip_close(z), 0);
}

}  // namespace

// PrairieLearn keeps an uploaded zip as a file: it is unpacked and graded like
// the folders in it; a zip that would write outside the upload is refused.
TEST(PrairieLearn, AZipUploadIsUnpackedAndAHostileOneRefused) {
    ScratchDir dir;
    ScratchDir labs;
    writeSolvedLabs(labs / "my-labs");
    nlohmann::json zipped = gradeForPrairieLearn(dir, "zipped", [&](const fs::path& s) {
        CommandResult z = runCommand("cd " + quote(labs.path()) + " && zip -qr " +
                                     quote(s / "labs.zip") + " my-labs");
        ASSERT_EQ(z.exitCode, 0) << z.all();
    });
    EXPECT_TRUE(zipped["gradable"].get<bool>()) << zipped.dump();
    EXPECT_DOUBLE_EQ(zipped["score"].get<double>(), 1.0) << zipped.dump();
    EXPECT_NE(zipped["output"].get<std::string>().find("labs.zip: unpacked"), std::string::npos);

    // Loose shader files in a zip: one stage's, over the lab's own files.
    nlohmann::json loose = gradeForPrairieLearn(dir, "loose-zip", [&](const fs::path& s) {
        std::vector<std::pair<std::string, std::string>> files;
        for (const char* f : {"intersect_sphere.glsl", "find_closest.glsl"})
            files.emplace_back(f, readFile(labs / "my-labs" / "01-raycast" / f));
        writeZip(s / "mine.zip", files);
    });
    EXPECT_DOUBLE_EQ(loose["score"].get<double>(), 1.0) << loose.dump();

    nlohmann::json hostile = gradeForPrairieLearn(dir, "hostile", [&](const fs::path& s) {
        writeZip(s / "evil.zip",
                 {{"01-raycast/intersect_sphere.glsl", "x"}, {"../../escaped.glsl", "x"}});
    });
    EXPECT_FALSE(hostile["gradable"].get<bool>());
    EXPECT_NE(hostile["message"].get<std::string>().find("outside the upload"), std::string::npos)
        << hostile.dump();
    EXPECT_FALSE(fs::exists(dir / "escaped.glsl"));
    EXPECT_FALSE(fs::exists(dir / "hostile" / "escaped.glsl"));

    const struct {
        const char* name;
        std::vector<std::pair<std::string, std::string>> entries;
        const char* expected;
    } refused[] = {
        {"absolute", {{"/tmp/escaped.glsl", "x"}}, "outside the upload"},
        {"link",
         {{"@link:01-raycast/intersect_sphere.glsl", "../../solution/01-raycast/x.glsl"}},
         "is a symbolic link"},
        {"bomb",
         {{"01-raycast/intersect_sphere.glsl", std::string(65u << 20, ' ')}},
         "more than 64 MB unpacked"},
    };
    for (const auto& r : refused) {
        nlohmann::json j = gradeForPrairieLearn(
            dir, r.name, [&](const fs::path& s) { writeZip(s / "up.zip", r.entries); });
        EXPECT_FALSE(j["gradable"].get<bool>()) << r.name;
        EXPECT_NE(j["message"].get<std::string>().find(r.expected), std::string::npos)
            << r.name << ": " << j.dump();
    }

    // A stage folder uploaded with a link in it (a grader that keeps links):
    // the link is left out and said so, never followed into the solution.
    nlohmann::json linked = gradeForPrairieLearn(dir, "linked", [&](const fs::path& s) {
        fs::create_directories(s / "01-raycast");
        for (const char* f : {"intersect_sphere.glsl", "find_closest.glsl"})
            fs::create_symlink(sourceDir() / "solution/01-raycast" / f, s / "01-raycast" / f);
    });
    EXPECT_LT(linked["score"].get<double>(), 0.5) << "the solution was not followed";
    EXPECT_NE(linked["output"].get<std::string>().find("a symbolic link, left out"),
              std::string::npos)
        << linked.dump();

    nlohmann::json damaged = gradeForPrairieLearn(dir, "damaged", [&](const fs::path& s) {
        writeFile(s / "labs.zip", "PK\x03\x04 not really a zip");
    });
    EXPECT_FALSE(damaged["gradable"].get<bool>());
    EXPECT_NE(damaged["message"].get<std::string>().find("labs.zip: not a readable zip"),
              std::string::npos)
        << damaged.dump();

    // The question's upload element takes any number of the patterns (none required).
    const std::string question = readFile(sourceDir() / "examples/prairielearn/question.html");
    EXPECT_NE(question.find("optional-file-patterns=\""), std::string::npos);
    EXPECT_EQ(question.find(" file-patterns="), std::string::npos);
}

// `raylab function-tables --check`: web/function_tables.json (the page's
// expected values) is current; a copy with one value changed is not.
TEST(FunctionTablesCommand, ChecksTheShippedFile) {
    const fs::path shipped = sourceDir() / "web/function_tables.json";
    CommandResult r = runRaylab("function-tables --check " + quote(shipped));
    EXPECT_EQ(r.exitCode, 0) << r.all();
    ScratchDir dir;
    std::string text = readFile(shipped);
    const auto at = text.find("\"want\":[");
    ASSERT_NE(at, std::string::npos);
    text.insert(at + std::string("\"want\":[").size(), "0.5,");  // five numbers
    writeFile(dir / "tables.json", text);
    r = runRaylab("function-tables --check " + quote(dir / "tables.json"));
    EXPECT_NE(r.exitCode, 0) << r.all();
    EXPECT_NE(r.err.find("tables.json: "), std::string::npos) << r.err;
}

// `raylab render` says where an OBJ model went (its bounds, the fit), and
// that a picture of one colour is one: with one shell, a shellLayer that
// divides by shellCount - 1 puts every vertex at NaN and nothing is drawn.
TEST(RenderCommand, SaysWhereAModelWentAndWhenNothingWasDrawn) {
    ScratchDir dir;
    CommandResult blob = runRaylab("render --stage f1 --solution --scene " +
                                   quote(sourceDir() / "assets/scenes/fur/blob.json") +
                                   " --size "
                                   "64x48 --out " +
                                   quote(dir / "blob.png"));
    ASSERT_EQ(blob.exitCode, 0) << blob.all();
    EXPECT_NE(blob.out.find("mesh assets/meshes/blob.obj: 960 triangles, bounds (-1, -1.103, "
                            "-1.079) .. (1.13, 1.077, 1.079); fitted to the box from -1 to 1"),
              std::string::npos)
        << blob.out;
    EXPECT_EQ(blob.err.find("every pixel"), std::string::npos) << blob.err;

    writeSolvedLabs(dir / "lab");
    replaceInFile(dir / "lab" / "f2-shells" / "shell_layer.glsl",
                  "return shellCount > 1 ? float(drawIndex) / float(shellCount - 1) : 0.0;",
                  "return float(drawIndex) / float(shellCount - 1);");
    CommandResult one = runRaylab("render --stage f2 --lab " + quote(dir / "lab") +
                                  " --shells 1 --size 64x48 --out " + quote(dir / "one.png"));
    ASSERT_EQ(one.exitCode, 0) << one.all();
    EXPECT_NE(one.err.find("every pixel of the picture is (20, 23, 31): nothing was drawn in front "
                           "of the background"),
              std::string::npos)
        << one.err;
    CommandResult two = runRaylab("render --stage f2 --lab " + quote(dir / "lab") +
                                  " --shells 2 --size 64x48 --out " + quote(dir / "two.png"));
    EXPECT_EQ(two.err.find("every pixel"), std::string::npos) << two.err;
}
