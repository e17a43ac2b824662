// Grading output: Gradescope JSON, class CSV, JUnit XML and the HTML report,
// plus the atomic text writes they all go through.
#include "atomic_file.h"
#include "error.h"
#include "grade_report.h"
#include "test_support.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <set>

using namespace raylab;
namespace fs = std::filesystem;
using raylab::test::readFile;
using raylab::test::ScratchDir;
using raylab::test::writeFile;

namespace {

const std::string kQuoted = "Doe, \"Jo\"";
const std::string kHostile = "<script>x</script>";
const std::string kLog =
    "04-recursion/trace.glsl:12: error: 'depth' : undeclared identifier\n"
    "04-recursion/trace.glsl:13: error: '<' : wrong operand types (vec3 & float)\n"
    "\x01 2 compilation errors";

CheckResult check(const std::string& name, const std::string& kind, double score, double maxScore,
                  const std::string& output) {
    CheckResult c;
    c.name = name;
    c.kind = kind;
    c.score = score;
    c.maxScore = maxScore;
    c.passed = score >= maxScore;
    c.output = output;
    return c;
}

StageResult stage(const std::string& id, const std::string& status, double score,
                  std::vector<CheckResult> checks = {}) {
    StageResult s;
    s.stage = id;
    s.status = status;
    s.score = score;
    s.maxScore = 100;
    s.seconds = 2.25;
    s.checks = std::move(checks);
    return s;
}

// Two students, two stages: one compile error, one "not submitted", one
// image check without a student image, and a hostile folder name.
ClassResult sampleClass() {
    ClassResult r;
    r.stages = {"01-raycast", "04-recursion"};
    r.seed = 1234;
    r.machine = "OpenGL 4.5 (Core Profile) Mesa 22.3.6 on llvmpipe";
    r.seconds = 42.5;

    StudentResult a;
    a.name = kQuoted;
    CheckResult front = check("front", "image", 40, 40, "0.0% of pixels differ");
    front.studentImage = "students/0/01-raycast/front.png";
    front.referenceImage = "reference/01-raycast/front.png";
    front.diffImage = "students/0/01-raycast/front-diff.png";
    CheckResult side = check("side", "image", 10, 40, "no image written");
    side.referenceImage = "reference/01-raycast/side.png";
    a.stages.push_back(
        stage("01-raycast", "graded", 70,
              {front, side, check("intersectSphere", "function", 20, 20, "12/12 rays agree")}));
    StageResult broken = stage("04-recursion", "compile error", 0);
    broken.message = kLog;
    a.stages.push_back(broken);

    StudentResult b;
    b.name = kHostile;
    b.stages.push_back(stage("01-raycast", "not submitted", 0));
    b.stages.push_back(
        stage("04-recursion", "graded", 83.3333,
              {check("reflect", "image", 33.3333, 50, "3.1% of pixels differ (max 255/255)"),
               check("bounce", "function", 50, 50, "ok")}));
    r.students = {a, b};
    return r;
}

std::size_t count(const std::string& text, const std::string& what) {
    std::size_t n = 0;
    for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1))
        ++n;
    return n;
}

std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    return s;
}

// Every '<' opens a tag, comment or declaration and every '&' starts an entity:
// what escaping has to guarantee for student text inside markup.
void expectEscapedMarkup(const std::string& text) {
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (text[i] == '<') {
            ASSERT_LT(i + 1, text.size());
            char n = text[i + 1];
            EXPECT_TRUE(std::isalpha(static_cast<unsigned char>(n)) || n == '/' || n == '?' ||
                        n == '!')
                << "raw '<' at " << text.substr(i, 40);
        } else if (text[i] == '&') {
            std::size_t semi = text.find(';', i);
            ASSERT_NE(semi, std::string::npos) << text.substr(i, 40);
            std::string entity = text.substr(i + 1, semi - i - 1);
            bool known = entity == "amp" || entity == "lt" || entity == "gt" || entity == "quot" ||
                         entity == "#39" || entity == "#10" || entity == "#13" || entity == "#9" ||
                         entity == "ndash" || entity == "ge" || entity == "#10003" ||
                         entity == "#10007" || entity == "#8593" || entity == "rarr";
            EXPECT_TRUE(known) << "raw '&' at " << text.substr(i, 40);
        } else {
            unsigned char c = static_cast<unsigned char>(text[i]);
            EXPECT_FALSE(c < 0x20 && c != '\n' && c != '\r' && c != '\t')
                << "control character " << int(c) << " at " << i;
        }
    }
}

