// The classroom module (framework/src/classroom/) on its own, without
// grading anything: the course file's extensions and excused stages under
// the late policy, the LMS list, pseudonyms and the paths a student may see,
// a report per section with its own files, the regrade's record in
// class.json, the cost estimate from a sample. `raylab grade` runs them end
// to end in tests/e2e.
#include "class_file.h"
#include "class_finish.h"
#include "class_sections.h"
#include "course_file.h"
#include "error.h"
#include "grade_estimate.h"
#include "lms_exports.h"
#include "pseudonyms.h"
#include "submission_times.h"
#include "test_support.h"

#include <gtest/gtest.h>

using namespace raylab;
using raylab::test::errorOf;
using raylab::test::readFile;
using raylab::test::ScratchDir;
using raylab::test::writeFile;
namespace fs = std::filesystem;

namespace {

StageResult graded(const std::string& stage, double score) {
    StageResult s;
    s.stage = stage;
    s.status = "graded";
    s.score = score;
    return s;
}

// bob and carol, 01 and 02 graded 80 each.
ClassResult twoStudents() {
    ClassResult r;
    r.stages = {"01-raycast", "02-shading"};
    for (const char* name : {"bob", "carol"}) {
        StudentResult st;
        st.name = name;
        st.stages = {graded("01-raycast", 80), graded("02-shading", 80)};
        r.students.push_back(st);
    }
    return r;
}

}  // namespace

TEST(CourseRules, AnExtensionMovesOneStudentsDeadlineAndAnExcusedStageCountsForNothing) {
    ScratchDir dir;
    writeFile(dir / "course.json", R"({
      "late": {"deadline": "2026-12-01T12:00:00Z", "penalty_per_day": 10},
      "extensions": [{"student": "bob", "stages": "02", "days": 2, "reason": "ill"},
                     {"student": "carol", "until": "2026-12-10T12:00:00Z"}],
      "excused": [{"student": "bob", "stages": "01", "reason": "exchange week"}]
    })");
    const CourseSettings course = readCourseFile(dir / "course.json");
    // Both submitted everything on 3 December, 11:00: two days late for all
    // but bob's 02 (extended by two days) and carol's (until the 10th).
    writeFile(dir / "times.csv", "student,submitted\nbob,2026-12-03T11:00:00Z\n"
                                 "carol,2026-12-03T11:00:00Z\n");
    const SubmissionTimes times = SubmissionTimes::read((dir / "times.csv").string(), dir.path());
    ClassResult r = twoStudents();
    applyCourseRules(r, course, &times, {});
    const StudentResult& bob = r.students[0];
    EXPECT_TRUE(bob.stages[0].excused);
    EXPECT_EQ(bob.stages[0].excuseNote, "exchange week");
    EXPECT_DOUBLE_EQ(bob.stages[1].score, 80) << bob.stages[1].lateNote;
    EXPECT_NE(bob.stages[1].lateNote.find("on time, extended to 2026-12-03 12:00 UTC (ill)"),
              std::string::npos)
        << bob.stages[1].lateNote;
    EXPECT_DOUBLE_EQ(bob.score(), 80) << "the excused stage counts for nothing";
    EXPECT_DOUBLE_EQ(bob.maxScore(), 100);
    const StudentResult& carol = r.students[1];
    EXPECT_DOUBLE_EQ(carol.stages[0].score, 80);
    EXPECT_DOUBLE_EQ(carol.score(), 160);
    // Without the extensions the same times cost two days: the control.
    CourseSettings plain = course;
    plain.extensions.clear();
    plain.excused.clear();
    ClassResult control = twoStudents();
    applyCourseRules(control, plain, &times, {});
    EXPECT_DOUBLE_EQ(control.students[0].stages[1].score, 64);
    EXPECT_DOUBLE_EQ(control.students[1].score(), 128);
}

