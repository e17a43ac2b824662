// The course's data behind grading and handouts: stage lists, the grading
// weights and credit curves, course files with their late policy, the CSV an
// instructor gives, what a handout puts where.
#include "class_finish.h"
#include "course_file.h"
#include "csv_text.h"
#include "error.h"
#include "handout.h"
#include "stage_list.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>

using namespace raylab;
using raylab::test::errorOf;
using raylab::test::ScratchDir;
using raylab::test::writeFile;

namespace {

std::vector<std::string> ids(const std::string& list) { return parseStageIds(list); }

}  // namespace

TEST(StageList, RangesListsAndAllInCourseOrder) {
    EXPECT_EQ(ids("01-03"), (std::vector<std::string>{"01-raycast", "02-shading", "03-shadows"}));
    EXPECT_EQ(ids("03,01"), (std::vector<std::string>{"01-raycast", "03-shadows"}));
    EXPECT_EQ(ids("f1-f2, 01"), (std::vector<std::string>{"01-raycast", "f1-mesh", "f2-shells"}));
    EXPECT_EQ(ids("02-shading"), std::vector<std::string>{"02-shading"});
    EXPECT_EQ(ids("01-02,02-03"),
              (std::vector<std::string>{"01-raycast", "02-shading", "03-shadows"}));
    EXPECT_EQ(ids("all").size(), allStages().size());
}

TEST(StageList, BadListsAreOneLineErrorsNamingTheOption) {
    EXPECT_NE(errorOf([] { ids("01-f2"); }).find("different tracks"), std::string::npos);
    EXPECT_NE(errorOf([] { ids("03-01"); }).find("comes after"), std::string::npos);
    EXPECT_NE(errorOf([] { ids("42"); }).find("unknown stage '42'"), std::string::npos);
    EXPECT_NE(errorOf([] { ids("01,,02"); }).find("an empty item"), std::string::npos);
    EXPECT_NE(errorOf([] { ids(""); }).find("no stage given"), std::string::npos);
    EXPECT_NE(errorOf([] { parseStageList("01-99", "--stages"); }).find("--stages 01-99"),
              std::string::npos);
}

// The credit falls with what a check measured, with no jump anywhere.
TEST(StageGrading, CreditCurvesHaveNoCliff) {
    EXPECT_EQ(viewCredit(0.0), 1.0);
    EXPECT_EQ(viewCredit(0.005), 1.0);
    EXPECT_GT(viewCredit(0.0051), 0.98) << "just past the tolerance costs almost nothing";
    EXPECT_NEAR(viewCredit(0.01), 0.77, 0.005);
    EXPECT_NEAR(viewCredit(0.05), 0.23, 0.005);
    EXPECT_EQ(viewCredit(kViewZeroShare), 0.0);
    EXPECT_EQ(viewCredit(0.5), 0.0);
    double previous = 1.0, worstStep = 0.0;
    for (double share = 0.0; share <= 0.2; share += 0.0001) {
        const double c = viewCredit(share);
        EXPECT_LE(c, previous + 1e-12) << share;
        worstStep = std::max(worstStep, previous - c);
        previous = c;
    }
    EXPECT_LT(worstStep, 0.01) << "a step of 0.01% of the pixels never costs 1% of the points";
    EXPECT_EQ(caseCredit(0.0), 1.0);
    EXPECT_NEAR(caseCredit(0.05), 0.8, 1e-12);
    EXPECT_EQ(caseCredit(kCaseZeroShare), 0.0);
    EXPECT_EQ(caseCredit(1.0), 0.0);
}