std::set<std::string> entries(const fs::path& dir) {
    std::set<std::string> names;
    for (const auto& e : fs::directory_iterator(dir)) names.insert(e.path().filename().string());
    return names;
}

}  // namespace

TEST(GradeResult, StudentScoresSumOverStages) {
    ClassResult r = sampleClass();
    EXPECT_DOUBLE_EQ(r.students[0].score(), 70);
    EXPECT_DOUBLE_EQ(r.students[0].maxScore(), 200);
    EXPECT_DOUBLE_EQ(r.students[1].score(), 83.3333);
    EXPECT_DOUBLE_EQ(StudentResult{}.maxScore(), 0);
}

TEST(GradeReport, GradescopeJsonHasOneTestPerCheckAndPerUngradedStage) {
    ClassResult r = sampleClass();
    double classMax = 0, maxScoreSum = 0;
    for (const StudentResult& s : r.students) {
        classMax += s.maxScore();
        nlohmann::json j = nlohmann::json::parse(gradescopeJson(s));
        ASSERT_TRUE(j.contains("tests"));
        for (const auto& t : j["tests"]) {
            maxScoreSum += t["max_score"].get<double>();
            for (const char* key : {"name", "score", "max_score", "output", "status"})
                EXPECT_TRUE(t.contains(key)) << key << " in " << t;
            EXPECT_TRUE(t["status"] == "passed" || t["status"] == "failed") << t;
        }
        EXPECT_TRUE(j["output"].is_string());
        EXPECT_EQ(j["output"].get<std::string>().find('\n'), std::string::npos);
    }
    EXPECT_DOUBLE_EQ(maxScoreSum, classMax);
    EXPECT_DOUBLE_EQ(classMax, 400);

    nlohmann::json a = nlohmann::json::parse(gradescopeJson(r.students[0]));
    EXPECT_DOUBLE_EQ(a["score"].get<double>(), 70);
    ASSERT_EQ(a["tests"].size(), 4u);  // 3 checks + the compile error
    EXPECT_EQ(a["tests"][0]["name"], "01-raycast / front");
    EXPECT_EQ(a["tests"][0]["status"], "passed");
    EXPECT_EQ(a["tests"][1]["name"], "01-raycast / side");
    EXPECT_EQ(a["tests"][1]["status"], "failed");
    EXPECT_DOUBLE_EQ(a["tests"][1]["score"].get<double>(), 10);
    EXPECT_DOUBLE_EQ(a["tests"][1]["max_score"].get<double>(), 40);
    EXPECT_EQ(a["tests"][3]["name"], "04-recursion: compile error");
    EXPECT_EQ(a["tests"][3]["status"], "failed");
    EXPECT_DOUBLE_EQ(a["tests"][3]["score"].get<double>(), 0);
    EXPECT_DOUBLE_EQ(a["tests"][3]["max_score"].get<double>(), 100);
    EXPECT_EQ(a["tests"][3]["output"], kLog);  // the whole multi-line log, JSON-escaped

    nlohmann::json b = nlohmann::json::parse(gradescopeJson(r.students[1]));
    ASSERT_EQ(b["tests"].size(), 3u);  // not submitted + 2 checks
    EXPECT_EQ(b["tests"][0]["name"], "01-raycast: not submitted");
    EXPECT_DOUBLE_EQ(b["score"].get<double>(), 83.33);  // rounded to 2 decimals
    EXPECT_DOUBLE_EQ(b["tests"][1]["score"].get<double>(), 33.33);
    EXPECT_EQ(gradescopeJson(r.students[1]).find("83.333"), std::string::npos);
}