TEST(CourseRules, BadExtensionsAreOneLineErrorsNamingTheKey) {
    ScratchDir dir;
    auto error = [&](const std::string& text) {
        writeFile(dir / "course.json", text);
        return errorOf([&] { readCourseFile(dir / "course.json"); });
    };
    const std::string late = R"("late": {"deadline": "2026-12-01T12:00:00Z"})";
    EXPECT_NE(error("{" + late + R"(, "extensions": [{"student": "bob"}]})")
                  .find("extensions[0]: give \"days\""),
              std::string::npos);
    EXPECT_NE(error("{" + late + R"(, "extensions": [{"student": "bob", "days": -1}]})")
                  .find("extensions[0].days"),
              std::string::npos);
    EXPECT_NE(error(R"({"extensions": [{"student": "bob", "days": 1}]})").find("no late policy"),
              std::string::npos);
    EXPECT_NE(
        error(R"({"excused": [{"student": "bob", "stages": "09"}]})").find("excused[0].stages"),
        std::string::npos);
    EXPECT_NE(error(R"({"excused": [{"stages": "01"}]})").find("no \"student\""),
              std::string::npos);
    EXPECT_NE(
        error(R"({"lms": {"canvas_assignments": {"01": "x1"}}})").find("lms.canvas_assignments.01"),
        std::string::npos);
}

TEST(LmsExports, TheListNamesKnownLmssOnly) {
    EXPECT_EQ(parseLmsList("canvas, moodle,canvas"),
              (std::vector<std::string>{"canvas", "moodle"}));
    EXPECT_TRUE(parseLmsList("").empty());
    EXPECT_NE(errorOf([] { parseLmsList("canvas,sakai"); }).find("'sakai' is not an LMS"),
              std::string::npos);
}

TEST(StudentText, NoMachinePathAndNoNameWhenAnonymised) {
    ScratchDir dir;
    const fs::path submissions = dir / "class";
    fs::create_directories(submissions / "alice/01-raycast");
    const std::string message =
        (fs::absolute(submissions) / "alice/01-raycast/shade.glsl").string() + ":12: error";
    EXPECT_EQ(withoutMachinePath(message, "alice", submissions),
              "alice/01-raycast/shade.glsl:12: error");
    EXPECT_EQ(withoutName(message, "alice", "student-1234abcd", submissions),
              "student-1234abcd/01-raycast/shade.glsl:12: error");
    EXPECT_EQ(withoutMachinePath("nothing to hide", "alice", submissions), "nothing to hide");
}

TEST(Sections, EachSectionGetsItsOwnReportAndItsStudentsFilesOnly) {
    ScratchDir dir;
    ClassResult r = twoStudents();
    r.students[0].roster.section = "Mon 10:00";
    r.students[1].roster.section = "Tue";
    for (const char* name : {"bob", "carol"})
        writeFile(dir / "students" / name / "01-raycast/front.png", name);
    writeFile(dir / "reference/01-raycast/front.png", "ref");
    const auto links = writeSectionReports(r, dir.path());
    ASSERT_EQ(links.size(), 2u);
    EXPECT_EQ(links[0], std::make_pair(std::string("Mon 10:00"),
                                       std::string("sections/Mon_10_00/report.html")));
    const fs::path mon = dir / "sections/Mon_10_00";
    EXPECT_NE(readFile(mon / "report.html").find("section Mon 10:00"), std::string::npos);
    EXPECT_EQ(readFile(mon / "students/bob/01-raycast/front.png"), "bob");
    EXPECT_TRUE(fs::exists(mon / "students/bob/report.html"));
    EXPECT_FALSE(fs::exists(mon / "students/carol")) << "another section's student";
    EXPECT_EQ(readFile(mon / "reference/01-raycast/front.png"), "ref");
    EXPECT_NE(readFile(mon / "summary.csv").find("bob"), std::string::npos);
    EXPECT_EQ(readFile(mon / "summary.csv").find("carol"), std::string::npos);
    // No sections: no folder, and none of an earlier run left.
    for (StudentResult& st : r.students) st.roster.section.clear();
    EXPECT_TRUE(writeSectionReports(r, dir.path()).empty());
    EXPECT_FALSE(fs::exists(dir / "sections"));
    EXPECT_EQ(sectionFolderName(".."), "_..");
    EXPECT_EQ(sectionFolderName("A/B"), "A_B");
}

