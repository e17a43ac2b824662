// `raylab grade` on a class of 30 generated submissions (raylab-classgen):
// pristine solutions, untouched labs, partial submissions, every known
// mistake and every broken submission of tests/grading/broken/. The scores
// must match what classgen expects: pristine 100% everywhere, every mistake
// loses points on its own stage and nowhere else, each broken submission is
// reported with its status while grading goes on, and nobody's score depends
// on anybody else's. The wall time is printed (a benchmark figure, not
// asserted: see the README's grading section).
#include "stage_catalog.h"
#include "test_support.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <map>
#include <regex>

using namespace raylab::test;
using nlohmann::json;

namespace {

#ifndef RAYLAB_CLASSGEN_EXE
#error RAYLAB_CLASSGEN_EXE must be defined by CMake
#endif

bool statusMatches(const std::string& status, const std::string& alternatives) {
    std::size_t start = 0;
    while (true) {
        std::size_t bar = alternatives.find('|', start);
        if (alternatives.substr(start, bar - start) == status) return true;
        if (bar == std::string::npos) return false;
        start = bar + 1;
    }
}

}  // namespace

TEST(GradeClass, ThirtySubmissionsScoreAsExpected) {
    ScratchDir dir;
    CommandResult gen = runCommand(quote(RAYLAB_CLASSGEN_EXE) + " " + quote(dir.path().string()));
    ASSERT_EQ(gen.exitCode, 0) << gen.all();
    const json expected = json::parse(readFile(dir / "expected.json"));
    ASSERT_EQ(expected.size(), 30u);

    auto start = std::chrono::steady_clock::now();
    CommandResult r =
        runRaylab("grade --submissions " + quote((dir / "submissions").string()) + " --out " +
                  quote((dir / "out").string()) + " --jobs 2 --timeout 10 --seed 7");
    double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("[ figure   ] 30 students x %zu stages graded in %.1f s with --jobs 2\n",
                raylab::allStages().size(), seconds);
    ASSERT_EQ(r.exitCode, 0) << r.all();
    std::smatch once;
    if (std::regex_search(r.out, once, std::regex(R"((\d+) of (\d+) items the same work)")))
        std::printf("[ figure   ] %s of %s items the same work as another student's: graded "
                    "once\n",
                    once[1].str().c_str(), once[2].str().c_str());

    int checked = 0;
    for (const auto& [student, stages] : expected.items()) {
        SCOPED_TRACE(student);
        const fs::path resultsFile = dir / "out" / "students" / student / "results.json";
        ASSERT_TRUE(fs::exists(resultsFile));
        for (const auto& [stage, want] : stages.items()) {
            if (stage == "_mistakes") continue;
            SCOPED_TRACE(stage);
            const fs::path stageResult = dir / "out" / "students" / student / stage / "result.json";
            const std::string w = want;
            if (w == "not submitted") {
                EXPECT_FALSE(fs::exists(stageResult));
                EXPECT_NE(readFile(dir / "out" / "summary.csv").find(stage + ": not submitted"),
                          std::string::npos);
                ++checked;
                continue;
            }
            // A child that died leaves no result.json: its status is in the Gradescope file.
            json gs = json::parse(readFile(resultsFile));
            double stageScore = 0, stageMax = 0;
            std::string notGraded;
            for (const auto& t : gs["tests"]) {
                std::string name = t["name"];
                if (name.rfind(stage + " / ", 0) == 0) {
                    stageScore += t["score"].get<double>();
                    stageMax += t["max_score"].get<double>();
                } else if (name.rfind(stage + ": ", 0) == 0) {
                    notGraded = name.substr(stage.size() + 2);
                    stageMax += t["max_score"].get<double>();
                }
            }
            EXPECT_NEAR(stageMax, 100.0, 0.05);
            if (w == "100") {
                EXPECT_TRUE(notGraded.empty()) << notGraded;
                EXPECT_NEAR(stageScore, 100.0, 0.05);
            } else if (w == "<100") {
                EXPECT_TRUE(notGraded.empty()) << notGraded;
                EXPECT_LT(stageScore, 99.5) << "a mistake or an unfinished lab must lose points";
            } else {
                ASSERT_EQ(w.rfind("status:", 0), 0u) << w;
                EXPECT_TRUE(statusMatches(notGraded, w.substr(7)))
                    << "status '" << notGraded << "', expected " << w;
                EXPECT_EQ(stageScore, 0.0);
            }
            ++checked;
        }
    }
    EXPECT_EQ(checked, 30 * int(raylab::allStages().size()));

    // Fair scores (docs/grading.md): every catalogued mistake costs at least
    // 5 of its stage's 100 points, one of the stage's skill ("central") at
    // least 30; the table of what each costs is the one in docs/grading.md.
    std::map<std::string, std::pair<double, bool>> lost;  // "stage | mistake" -> (points, central)
    for (const auto& [student, stages] : expected.items()) {
        if (!stages.contains("_mistakes")) continue;
        for (const auto& file : stages["_mistakes"]) {
            const json spec = json::parse(readFile(sourceDir() / file.get<std::string>()));
            const std::string stage = spec["stage"];
            const json result =
                json::parse(readFile(dir / "out" / "students" / student / stage / "result.json"));
            const double points = 100.0 - result["score"].get<double>();
            const bool central = spec.value("central", false);
            const std::string name = fs::path(file.get<std::string>()).stem().string();
            lost[stage + " | " + name] = {points, central};
            EXPECT_GE(points, central ? 30.0 : 5.0)
                << student << " " << stage << " " << name << (central ? " (central)" : "");
        }
    }
    std::size_t catalogued = 0;
    for (const raylab::StageInfo& s : raylab::allStages())
        for (const auto& e : fs::directory_iterator(sourceDir() / s.mistakes))
            catalogued += e.path().extension() == ".json";
    EXPECT_EQ(lost.size(), catalogued) << "every catalogued mistake is graded";
    std::string table =
        "| stage | mistake | the stage's skill | points lost |\n| --- | --- | --- | --- |\n";
    for (const auto& [key, value] : lost) {
        char points[32];
        std::snprintf(points, sizeof points, "%.1f", value.first);
        table += "| " + key.substr(0, key.find(" | ")) + " | " + key.substr(key.find(" | ") + 3) +
                 " | " + (value.second ? "yes" : "") + " | " + points + " |\n";
    }
    const fs::path doc = sourceDir() / "docs" / "grading.md";
    const std::string text = readFile(doc);
    const std::string open =
                          "<!-- mistakes-table: GradeClass.ThirtySubmissionsScoreAsExpected -->\n",
                      close = "<!-- /mistakes-table -->";
    const std::size_t a = text.find(open), b = text.find(close);
    ASSERT_TRUE(a != std::string::npos && b != std::string::npos) << doc;
    const std::string documented = text.substr(a + open.size(), b - a - open.size());
    if (std::getenv("RAYLAB_UPDATE_DOCS")) {
        writeFile(doc, text.substr(0, a + open.size()) + table + text.substr(b));
    } else {
        EXPECT_EQ(documented, table)
            << "docs/grading.md's table differs from what grading gives now; rerun this test "
               "with RAYLAB_UPDATE_DOCS=1 to write it";
    }
    std::printf("[ figure   ] %zu catalogued mistakes graded, the table of docs/grading.md\n",
                lost.size());

    // The broken submissions are explained in the report.
    const std::string html = readFile(dir / "out" / "report.html") + studentPages(dir / "out");
    EXPECT_NE(html.find("fin.geom:"), std::string::npos)
        << "the broken geometry shader's file and line";
    EXPECT_NE(html.find("intersect_sphere.glsl:"), std::string::npos)
        << "the compile error names the student's file";
    EXPECT_NE(html.find("timed out"), std::string::npos);
    EXPECT_NE(html.find("NaN or Inf"), std::string::npos);
    EXPECT_NE(html.find("is not allowed"), std::string::npos);
    for (const char* file : {"summary.csv", "junit.xml", "report.html"})
        EXPECT_TRUE(fs::exists(dir / "out" / file)) << file;
    // The class page stays small: pictures live on the students' own pages.
    const std::uintmax_t index = fs::file_size(dir / "out" / "report.html");
    EXPECT_LT(index, 1u << 20);
    EXPECT_EQ(readFile(dir / "out" / "report.html").find("<img"), std::string::npos);
    std::printf("[ figure   ] report.html for %zu students: %ju bytes\n", std::size_t(30), index);
}