TEST(StageGrading, PointsFollowTheWeightsAndAddUpTo100) {
    StageGrading g;
    g.viewPoints = 50;
    g.weights = {{"far", 2.0}, {"off", 0.0}, {"lightVisible", 3.0}};
    const std::vector<double> p =
        checkPoints(g, {"front", "far", "off", "front"}, {"lightVisible", "other"});
    ASSERT_EQ(p.size(), 6u);
    EXPECT_DOUBLE_EQ(p[0], 12.5);  // 50 * 1/4
    EXPECT_DOUBLE_EQ(p[1], 25.0);  // 50 * 2/4
    EXPECT_DOUBLE_EQ(p[2], 0.0);
    EXPECT_DOUBLE_EQ(p[4], 37.5);  // 50 * 3/4
    EXPECT_DOUBLE_EQ(p[5], 12.5);
    EXPECT_DOUBLE_EQ(std::accumulate(p.begin(), p.end(), 0.0), 100.0);
    // No function or count check: the views get all 100.
    const std::vector<double> only = checkPoints(g, {"a", "b"}, {});
    EXPECT_DOUBLE_EQ(only[0] + only[1], 100.0);
}

TEST(StageGrading, EveryStageSharesItsHundredPoints) {
    for (const StageInfo& s : allStages()) {
        std::vector<std::string> views, others(s.functionChecks);
        for (const CheckView& v : s.checkViews) views.push_back(v.name);
        others.insert(others.end(), s.countChecks.begin(), s.countChecks.end());
        const std::vector<double> p = checkPoints(s.grading, views, others);
        EXPECT_NEAR(std::accumulate(p.begin(), p.end(), 0.0), 100.0, 1e-9) << s.id;
    }
}

TEST(StageGrading, WeightsForChecksTheStageDoesNotHaveAreRefused) {
    const StageInfo& stage = findStage("03");
    StageGrading g = stage.grading;
    g.weights["lightvisible"] = 2;  // a typo
    EXPECT_NE(errorOf([&] {
                  validateGrading(g, stage, "x.json: grading");
              }).find("x.json: grading.weights.lightvisible: not a check of 03-shadows"),
              std::string::npos);
    g.weights = {{"lightVisible", -1}};
    EXPECT_NE(errorOf([&] { validateGrading(g, stage, "x"); }).find("expected a weight"),
              std::string::npos);
    g.weights = {{"lightVisible", 0}};
    EXPECT_NE(errorOf([&] { validateGrading(g, stage, "x"); }).find("add up to 0"),
              std::string::npos);
    g = stage.grading;
    g.viewPoints = 120;
    EXPECT_NE(errorOf([&] { validateGrading(g, stage, "x"); }).find("from 0 to 100"),
              std::string::npos);
}

TEST(StageGrading, TheGuideSectionIsWrittenFromTheWeights) {
    const StageInfo& stage = findStage("03");
    StageGrading g = stage.grading;
    g.viewPoints = 40;
    const std::string guide = "# Lab\n\n## How you are graded\n\n<!-- grading: generated -->\nold "
                              "text\n<!-- /grading -->\n\n## Next\n";
    const std::string out = withGradingSection(guide, stage, g);
    EXPECT_NE(out.find("**Images, 40 points**"), std::string::npos) << out;
    EXPECT_NE(out.find("`lightVisible` 60"), std::string::npos) << out;
    EXPECT_EQ(out.find("old text"), std::string::npos);
    EXPECT_NE(out.find("<!-- /grading -->\n\n## Next\n"), std::string::npos);
    EXPECT_EQ(withGradingSection("no markers", stage, g), "no markers");
    EXPECT_THROW(withGradingSection("<!-- grading: x -->\nnever closed", stage, g), Error);
}