TEST(GradeReport, GradescopeJsonSurvivesInvalidUtf8) {
    StudentResult s;
    s.name = "bad\xff";
    s.stages.push_back(stage("01-raycast", "compile error", 0));
    s.stages[0].message = "error near '\xc3('";
    std::string text;
    ASSERT_NO_THROW(text = gradescopeJson(s));
    EXPECT_TRUE(nlohmann::json::accept(text)) << text;
}

TEST(GradeReport, WriteGradescopeResultsWritesTheJson) {
    ScratchDir dir;
    ClassResult r = sampleClass();
    writeGradescopeResults(r.students[0], dir / "results.json");
    EXPECT_EQ(readFile(dir / "results.json"), gradescopeJson(r.students[0]));
}

TEST(GradeReport, SummaryCsvHasHeaderNumbersNotesAndRfc4180Quoting) {
    std::string csv = summaryCsv(sampleClass());
    EXPECT_EQ(csv, "student,id,01-raycast,04-recursion,total,max,notes\r\n"
                   "\"Doe, \"\"Jo\"\"\",,70,0,70,200,04-recursion: compile error\r\n"
                   "<script>x</script>,,,83.33,83.33,200,01-raycast: not submitted\r\n");
}

// An LMS tells "not submitted" from 0 by an empty cell; the roster's id and a
// late penalty's note go with it.
TEST(GradeReport, SummaryCsvHasIdsLeavesNotSubmittedEmptyAndNotesLateness) {
    ClassResult r = sampleClass();
    r.students[0].roster.id = "s0042";
    r.students[0].stages[0].latePenalty = 7;
    r.students[0].stages[0].score = 63;
    r.students[0].stages[0].lateNote = "submitted 2026-12-12 09:10 UTC, 1 day late: -10%";
    StudentResult ghost;
    ghost.name = "ghost";
    ghost.hasFolder = false;
    ghost.roster.id = "s0099";
    for (const std::string& id : r.stages) ghost.stages.push_back(stage(id, "not submitted", 0));
    r.students.push_back(ghost);
    const std::string csv = summaryCsv(r);
    EXPECT_NE(csv.find("\"Doe, \"\"Jo\"\"\",s0042,63,0,63,200,\"01-raycast: submitted 2026-12-12 "
                       "09:10 UTC, 1 day late: -10%; 04-recursion: compile error\"\r\n"),
              std::string::npos)
        << csv;
    EXPECT_NE(csv.find("ghost,s0099,,,0,200,no submission folder\r\n"), std::string::npos) << csv;
}

TEST(GradeReport, CanvasCsvHasCanvasColumnsPointsPossibleAndOnlyMatchableStudents) {
    ClassResult r = sampleClass();
    r.students[0].roster = {"s0042", "Doe, Jo", "1234", "jdoe", "Mon 10:00"};
    const std::string csv = canvasCsv(r, GradebookColumns{});
    EXPECT_EQ(csv, "Student,ID,SIS User ID,SIS Login ID,Section,RayLab 01-raycast,RayLab "
                   "04-recursion\r\n"
                   "Points Possible,,,,,100,100\r\n"
                   "\"Doe, Jo\",1234,s0042,jdoe,Mon 10:00,70,0\r\n")
        << "the second student has no id Canvas can match: left out";
    r.students[0].roster = {};
    EXPECT_THROW(canvasCsv(r, GradebookColumns{}), Error);
}

TEST(GradeReport, HtmlOpensWithTheClassSummary) {
    ClassResult r = sampleClass();
    r.mistakes.push_back({"04-recursion",
                          "stack-never-popped",
                          "the path ends without popping",
                          true,
                          {"bounce", "reflect"},
                          1});
    r.mistakes.push_back({"01-raycast", "far-root", "takes the far root", true, {"front"}, 0});
    const std::string html = htmlClassPage(r);
    const std::size_t summary = html.find("Checks that fail most");
    ASSERT_NE(summary, std::string::npos);
    EXPECT_LT(summary, html.find("class=\"summary sortable\">"))
        << "the class summary comes before the class table";
    EXPECT_NE(html.find("<td>04-recursion</td><td>reflect</td><td class=\"muted\">image</td>"
                        "<td class=\"num\">1 of 1</td>"),
              std::string::npos)
        << html;
    EXPECT_NE(html.find("the path ends without popping"), std::string::npos);
    EXPECT_EQ(html.find("takes the far root"), std::string::npos) << "no stage matched it";
    expectEscapedMarkup(html);
}

