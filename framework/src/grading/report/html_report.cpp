// The self-contained HTML report (grade_report.h).
#include "grade_report.h"

#include "atomic_file.h"
#include "report_text.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace raylab {

using namespace report;
namespace fs = std::filesystem;

namespace {

// ---------------------------------------------------------------- HTML

const char* kCss = R"css(
:root{--fg:#1f2328;--muted:#656d76;--border:#d0d7de;--soft:#f6f8fa;--link:#0969da;
--ok:#116329;--ok-bg:#dafbe1;--warn:#7d4e00;--warn-bg:#fff1c2;--bad:#a40e26;--bad-bg:#ffe3e0;--none:#57606a;--none-bg:#eaeef2}
*{box-sizing:border-box}
body{margin:0;color:var(--fg);background:#fff;font:14px/1.5 -apple-system,BlinkMacSystemFont,"Segoe UI","Noto Sans",Helvetica,Arial,sans-serif}
header{background:#24292f;color:#f6f8fa;padding:22px 32px}
header h1{margin:0 0 6px;font-size:22px;font-weight:600}
.meta{display:flex;flex-wrap:wrap;gap:6px 22px;margin:0;color:#c9d1d9;font-size:13px}
.meta b{color:#fff;font-weight:600}
main{max-width:1240px;margin:0 auto;padding:24px 32px 64px}
h2{font-size:18px;margin:0}
a{color:var(--link);text-decoration:none}
a:hover{text-decoration:underline}
.muted{color:var(--muted)}
.scroll{overflow-x:auto;border:1px solid var(--border);border-radius:8px}
table{border-collapse:collapse;width:100%}
th,td{padding:7px 12px;text-align:left;vertical-align:top}
thead th{background:var(--soft);font-weight:600;font-size:12px;color:var(--muted);border-bottom:1px solid var(--border);white-space:nowrap}
.summary td,.summary th{border-bottom:1px solid var(--border)}
.summary tbody tr:last-child td{border-bottom:none}
.summary td.num,.summary th.num{text-align:center;white-space:nowrap}
.summary td.name{font-weight:600;max-width:260px;overflow-wrap:anywhere}
.summary tfoot td{background:var(--soft);color:var(--muted);font-weight:600;border-top:1px solid var(--border)}
td.cell{padding:3px}
td.cell a{display:block;padding:4px 8px;border-radius:5px;color:inherit;font-weight:600}
td.cell a:hover{text-decoration:none;filter:brightness(.95)}
.ok{background:var(--ok-bg);color:var(--ok)}
.warn{background:var(--warn-bg);color:var(--warn)}
.bad{background:var(--bad-bg);color:var(--bad)}
.none{background:var(--none-bg);color:var(--none)}
td.cell a.status{font-weight:500;font-size:12px}
.bar{display:inline-block;width:64px;height:6px;border-radius:3px;background:var(--none-bg);vertical-align:middle;margin-right:8px;overflow:hidden}
.bar i{display:block;height:100%}
.bar i.ok{background:#2da44e}.bar i.warn{background:#d4a72c}.bar i.bad{background:#cf222e}
.legend{margin:10px 0 0;font-size:12px;color:var(--muted);display:flex;gap:14px;flex-wrap:wrap}
.legend span.pill{margin-right:4px}
.pill{display:inline-block;padding:1px 9px;border-radius:999px;font-size:12px;font-weight:600;white-space:nowrap}
.student{border:1px solid var(--border);border-radius:8px;margin:28px 0 0;overflow:hidden}
.student-head{display:flex;align-items:center;gap:12px;background:var(--soft);padding:12px 16px;border-bottom:1px solid var(--border)}
.student-head h2{overflow-wrap:anywhere}
.student-head .top{margin-left:auto;font-size:12px;white-space:nowrap}
.stage{padding:14px 16px 16px;border-top:1px solid var(--border)}
.student-head+.stage{border-top:none}
.stage:target{box-shadow:inset 4px 0 0 var(--link);background:#f6faff}
.stage-head{display:flex;align-items:center;flex-wrap:wrap;gap:8px;margin-bottom:8px}
.stage-head h3{margin:0 6px 0 0;font-size:15px;font-family:ui-monospace,SFMono-Regular,Menlo,Consolas,monospace}
pre.log{margin:8px 0 4px;padding:10px 12px;background:#fbfcfd;border:1px solid var(--border);border-left:3px solid var(--bad);border-radius:6px;
font:12px/1.45 ui-monospace,SFMono-Regular,Menlo,Consolas,monospace;white-space:pre-wrap;overflow-wrap:anywhere;max-height:26em;overflow:auto}
.checks{border:1px solid var(--border);border-radius:6px;border-collapse:separate;border-spacing:0;margin-top:6px;table-layout:fixed}
.checks th:nth-child(1){width:190px}.checks th:nth-child(2){width:90px}.checks th:nth-child(3){width:100px}
.checks td{border-top:1px solid var(--border)}
.checks td.check{font-weight:600;overflow-wrap:anywhere}
.checks td.kind{color:var(--muted);white-space:nowrap}
.checks td.score{white-space:nowrap}
.checks td.out{overflow-wrap:anywhere}
.mark-ok{color:#1a7f37}.mark-bad{color:#cf222e}
.thumbs{display:flex;flex-wrap:wrap;gap:10px;margin-top:8px}
figure{margin:0;width:180px}
figure img{display:block;width:180px;height:auto;border:1px solid var(--border);border-radius:4px;background:var(--soft)}
figure .noimg{display:flex;align-items:center;justify-content:center;width:180px;height:135px;border:1px dashed var(--border);border-radius:4px;color:var(--muted);font-size:12px;background:var(--soft)}
figcaption{font-size:11px;color:var(--muted);text-align:center;margin-top:3px;text-transform:uppercase;letter-spacing:.04em}
footer{max-width:1240px;margin:0 auto;padding:0 32px 32px;color:var(--muted);font-size:12px}
.overview{display:grid;grid-template-columns:repeat(auto-fit,minmax(420px,1fr));gap:18px;margin:0 0 24px}
.overview h2{margin:0 0 8px}
.overview td.num{text-align:right;white-space:nowrap}
.overview td.checks-list{font-family:ui-monospace,SFMono-Regular,Menlo,Consolas,monospace;font-size:12px;overflow-wrap:anywhere}
.late{color:var(--warn);font-size:12px}
)css";

const char* tone(double score, double maxScore) {
    double f = fraction(score, maxScore);
    return f >= 0.9 ? "ok" : f >= 0.5 ? "warn" : "bad";
}

const char* statusTone(const StageResult& s) {
    return s.status == "not submitted" ? "none" : "bad";
}

std::string anchor(std::size_t student, std::size_t stage) {
    return "s" + std::to_string(student) + "-" + std::to_string(stage);
}

std::string bar(double score, double maxScore) {
    double f = std::min(1.0, std::max(0.0, fraction(score, maxScore)));
    return "<span class=\"bar\"><i class=\"" + std::string(tone(score, maxScore)) +
           "\" style=\"width:" + std::to_string(std::lround(f * 100)) + "%\"></i></span>";
}

std::string figure(const std::string& path, const char* caption) {
    std::string out = "<figure>";
    if (path.empty()) {
        out += "<div class=\"noimg\">no image</div>";
    } else {
        std::string src = escapeMarkup(urlPath(path), true);
        out += "<a href=\"" + src + "\"><img src=\"" + src + "\" alt=\"" + caption +
               " image\" loading=\"lazy\"></a>";
    }
    return out + "<figcaption>" + caption + "</figcaption></figure>";
}

void htmlSummaryTable(std::string& h, const ClassResult& r) {
    h += "<div class=\"scroll\"><table class=\"summary\">\n<thead><tr><th>Student</th>";
    for (const std::string& id : r.stages) h += "<th class=\"num\">" + escapeMarkup(id) + "</th>";
    h += "<th class=\"num\">Total</th><th>%</th></tr></thead>\n<tbody>\n";
    std::vector<double> stageSum(r.stages.size(), 0.0), stageMax(r.stages.size(), 0.0);
    std::vector<int> stageCount(r.stages.size(), 0);
    double totalSum = 0, totalMax = 0;
    for (std::size_t i = 0; i < r.students.size(); ++i) {
        const StudentResult& st = r.students[i];
        h += "<tr><td class=\"name\"><a href=\"#s" + std::to_string(i) + "\">" +
             escapeMarkup(st.name) + "</a></td>";
        for (std::size_t j = 0; j < r.stages.size(); ++j) {
            const StageResult* s = findStage(st, r.stages[j]);
            if (!s) {
                h += "<td class=\"num muted\" title=\"no result\">&ndash;</td>";
                continue;
            }
            std::size_t k = std::size_t(s - st.stages.data());
            if (s->status != "not submitted") {  // the average of those who handed it in
                stageSum[j] += s->score;
                stageMax[j] += s->maxScore;
                ++stageCount[j];
            }
            if (isGraded(*s)) {
                const std::string title = s->latePenalty > 0
                                              ? num(s->rawScore()) + " before the late penalty: " +
                                                    escapeMarkup(s->lateNote, true)
                                              : num(s->score) + " / " + num(s->maxScore);
                h += "<td class=\"cell num\"><a class=\"" +
                     std::string(tone(s->score, s->maxScore)) + "\" href=\"#" + anchor(i, k) +
                     "\" title=\"" + title + "\">" + num(s->score) +
                     (s->latePenalty > 0 ? "<span class=\"late\"> late</span>" : "") + "</a></td>";
            } else {
                h += "<td class=\"cell num\"><a class=\"status " + std::string(statusTone(*s)) +
                     "\" href=\"#" + anchor(i, k) + "\">" + escapeMarkup(statusWord(*s)) +
                     "</a></td>";
            }
        }
        double score = st.score(), maxScore = st.maxScore();
        totalSum += score;
        totalMax += maxScore;
        h += "<td class=\"num\"><b>" + num(score) + "</b> <span class=\"muted\">/ " +
             num(maxScore) + "</span></td>";
        h += "<td class=\"num\">" + bar(score, maxScore) +
             std::to_string(std::lround(100 * fraction(score, maxScore))) + "%</td></tr>\n";
    }
    h += "</tbody>\n";
    if (!r.students.empty()) {
        h += "<tfoot><tr><td title=\"per stage: of those who handed it in\">Class average</td>";
        for (std::size_t j = 0; j < r.stages.size(); ++j)
            h += "<td class=\"num\">" +
                 (stageCount[j] ? num(stageSum[j] / stageCount[j]) : std::string("&ndash;")) +
                 "</td>";
        double n = double(r.students.size());
        h += "<td class=\"num\">" + num(totalSum / n) + " / " + num(totalMax / n) +
             "</td><td class=\"num\">" +
             std::to_string(std::lround(100 * fraction(totalSum, totalMax))) +
             "%</td></tr></tfoot>\n";
    }
    h += "</table></div>\n";
    h += "<p class=\"legend\"><span><span class=\"pill ok\">&ge; 90%</span></span><span><span "
         "class=\"pill warn\">50&ndash;90%</span></span>"
         "<span><span class=\"pill bad\">&lt; 50%</span></span><span><span class=\"pill none\">not "
         "submitted</span></span>"
         "<span>Click a cell for the details.</span></p>\n";
}

// The class at a glance: the checks that fail most, and the catalogued
// mistakes whose failed checks the class's failures repeat exactly.
void htmlClassSummary(std::string& h, const ClassResult& r) {
    struct Count {
        std::string stage, check, kind;
        int failed = 0, graded = 0;
    };
    std::vector<Count> counts;
    int gradedStages = 0, failingStages = 0;
    for (const StudentResult& st : r.students)
        for (const StageResult& s : st.stages) {
            if (!isGraded(s)) continue;
            ++gradedStages;
            bool anyFailed = false;
            for (const CheckResult& c : s.checks) {
                if (c.seeded) continue;  // each seeded view is its own camera: not comparable
                auto it = std::find_if(counts.begin(), counts.end(), [&](const Count& x) {
                    return x.stage == s.stage && x.check == c.name;
                });
                if (it == counts.end()) {
                    counts.push_back({s.stage, c.name, c.kind, 0, 0});
                    it = counts.end() - 1;
                }
                ++it->graded;
                it->failed += c.passed ? 0 : 1;
                anyFailed = anyFailed || !c.passed;
            }
            failingStages += anyFailed ? 1 : 0;
        }
    std::stable_sort(counts.begin(), counts.end(),
                     [](const Count& a, const Count& b) { return a.failed > b.failed; });
    h += "<div class=\"overview\">\n<div><h2>Checks that fail most</h2>\n";
    if (counts.empty() || counts.front().failed == 0) {
        h += "<p class=\"muted\">No check failed.</p>\n";
    } else {
        h +=
            "<div class=\"scroll\"><table class=\"summary\"><thead><tr><th>Stage</th><th>Check</th>"
            "<th>Kind</th><th class=\"num\">Failed</th></tr></thead><tbody>\n";
        for (const Count& c : counts) {
            if (c.failed == 0) break;
            h += "<tr><td>" + escapeMarkup(c.stage) + "</td><td>" + escapeMarkup(c.check) +
                 "</td><td class=\"muted\">" + escapeMarkup(c.kind) + "</td><td class=\"num\">" +
                 std::to_string(c.failed) + " of " + std::to_string(c.graded) + "</td></tr>\n";
        }
        h += "</tbody></table></div>\n";
    }
    h += "<p class=\"legend\">" + std::to_string(failingStages) + " of " +
         std::to_string(gradedStages) +
         " graded stages fail at least one check (seeded views aside).</p></div>\n";
    h += "<div><h2>Known mistakes the failures look like</h2>\n";
    int matched = 0;
    for (const MistakeMatch& m : r.mistakes) matched += m.matches;
    if (r.mistakes.empty()) {
        h += "<p class=\"muted\">No mistakes catalogue for these stages.</p>\n";
    } else if (matched == 0) {
        h += "<p class=\"muted\">No failure repeats a catalogued mistake's checks and hints "
             "exactly.</p>\n";
    } else {
        h += "<div class=\"scroll\"><table "
             "class=\"summary\"><thead><tr><th>Stage</th><th>Mistake</th>"
             "<th>Fails exactly</th><th class=\"num\">Stages</th></tr></thead><tbody>\n";
        for (const MistakeMatch& m : r.mistakes) {
            if (m.matches == 0) continue;
            std::string checks;
            for (const std::string& c : m.checks) checks += (checks.empty() ? "" : ", ") + c;
            h += "<tr><td>" + escapeMarkup(m.stage) + "</td><td>" + escapeMarkup(m.description) +
                 (m.central ? " <span class=\"pill bad\">the stage's skill</span>" : "") +
                 "</td><td class=\"checks-list\">" + escapeMarkup(checks) +
                 "</td><td class=\"num\">" + std::to_string(m.matches) + "</td></tr>\n";
        }
        h += "</tbody></table></div>\n";
    }
    h += "<p class=\"legend\">A graded stage counts for a mistake of the catalogue (the "
         "course's tests/mistakes) when the checks it fails are exactly the ones that mistake "
         "fails and its hints name the same causes (the function checks' hints read the "
         "failing cases); mistakes that look alike in both share one row. A likeness, not a "
         "diagnosis: other code can fail the same checks.</p></div>\n</div>\n";
}

void htmlStage(std::string& h, const StageResult& s, const std::string& id) {
    h += "<div class=\"stage\" id=\"" + id + "\">\n<div class=\"stage-head\"><h3>" +
         escapeMarkup(s.stage) + "</h3>";
    h += "<span class=\"pill " +
         std::string(isGraded(s) ? tone(s.score, s.maxScore) : statusTone(s)) + "\">" +
         num(s.score) + " / " + num(s.maxScore) + "</span>";
    if (!isGraded(s))
        h += "<span class=\"pill " + std::string(statusTone(s)) + "\">" +
             escapeMarkup(statusWord(s)) + "</span>";
    if (s.seconds > 0) h += "<span class=\"muted\">" + duration(s.seconds) + "</span>";
    if (!s.lateNote.empty()) h += "<span class=\"late\">" + escapeMarkup(s.lateNote) + "</span>";
    h += "</div>\n";
    if (!s.message.empty()) h += "<pre class=\"log\">" + escapeMarkup(s.message) + "</pre>\n";
    if (s.checks.empty()) {
        if (isGraded(s)) h += "<p class=\"muted\">No checks.</p>\n";
        h += "</div>\n";
        return;
    }
    h += "<table "
         "class=\"checks\"><thead><tr><th>Check</th><th>Kind</th><th>Score</th><th>Result</th></"
         "tr></thead><tbody>\n";
    for (const CheckResult& c : s.checks) {
        h += "<tr><td class=\"check\">";
        h += c.passed ? "<span class=\"mark-ok\" title=\"passed\">&#10003;</span> "
                      : "<span class=\"mark-bad\" title=\"failed\">&#10007;</span> ";
        h += escapeMarkup(c.name) + "</td><td class=\"kind\">" + escapeMarkup(c.kind) + "</td>";
        h += "<td class=\"score\"><span class=\"pill " + std::string(tone(c.score, c.maxScore)) +
             "\">" + num(c.score) + " / " + num(c.maxScore) + "</span></td><td class=\"out\">" +
             escapeMarkup(c.output);
        if (c.kind == "image")
            h += "<div class=\"thumbs\">" + figure(c.studentImage, "submitted") +
                 figure(c.referenceImage, "reference") + figure(c.diffImage, "difference") +
                 "</div>";
        h += "</td></tr>\n";
    }
    h += "</tbody></table>\n</div>\n";
}

}  // namespace

// ---------------------------------------------------------------- HTML

std::string htmlReport(const ClassResult& r) {
    std::string h;
    h += "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
         "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
         "<title>RayLab grading report</title>\n<style>";
    h += kCss;
    h += "</style>\n</head>\n<body>\n<header id=\"top\">\n<h1>RayLab grading report</h1>\n<p "
         "class=\"meta\">";
    h += "<span><b>" + std::to_string(r.students.size()) + "</b> student" +
         (r.students.size() == 1 ? "" : "s") + "</span>";
    h += "<span><b>" + std::to_string(r.stages.size()) + "</b> stage" +
         (r.stages.size() == 1 ? "" : "s") + "</span>";
    h += "<span>seed <b>" + std::to_string(r.seed) + "</b></span>";
    if (!r.machine.empty()) h += "<span>machine <b>" + escapeMarkup(r.machine) + "</b></span>";
    h += "<span>wall time <b>" + duration(r.seconds) + "</b></span>";
    h += "</p>\n</header>\n<main>\n";

    if (r.students.empty()) {
        h += "<p class=\"muted\">No submissions were found.</p>\n";
    } else {
        htmlClassSummary(h, r);
        htmlSummaryTable(h, r);
    }

    for (std::size_t i = 0; i < r.students.size(); ++i) {
        const StudentResult& st = r.students[i];
        h += "<section class=\"student\" id=\"s" + std::to_string(i) +
             "\">\n<div class=\"student-head\"><h2>" + escapeMarkup(st.name) + "</h2>";
        h += "<span class=\"pill " + std::string(tone(st.score(), st.maxScore())) + "\">" +
             num(st.score()) + " / " + num(st.maxScore()) + "</span>";
        h += "<a class=\"top\" href=\"#top\">&#8593; class table</a></div>\n";
        for (std::size_t k = 0; k < st.stages.size(); ++k) htmlStage(h, st.stages[k], anchor(i, k));
        h += "</section>\n";
    }
    h += "</main>\n<footer>Generated by <code>raylab grade</code>. Scores are rounded to 2 "
         "decimals.</footer>\n</body>\n</html>\n";
    return h;
}

void writeHtmlReport(const ClassResult& result, const fs::path& outDir) {
    writeTextFileAtomic(outDir / "report.html", htmlReport(result));
}

}  // namespace raylab