TEST(CourseFile, OverridesWeightsAndReadsALatePolicy) {
    ScratchDir dir;
    writeFile(dir / "course.json", R"({
      "stages": {"03": {"grading": {"views": 40, "weights": {"front": 2}}}},
      "late": {"deadline": "2026-12-10T23:59:00+01:00", "deadlines": {"02": "2026-12-20T12:00:00Z"},
               "grace_minutes": 15, "penalty_per_day": 10, "max_penalty": 25}
    })");
    const CourseSettings c = readCourseFile(dir / "course.json");
    const StageGrading& g = c.gradingOf(findStage("03"));
    EXPECT_EQ(g.viewPoints, 40);
    EXPECT_EQ(g.weight("front"), 2);
    EXPECT_EQ(&c.gradingOf(findStage("01")), &findStage("01").grading)
        << "others keep stage.json's";
    ASSERT_TRUE(c.late);
    const std::int64_t due = parseIsoTime("2026-12-10T22:59:00Z", "t");
    EXPECT_EQ(c.late->daysLate("01-raycast", due + 14 * 60), 0) << "within the grace minutes";
    EXPECT_EQ(c.late->daysLate("01-raycast", due + 16 * 60), 1) << "a part of a day is a day";
    EXPECT_EQ(c.late->daysLate("01-raycast", due + 86400 + 16 * 60), 2);
    EXPECT_EQ(c.late->penaltyPercent("01-raycast", due + 86400 + 16 * 60), 20);
    EXPECT_EQ(c.late->penaltyPercent("01-raycast", due + 9 * 86400), 25) << "capped";
    EXPECT_EQ(c.late->daysLate("02-shading", due + 3 * 86400), 0) << "its own deadline";
}

TEST(CourseFile, MistakesAreOneLineErrorsNamingFileAndKey) {
    ScratchDir dir;
    const struct {
        const char* json;
        const char* expected;
    } cases[] = {
        {R"({"stage": {}})", "unknown key"},
        {R"({"stages": {"99": {}}})", "stages.99: unknown stage"},
        {R"({"stages": {"03": {"grading": {"weights": {"frnt": 1}}}}})", "not a check of 03"},
        {R"({"late": {"deadline": "next friday"}})", "late.deadline: 'next friday' is not a time"},
        {R"({"late": {"deadline": "2026-12-10T23:59:00"}})", "with a zone"},
        {R"({"late": {"penalty_per_day": 10}})", "needs a deadline"},
        {R"({"late": {"deadline": "2026-12-10T23:59Z", "penalty_per_day": 120}})", "percentage"},
    };
    for (const auto& c : cases) {
        writeFile(dir / "c.json", c.json);
        const std::string e = errorOf([&] { readCourseFile(dir / "c.json"); });
        EXPECT_NE(e.find("c.json"), std::string::npos) << e;
        EXPECT_NE(e.find(c.expected), std::string::npos) << c.json << " -> " << e;
        EXPECT_EQ(e.find('\n'), std::string::npos) << e;
    }
}

TEST(CourseFile, IsoTimesNeedAZoneAndARealDate) {
    EXPECT_EQ(parseIsoTime("1970-01-01T00:00:00Z", "t"), 0);
    EXPECT_EQ(parseIsoTime("1970-01-01T01:00+01:00", "t"), 0);
    EXPECT_EQ(parseIsoTime("1970-01-01 00:00:30.25Z", "t"), 30);
    EXPECT_EQ(parseIsoTime("2026-12-10T23:59:00-05:00", "t"),
              parseIsoTime("2026-12-11T04:59:00Z", "t"));
    EXPECT_EQ(formatUtc(parseIsoTime("2026-12-11T04:59:00Z", "t")), "2026-12-11 04:59 UTC");
    for (const char* bad : {"2026-02-30T00:00Z", "2026-12-10", "2026-13-01T00:00Z",
                            "2026-12-10T25:00Z", "2026-12-10T10:00+1"})
        EXPECT_THROW(parseIsoTime(bad, "t"), Error) << bad;
}