TEST(GradeReport, SummaryCsvDefusesFormulasAndMarksMissingStages) {
    ClassResult r = sampleClass();
    r.students[1].name = "=HYPERLINK(\"http://x\",\"y\")";
    r.students[1].stages.pop_back();  // no result for 04-recursion
    std::string csv = summaryCsv(r);
    EXPECT_NE(csv.find("\"'=HYPERLINK(\"\"http://x\"\",\"\"y\"\")\",,,,0,100,01-raycast: not "
                       "submitted; 04-recursion: no result\r\n"),
              std::string::npos)
        << csv;
}

TEST(GradeReport, JunitXmlCountsFailuresAndErrors) {
    std::string xml = junitXml(sampleClass());
    EXPECT_EQ(xml.rfind("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites name=\"raylab "
                        "grade\" tests=\"7\" failures=\"3\" errors=\"1\"",
                        0),
              0u)
        << xml;
    EXPECT_EQ(count(xml, "<testsuite "), 2u);
    EXPECT_EQ(count(xml, "<testcase "), 7u);
    EXPECT_EQ(count(xml, "<failure "), 3u);  // side, not submitted, reflect
    EXPECT_EQ(count(xml, "<error "), 1u);    // compile error
    EXPECT_NE(
        xml.find("<testsuite name=\"Doe, &quot;Jo&quot;\" tests=\"4\" failures=\"1\" errors=\"1\""),
        std::string::npos)
        << xml;
    EXPECT_NE(xml.find("<testsuite name=\"&lt;script&gt;x&lt;/script&gt;\" tests=\"3\" "
                       "failures=\"2\" errors=\"0\""),
              std::string::npos)
        << xml;
    EXPECT_NE(xml.find("<testcase classname=\"Doe, &quot;Jo&quot;.01-raycast\" name=\"front\"/>"),
              std::string::npos)
        << xml;
    EXPECT_NE(xml.find("<failure message=\"not submitted\" type=\"not submitted\">"),
              std::string::npos)
        << xml;
    EXPECT_NE(xml.find("<error message=\"compile error: 04-recursion/trace.glsl:12: error: "
                       "&#39;depth&#39; : undeclared identifier\""),
              std::string::npos)
        << xml;
    EXPECT_NE(xml.find("error: &#39;&lt;&#39; : wrong operand types (vec3 &amp; float)\n"),
              std::string::npos)
        << xml;
    EXPECT_EQ(xml.find("<script"), std::string::npos);
    expectEscapedMarkup(xml);
}

TEST(GradeReport, TheClassPageEscapesStudentTextAndLinksEachStudentsPage) {
    const std::string html = htmlClassPage(sampleClass());
    EXPECT_EQ(html.rfind("<!DOCTYPE html>", 0), 0u);
    EXPECT_NE(html.find("&lt;script&gt;x&lt;/script&gt;"), std::string::npos);
    EXPECT_EQ(count(lower(html), "<script"), 1u) << "the sorting script only";
    EXPECT_NE(html.find("Doe, &quot;Jo&quot;"), std::string::npos);
    // No pictures on the class page: it must stay small for hundreds.
    EXPECT_EQ(count(html, "<img "), 0u);
    // Header facts, and no date: the report must be reproducible.
    EXPECT_NE(html.find("seed <b>1234</b>"), std::string::npos);
    EXPECT_NE(html.find("Mesa 22.3.6 on llvmpipe"), std::string::npos);
    EXPECT_NE(html.find("42.5 s"), std::string::npos);
    // Each row links to the student's page and its stages, names encoded.
    EXPECT_NE(html.find("<a href=\"students/Doe%2C%20%22Jo%22/report.html\">Doe, "
                        "&quot;Jo&quot;</a>"),
              std::string::npos)
        << html;
    EXPECT_NE(html.find("href=\"students/Doe%2C%20%22Jo%22/report.html#04-recursion\">"
                        "compile error</a>"),
              std::string::npos);
    EXPECT_NE(
        html.find(
            "data-v=\"83.33\"><a class=\"warn\" "
            "href=\"students/%3Cscript%3Ex%3C/script%3E/report.html#04-recursion\">83.33</a>"),
        std::string::npos);
    // Sortable by keyboard: a button in every column head, numbers by value.
    EXPECT_EQ(count(html, "<th scope=\"col\""), count(html, "<button type=\"button\">"));
    EXPECT_NE(html.find("data-v=\"83.33\""), std::string::npos);
    // Self-contained.
    EXPECT_EQ(html.find("http://"), std::string::npos);
    EXPECT_EQ(html.find("https://"), std::string::npos);
    EXPECT_EQ(html.find("<link"), std::string::npos);
    expectEscapedMarkup(html);
}