TEST(Estimate, FromASampleToTheClassThisMachineSlurmAndGradescope) {
    // A sample of 3 x 2 stages: five items of 2-4 s, one not submitted, one
    // endless loop (left out of the average: it costs the timeout once).
    const std::vector<ItemCost> items = {{2, 300, false}, {3, 310, false}, {4, 420, false},
                                         {3, 280, false}, {3, 300, false}, {60, 900, true}};
    const ClassEstimate e = estimateFrom(items, 1, 20.0, 200, 2, 3, 2);
    EXPECT_DOUBLE_EQ(e.itemSeconds, 3.0);
    EXPECT_DOUBLE_EQ(e.itemMaxSeconds, 4.0);
    EXPECT_DOUBLE_EQ(e.peakMb, 420) << "the endless loop's memory is not a typical stage's";
    EXPECT_NEAR(e.submittedShare, 6.0 / 7.0, 1e-12);
    EXPECT_DOUBLE_EQ(e.fixedSeconds, 20.0 - 15.0 / 2.0);
    // 400 items, 6/7 of them submitted, 3 s each, 2 at a time, plus the references.
    EXPECT_NEAR(e.classSeconds(), 12.5 + 400.0 * 6.0 / 7.0 * 3.0 / 2.0, 1e-9);
    EXPECT_NEAR(e.taskSeconds(4, 2), 12.5 + 50.0 * 2.0 * 6.0 / 7.0 * 3.0 / 2.0, 1e-9);
    EXPECT_LT(e.taskSeconds(8, 2), e.taskSeconds(4, 2));
    EXPECT_GT(e.uploadSeconds(), 2.0 * 2.0 * 3.0 * 6.0 / 7.0) << "half a CPU";
    GradeOptions g;
    const std::string text = describeEstimate(e, g);
    EXPECT_NE(text.find("3 of 200 students x 2 stages"), std::string::npos) << text;
    EXPECT_NE(text.find("420 MB at most"), std::string::npos) << text;
    EXPECT_NE(text.find("16 tasks"), std::string::npos) << text;
    // The sample spreads over the class, ends included.
    const std::vector<std::string> names = {"a", "b", "c", "d", "e", "f", "g"};
    EXPECT_EQ(sampleStudents(names, 3), (std::vector<std::string>{"a", "d", "g"}));
    EXPECT_EQ(sampleStudents(names, 9), names);
}

TEST(ClassFile, KeepsEachStudentsRegrades) {
    ScratchDir dir;
    ClassResult r = twoStudents();
    r.students[1].regrades.push_back(
        {"2026-12-07 09:14 UTC", "upload fixed", {{"02-shading", "0", "80"}}});
    writeClassFile(r, {}, dir.path());
    const ClassResult back = readClassFile(dir.path());
    ASSERT_EQ(back.students[1].regrades.size(), 1u);
    EXPECT_EQ(back.students[1].regrades[0].reason, "upload fixed");
    EXPECT_EQ(back.students[1].regrades[0].changes[0].after, "80");
    EXPECT_TRUE(back.students[0].regrades.empty());
}

TEST(Pseudonyms, KeyedStableWithTheKeyFileAndUnlikeEachOther) {
    ScratchDir dir;
    PseudonymKey key(dir / "key.json");
    const std::string alice = key.pseudonym("alice");
    EXPECT_EQ(alice.rfind("student-", 0), 0u);
    EXPECT_EQ(alice.size(), std::string("student-").size() + 8);
    EXPECT_EQ(alice.find("alice"), std::string::npos);
    EXPECT_NE(alice, key.pseudonym("alicf"));
    EXPECT_EQ(key.nameOf(alice), "alice");
    key.save();
    PseudonymKey again(dir / "key.json");
    EXPECT_EQ(again.pseudonym("alice"), alice) << "the same key file, the same pseudonym";
    EXPECT_EQ(again.nameOf(alice), "alice");
    PseudonymKey other(dir / "other.json");
    EXPECT_NE(other.pseudonym("alice"), alice) << "another key, another pseudonym";
    writeFile(dir / "bad.json", "{}");
    EXPECT_THROW(PseudonymKey(dir / "bad.json"), Error);
}
