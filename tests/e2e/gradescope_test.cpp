// The Gradescope autograder: `raylab autograder` writes the bundle, and its
// run_autograder grades real submissions against a temporary /autograder
// (AUTOGRADER_ROOT), each results.json checked against the fields
// Gradescope documents (gradescope-autograders.readthedocs.io, "Autograder
// Specifications").
#include "test_support.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <set>

using namespace raylab::test;
using nlohmann::json;

namespace {

// What is wrong with J as a Gradescope results.json (empty: nothing). The
// documented fields and values; RayLab's own rules on top: every test has a
// score within 0..max_score, and the top-level score is their sum.
std::vector<std::string> gradescopeProblems(const json& j) {
    std::vector<std::string> problems;
    auto bad = [&](const std::string& what) { problems.push_back(what); };
    const std::set<std::string> visibilities = {"visible", "hidden", "after_due_date",
                                                "after_published"};
    const std::set<std::string> topKeys = {
        "score",         "execution_time",     "output",
        "output_format", "test_output_format", "test_name_format",
        "visibility",    "stdout_visibility",  "extra_data",
        "tests",         "leaderboard"};
    const std::set<std::string> testKeys = {
        "score",  "max_score",     "status", "name",       "name_format", "number",
        "output", "output_format", "tags",   "visibility", "extra_data"};
    if (!j.is_object()) return {"not a JSON object"};
    for (const auto& [key, value] : j.items())
        if (!topKeys.count(key)) bad("unknown top-level field '" + key + "'");
    auto isFinite = [](const json& v) { return v.is_number() && std::isfinite(v.get<double>()); };
    if (j.contains("score") && !isFinite(j["score"])) bad("score is not a number");
    if (j.contains("execution_time") &&
        (!j["execution_time"].is_number_integer() || j["execution_time"].get<long>() < 0))
        bad("execution_time is not a whole number of seconds");
    if (j.contains("output") && !j["output"].is_string()) bad("output is not a string");
    const std::set<std::string> formats = {"text", "html", "simple_format", "md", "ansi"};
    for (const char* key : {"output_format", "test_output_format", "test_name_format"})
        if (j.contains(key) && (!j[key].is_string() || !formats.count(j[key].get<std::string>())))
            bad(std::string(key) + " is not one of Gradescope's output formats");
    for (const char* key : {"visibility", "stdout_visibility"})
        if (j.contains(key) &&
            (!j[key].is_string() || !visibilities.count(j[key].get<std::string>())))
            bad(std::string(key) + " is not one of Gradescope's visibility values");
    if (!j.contains("tests")) {
        if (!j.contains("score")) bad("neither a top-level score nor tests");
        return problems;
    }
    if (!j["tests"].is_array()) return (bad("tests is not a list"), problems);
    double sum = 0;
    bool allScored = true;
    for (const json& t : j["tests"]) {
        const std::string name = t.is_object() && t.contains("name") && t["name"].is_string()
                                     ? t["name"].get<std::string>()
                                     : "?";
        if (!t.is_object()) {
            bad("a test is not an object");
            continue;
        }
        for (const auto& [key, value] : t.items())
            if (!testKeys.count(key)) bad(name + ": unknown field '" + key + "'");
        for (const char* key : {"name", "number", "output"})
            if (t.contains(key) && !t[key].is_string()) bad(name + ": " + key + " is not a string");
        if (t.contains("status") &&
            (!t["status"].is_string() || (t["status"] != "passed" && t["status"] != "failed")))
            bad(name + ": status is not passed or failed");
        if (t.contains("visibility") && (!t["visibility"].is_string() ||
                                         !visibilities.count(t["visibility"].get<std::string>())))
            bad(name + ": visibility is not one of Gradescope's values");
        if (t.contains("tags")) {
            if (!t["tags"].is_array()) bad(name + ": tags is not a list");
            else
                for (const json& tag : t["tags"])
                    if (!tag.is_string()) bad(name + ": a tag is not a string");
        }
        if (!t.contains("score") || !isFinite(t["score"]) || !t.contains("max_score") ||
            !isFinite(t["max_score"])) {
            allScored = false;
            bad(name + ": no score and max_score");
            continue;
        }
        const double score = t["score"].get<double>(), max = t["max_score"].get<double>();
        if (max < 0 || score < 0 || score > max + 1e-9)
            bad(name + ": score " + std::to_string(score) + " not within 0.." +
                std::to_string(max));
        sum += score;
    }
    if (!j.contains("score") && !allScored) bad("no top-level score and tests without scores");
    if (j.contains("score") && isFinite(j["score"]) && allScored &&
        std::abs(j["score"].get<double>() - sum) > 0.01 * double(j["tests"].size()) + 1e-9)
        bad("the score is not the sum of the tests' scores");
    return problems;
}

std::string joined(const std::vector<std::string>& lines) {
    std::string out;
    for (const std::string& l : lines) out += l + "\n";
    return out;
}

}  // namespace

