// The class's page (grade_report.h): the class at a glance, then one row
// per student, sortable, each linking to the student's own page.
#include "grade_report.h"

#include "html_page.h"
#include "report_text.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace raylab {

using namespace report;

namespace {

// Sorting the class table: a click (or Enter) on a column's button sorts by
// it, again reverses; numbers by their data-v value. The only script of the
// report, and the table reads in its first order without it.
const char* kSortScript = R"js(
document.querySelectorAll("table.sortable").forEach(function (table) {
  var heads = table.tHead.rows[0].cells;
  Array.prototype.forEach.call(heads, function (th, col) {
    var button = th.querySelector("button");
    if (!button) return;
    button.addEventListener("click", function () {
      var down = th.getAttribute("aria-sort") === "ascending";
      Array.prototype.forEach.call(heads, function (h) { h.removeAttribute("aria-sort"); });
      th.setAttribute("aria-sort", down ? "descending" : "ascending");
      var body = table.tBodies[0], rows = Array.prototype.slice.call(body.rows);
      function key(row) {
        var cell = row.cells[col], v = cell.getAttribute("data-v");
        return v === null ? cell.textContent.trim().toLowerCase() : parseFloat(v);
      }
      rows.sort(function (a, b) {
        var x = key(a), y = key(b), c = y > x ? -1 : x > y ? 1 : 0;
        return down ? -c : c;
      });
      rows.forEach(function (row) { body.appendChild(row); });
    });
  });
});
)js";

bool anySection(const ClassResult& r) {
    return std::any_of(r.students.begin(), r.students.end(),
                       [](const StudentResult& st) { return !st.roster.section.empty(); });
}

std::string sortHead(const std::string& label, bool numeric) {
    return std::string("<th scope=\"col\"") + (numeric ? " class=\"num\"" : "") +
           "><button type=\"button\">" + label + "</button></th>";
}

void htmlSummaryTable(std::string& h, const ClassResult& r) {
    const bool sections = anySection(r);
    h += "<div class=\"scroll\"><table class=\"summary sortable\">\n<caption>One row per "
         "student; a column's name sorts the table by it. A student's name opens their page "
         "with every check and picture.</caption>\n<thead><tr>" +
         sortHead("Student", false);
    if (sections) h += sortHead("Section", false);
    for (const std::string& id : r.stages) h += sortHead(escapeMarkup(id), true);
    h += sortHead("Total", true) + sortHead("%", true) + "</tr></thead>\n<tbody>\n";
    std::vector<double> stageSum(r.stages.size(), 0.0), stageMax(r.stages.size(), 0.0);
    std::vector<int> stageCount(r.stages.size(), 0);
    double totalSum = 0, totalMax = 0;
    for (const StudentResult& st : r.students) {
        const std::string page = studentPage(st.name);
        h += "<tr><th scope=\"row\" class=\"name\">" +
             (st.hasFolder
                  ? "<a href=\"" + escapeMarkup(page, true) + "\">" + escapeMarkup(st.name) + "</a>"
                  : escapeMarkup(st.name)) +
             "</th>";
        if (sections) h += "<td>" + escapeMarkup(st.roster.section) + "</td>";
        for (std::size_t j = 0; j < r.stages.size(); ++j) {
            const StageResult* s = findStage(st, r.stages[j]);
            if (!s) {
                h += "<td class=\"num muted\" data-v=\"-1\" title=\"no result\">&ndash;</td>";
                continue;
            }
            if (s->status != "not submitted" && !s->excused) {
                // The average of those who handed it in.
                stageSum[j] += s->score;
                stageMax[j] += s->maxScore;
                ++stageCount[j];
            }
            const std::string value = s->excused ? "-2" : isGraded(*s) ? num(s->score) : "-1";
            const std::string link =
                st.hasFolder ? escapeMarkup(page, true) + "#" + stageAnchor(s->stage) : "";
            std::string title;
            if (s->excused) title = escapeMarkup(s->excuseNote, true);
            else if (s->latePenalty > 0)
                title = num(s->rawScore()) +
                        " before the late penalty: " + escapeMarkup(s->lateNote, true);
            const char* cls = s->excused                     ? "status none"
                              : isGraded(*s)                 ? tone(s->score, s->maxScore)
                              : s->status == "not submitted" ? "status none"
                                                             : "status bad";
            const std::string text =
                escapeMarkup(stageCellText(*s)) +
                (s->latePenalty > 0 ? "<span class=\"late\"> late</span>" : "");
            h += "<td class=\"c\" data-v=\"" + value + "\">";
            if (link.empty())
                h += "<span class=\"pill " + std::string(cls) + "\">" + text + "</span>";
            else
                h += "<a class=\"" + std::string(cls) + "\" href=\"" + link + "\"" +
                     (title.empty() ? "" : " title=\"" + title + "\"") + ">" + text + "</a>";
            h += "</td>";
        }
        double score = st.score(), maxScore = st.maxScore();
        totalSum += score;
        totalMax += maxScore;
        const long percent = std::lround(100 * fraction(score, maxScore));
        h += "<td class=\"num\" data-v=\"" + num(score) + "\"><b>" + num(score) +
             "</b> <span class=\"muted\">/ " + num(maxScore) + "</span></td>";
        h += "<td class=\"num\" data-v=\"" + std::to_string(percent) + "\">" +
             bar(score, maxScore) + std::to_string(percent) + "%</td></tr>\n";
    }
    h += "</tbody>\n";
    if (!r.students.empty()) {
        h += "<tfoot><tr><td title=\"per stage: of those who handed it in\"" +
             std::string(sections ? " colspan=\"2\"" : "") + ">Class average</td>";
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
         "<span><span class=\"pill bad\">&lt; 50%</span></span><span><span class=\"pill "
         "none\">not submitted or excused</span></span></p>\n";
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

}  // namespace

std::string htmlClassPage(const ClassResult& r, const ClassPageOptions& options) {
    std::string meta;
    meta += "<span><b>" + std::to_string(r.students.size()) + "</b> student" +
            (r.students.size() == 1 ? "" : "s") + "</span>";
    meta += "<span><b>" + std::to_string(r.stages.size()) + "</b> stage" +
            (r.stages.size() == 1 ? "" : "s") + "</span>";
    meta += "<span>seed <b>" + std::to_string(r.seed) + "</b></span>";
    if (!r.machine.empty()) meta += "<span>machine <b>" + escapeMarkup(r.machine) + "</b></span>";
    meta += "<span>wall time <b>" + duration(r.seconds) + "</b></span>";
    std::string h = pageStart(options.title, meta);
    if (!options.sections.empty()) {
        h += "<nav class=\"sections\" aria-label=\"Sections\">Sections:";
        for (const auto& [name, link] : options.sections)
            h += " <a href=\"" + escapeMarkup(urlPath(link), true) + "\">" + escapeMarkup(name) +
                 "</a>";
        h += "</nav>\n";
    }
    if (r.students.empty()) {
        h += "<p class=\"muted\">No submissions were found.</p>\n";
    } else {
        htmlClassSummary(h, r);
        htmlSummaryTable(h, r);
        h += "<script>" + std::string(kSortScript) + "</script>\n";
    }
    return h + pageEnd();
}

}  // namespace raylab
