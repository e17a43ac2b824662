#include "grade_report.h"

#include "atomic_file.h"
#include "csv_text.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string_view>
#include <vector>

namespace raylab {

namespace fs = std::filesystem;

namespace {

// ---------------------------------------------------------------- numbers

// Scores as written everywhere: rounded to 2 decimals, never NaN/Inf or -0.
double round2(double v) {
    if (!std::isfinite(v)) return 0;
    double r = std::round(v * 100.0) / 100.0;
    return r == 0 ? 0.0 : r;
}

// "87.5", "100", "0.33": at most 2 decimals, no trailing zeros, no locale.
std::string num(double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.2f", round2(v));
    std::string s = buf;
    while (s.back() == '0') s.pop_back();
    if (s.back() == '.') s.pop_back();
    return s;
}

double fraction(double score, double maxScore) { return maxScore > 0 ? score / maxScore : 1.0; }

// "4.2 s", "3 min 07 s", "1 h 02 min".
std::string duration(double seconds) {
    if (!std::isfinite(seconds) || seconds < 0) seconds = 0;
    char buf[64];
    if (seconds < 60) {
        std::snprintf(buf, sizeof buf, "%.1f s", seconds);
    } else if (seconds < 3600) {
        long s = std::lround(seconds);
        std::snprintf(buf, sizeof buf, "%ld min %02ld s", s / 60, s % 60);
    } else {
        long m = std::lround(seconds / 60);
        std::snprintf(buf, sizeof buf, "%ld h %02ld min", m / 60, m % 60);
    }
    return buf;
}

// ---------------------------------------------------------------- text

void appendCodePoint(std::string& out, unsigned cp) {
    if (cp < 0x80) {
        out += char(cp);
    } else if (cp < 0x800) {
        out += char(0xC0 | (cp >> 6));
        out += char(0x80 | (cp & 0x3F));
    } else if (cp < 0x10000) {
        out += char(0xE0 | (cp >> 12));
        out += char(0x80 | ((cp >> 6) & 0x3F));
        out += char(0x80 | (cp & 0x3F));
    } else {
        out += char(0xF0 | (cp >> 18));
        out += char(0x80 | ((cp >> 12) & 0x3F));
        out += char(0x80 | ((cp >> 6) & 0x3F));
        out += char(0x80 | (cp & 0x3F));
    }
}

// Valid UTF-8 that XML 1.0 and HTML accept: invalid byte sequences, control
// characters other than tab/newline/CR, and U+FFFE/U+FFFF become U+FFFD.
// Student folder names and compiler logs can hold anything.
std::string cleanText(std::string_view s) {
    constexpr unsigned kReplacement = 0xFFFD;
    std::string out;
    out.reserve(s.size());
    std::size_t i = 0;
    while (i < s.size()) {
        const unsigned c = static_cast<unsigned char>(s[i]);
        unsigned cp = 0, min = 0;
        std::size_t len = 0;
        if (c < 0x80) { cp = c; len = 1; }
        else if ((c & 0xE0) == 0xC0) { cp = c & 0x1F; len = 2; min = 0x80; }
        else if ((c & 0xF0) == 0xE0) { cp = c & 0x0F; len = 3; min = 0x800; }
        else if ((c & 0xF8) == 0xF0) { cp = c & 0x07; len = 4; min = 0x10000; }
        bool ok = len > 0 && i + len <= s.size();
        for (std::size_t k = 1; ok && k < len; ++k) {
            const unsigned cc = static_cast<unsigned char>(s[i + k]);
            if ((cc & 0xC0) != 0x80) ok = false;
            else cp = (cp << 6) | (cc & 0x3F);
        }
        if (ok && len > 1 && (cp < min || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF))) ok = false;
        if (!ok) {
            appendCodePoint(out, kReplacement);
            ++i;
            continue;
        }
        if ((cp < 0x20 && cp != '\t' && cp != '\n' && cp != '\r') || cp == 0xFFFE || cp == 0xFFFF)
            appendCodePoint(out, kReplacement);
        else
            out.append(s.substr(i, len));
        i += len;
    }
    return out;
}

// Text for XML/HTML element content and attribute values (either quote).
// ATTRIBUTE also keeps tab/newline/CR through attribute-value normalisation.
std::string escapeMarkup(std::string_view s, bool attribute = false) {
    std::string clean = cleanText(s), out;
    out.reserve(clean.size() + clean.size() / 8);
    for (char c : clean) {
        switch (c) {
        case '&': out += "&amp;"; break;
        case '<': out += "&lt;"; break;
        case '>': out += "&gt;"; break;
        case '"': out += "&quot;"; break;
        case '\'': out += "&#39;"; break;
        case '\n': out += attribute ? "&#10;" : "\n"; break;
        case '\r': out += attribute ? "&#13;" : "\r"; break;
        case '\t': out += attribute ? "&#9;" : "\t"; break;
        default: out += c;
        }
    }
    return out;
}

// A relative path as a URL path: every byte but unreserved characters and '/'
// percent-encoded, so that '#', '?', ':' or spaces in a student's folder name
// cannot change what the link points to.
std::string urlPath(std::string_view path) {
    static const char* hex = "0123456789ABCDEF";
    std::string out;
    for (char ch : path) {
        const unsigned char c = static_cast<unsigned char>(ch);
        if ((c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-' || c == '.' || c == '_' ||
            c == '~' || c == '/') {
            out += ch;
        } else {
            out += '%';
            out += hex[c >> 4];
            out += hex[c & 15];
        }
    }
    return out;
}

std::string firstLine(const std::string& s) {
    std::size_t end = s.find_first_of("\r\n");
    return end == std::string::npos ? s : s.substr(0, end);
}

bool isGraded(const StageResult& s) { return s.status == "graded"; }

// The status word shown for a stage ("compile error"), never empty.
std::string statusWord(const StageResult& s) { return s.status.empty() ? std::string("error") : s.status; }

// The student's result for stage ID, or null.
const StageResult* findStage(const StudentResult& student, const std::string& id) {
    for (const StageResult& s : student.stages)
        if (s.stage == id) return &s;
    return nullptr;
}

// ---------------------------------------------------------------- CSV

// A CSV text field (csv_text.h) of cleaned text.
std::string csvField(const std::string& raw) { return csvText(cleanText(raw)); }

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
)css";

const char* tone(double score, double maxScore) {
    double f = fraction(score, maxScore);
    return f >= 0.9 ? "ok" : f >= 0.5 ? "warn" : "bad";
}

const char* statusTone(const StageResult& s) { return s.status == "not submitted" ? "none" : "bad"; }

std::string anchor(std::size_t student, std::size_t stage) { return "s" + std::to_string(student) + "-" + std::to_string(stage); }

std::string bar(double score, double maxScore) {
    double f = std::min(1.0, std::max(0.0, fraction(score, maxScore)));
    return "<span class=\"bar\"><i class=\"" + std::string(tone(score, maxScore)) + "\" style=\"width:" + std::to_string(std::lround(f * 100)) +
           "%\"></i></span>";
}

std::string figure(const std::string& path, const char* caption) {
    std::string out = "<figure>";
    if (path.empty()) {
        out += "<div class=\"noimg\">no image</div>";
    } else {
        std::string src = escapeMarkup(urlPath(path), true);
        out += "<a href=\"" + src + "\"><img src=\"" + src + "\" alt=\"" + caption + " image\" loading=\"lazy\"></a>";
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
        h += "<tr><td class=\"name\"><a href=\"#s" + std::to_string(i) + "\">" + escapeMarkup(st.name) + "</a></td>";
        for (std::size_t j = 0; j < r.stages.size(); ++j) {
            const StageResult* s = findStage(st, r.stages[j]);
            if (!s) {
                h += "<td class=\"num muted\" title=\"no result\">&ndash;</td>";
                continue;
            }
            std::size_t k = std::size_t(s - st.stages.data());
            stageSum[j] += s->score;
            stageMax[j] += s->maxScore;
            ++stageCount[j];
            if (isGraded(*s)) {
                h += "<td class=\"cell num\"><a class=\"" + std::string(tone(s->score, s->maxScore)) + "\" href=\"#" + anchor(i, k) + "\" title=\"" +
                     num(s->score) + " / " + num(s->maxScore) + "\">" + num(s->score) + "</a></td>";
            } else {
                h += "<td class=\"cell num\"><a class=\"status " + std::string(statusTone(*s)) + "\" href=\"#" + anchor(i, k) + "\">" +
                     escapeMarkup(statusWord(*s)) + "</a></td>";
            }
        }
        double score = st.score(), maxScore = st.maxScore();
        totalSum += score;
        totalMax += maxScore;
        h += "<td class=\"num\"><b>" + num(score) + "</b> <span class=\"muted\">/ " + num(maxScore) + "</span></td>";
        h += "<td class=\"num\">" + bar(score, maxScore) + std::to_string(std::lround(100 * fraction(score, maxScore))) + "%</td></tr>\n";
    }
    h += "</tbody>\n";
    if (!r.students.empty()) {
        h += "<tfoot><tr><td>Class average</td>";
        for (std::size_t j = 0; j < r.stages.size(); ++j)
            h += "<td class=\"num\">" + (stageCount[j] ? num(stageSum[j] / stageCount[j]) : std::string("&ndash;")) + "</td>";
        double n = double(r.students.size());
        h += "<td class=\"num\">" + num(totalSum / n) + " / " + num(totalMax / n) + "</td><td class=\"num\">" +
             std::to_string(std::lround(100 * fraction(totalSum, totalMax))) + "%</td></tr></tfoot>\n";
    }
    h += "</table></div>\n";
    h += "<p class=\"legend\"><span><span class=\"pill ok\">&ge; 90%</span></span><span><span class=\"pill warn\">50&ndash;90%</span></span>"
         "<span><span class=\"pill bad\">&lt; 50%</span></span><span><span class=\"pill none\">not submitted</span></span>"
         "<span>Click a cell for the details.</span></p>\n";
}

void htmlStage(std::string& h, const StageResult& s, const std::string& id) {
    h += "<div class=\"stage\" id=\"" + id + "\">\n<div class=\"stage-head\"><h3>" + escapeMarkup(s.stage) + "</h3>";
    h += "<span class=\"pill " + std::string(isGraded(s) ? tone(s.score, s.maxScore) : statusTone(s)) + "\">" + num(s.score) + " / " +
         num(s.maxScore) + "</span>";
    if (!isGraded(s)) h += "<span class=\"pill " + std::string(statusTone(s)) + "\">" + escapeMarkup(statusWord(s)) + "</span>";
    if (s.seconds > 0) h += "<span class=\"muted\">" + duration(s.seconds) + "</span>";
    h += "</div>\n";
    if (!s.message.empty()) h += "<pre class=\"log\">" + escapeMarkup(s.message) + "</pre>\n";
    if (s.checks.empty()) {
        if (isGraded(s)) h += "<p class=\"muted\">No checks.</p>\n";
        h += "</div>\n";
        return;
    }
    h += "<table class=\"checks\"><thead><tr><th>Check</th><th>Kind</th><th>Score</th><th>Result</th></tr></thead><tbody>\n";
    for (const CheckResult& c : s.checks) {
        h += "<tr><td class=\"check\">";
        h += c.passed ? "<span class=\"mark-ok\" title=\"passed\">&#10003;</span> " : "<span class=\"mark-bad\" title=\"failed\">&#10007;</span> ";
        h += escapeMarkup(c.name) + "</td><td class=\"kind\">" + escapeMarkup(c.kind) + "</td>";
        h += "<td class=\"score\"><span class=\"pill " + std::string(tone(c.score, c.maxScore)) + "\">" + num(c.score) + " / " + num(c.maxScore) +
             "</span></td><td class=\"out\">" + escapeMarkup(c.output);
        if (c.kind == "image")
            h += "<div class=\"thumbs\">" + figure(c.studentImage, "submitted") + figure(c.referenceImage, "reference") +
                 figure(c.diffImage, "difference") + "</div>";
        h += "</td></tr>\n";
    }
    h += "</tbody></table>\n</div>\n";
}

} // namespace