TEST(Gradescope, TheValidatorRejectsWhatGradescopeDoesNotDocument) {
    const json good = json::parse(R"({"score": 3, "execution_time": 2, "output": "x",
        "visibility": "visible", "stdout_visibility": "hidden",
        "tests": [{"name": "a", "score": 1, "max_score": 2, "status": "failed",
                   "visibility": "after_due_date", "number": "1.1", "tags": ["01"]},
                  {"name": "b", "score": 2, "max_score": 2, "status": "passed"}]})");
    EXPECT_EQ(joined(gradescopeProblems(good)), "");
    const std::vector<std::pair<std::function<void(json&)>, std::string>> wrongs = {
        {[](json& j) { j["tests"][0]["status"] = "ok"; }, "status"},
        {[](json& j) { j["tests"][0]["visibility"] = "later"; }, "visibility"},
        {[](json& j) { j["stdout_visibility"] = "secret"; }, "stdout_visibility"},
        {[](json& j) { j["tests"][0]["score"] = 3; }, "not within"},
        {[](json& j) { j["tests"][1].erase("score"); }, "no score"},
        {[](json& j) { j["tests"][0]["number"] = 1.1; }, "number is not a string"},
        {[](json& j) { j["tests"][0]["tags"] = "01"; }, "tags is not a list"},
        {[](json& j) { j["execution_time"] = 2.5; }, "execution_time"},
        {[](json& j) { j["score"] = "3"; }, "score is not a number"},
        {[](json& j) { j["score"] = 4; }, "not the sum"},
        {[](json& j) { j["points"] = 4; }, "unknown top-level field"},
        {[](json& j) { j["tests"][0]["points"] = 1; }, "unknown field"},
        {[](json& j) { j = json::object(); }, "neither"},
        {[](json& j) { j["output_format"] = "plain"; }, "output formats"},
    };
    for (const auto& [spoil, expected] : wrongs) {
        json j = good;
        spoil(j);
        const std::string found = joined(gradescopeProblems(j));
        EXPECT_NE(found.find(expected), std::string::npos)
            << "expected '" << expected << "' for " << j.dump() << "\ngot: " << found;
    }
}

namespace {

// /autograder in ROOT: the unpacked bundle as source/, the upload made by
// UPLOAD in submission/; run_autograder run with the raylab of this build.
json runAutograder(const fs::path& bundle, const fs::path& root,
                   const std::function<void(const fs::path&)>& upload) {
    fs::create_directories(root / "submission");
    fs::create_directory_symlink(bundle, root / "source");
    upload(root / "submission");
    CommandResult r =
        runCommand("AUTOGRADER_ROOT=" + quote(root) + " RAYLAB_EXE=" + quote(raylabExe()) + " " +
                   quote(bundle / "run_autograder"));
    EXPECT_EQ(r.exitCode, 0) << root << ": " << r.all();
    const fs::path results = root / "results" / "results.json";
    EXPECT_TRUE(fs::exists(results)) << root;
    if (!fs::exists(results)) return json::object();
    const json j = json::parse(readFile(results));
    EXPECT_EQ(joined(gradescopeProblems(j)), "") << root << ":\n" << j.dump(1);
    return j;
}

void copyStage(const fs::path& labs, const std::string& stage, const fs::path& to) {
    fs::copy(labs / stage, to / stage, fs::copy_options::recursive);
}

}  // namespace