// The same work handed in by several students (a team's code in each
// member's folder) is graded once (same_work.h): each gets the result, with
// the pictures in their own folder; a result that names its student (a
// compile error names the file's folder) is not given on: that work is
// graded again for each.
TEST(GradeClass, TheSameWorkIsGradedOnceAndEachStudentKeepsTheirOwnPictures) {
    ScratchDir dir;
    ScratchDir solved;
    writeSolvedLabs(solved.path());
    const fs::path subs = dir / "submissions";
    for (const char* name : {"ada", "ben", "cid", "dan"}) {
        fs::create_directories(subs / name);
        fs::copy(solved / "01-raycast", subs / name / "01-raycast", fs::copy_options::recursive);
    }
    for (const char* name : {"cid", "dan"}) {
        const fs::path file = subs / name / "01-raycast" / "intersect_sphere.glsl";
        writeFile(file, readFile(file) + "\nthis is not GLSL\n");
    }
    CommandResult r = runRaylab("grade --submissions " + quote(subs.string()) + " --out " +
                                quote((dir / "out").string()) + " --stages 01 --jobs 2");
    ASSERT_EQ(r.exitCode, 0) << r.all();
    EXPECT_NE(r.out.find("raylab grade: 1 of 4 items the same work as another student's: graded "
                         "once"),
              std::string::npos)
        << r.out;
    auto result = [&](const std::string& name) {
        return json::parse(readFile(dir / "out/students" / name / "01-raycast/result.json"));
    };
    const json ada = result("ada"), ben = result("ben");
    EXPECT_EQ(ada["score"], 100.0);
    // Ben's copy ran no child: no time of its own in the class's results
    // (ada's is the grading's), which grade --estimate adds up.
    const json whole = json::parse(readFile(dir / "out/class.json"));
    std::map<std::string, double> seconds;
    for (const json& st : whole["students"]) seconds[st["name"]] = st["stages"][0]["seconds"];
    EXPECT_GT(seconds["ada"], 0.0);
    EXPECT_EQ(seconds["ben"], 0.0);
    ASSERT_EQ(ada["checks"].size(), ben["checks"].size());
    int pictures = 0;
    for (std::size_t i = 0; i < ada["checks"].size(); ++i) {
        const json &a = ada["checks"][i], &b = ben["checks"][i];
        EXPECT_EQ(a["score"], b["score"]);
        EXPECT_EQ(a["output"], b["output"]);
        if (!a.contains("student_image") || a["student_image"] == "") continue;  // a function
        const std::string mine = b["student_image"];
        EXPECT_EQ(mine.rfind("students/ben/01-raycast/", 0), 0u) << mine;
        EXPECT_TRUE(fs::is_regular_file(dir / "out" / mine)) << mine;
        ++pictures;
    }
    EXPECT_GT(pictures, 5);
    EXPECT_EQ(readFile(dir / "out/students/ben/01-raycast/result.json").find("ada"),
              std::string::npos);
    // The compile errors name each student's own file.
    for (const char* name : {"cid", "dan"}) {
        const json c = result(name);
        EXPECT_EQ(c["status"], "compile error");
        const std::string message = c["message"];
        EXPECT_NE(message.find(std::string(name) + "/01-raycast/intersect_sphere.glsl"),
                  std::string::npos)
            << message;
    }
}
