#include "csv_text.h"

#include "error.h"

#include <algorithm>
#include <cctype>

namespace raylab {

std::string csvText(const std::string& raw) {
    std::string s = raw;
    if (!s.empty() &&
        (s[0] == '=' || s[0] == '+' || s[0] == '-' || s[0] == '@' || s[0] == '\t' || s[0] == '\r'))
        s.insert(0, 1, '\'');
    if (s.find_first_of(",\"\r\n") == std::string::npos) return s;
    std::string out = "\"";
    for (char c : s) {
        if (c == '"') out += '"';
        out += c;
    }
    return out + "\"";
}

namespace {

std::string normalised(const std::string& s) {
    std::string out;
    for (char c : s)
        if (!std::isspace(static_cast<unsigned char>(c)))
            out += char(std::tolower(static_cast<unsigned char>(c)));
    return out;
}

}  // namespace

int CsvTable::column(const std::string& name) const {
    for (std::size_t i = 0; i < header.size(); ++i)
        if (normalised(header[i]) == normalised(name)) return int(i);
    return -1;
}

CsvTable parseCsv(const std::string& input, const std::string& where) {
    std::string text = input;
    if (text.rfind("\xEF\xBB\xBF", 0) == 0) text.erase(0, 3);
    std::vector<std::vector<std::string>> records;
    std::vector<int> lines;
    std::vector<std::string> record;
    std::string field;
    bool quoted = false, fieldStarted = false;
    int line = 1, recordLine = 1;
    bool wasQuoted = false;
    auto endField = [&] {
        // Spreadsheets pad cells: an unquoted field's surrounding spaces go.
        if (!wasQuoted) {
            const auto a = field.find_first_not_of(" \t");
            field = a == std::string::npos ? ""
                                           : field.substr(a, field.find_last_not_of(" \t") - a + 1);
        }
        wasQuoted = false;
        record.push_back(field);
        field.clear();
        fieldStarted = false;
    };
    auto endRecord = [&] {
        endField();
        const bool blank = record.size() == 1 && record[0].empty();
        if (!blank) {
            records.push_back(record);
            lines.push_back(recordLine);
        }
        record.clear();
    };
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (quoted) {
            if (c == '"' && i + 1 < text.size() && text[i + 1] == '"') {
                field += '"';
                ++i;
            } else if (c == '"') {
                quoted = false;
            } else {
                if (c == '\n') ++line;
                field += c;
            }
            continue;
        }
        if (c == '"' && field.find_first_not_of(" \t") == std::string::npos) {
            field.clear();  // spaces before an opening quote
            quoted = fieldStarted = wasQuoted = true;
        } else if (c == ',') {
            endField();
        } else if (c == '\n' || c == '\r') {
            if (c == '\r' && i + 1 < text.size() && text[i + 1] == '\n') ++i;
            endRecord();
            recordLine = ++line;
        } else {
            field += c;
            fieldStarted = true;
        }
    }
    if (quoted)
        throw Error(where + ": line " + std::to_string(recordLine) + ": a quote is not closed");
    if (!field.empty() || !record.empty()) endRecord();
    CsvTable t;
    if (records.empty()) throw Error(where + ": empty (expected a header row naming the columns)");
    t.header = records.front();
    for (std::size_t i = 1; i < records.size(); ++i) {
        if (records[i].size() != t.header.size())
            throw Error(where + ": line " + std::to_string(lines[i]) + ": " +
                        std::to_string(records[i].size()) + " fields, the header has " +
                        std::to_string(t.header.size()));
        t.rows.push_back(records[i]);
        t.lines.push_back(lines[i]);
    }
    return t;
}

}  // namespace raylab