TEST(Csv, QuotesLineEndsAndAByteOrderMark) {
    const CsvTable t = parseCsv(
        "\xEF\xBB\xBFStudent ,Name\r\nalice,\"Doe, \"\"Al\"\"\"\r\n\r\nbob,\"two\nlines\"\n",
        "r.csv");
    EXPECT_EQ(t.column("student"), 0) << "names ignore case and surrounding space";
    EXPECT_EQ(t.column("name"), 1);
    EXPECT_EQ(t.column("id"), -1);
    ASSERT_EQ(t.rows.size(), 2u);
    EXPECT_EQ(t.rows[0][1], "Doe, \"Al\"");
    EXPECT_EQ(t.rows[1][1], "two\nlines");
    EXPECT_EQ(t.lines[1], 4);
    EXPECT_NE(errorOf([] { parseCsv("a,b\n1,2,3\n", "r.csv"); }).find("r.csv: line 2: 3 fields"),
              std::string::npos);
    EXPECT_NE(errorOf([] { parseCsv("a\n\"open\n", "r.csv"); }).find("not closed"),
              std::string::npos);
    EXPECT_NE(errorOf([] { parseCsv("", "r.csv"); }).find("empty"), std::string::npos);
}

// A handout never holds the solution of a stage it hands out: a later stage's
// folder holds its own files, and reads the earlier ones from the student's.
TEST(Handout, AStageFolderHoldsItsOwnFilesAndReadsTheRestFromTheStudents) {
    const std::vector<HandoutStage> plan = planHandout(parseStageList("01-03"), Carry::Own);
    ASSERT_EQ(plan.size(), 3u);
    EXPECT_EQ(plan[2].ownFiles, std::vector<std::string>{"light_visibility.glsl"});
    EXPECT_TRUE(plan[2].carried.empty());
    ASSERT_TRUE(plan[2].fromStudent.count("02-shading"));
    ASSERT_TRUE(plan[2].fromStudent.count("01-raycast"));
    const auto& from02 = plan[2].fromStudent.at("02-shading");
    EXPECT_NE(std::find(from02.begin(), from02.end(), "blinn_phong.glsl"), from02.end());
    EXPECT_EQ(std::find(from02.begin(), from02.end(), "light_visibility.glsl"), from02.end())
        << "03's own file replaces 02's";

    // Stage 03 alone, carrying the earlier stages solved: they are not handed out.
    const std::vector<HandoutStage> solved = planHandout(parseStageList("03"), Carry::Solved);
    EXPECT_TRUE(solved[0].fromStudent.empty());
    EXPECT_TRUE(solved[0].carried.count("01-raycast") && solved[0].carried.count("02-shading"));
    // 02 and 03 released, carried solved: 01 solved, 02 never (it is handed out).
    const std::vector<HandoutStage> both = planHandout(parseStageList("02-03"), Carry::Solved);
    EXPECT_TRUE(both[1].carried.count("01-raycast"));
    EXPECT_FALSE(both[1].carried.count("02-shading"));
    EXPECT_TRUE(both[1].fromStudent.count("02-shading"));
}

TEST(Handout, TheGuideSaysWhereEveryFileComesFrom) {
    const std::string guide = "# Lab 03\n\nintro\n\n<!-- provided -->\nEverything from labs 01 and "
                              "02 is provided, solved.\n<!-- /provided -->\n\n## 1. Next\n";
    const std::vector<HandoutStage> own = planHandout(parseStageList("01-03"), Carry::Own);
    const std::string text = handoutGuide(guide, own[2]);
    EXPECT_EQ(text.find("provided, solved"), std::string::npos) << text;
    EXPECT_EQ(text.find("<!--"), std::string::npos) << text;
    EXPECT_NE(text.find("`light_visibility.glsl`"), std::string::npos) << text;
    EXPECT_NE(text.find("`02-shading/` (`blinn_phong.glsl`"), std::string::npos) << text;
    EXPECT_NE(text.find("## 1. Next"), std::string::npos);
    // Every earlier file in the folder, solved: the guide's own words stay.
    const std::vector<HandoutStage> solved = planHandout(parseStageList("03"), Carry::Solved);
    EXPECT_NE(handoutGuide(guide, solved[0]).find("Everything from labs 01 and 02 is provided"),
              std::string::npos);
}