TEST(GradeReport, TheClassPageOfTwoHundredStudentsStaysSmall) {
    // 200 students x 12 stages, every stage graded with 8 checks: the class
    // page has a row per student and no pictures.
    ClassResult r = sampleClass();
    r.stages.clear();
    for (int k = 1; k <= 12; ++k) r.stages.push_back("stage-" + std::to_string(k));
    r.students.clear();
    for (int i = 0; i < 200; ++i) {
        StudentResult st;
        st.name = "student-" + std::to_string(10000000 + i);
        st.roster.section = "Section " + std::to_string(i % 8);
        for (const std::string& id : r.stages) {
            std::vector<CheckResult> checks;
            for (int c = 0; c < 8; ++c) {
                CheckResult k = check("view-" + std::to_string(c), "image", 5, 10, "2.1% differ");
                k.studentImage = "students/" + st.name + "/" + id + "/view.png";
                checks.push_back(k);
            }
            st.stages.push_back(stage(id, "graded", 62.5, checks));
        }
        r.students.push_back(st);
    }
    const std::size_t bytes = htmlClassPage(r).size();
    EXPECT_LT(bytes, 400u * 1024u) << "a few hundred kilobytes at most";
    std::printf("[ figure   ] the class page of 200 students x 12 stages: %zu KB\n", bytes / 1024);
}

TEST(GradeReport, AStudentsPageShowsTheirPicturesWithAltTextThatSaysWhose) {
    const ClassResult r = sampleClass();
    const std::string html = htmlStudentPage(r, r.students[0]);
    EXPECT_EQ(lower(html).find("<script"), std::string::npos);
    // The compile log, escaped, lines kept, in a <pre>.
    EXPECT_NE(html.find("<pre class=\"log\">04-recursion/trace.glsl:12: error: &#39;depth&#39; : "
                        "undeclared identifier\n"
                        "04-recursion/trace.glsl:13: error: &#39;&lt;&#39; : wrong operand types "
                        "(vec3 &amp; float)\n"),
              std::string::npos);
    // Image check: the three pictures where available (from two folders up),
    // lazily, "no image" where not.
    EXPECT_NE(html.find("<img src=\"../../students/0/01-raycast/front.png\" alt=\"Doe, "
                        "&quot;Jo&quot;&#39;s picture of 01-raycast, view front\" width=\"180\" "
                        "height=\"135\" loading=\"lazy\">"),
              std::string::npos)
        << html;
    EXPECT_NE(html.find("<img src=\"../../reference/01-raycast/front.png\" alt=\"the reference "
                        "picture of 01-raycast, view front\""),
              std::string::npos);
    EXPECT_NE(html.find("<img src=\"../../students/0/01-raycast/front-diff.png\" alt=\"where "
                        "Doe, &quot;Jo&quot;&#39;s picture of 01-raycast, view front differs"),
              std::string::npos);
    EXPECT_NE(html.find("<img src=\"../../reference/01-raycast/side.png\""), std::string::npos);
    EXPECT_EQ(count(html, "<img "), 4u);
    EXPECT_EQ(count(html, ">no image<"), 2u);  // side: the student's picture and the difference
    EXPECT_NE(html.find("id=\"04-recursion\""), std::string::npos);
    EXPECT_NE(html.find("href=\"../../report.html\""), std::string::npos) << "back to the class";
    expectEscapedMarkup(html);
}

