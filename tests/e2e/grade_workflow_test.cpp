// A course's everyday grading on a small class (stages 01 and 02): a roster
// and Canvas's import, a late policy from a course file, a regrade of one
// student into the existing report, anonymised reports for TAs, and the class
// summary's catalogued mistakes. Each also fails on a wrong input.
#include "test_support.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <sstream>

using namespace raylab::test;
using nlohmann::json;

namespace {

// alice solved 01 and 02; bob solved 01 and made a catalogued mistake in 02
// (Phong's reflected vector); carol handed in 01 only, solved.
void writeClass(const fs::path& solved, const fs::path& cls) {
    for (const char* student : {"alice", "bob", "carol"})
        for (const char* stage : {"01-raycast", "02-shading"}) {
            if (std::string(student) == "carol" && std::string(stage) == "02-shading") continue;
            fs::create_directories(cls / student);
            fs::copy(solved / stage, cls / student / stage, fs::copy_options::recursive);
        }
    const json mistake = json::parse(
        readFile(sourceDir() / "tests/mistakes/02-shading/phong-instead-of-blinn.json"));
    for (const auto& pair : mistake["replace"])
        replaceInFile(cls / "bob" / "02-shading" / mistake["file"].get<std::string>(), pair[0],
                      pair[1]);
}

std::string grade(const fs::path& dir, const std::string& args) {
    CommandResult r =
        runCommand("cd " + quote(dir) + " && " + quote(raylabExe()) +
                   " grade --submissions class --stages 01-02 --jobs 2 --seed 3 " + args);
    EXPECT_EQ(r.exitCode, 0) << args << "\n" << r.all();
    return r.all();
}

std::size_t count(const std::string& text, const std::string& what) {
    std::size_t n = 0;
    for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1))
        ++n;
    return n;
}

std::string row(const std::string& csv, const std::string& student) {
    const std::size_t at = csv.find("\n" + student + ",");
    if (at == std::string::npos) return "";
    return csv.substr(at + 1, csv.find("\r\n", at + 1) - at - 1);
}

}  // namespace

