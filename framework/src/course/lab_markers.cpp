#include "lab_markers.h"

#include "error.h"

#include <sstream>
#include <vector>

namespace raylab {

namespace {

bool startsWith(const std::string& s, const char* prefix) { return s.rfind(prefix, 0) == 0; }

std::string leftTrimmed(const std::string& s) {
    std::size_t i = s.find_first_not_of(" \t");
    return i == std::string::npos ? std::string() : s.substr(i);
}

}  // namespace

std::string transformMarkedSource(const std::string& text, MarkedForm form,
                                  const std::string& file) {
    enum class State { Normal, Solution, Stub } state = State::Normal;
    std::vector<std::string> out;
    long headerStart = -1;  // index in `out` of the current "// TODO(" line, -1 when none
    int regionLine = 0;
    std::istringstream in(text);
    std::string line;
    auto fail = [&](int n, const std::string& what) -> void {
        throw Error(file + ":" + std::to_string(n) + ": " + what);
    };

    for (int n = 1; std::getline(in, line); ++n) {
        const std::string t = leftTrimmed(line);
        switch (state) {
        case State::Normal:
            if (startsWith(t, "//@solution")) {
                if (headerStart < 0)
                    fail(n, "//@solution needs a \"// TODO(id): ...\" comment right above it");
                if (form == MarkedForm::Solved) out.resize(std::size_t(headerStart));
                state = State::Solution;
                regionLine = n;
            } else if (startsWith(t, "//@")) {
                fail(n, "marker '" + t + "' outside a //@solution ... //@end region");
            } else {
                out.push_back(line);
                if (startsWith(t, "// TODO(")) headerStart = long(out.size()) - 1;
                else if (!startsWith(t, "//")) headerStart = -1;
            }
            break;
        case State::Solution:
            if (startsWith(t, "//@stub")) state = State::Stub;
            else if (startsWith(t, "//@")) fail(n, "expected //@stub before '" + t + "'");
            else if (form == MarkedForm::Solved) out.push_back(line);
            break;
        case State::Stub:
            if (startsWith(t, "//@end")) {
                state = State::Normal;
                headerStart = -1;
            } else if (t == "//@" || startsWith(t, "//@ ")) {
                if (form == MarkedForm::Lab)
                    out.push_back(line.substr(0, line.size() - t.size()) +
                                  (t.size() > 4 ? t.substr(4) : ""));
            } else {
                fail(n, "stub lines must start with \"//@ \" (found '" + t + "')");
            }
            break;
        }
    }
    if (state != State::Normal) fail(regionLine, "region not closed with //@end");

    std::string result;
    for (const std::string& l : out) result += l + "\n";
    return result;
}

std::vector<int> solutionLineNumbers(const std::string& text) {
    std::vector<int> lines;
    bool inSolution = false;
    std::istringstream in(text);
    std::string line;
    for (int n = 1; std::getline(in, line); ++n) {
        const std::string t = leftTrimmed(line);
        if (startsWith(t, "//@")) inSolution = startsWith(t, "//@solution");
        else if (inSolution) lines.push_back(n);
    }
    return lines;
}

}  // namespace raylab
