// One student's page (grade_report.h): every stage with its checks, the
// pictures beside the reference's, the compiler's messages, the late and
// excused notes and the regrades. Loaded only when opened from the class
// table, so that the class page stays small.
#include "grade_report.h"

#include "html_page.h"
#include "report_text.h"

namespace raylab {

using namespace report;

namespace {

// The student's pages lie in students/<name>/: image paths (relative to the
// report's folder) go up two folders.
constexpr const char* kUp = "../../";

std::string figure(const std::string& path, const std::string& caption, const std::string& alt) {
    std::string out = "<figure>";
    if (path.empty()) {
        out += "<div class=\"noimg\">no image</div>";
    } else {
        const std::string src = escapeMarkup(kUp + urlPath(path), true);
        out += "<a href=\"" + src + "\"><img src=\"" + src + "\" alt=\"" + escapeMarkup(alt, true) +
               "\" width=\"180\" height=\"135\" loading=\"lazy\"></a>";
    }
    return out + "<figcaption>" + caption + "</figcaption></figure>";
}

void htmlStage(std::string& h, const std::string& student, const StageResult& s) {
    h += "<section class=\"stage\" id=\"" + stageAnchor(s.stage) +
         "\">\n<div class=\"stage-head\"><h2>" + escapeMarkup(s.stage) + "</h2>";
    h += "<span class=\"pill " +
         std::string(isGraded(s) && !s.excused ? tone(s.score, s.maxScore) : statusTone(s)) +
         "\">" + num(s.score) + " / " + num(s.maxScore) + "</span>";
    if (!isGraded(s))
        h += "<span class=\"pill " + std::string(statusTone(s)) + "\">" +
             escapeMarkup(statusWord(s)) + "</span>";
    if (s.excused)
        h += "<span class=\"excused\">excused" +
             (s.excuseNote.empty() ? "" : ": " + escapeMarkup(s.excuseNote)) +
             " (counts for nothing)</span>";
    if (s.seconds > 0) h += "<span class=\"muted\">" + duration(s.seconds) + "</span>";
    if (!s.lateNote.empty()) h += "<span class=\"late\">" + escapeMarkup(s.lateNote) + "</span>";
    h += "</div>\n";
    if (!s.message.empty()) h += "<pre class=\"log\">" + escapeMarkup(s.message) + "</pre>\n";
    if (s.checks.empty()) {
        if (isGraded(s)) h += "<p class=\"muted\">No checks.</p>\n";
        h += "</section>\n";
        return;
    }
    h += "<table class=\"checks\"><thead><tr><th scope=\"col\">Check</th><th "
         "scope=\"col\">Kind</th><th scope=\"col\">Score</th><th "
         "scope=\"col\">Result</th></tr></thead><tbody>\n";
    for (const CheckResult& c : s.checks) {
        h += "<tr><td class=\"check\">";
        h += c.passed
                 ? "<span class=\"mark-ok\" role=\"img\" aria-label=\"passed\">&#10003;</span> "
                 : "<span class=\"mark-bad\" role=\"img\" aria-label=\"failed\">&#10007;</span> ";
        h += escapeMarkup(c.name) + "</td><td class=\"kind\">" + escapeMarkup(c.kind) + "</td>";
        h += "<td class=\"score\"><span class=\"pill " + std::string(tone(c.score, c.maxScore)) +
             "\">" + num(c.score) + " / " + num(c.maxScore) + "</span></td><td class=\"out\">" +
             escapeMarkup(c.output);
        if (c.kind == "image") {
            // Alt text says whose picture of which stage and view it is.
            const std::string view = s.stage + ", view " + c.name;
            h += "<div class=\"thumbs\">" +
                 figure(c.studentImage, "submitted", student + "'s picture of " + view) +
                 figure(c.referenceImage, "reference", "the reference picture of " + view) +
                 figure(c.diffImage, "difference",
                        "where " + student + "'s picture of " + view +
                            " differs from the reference (red: differs)") +
                 "</div>";
        }
        h += "</td></tr>\n";
    }
    h += "</tbody></table>\n</section>\n";
}

void htmlRegrades(std::string& h, const StudentResult& st) {
    if (st.regrades.empty()) return;
    h += "<section class=\"history\" id=\"regrades\"><h2>Regrades</h2>\n<table "
         "class=\"checks\"><thead><tr><th scope=\"col\">When</th><th "
         "scope=\"col\">Why</th><th scope=\"col\">Stage</th><th scope=\"col\">Before, "
         "after</th></tr></thead><tbody>\n";
    for (const Regrade& g : st.regrades) {
        const std::string when = "<td>" + escapeMarkup(g.when) + "</td><td>" +
                                 escapeMarkup(g.reason.empty() ? "(no reason given)" : g.reason) +
                                 "</td>";
        if (g.changes.empty()) h += "<tr>" + when + "<td colspan=\"2\">nothing changed</td></tr>\n";
        for (const RegradeChange& c : g.changes)
            h += "<tr>" + when + "<td>" + escapeMarkup(c.stage) + "</td><td>" +
                 escapeMarkup(c.before) + " &rarr; " + escapeMarkup(c.after) + "</td></tr>\n";
    }
    h += "</tbody></table></section>\n";
}

}  // namespace

std::string htmlStudentPage(const ClassResult& r, const StudentResult& st) {
    std::string meta =
        "<span><b>" + num(st.score()) + "</b> of " + num(st.maxScore()) + " points</span>";
    if (!st.roster.section.empty())
        meta += "<span>section <b>" + escapeMarkup(st.roster.section) + "</b></span>";
    meta += "<span>seed <b>" + std::to_string(r.seed) + "</b></span>";
    if (!r.machine.empty()) meta += "<span>machine <b>" + escapeMarkup(r.machine) + "</b></span>";
    std::string h = pageStart(st.name, meta);
    h += "<p><a href=\"" + std::string(kUp) + "report.html\">&#8593; the class table</a></p>\n";
    h += "<div class=\"student\">\n";
    for (const StageResult& s : st.stages) htmlStage(h, st.name, s);
    h += "</div>\n";
    htmlRegrades(h, st);
    return h + pageEnd();
}

}  // namespace raylab