TEST(GradeWorkflow, RosterLatePolicyCanvasAndTheClassSummary) {
    ScratchDir dir, solved;
    writeSolvedLabs(solved.path());
    writeClass(solved.path(), dir / "class");
    writeFile(dir / "roster.csv", "student,id,name,canvas_id,login_id,section\n"
                                  "alice,s1,\"Liddell, Alice\",101,alice1,A\n"
                                  "bob,s2,\"Builder, Bob\",102,bob2,A\n"
                                  "dave,s4,\"Bowman, Dave\",104,dave4,B\n");
    writeFile(dir / "course.json", R"({"late": {"deadline": "2026-12-01T12:00:00Z",
        "penalty_per_day": 10, "max_penalty": 30},
        "extensions": [{"student": "alice", "stages": "02", "days": 1, "reason": "ill"}],
        "excused": [{"student": "dave", "stages": "02", "reason": "exchange week"}],
        "lms": {"canvas_assignments": {"02": 87568490}}})");
    writeFile(dir / "times.csv", "student,submitted,stage\n"
                                 "alice,2026-12-01T11:00:00Z,\n"
                                 "alice,2026-12-02T09:00:00Z,02\n"
                                 "bob,2026-12-01T11:00:00Z,\n"
                                 "bob,2026-12-03T09:00:00Z,02\n"
                                 "carol,2026-12-30T09:00:00Z,\n");
    grade(dir.path(), "--out graded --roster roster.csv --course course.json --submitted "
                      "times.csv --lms canvas,moodle,blackboard,brightspace");
    // A regrade of one student finishes the class as the run did, and is logged.
    grade(dir.path(), "--out graded --only carol --reason \"re-uploaded\"");
    const std::string log = readFile(dir / "graded/regrades.csv");
    EXPECT_EQ(log.rfind("when,student,reason,stage,before,after\r\n", 0), 0u) << log;
    EXPECT_NE(log.find(",carol,re-uploaded,,,\r\n"), std::string::npos)
        << "the same files: nothing changed\n"
        << log;
    EXPECT_TRUE(fs::exists(dir / "graded/history/carol/1/01-raycast/result.json"))
        << "the earlier result is kept";
    EXPECT_NE(readFile(dir / "graded/students/carol/report.html").find("re-uploaded"),
              std::string::npos);
    const std::string csv = readFile(dir / "graded/summary.csv");
    EXPECT_EQ(csv.rfind("student,id,01-raycast,02-shading,total,max,notes\r\n", 0), 0u) << csv;
    // alice's 02 came a day late, within her extension.
    EXPECT_EQ(row(csv, "alice").rfind("alice,s1,100,100,200,200,", 0), 0u) << csv;
    // bob: 02 two days late (a part of a day counts), 20% of what it earned.
    const std::string bob = row(csv, "bob");
    EXPECT_NE(bob.find("02-shading: submitted 2026-12-03 09:00 UTC, 2 days late: -20%"),
              std::string::npos)
        << bob;
    // carol: 29 days late, capped at 30%; 02 not submitted is an empty cell, not 0.
    EXPECT_EQ(row(csv, "carol").rfind("carol,,70,,70,200,", 0), 0u) << csv;
    EXPECT_EQ(row(csv, "dave").rfind("dave,s4,,EX,0,100,", 0), 0u) << "02 excused\n" << csv;

    const std::string canvas = readFile(dir / "graded/canvas.csv");
    EXPECT_EQ(canvas.rfind("Student,ID,SIS User ID,SIS Login ID,Section,RayLab 01-raycast,RayLab "
                           "02-shading (87568490)\r\nPoints Possible,,,,,100,100\r\n",
                           0),
              0u)
        << canvas;
    EXPECT_NE(canvas.find("\"Liddell, Alice\",101,s1,alice1,A,100,100\r\n"), std::string::npos);
    EXPECT_NE(canvas.find("\"Bowman, Dave\",104,s4,dave4,B,,EX\r\n"), std::string::npos);
    // The other LMSs, each from the same roster.
    EXPECT_NE(readFile(dir / "graded/moodle.csv").find("Alice,Liddell,s1,,alice1,100,100\r\n"),
              std::string::npos);
    EXPECT_NE(readFile(dir / "graded/blackboard.csv")
                  .find("\"Liddell\",\"Alice\",\"alice1\",\"s1\",\"100\",\"100\"\r\n"),
              std::string::npos);
    EXPECT_NE(readFile(dir / "graded/brightspace.csv").find("#s1,#alice1,100,100,#\r\n"),
              std::string::npos);
    // A report per section, with its students only.
    const std::string a = readFile(dir / "graded/sections/A/report.html");
    EXPECT_NE(a.find(">bob</a>"), std::string::npos);
    EXPECT_EQ(a.find("Bowman"), std::string::npos);
    EXPECT_EQ(a.find(">dave<"), std::string::npos) << "dave is in section B";
    EXPECT_TRUE(fs::exists(dir / "graded/sections/A/students/bob/02-shading/result.json"));
    EXPECT_FALSE(fs::exists(dir / "graded/sections/A/students/carol")) << "carol is in no section";
    EXPECT_NE(readFile(dir / "graded/report.html").find("href=\"sections/B/report.html\""),
              std::string::npos);
    EXPECT_EQ(canvas.find("carol"), std::string::npos) << "no id Canvas could match";

    // The class summary: the checks that fail most, bob's catalogued mistake.
    const std::string html = readFile(dir / "graded/report.html");
    EXPECT_NE(html.find("Checks that fail most"), std::string::npos);
    EXPECT_NE(html.find("Phong&#39;s reflected vector instead of the half vector"),
              std::string::npos)
        << "bob's failures are exactly the catalogued mistake's";
    EXPECT_NE(html.find("before the late penalty"), std::string::npos) << "raw and final shown";
}

