#include "report_text.h"

#include "csv_text.h"
#include "error.h"
#include "text_format.h"

#include <cmath>
#include <cstdio>

namespace raylab::report {

// ---------------------------------------------------------------- numbers

// Scores as written everywhere: rounded to 2 decimals, never NaN/Inf or -0.
double round2(double v) {
    if (!std::isfinite(v)) return 0;
    double r = std::round(v * 100.0) / 100.0;
    return r == 0 ? 0.0 : r;
}

// "87.5", "100", "0.33": at most 2 decimals, no trailing zeros, no locale.
std::string num(double v) { return trimmedFixed(round2(v), 2); }

double fraction(double score, double maxScore) { return maxScore > 0 ? score / maxScore : 1.0; }

// "4.2 s", "3 min 07 s", "1 h 02 min".
std::string duration(double seconds) { return durationText(seconds); }

// ---------------------------------------------------------------- text

namespace {

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

}  // namespace

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
        if (c < 0x80) {
            cp = c;
            len = 1;
        } else if ((c & 0xE0) == 0xC0) {
            cp = c & 0x1F;
            len = 2;
            min = 0x80;
        } else if ((c & 0xF0) == 0xE0) {
            cp = c & 0x0F;
            len = 3;
            min = 0x800;
        } else if ((c & 0xF8) == 0xF0) {
            cp = c & 0x07;
            len = 4;
            min = 0x10000;
        }
        bool ok = len > 0 && i + len <= s.size();
        for (std::size_t k = 1; ok && k < len; ++k) {
            const unsigned cc = static_cast<unsigned char>(s[i + k]);
            if ((cc & 0xC0) != 0x80) ok = false;
            else cp = (cp << 6) | (cc & 0x3F);
        }
        if (ok && len > 1 && (cp < min || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF)))
            ok = false;
        if (!ok) {
            appendCodePoint(out, kReplacement);
            ++i;
            continue;
        }
        if ((cp < 0x20 && cp != '\t' && cp != '\n' && cp != '\r') || cp == 0xFFFE || cp == 0xFFFF)
            appendCodePoint(out, kReplacement);
        else out.append(s.substr(i, len));
        i += len;
    }
    return out;
}

// Text for XML/HTML element content and attribute values (either quote).
// ATTRIBUTE also keeps tab/newline/CR through attribute-value normalisation.
std::string escapeMarkup(std::string_view s, bool attribute) {
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
        if ((c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') ||
            c == '-' || c == '.' || c == '_' || c == '~' || c == '/') {
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
std::string statusWord(const StageResult& s) {
    return s.status.empty() ? std::string("error") : s.status;
}

// The student's result for stage ID, or null.
const StageResult* findStage(const StudentResult& student, const std::string& id) {
    for (const StageResult& s : student.stages)
        if (s.stage == id) return &s;
    return nullptr;
}

// ---------------------------------------------------------------- CSV

// A CSV text field (csv_text.h) of cleaned text.
std::string gradebookCell(const StudentResult& student, const std::string& id,
                          const std::string& excused) {
    const StageResult* s = findStage(student, id);
    if (!s) return "";
    if (s->excused) return excused;
    return s->status == "not submitted" ? "" : num(s->score);
}

std::string gradebookRows(const ClassResult& result,
                          const std::function<bool(const RosterEntry&)>& matchable,
                          const std::function<std::string(const StudentResult&)>& row,
                          const std::string& noMatch) {
    std::string rows;
    for (const StudentResult& st : result.students)
        if (matchable(st.roster)) rows += row(st) + "\r\n";
    if (rows.empty()) throw Error(noMatch);
    return rows;
}

std::pair<std::string, std::string> lastAndFirst(const std::string& fullName) {
    const std::size_t comma = fullName.find(',');
    if (comma == std::string::npos) return {fullName, ""};
    std::string first = fullName.substr(comma + 1);
    first.erase(0, first.find_first_not_of(' '));
    return {fullName.substr(0, comma), first};
}

std::string csvField(const std::string& raw) { return csvText(cleanText(raw)); }

}  // namespace raylab::report
