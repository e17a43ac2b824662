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

bool isStubLine(const std::string& t) { return t == "//@" || startsWith(t, "//@ "); }

// A stub line ("    //@ code") as the lab shows it ("    code").
std::string unstubbed(const std::string& line, const std::string& t) {
    return line.substr(0, line.size() - t.size()) + (t.size() > 4 ? t.substr(4) : "");
}

}  // namespace

Level parseLevel(const std::string& name) {
    if (name == "guided") return Level::Guided;
    if (name == "open") return Level::Open;
    throw Error("unknown level '" + name + "' (expected guided or open)");
}

const char* levelName(Level level) { return level == Level::Open ? "open" : "guided"; }

std::string transformMarkedSource(const std::string& text, MarkedForm form, const std::string& file,
                                  Level level) {
    // Where we are: in a //@solution region (Solution, Stub), in an open
    // region's stub (OpenStub); `open` says whether we are inside an open
    // region's guided part, which may hold //@solution regions of its own.
    enum class State { Normal, Solution, Stub, OpenStub } state = State::Normal;
    bool open = false;
    const bool openLab = form == MarkedForm::Lab && level == Level::Open;
    std::vector<std::string> out;
    // A "// TODO(" comment right above: whether there is one, and its index
    // in `out` (the solved form drops it; it always keeps what it reads).
    bool header = false;
    std::size_t headerStart = 0;
    int regionLine = 0, openLine = 0;
    std::istringstream in(text);
    std::string line;
    auto fail = [&](int n, const std::string& what) -> void {
        throw Error(file + ":" + std::to_string(n) + ": " + what);
    };
    // The open lab drops an open region's guided part whole.
    auto keep = [&](const std::string& l) {
        if (!(open && openLab)) out.push_back(l);
    };

    for (int n = 1; std::getline(in, line); ++n) {
        const std::string t = leftTrimmed(line);
        switch (state) {
        case State::Normal:
            if (startsWith(t, "//@solution")) {
                if (!header)
                    fail(n, "//@solution needs a \"// TODO(id): ...\" comment right above it");
                if (form == MarkedForm::Solved) out.resize(headerStart);
                state = State::Solution;
                regionLine = n;
            } else if (t == "//@open") {
                if (open)
                    fail(n, "//@open inside the open region opened on line " +
                                std::to_string(openLine));
                state = State::OpenStub;
                openLine = n;
                header = false;
            } else if (t == "//@end-open") {
                if (!open) fail(n, "marker '//@end-open' outside an //@open region");
                open = false;
                header = false;
            } else if (startsWith(t, "//@")) {
                fail(n, "marker '" + t + "' outside a //@solution ... //@end region");
            } else {
                keep(line);
                if (startsWith(t, "// TODO(")) {
                    header = true;
                    headerStart = out.size() - 1;
                } else if (!startsWith(t, "//")) {
                    header = false;
                }
            }
            break;
        case State::Solution:
            if (startsWith(t, "//@stub")) state = State::Stub;
            else if (startsWith(t, "//@")) fail(n, "expected //@stub before '" + t + "'");
            else if (form == MarkedForm::Solved) keep(line);
            break;
        case State::Stub:
            if (startsWith(t, "//@end")) {
                state = State::Normal;
                header = false;
            } else if (isStubLine(t)) {
                if (form == MarkedForm::Lab) keep(unstubbed(line, t));
            } else {
                fail(n, "stub lines must start with \"//@ \" (found '" + t + "')");
            }
            break;
        case State::OpenStub:
            if (t == "//@guided") {
                state = State::Normal;
                open = true;
            } else if (isStubLine(t)) {
                if (openLab) out.push_back(unstubbed(line, t));
            } else {
                fail(n, "an //@open region's stub lines start with \"//@ \" and end with "
                        "//@guided (found '" +
                            t + "')");
            }
            break;
        }
    }
    if (state == State::Solution || state == State::Stub)
        fail(regionLine, "region not closed with //@end");
    if (state == State::OpenStub) fail(openLine, "//@open region without //@guided");
    if (open) fail(openLine, "//@open region not closed with //@end-open");

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

int studentCodeLines(const std::string& text, Level level) {
    int count = 0;
    bool inSolution = false, inOpen = false, inOpenStub = false;
    std::istringstream in(text);
    std::string line;
    while (std::getline(in, line)) {
        const std::string t = leftTrimmed(line);
        if (t == "//@open") inOpen = inOpenStub = true;
        else if (t == "//@guided") inOpenStub = false;
        else if (t == "//@end-open") inOpen = false;
        else if (startsWith(t, "//@solution")) inSolution = true;
        else if (startsWith(t, "//@"))
            inSolution = inSolution && !startsWith(t, "//@stub") && !startsWith(t, "//@end");
        else if (!t.empty() && !startsWith(t, "//") && !inOpenStub &&
                 (inSolution || (level == Level::Open && inOpen)))
            ++count;
    }
    return count;
}

}  // namespace raylab