// ---------------------------------------------------------------- Gradescope

std::string gradescopeJson(const StudentResult& student) {
    using Json = nlohmann::ordered_json;
    Json tests = Json::array();
    std::string summary = "Total " + num(student.score()) + " / " + num(student.maxScore());
    double seconds = 0;
    for (std::size_t i = 0; i < student.stages.size(); ++i) {
        const StageResult& s = student.stages[i];
        seconds += std::isfinite(s.seconds) ? s.seconds : 0;
        summary += (i == 0 ? ". " : "; ") + cleanText(s.stage) + ": ";
        summary += isGraded(s) ? num(s.score) + " / " + num(s.maxScore) : statusWord(s);
        if (isGraded(s) && !s.checks.empty()) {
            for (const CheckResult& c : s.checks) {
                tests.push_back(Json{{"name", s.stage + " / " + c.name},
                                     {"score", round2(c.score)},
                                     {"max_score", round2(c.maxScore)},
                                     {"status", c.passed ? "passed" : "failed"},
                                     {"output", c.output}});
            }
        } else {
            // Not graded (or graded without checks): the stage as one test.
            bool graded = isGraded(s);
            tests.push_back(Json{{"name", graded ? s.stage : s.stage + ": " + statusWord(s)},
                                 {"score", round2(s.score)},
                                 {"max_score", round2(s.maxScore)},
                                 {"status", graded && s.score >= s.maxScore ? "passed" : "failed"},
                                 {"output", s.message.empty() ? statusWord(s) : s.message}});
        }
    }
    Json j{{"score", round2(student.score())},
           {"execution_time", std::lround(seconds)},
           {"output", summary},
           {"tests", std::move(tests)}};
    // Student-controlled text may not be UTF-8: replace, never throw.
    return j.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
}