TEST(GradeWorkflow, OnlyRegradesOneStudentIntoTheReport) {
    ScratchDir dir, solved;
    writeSolvedLabs(solved.path());
    writeClass(solved.path(), dir / "class");
    grade(dir.path(), "--out graded");
    const std::string aliceBefore = readFile(dir / "graded/students/alice/01-raycast/result.json");
    const std::string bobBefore = readFile(dir / "graded/students/bob/02-shading/result.json");
    const std::string carolBefore = readFile(dir / "graded/students/carol/01-raycast/result.json");
    EXPECT_EQ(row(readFile(dir / "graded/summary.csv"), "alice").substr(0, 19),
              "alice,,100,100,200,");

    // The report's wall time: the class run's, before and after a regrade.
    auto wallTime = [&] {
        const std::string html = readFile(dir / "graded/report.html");
        const std::size_t at = html.find("wall time <b>");
        return at == std::string::npos ? std::string()
                                       : html.substr(at, html.find("</b>", at) - at);
    };
    const std::string classWallTime = wallTime();
    ASSERT_FALSE(classWallTime.empty());

    // alice hands in a fix that breaks 01: regrade her alone.
    replaceInFile(dir / "class/alice/01-raycast/find_closest.glsl", "t < hit.t", "t > hit.t");
    const std::string out = grade(dir.path(), "--out graded --only alice");
    EXPECT_EQ(wallTime(), classWallTime) << "a regrade is not the class's wall time";
    EXPECT_NE(out.find("1 student x 2 stages"), std::string::npos) << out;
    EXPECT_NE(readFile(dir / "graded/students/alice/01-raycast/result.json"), aliceBefore);
    EXPECT_EQ(readFile(dir / "graded/students/bob/02-shading/result.json"), bobBefore);
    EXPECT_EQ(readFile(dir / "graded/students/carol/01-raycast/result.json"), carolBefore);
    const std::string csv = readFile(dir / "graded/summary.csv");
    EXPECT_EQ(row(csv, "alice").find("alice,,100,"), std::string::npos) << csv;
    EXPECT_FALSE(row(csv, "bob").empty() || row(csv, "carol").empty()) << csv;

    // Refused: another seed, a student with no folder, a folder never graded,
    // other weights than the run's.
    writeFile(dir / "weights.json", R"({"stages": {"01": {"grading": {"views": 10}}}})");
    for (const std::string& args :
         {std::string("--out graded --only alice --seed 4"), std::string("--out graded --only zed"),
          std::string("--out elsewhere --only alice"),
          std::string("--out graded --only alice --course weights.json")}) {
        CommandResult r = runCommand("cd " + quote(dir.path()) + " && " + quote(raylabExe()) +
                                     " grade --submissions class --jobs 2 --seed 3 " + args);
        EXPECT_EQ(r.exitCode, 2) << args << "\n" << r.all();
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    }
    EXPECT_FALSE(fs::exists(dir / "elsewhere/report.html"));
}

TEST(GradeWorkflow, AnonymisedReportsNameNoStudent) {
    ScratchDir dir, solved;
    writeSolvedLabs(solved.path());
    writeClass(solved.path(), dir / "class");
    // A compile error, so that a message names the student's file.
    replaceInFile(dir / "class/carol/01-raycast/intersect_sphere.glsl", "    return",
                  "    float = 1.0;\n    return");
    // A folder whose name is part of every pseudonym ("stud" of "student-").
    fs::create_directories(dir / "class" / "stud");
    fs::copy(solved / "01-raycast", dir / "class" / "stud" / "01-raycast",
             fs::copy_options::recursive);
    grade(dir.path(), "--out tas --anonymise key.json");
    EXPECT_NE(readFile(dir / "key.json").find("\"alice\""), std::string::npos)
        << "the key file says whose each pseudonym is";
    int files = 0;
    for (const std::string& f : filesUnder(dir / "tas")) {
        ++files;
        const std::string text = readFile(dir / "tas" / f);
        for (const char* name : {"alice", "bob/", "carol", "/stud/"}) {
            EXPECT_EQ(f.find(name), std::string::npos) << f;
            EXPECT_EQ(text.find(name), std::string::npos) << name << " in " << f;
        }
    }
    EXPECT_GT(files, 20);
    EXPECT_NE(studentPages(dir / "tas").find("01-raycast/intersect_sphere.glsl:"),
              std::string::npos)
        << "the compile error still names the file";
    EXPECT_NE(readFile(dir / "tas/summary.csv").find("student-"), std::string::npos);
    // In the pseudonyms' order, not the names': a class list must not tell them.
    std::vector<std::string> rows;
    std::istringstream csv(readFile(dir / "tas/summary.csv"));
    for (std::string line; std::getline(csv, line);)
        if (line.rfind("student-", 0) == 0) rows.push_back(line.substr(0, line.find(',')));
    EXPECT_EQ(rows.size(), 4u);
    EXPECT_TRUE(std::is_sorted(rows.begin(), rows.end()));
    // The same key gives the same pseudonyms; another key others.
    grade(dir.path(), "--out tas2 --anonymise key.json");
    EXPECT_EQ(readFile(dir / "tas/summary.csv"), readFile(dir / "tas2/summary.csv"));
    grade(dir.path(), "--out tas3 --anonymise other-key.json");
    EXPECT_NE(readFile(dir / "tas/summary.csv"), readFile(dir / "tas3/summary.csv"));
    // Sections survive anonymising: the pseudonyms carry them, no id does.
    writeFile(dir / "roster.csv", "student,id,section\nalice,s1,A\nbob,s2,A\ncarol,s3,B\n");
    grade(dir.path(), "--out tas4 --anonymise key.json --roster roster.csv");
    for (const std::string& f : filesUnder(dir / "tas4")) {
        const std::string text = readFile(dir / "tas4" / f);
        for (const char* name : {"alice", "carol", "s1,", "s2,"})
            EXPECT_EQ(text.find(name), std::string::npos) << name << " in " << f;
    }
    EXPECT_EQ(count(readFile(dir / "tas4/sections/A/summary.csv"), "student-"), 2u);
    EXPECT_EQ(count(readFile(dir / "tas4/sections/B/summary.csv"), "student-"), 1u);
    // The control: without --anonymise the names are there, the message's too.
    grade(dir.path(), "--out named");
    EXPECT_NE(readFile(dir / "named/students/carol/report.html")
                  .find("carol/01-raycast/intersect_sphere.glsl:"),
              std::string::npos);
}