TEST(Gradescope, TheBundleGradesSolvedUntouchedBrokenAndEmptySubmissions) {
    ScratchDir dir;
    CommandResult made =
        runRaylab("autograder --out " + quote(dir / "out") + " --stages 01,02 --seed 7");
    ASSERT_EQ(made.exitCode, 0) << made.all();
    const fs::path zip = dir / "out" / "autograder.zip";
    ASSERT_TRUE(fs::exists(zip));
    EXPECT_EQ(filesUnder(dir / "out"), std::vector<std::string>{"autograder.zip"})
        << "nothing but the zip is left";

    // Gradescope's layout: the two scripts at the zip's root, the sources, the settings.
    CommandResult listing = runCommand("unzip -Z1 " + quote(zip));
    ASSERT_EQ(listing.exitCode, 0) << listing.all();
    for (const char* entry :
         {"\nsetup.sh\n", "\nrun_autograder\n", "\nraylab-autograder.json\n", "\nCMakeLists.txt\n",
          "\nframework/shaders/ray.glsl\n", "\nsolution/01-raycast/stage.json\n"})
        EXPECT_NE(("\n" + listing.out).find(entry), std::string::npos) << entry;
    EXPECT_EQ(listing.out.find("tests/"), std::string::npos) << "no test sources";
    EXPECT_EQ(listing.out.find("web/"), std::string::npos);
    const fs::path bundle = dir / "source";
    CommandResult unzip = runCommand("unzip -q " + quote(zip) + " -d " + quote(bundle));
    ASSERT_EQ(unzip.exitCode, 0) << unzip.all();
    EXPECT_NE(fs::status(bundle / "run_autograder").permissions() & fs::perms::owner_exec,
              fs::perms::none);
    const json config = json::parse(readFile(bundle / "raylab-autograder.json"));
    EXPECT_EQ(config["seed"], 7);
    EXPECT_EQ(config["stages"], json::array({"01-raycast", "02-shading"}));

    // setup.sh from the bundle's root finds its sources and configures the
    // headless build without Dear ImGui (apt-get and the build itself, minutes
    // long, are left out here).
    CommandResult setup = runCommand("RAYLAB_BUILD_DIR=" + quote(dir / "setup-build") + " bash " +
                                     quote(bundle / "setup.sh") + " --no-apt --configure-only");
    ASSERT_EQ(setup.exitCode, 0) << setup.all();
    const std::string cache = readFile(dir / "setup-build" / "CMakeCache.txt");
    EXPECT_NE(cache.find("RAYLAB_WINDOW:BOOL=OFF"), std::string::npos);
    EXPECT_NE(cache.find("CMAKE_HOME_DIRECTORY:INTERNAL=" + bundle.string()), std::string::npos);
    EXPECT_EQ(cache.find("IMGUI"), std::string::npos) << "no Dear ImGui in a headless build";

    // A zip of the labs folder: one extra top folder around every stage.
    const json solved = runAutograder(bundle, dir / "solved",
                                      [](const fs::path& s) { writeSolvedLabs(s / "my-labs"); });
    EXPECT_DOUBLE_EQ(solved.value("score", -1.0), 200.0);
    int seeded = 0;
    for (const json& t : solved["tests"]) {
        const bool isSeeded = t["name"].get<std::string>().find("/ seeded-") != std::string::npos;
        seeded += isSeeded;
        EXPECT_EQ(t["visibility"], isSeeded ? "after_due_date" : "visible") << t.dump();
        EXPECT_EQ(t["status"], "passed") << t.dump();
    }
    EXPECT_EQ(seeded, 6) << "three seeded views per stage";
    EXPECT_NE(
        solved["output"].get<std::string>().find("3 more checks are shown after the due date"),
        std::string::npos)
        << solved["output"];

    // The stage folders as handed out: nothing earned, and the output says what failed.
    const json untouched = runAutograder(bundle, dir / "untouched", [](const fs::path& s) {
        for (const char* stage : {"01-raycast", "02-shading"})
            copyStage(sourceDir() / "labs", stage, s);
    });
    EXPECT_LT(untouched.value("score", -1.0), 40.0);
    const std::string shown = untouched["output"];
    EXPECT_NE(shown.find("01-raycast: "), std::string::npos) << shown;
    EXPECT_NE(shown.find("front: "), std::string::npos) << "failed views and how: " << shown;
    EXPECT_EQ(shown.find("seeded-"), std::string::npos) << "hidden views stay hidden: " << shown;
    EXPECT_EQ(shown.find("Total"), std::string::npos) << "no total while tests are hidden";
    // Plain text, said so: nothing escaped for HTML.
    EXPECT_EQ(untouched.value("output_format", ""), "text");
    EXPECT_EQ(untouched.value("test_output_format", ""), "text");
    for (const char* entity : {"&#39;", "&amp;", "&lt;", "&quot;"})
        EXPECT_EQ(shown.find(entity), std::string::npos) << entity << " in " << shown;

    // A compile error in stage 01: its file and line, stage 02 still graded.
    const json broken = runAutograder(bundle, dir / "broken", [](const fs::path& s) {
        writeSolvedLabs(s);
        replaceInFile(s / "01-raycast" / "intersect_sphere.glsl", "    return",
                      "    float = 1.0;\n    return");
    });
    EXPECT_DOUBLE_EQ(broken.value("score", -1.0), 100.0);
    const std::string text = broken.dump();
    EXPECT_NE(text.find("01-raycast: compile error"), std::string::npos) << text;
    EXPECT_NE(text.find("01-raycast/intersect_sphere.glsl:"), std::string::npos) << text;
    EXPECT_EQ(text.find("raylab-work"), std::string::npos) << "the student's paths only";
    const std::string brokenOutput = broken["output"];
    EXPECT_EQ(brokenOutput.find("&#39;"), std::string::npos) << brokenOutput;
    EXPECT_NE(brokenOutput.find("'"), std::string::npos)
        << "the compiler's quotes, as they are: " << brokenOutput;

    // Nothing, and something that cannot be graded: score 0 and the cause.
    const json empty = runAutograder(bundle, dir / "empty", [](const fs::path&) {});
    EXPECT_DOUBLE_EQ(empty.value("score", -1.0), 0.0);
    EXPECT_NE(empty["output"].get<std::string>().find("nothing was submitted"), std::string::npos);
    const json loose = runAutograder(bundle, dir / "loose", [](const fs::path& s) {
        writeFile(s / "intersect_sphere.glsl", "float x;\n");
    });
    EXPECT_DOUBLE_EQ(loose.value("score", -1.0), 0.0);
    EXPECT_NE(loose["output"].get<std::string>().find("loose files, but this assignment grades 2"),
              std::string::npos)
        << loose["output"];

    // The open level (`raylab autograder --level open` writes "level": "open"):
    // the open lab as handed out earns nothing; a level the grader does not
    // know is the bundle's fault, said so.
    EXPECT_EQ(config["level"], "guided");
    json open = config;
    open["level"] = "open";
    writeFile(bundle / "raylab-autograder.json", open.dump(2));
    ASSERT_EQ(runLabgen("--level open --labs " + quote(dir / "open-labs")).exitCode, 0);
    const json openUntouched =
        runAutograder(bundle, dir / "open-untouched", [&](const fs::path& s) {
            for (const char* stage : {"01-raycast", "02-shading"})
                copyStage(dir / "open-labs", stage, s);
        });
    EXPECT_DOUBLE_EQ(openUntouched.value("score", -1.0), 0.0) << openUntouched.dump(1);
    open["level"] = "expert";
    writeFile(bundle / "raylab-autograder.json", open.dump(2));
    const fs::path badRoot = dir / "bad-level";
    fs::create_directories(badRoot / "submission");
    fs::create_directory_symlink(bundle, badRoot / "source");
    writeSolvedLabs(badRoot / "submission");
    CommandResult bad =
        runCommand("AUTOGRADER_ROOT=" + quote(badRoot) + " RAYLAB_EXE=" + quote(raylabExe()) + " " +
                   quote(bundle / "run_autograder"));
    EXPECT_NE(bad.exitCode, 0) << "the staff's log shows the bundle's fault: " << bad.all();
    const json badLevel = json::parse(readFile(badRoot / "results" / "results.json"));
    EXPECT_DOUBLE_EQ(badLevel.value("score", -1.0), 0.0);
    EXPECT_NE(badLevel["output"].get<std::string>().find("level: expected guided or open"),
              std::string::npos)
        << badLevel["output"];
}

TEST(Gradescope, ABadBundleRequestWritesNothing) {
    ScratchDir dir;
    for (const std::string& args :
         {std::string("--stages 42"), std::string("--stages 01 --seeded-visibility later"),
          std::string("--stages 01 --level expert")}) {
        CommandResult r = runRaylab("autograder --out " + quote(dir / "out") + " " + args);
        EXPECT_EQ(r.exitCode, 2) << args << "\n" << r.all();
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "one line: " << r.err;
        EXPECT_FALSE(fs::exists(dir / "out")) << args;
    }
}