void writeGradescopeResults(const StudentResult& student, const fs::path& file) { writeTextFileAtomic(file, gradescopeJson(student)); }

// ---------------------------------------------------------------- CSV

std::string summaryCsv(const ClassResult& r) {
    const std::string eol = "\r\n";
    std::string out = "student";
    for (const std::string& id : r.stages) out += "," + csvField(id);
    out += ",total,max,notes" + eol;
    for (const StudentResult& st : r.students) {
        out += csvField(st.name);
        std::string notes;
        auto note = [&notes](const std::string& n) { notes += (notes.empty() ? "" : "; ") + n; };
        for (const std::string& id : r.stages) {
            const StageResult* s = findStage(st, id);
            out += ",";
            if (!s) {
                note(id + ": no result");
                continue;
            }
            out += num(s->score);
            if (!isGraded(*s)) note(id + ": " + statusWord(*s));
        }
        out += "," + num(st.score()) + "," + num(st.maxScore()) + "," + csvField(notes) + eol;
    }
    return out;
}

void writeSummaryCsv(const ClassResult& result, const fs::path& file) { writeTextFileAtomic(file, summaryCsv(result)); }

// ---------------------------------------------------------------- JUnit

std::string junitXml(const ClassResult& r) {
    struct Counts {
        int tests = 0, failures = 0, errors = 0;
    };
    auto attr = [](const std::string& s) { return escapeMarkup(s, true); };
    auto seconds = [](double v) {
        char buf[64];
        std::snprintf(buf, sizeof buf, "%.3f", std::isfinite(v) && v > 0 ? v : 0.0);
        return std::string(buf);
    };

    std::string suites;
    Counts all;
    for (const StudentResult& st : r.students) {
        Counts c;
        double time = 0;
        std::string cases;
        for (const StageResult& s : st.stages) {
            time += std::isfinite(s.seconds) ? s.seconds : 0;
            const std::string classname = attr(st.name + "." + s.stage);
            if (isGraded(s) && !s.checks.empty()) {
                for (const CheckResult& k : s.checks) {
                    ++c.tests;
                    cases += "    <testcase classname=\"" + classname + "\" name=\"" + attr(k.name) + "\"";
                    if (k.passed) {
                        cases += "/>\n";
                        continue;
                    }
                    ++c.failures;
                    cases += ">\n      <failure message=\"" + attr(firstLine(k.output)) + "\" type=\"" + attr(k.kind) + "\">" +
                             escapeMarkup("score " + num(k.score) + " / " + num(k.maxScore) + (k.output.empty() ? "" : ": " + k.output)) +
                             "</failure>\n    </testcase>\n";
                }
                continue;
            }
            ++c.tests;
            cases += "    <testcase classname=\"" + classname + "\" name=\"stage\" time=\"" + seconds(s.seconds) + "\"";
            const std::string text = escapeMarkup(s.message.empty() ? statusWord(s) : s.message);
            if (isGraded(s) && s.score >= s.maxScore) {
                cases += "/>\n";
            } else if (isGraded(s) || s.status == "not submitted") {
                ++c.failures;
                cases += ">\n      <failure message=\"" + attr(isGraded(s) ? "score " + num(s.score) + " / " + num(s.maxScore) : statusWord(s)) +
                         "\" type=\"" + attr(statusWord(s)) + "\">" + text + "</failure>\n    </testcase>\n";
            } else {
                ++c.errors;
                cases += ">\n      <error message=\"" + attr(statusWord(s) + (s.message.empty() ? "" : ": " + firstLine(s.message))) +
                         "\" type=\"" + attr(statusWord(s)) + "\">" + text + "</error>\n    </testcase>\n";
            }
        }
        suites += "  <testsuite name=\"" + attr(st.name) + "\" tests=\"" + std::to_string(c.tests) + "\" failures=\"" +
                  std::to_string(c.failures) + "\" errors=\"" + std::to_string(c.errors) + "\" skipped=\"0\" time=\"" + seconds(time) + "\"";
        suites += cases.empty() ? "/>\n" : ">\n" + cases + "  </testsuite>\n";
        all.tests += c.tests;
        all.failures += c.failures;
        all.errors += c.errors;
    }
    return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites name=\"raylab grade\" tests=\"" + std::to_string(all.tests) + "\" failures=\"" +
           std::to_string(all.failures) + "\" errors=\"" + std::to_string(all.errors) + "\" time=\"" + seconds(r.seconds) + "\">\n" + suites +
           "</testsuites>\n";
}