TEST(GradeWorkflow, BadCourseInputIsOneLineAndWritesNothing) {
    ScratchDir dir;
    fs::create_directories(dir / "class/alice/01-raycast");
    writeFile(dir / "bad-course.json", R"({"late": {"deadline": "soon"}})");
    writeFile(dir / "bad-roster.csv", "name,id\nx,1\n");
    writeFile(dir / "late.json",
              R"({"late": {"deadline": "2026-12-01T00:00Z", "penalty_per_day": 5}})");
    const struct {
        std::string args;
        const char* expected;
    } cases[] = {
        {"--lms canvas", "--lms canvas needs --roster"},
        {"--course bad-course.json", "late.deadline: 'soon' is not a time"},
        {"--roster bad-roster.csv", "no 'student' column"},
        {"--anonymise k.json --lms canvas --roster bad-roster.csv",
         "--anonymise cannot go with --lms"},
        {"--anonymise out/k.json", "keep the key file outside out"},
        {"--anonymise bad-course.json", "not a key file"},
        {"--course late.json", "has a late policy: say when each student submitted"},
        {"--submitted nowhere.csv --course bad-course.json", "not a time"},
        {"--lms moodle,sakai", "'sakai' is not an LMS"},
        {"--reason typo", "--reason says why a student is regraded"},
    };
    for (const auto& c : cases) {
        CommandResult r = runCommand("cd " + quote(dir.path()) + " && " + quote(raylabExe()) +
                                     " grade --submissions class --out out " + c.args);
        EXPECT_NE(r.exitCode, 0) << c.args << "\n" << r.all();
        EXPECT_NE(r.err.find(c.expected), std::string::npos) << c.args << ": " << r.err;
        EXPECT_FALSE(fs::exists(dir / "out")) << c.args;
    }
}

TEST(GradeWorkflow, EstimateGradesASampleAndSaysWhatTheClassWillCost) {
    ScratchDir dir, solved;
    writeSolvedLabs(solved.path());
    writeClass(solved.path(), dir / "class");
    const std::string raylab = "cd " + quote(dir.path()) + " && " + quote(raylabExe()) + " grade ";
    CommandResult r = runCommand(raylab + "--submissions class --stages 01 --estimate --sample 2");
    ASSERT_EQ(r.exitCode, 0) << r.all();
    EXPECT_NE(r.out.find("2 of 3 students x 1 stage graded as a sample"), std::string::npos)
        << r.out;
    for (const char* says : {"a student-stage:", "MB at most per stage", "on this machine with",
                             "2 tasks", "--mem-per-cpu", "per upload"})
        EXPECT_NE(r.out.find(says), std::string::npos) << says << "\n" << r.out;
    EXPECT_EQ(filesUnder(dir / "class").size(),
              filesUnder(solved.path() / "01-raycast").size() * 3 +
                  filesUnder(solved.path() / "02-shading").size() * 2)
        << "the class is as it was";
    std::size_t entries = 0;
    for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir.path())) ++entries;
    EXPECT_EQ(entries, 1u) << "nothing but the class: the sample is graded elsewhere";
    CommandResult refused = runCommand(raylab + "--submissions class --estimate --out graded");
    EXPECT_EQ(refused.exitCode, 2);
    EXPECT_NE(refused.err.find("--estimate writes no report"), std::string::npos) << refused.err;
}