TEST(GradeReport, AStudentsPageShowsTheRegradesAndAnExcusedStage) {
    ClassResult r = sampleClass();
    StudentResult& st = r.students[1];
    st.stages[1].excused = true;
    st.stages[1].excuseNote = "exchange week";
    st.regrades.push_back(
        {"2026-12-07 09:14 UTC", "late upload <fixed>", {{"04-recursion", "0", "83.33"}}});
    EXPECT_DOUBLE_EQ(st.score(), 0) << "an excused stage counts for nothing";
    EXPECT_DOUBLE_EQ(st.maxScore(), 100);
    const std::string html = htmlStudentPage(r, st);
    EXPECT_NE(html.find("excused: exchange week (counts for nothing)"), std::string::npos);
    EXPECT_NE(html.find("<td>2026-12-07 09:14 UTC</td><td>late upload &lt;fixed&gt;</td><td>"
                        "04-recursion</td><td>0 &rarr; 83.33</td>"),
              std::string::npos)
        << html;
    EXPECT_NE(htmlClassPage(r).find(">excused</a>"), std::string::npos);
    EXPECT_EQ(regradeCsv(r), "when,student,reason,stage,before,after\r\n"
                             "2026-12-07 09:14 UTC,<script>x</script>,late upload <fixed>,"
                             "04-recursion,0,83.33\r\n");
}

TEST(GradeReport, HtmlImagePathsCannotEscapeTheirAttribute) {
    ClassResult r = sampleClass();
    r.students[0].stages[0].checks[0].studentImage = "students/a\"b #1/front.png";
    std::string html = htmlStudentPage(r, r.students[0]);
    EXPECT_NE(html.find("<img src=\"../../students/a%22b%20%231/front.png\""), std::string::npos);
}

TEST(GradeReport, SameInputGivesByteIdenticalOutput) {
    ScratchDir dir;
    fs::create_directories(dir / "one");
    fs::create_directories(dir / "two");
    for (const char* sub : {"one", "two"}) {
        ClassResult r = sampleClass();  // a fresh copy each time
        writeHtmlReport(r, dir / sub);
        writeSummaryCsv(r, dir / sub / "summary.csv");
        writeJunitXml(r, dir / sub / "junit.xml");
        writeGradescopeResults(r.students[1], dir / sub / "results.json");
    }
    for (const char* file : {"report.html", "summary.csv", "junit.xml", "results.json"}) {
        std::string one = readFile(dir / "one" / file);
        EXPECT_FALSE(one.empty()) << file;
        EXPECT_EQ(one, readFile(dir / "two" / file)) << file;
    }
    EXPECT_EQ(entries(dir / "one"),
              (std::set<std::string>{"report.html", "summary.csv", "junit.xml", "results.json",
                                     "students"}));
    EXPECT_EQ(readFile(dir / "one/students/<script>x</script>/report.html"),
              readFile(dir / "two/students/<script>x</script>/report.html"));
}

TEST(AtomicFile, ReplacesAnExistingFileAndLeavesNoTemporaryFile) {
    ScratchDir dir;
    writeFile(dir / "out.txt", "old text that is longer than the new one\n");
    writeTextFileAtomic(dir / "out.txt", "new\n");
    EXPECT_EQ(readFile(dir / "out.txt"), "new\n");
    writeTextFileAtomic(dir / "empty.txt", "");
    EXPECT_TRUE(fs::is_regular_file(dir / "empty.txt"));
    EXPECT_EQ(fs::file_size(dir / "empty.txt"), 0u);
    EXPECT_EQ(entries(dir.path()), (std::set<std::string>{"out.txt", "empty.txt"}));
}

