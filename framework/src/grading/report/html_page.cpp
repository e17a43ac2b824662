#include "html_page.h"

#include "report_text.h"

#include <algorithm>
#include <cmath>

namespace raylab::report {

namespace {

const char* const kCss = R"css(
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
td.c{padding:3px;text-align:center;white-space:nowrap}
td.c a{display:block;padding:4px 8px;border-radius:5px;color:inherit;font-weight:600}
td.c a:hover{text-decoration:none;filter:brightness(.95)}
.ok{background:var(--ok-bg);color:var(--ok)}
.warn{background:var(--warn-bg);color:var(--warn)}
.bad{background:var(--bad-bg);color:var(--bad)}
.none{background:var(--none-bg);color:var(--none)}
td.c a.status{font-weight:500;font-size:12px}
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
.skip{position:absolute;left:-9999px}.skip:focus{left:12px;top:12px;background:#fff;padding:6px 10px;z-index:9}
th button{all:unset;cursor:pointer;font:inherit;color:inherit}
th button:focus-visible,a:focus-visible{outline:2px solid var(--link);outline-offset:2px}
th[aria-sort=ascending] button::after{content:" \2191"}th[aria-sort=descending] button::after{content:" \2193"}
caption{text-align:left;padding:8px 12px;color:var(--muted);font-size:12px;caption-side:bottom}
nav.sections{margin:0 0 18px;font-size:13px}nav.sections a{margin-right:12px}
.excused{color:var(--none);font-size:12px}
.history{margin:18px 16px 16px}
)css";

}  // namespace

std::string pageStart(const std::string& title, const std::string& meta) {
    return "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
           "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n<title>" +
           escapeMarkup(title) + "</title>\n<style>" + kCss +
           "</style>\n</head>\n<body>\n<a class=\"skip\" href=\"#main\">Skip to the "
           "results</a>\n<header id=\"top\">\n<h1>" +
           escapeMarkup(title) + "</h1>\n<p class=\"meta\">" + meta +
           "</p>\n</header>\n<main id=\"main\">\n";
}

std::string pageEnd() {
    return "</main>\n<footer>Generated by <code>raylab grade</code>. Scores are rounded to 2 "
           "decimals.</footer>\n</body>\n</html>\n";
}

const char* tone(double score, double maxScore) {
    double f = fraction(score, maxScore);
    return f >= 0.9 ? "ok" : f >= 0.5 ? "warn" : "bad";
}

const char* statusTone(const StageResult& s) {
    return s.status == "not submitted" || s.excused ? "none" : "bad";
}

std::string bar(double score, double maxScore) {
    double f = std::min(1.0, std::max(0.0, fraction(score, maxScore)));
    return "<span class=\"bar\" aria-hidden=\"true\"><i class=\"" +
           std::string(tone(score, maxScore)) +
           "\" style=\"width:" + std::to_string(std::lround(f * 100)) + "%\"></i></span>";
}

std::string studentPage(const std::string& name) {
    return "students/" + urlPath(name) + "/report.html";
}

std::string stageAnchor(const std::string& stage) { return urlPath(stage); }

std::string stageCellText(const StageResult& s) {
    if (s.excused) return "excused";
    return isGraded(s) ? num(s.score) : statusWord(s);
}

}  // namespace raylab::report