void writeJunitXml(const ClassResult& result, const fs::path& file) { writeTextFileAtomic(file, junitXml(result)); }

// ---------------------------------------------------------------- HTML

std::string htmlReport(const ClassResult& r) {
    std::string h;
    h += "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
         "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
         "<title>RayLab grading report</title>\n<style>";
    h += kCss;
    h += "</style>\n</head>\n<body>\n<header id=\"top\">\n<h1>RayLab grading report</h1>\n<p class=\"meta\">";
    h += "<span><b>" + std::to_string(r.students.size()) + "</b> student" + (r.students.size() == 1 ? "" : "s") + "</span>";
    h += "<span><b>" + std::to_string(r.stages.size()) + "</b> stage" + (r.stages.size() == 1 ? "" : "s") + "</span>";
    h += "<span>seed <b>" + std::to_string(r.seed) + "</b></span>";
    if (!r.machine.empty()) h += "<span>machine <b>" + escapeMarkup(r.machine) + "</b></span>";
    h += "<span>wall time <b>" + duration(r.seconds) + "</b></span>";
    h += "</p>\n</header>\n<main>\n";

    if (r.students.empty()) h += "<p class=\"muted\">No submissions were found.</p>\n";
    else htmlSummaryTable(h, r);

    for (std::size_t i = 0; i < r.students.size(); ++i) {
        const StudentResult& st = r.students[i];
        h += "<section class=\"student\" id=\"s" + std::to_string(i) + "\">\n<div class=\"student-head\"><h2>" + escapeMarkup(st.name) + "</h2>";
        h += "<span class=\"pill " + std::string(tone(st.score(), st.maxScore())) + "\">" + num(st.score()) + " / " + num(st.maxScore()) +
             "</span>";
        h += "<a class=\"top\" href=\"#top\">&#8593; class table</a></div>\n";
        for (std::size_t k = 0; k < st.stages.size(); ++k) htmlStage(h, st.stages[k], anchor(i, k));
        h += "</section>\n";
    }
    h += "</main>\n<footer>Generated by <code>raylab grade</code>. Scores are rounded to 2 decimals.</footer>\n</body>\n</html>\n";
    return h;
}

void writeHtmlReport(const ClassResult& result, const fs::path& outDir) { writeTextFileAtomic(outDir / "report.html", htmlReport(result)); }

} // namespace raylab