TEST(AtomicFile, MissingFolderThrowsAndWritesNothing) {
    ScratchDir dir;
    try {
        writeTextFileAtomic(dir / "missing" / "out.txt", "text");
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("cannot write "), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("out.txt: "), std::string::npos) << e.what();
    }
    EXPECT_TRUE(entries(dir.path()).empty());
    EXPECT_THROW(writeHtmlReport(sampleClass(), dir / "missing"), Error);
    EXPECT_TRUE(entries(dir.path()).empty());
}

TEST(AtomicFile, FailedRenameRemovesTheTemporaryFile) {
    ScratchDir dir;
    fs::create_directories(dir / "taken" /
                           "inside");  // a non-empty folder cannot be replaced by a file
    EXPECT_THROW(writeTextFileAtomic(dir / "taken", "text"), Error);
    EXPECT_EQ(entries(dir.path()), std::set<std::string>{"taken"});
    EXPECT_TRUE(fs::is_directory(dir / "taken" / "inside"));
}

// The four LMS imports, each against its documented columns (grade_report.h
// says where each LMS documents them).
namespace {

ClassResult rosterClass() {
    ClassResult r = sampleClass();
    r.students[0].roster = {"00246", "Doe, Jo", "1234", "jdoe", "A", "jo@example.edu"};
    r.students[1].roster = {"", "", "", "", "B", ""};  // no id any LMS can match
    r.students[0].stages[1].excused = true;
    return r;
}

}  // namespace

TEST(GradeReport, CanvasCsvNamesTheAssignmentIdsTheCourseFileGivesAndExcuses) {
    GradebookColumns c;
    c.ids = {{"01-raycast", "87568490"}};
    EXPECT_EQ(canvasCsv(rosterClass(), c),
              "Student,ID,SIS User ID,SIS Login ID,Section,RayLab 01-raycast (87568490),RayLab "
              "04-recursion\r\n"
              "Points Possible,,,,,100,100\r\n"
              "\"Doe, Jo\",1234,00246,jdoe,A,70,EX\r\n");
}

TEST(GradeReport, MoodleCsvHasItsIdentityColumnsAndAColumnPerStage) {
    EXPECT_EQ(moodleCsv(rosterClass(), GradebookColumns{}),
              "First name,Last name,ID number,Email address,Username,RayLab 01-raycast,RayLab "
              "04-recursion\r\n"
              "Jo,Doe,00246,jo@example.edu,jdoe,70,\r\n");
    ClassResult none = rosterClass();
    none.students[0].roster = {};
    EXPECT_THROW(moodleCsv(none, GradebookColumns{}), Error);
}

TEST(GradeReport, BlackboardCsvQuotesEveryFieldAndNamesColumnIds) {
    GradebookColumns c;
    c.prefix = "Lab ";
    c.ids = {{"04-recursion", "1234"}};
    EXPECT_EQ(blackboardCsv(rosterClass(), c),
              "\"Last Name\",\"First Name\",\"Username\",\"Student ID\",\"Lab 01-raycast\","
              "\"Lab 04-recursion [Total Pts: 100 Score] |1234\"\r\n"
              "\"Doe\",\"Jo\",\"jdoe\",\"00246\",\"70\",\"\"\r\n");
    ClassResult none = rosterClass();
    none.students[0].roster.loginId.clear();
    EXPECT_THROW(blackboardCsv(none, c), Error) << "the Grade Center matches by username only";
}

TEST(GradeReport, BrightspaceCsvHasPointsGradeColumnsAndTheEndOfLineIndicator) {
    EXPECT_EQ(brightspaceCsv(rosterClass(), GradebookColumns{}),
              "OrgDefinedId,Username,RayLab 01-raycast Points Grade,RayLab 04-recursion Points "
              "Grade,End-of-Line Indicator\r\n"
              "#00246,#jdoe,70,,#\r\n");
    ClassResult none = rosterClass();
    none.students[0].roster.id.clear();
    none.students[0].roster.loginId.clear();
    EXPECT_THROW(brightspaceCsv(none, GradebookColumns{}), Error);
}
