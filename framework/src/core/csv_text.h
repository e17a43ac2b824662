#pragma once
// One text field of a CSV file (RFC 4180), shared by the grade and bench
// reports: quoted when it holds a comma, quote or line break, and with a
// leading apostrophe when a spreadsheet would run it as a formula (=, +, -,
// @, tab, CR first) - a student's folder or a scene's name must not compute.
#include <map>
#include <string>
#include <vector>

namespace raylab {

std::string csvText(const std::string& raw);

// A CSV file an instructor gives (a roster, submission times): RFC 4180
// fields (quoted ones may hold commas, quotes and line breaks), LF or CRLF
// line ends, a UTF-8 byte-order mark (spreadsheets write one) skipped, blank
// lines skipped, spaces around an unquoted field dropped. The first row
// names the columns.
struct CsvTable {
    std::vector<std::string> header;
    std::vector<std::vector<std::string>> rows;  // each as long as the header
    std::vector<int> lines;                      // each row's line in the file, for messages
    // The column named NAME (case and surrounding space ignored), or -1.
    int column(const std::string& name) const;
};

// Throws Error("WHERE: line N: why") on an unclosed quote or a row whose
// field count differs from the header's.
CsvTable parseCsv(const std::string& text, const std::string& where);

}  // namespace raylab
