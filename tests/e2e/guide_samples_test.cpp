// The check output a lab guide shows ("On the untouched lab it prints") is
// what `raylab check` prints on that lab as handed out, at the guide's level:
// the open TODOs with their files and lines, each function check's failing
// line, every view it names failing, and the count of checks. A guide that
// drifts from the checks (a function check added, a TODO moved) fails here.
#include "stage_catalog.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <regex>
#include <sstream>

using namespace raylab::test;

namespace {

struct Sample {
    std::string level;  // "open" or "guided"
    std::vector<std::string> lines;
};

std::string trimmed(const std::string& s) {
    const auto a = s.find_first_not_of(' '), b = s.find_last_not_of(' ');
    return a == std::string::npos ? "" : s.substr(a, b - a + 1);
}

// The fenced blocks of GUIDE that end with "N passed, M failed", with the
// level of the <!-- open --> or <!-- guided --> section around them (both
// levels' guides hold a block outside such sections: "guided" then).
std::vector<Sample> samplesOf(const fs::path& guide) {
    std::vector<Sample> out;
    std::istringstream in(readFile(guide));
    std::string level = "guided", line;
    bool fenced = false;
    Sample current;
    while (std::getline(in, line)) {
        if (!fenced && line == "<!-- open -->") level = "open";
        if (!fenced && (line == "<!-- /open -->" || line == "<!-- /guided -->")) level = "guided";
        if (line.rfind("```", 0) == 0) {
            if (fenced && !current.lines.empty() &&
                std::regex_match(current.lines.back(), std::regex(R"(\d+ passed, \d+ failed)"))) {
                current.level = level;
                out.push_back(current);
            }
            fenced = !fenced;
            current = Sample{};
            continue;
        }
        if (fenced) current.lines.push_back(line);
    }
    return out;
}

}  // namespace

TEST(GuideSamples, TheUntouchedLabPrintsWhatItsGuideShows) {
    int samples = 0;
    for (const raylab::StageInfo& stage : raylab::allStages()) {
        for (const Sample& sample : samplesOf(stage.folder() / "guide.md")) {
            SCOPED_TRACE(stage.id + "'s guide, " + sample.level + " level");
            ScratchDir dir;
            const fs::path lab = dir / "lab";
            CommandResult h = runRaylab("handout --level " + sample.level + " --stages " +
                                        stage.id + " --carry solved --out " + quote(lab.string()));
            ASSERT_EQ(h.exitCode, 0) << h.all();
            CommandResult r =
                runRaylab("check --stage " + stage.id + " --lab " + quote(lab.string()));
            EXPECT_EQ(r.exitCode, 1) << r.all();
            const std::string printed = r.all();  // the TODO list goes to stderr
            const std::regex todo(R"(\s*\S*/(\S+:\d+: TODO\(.*)$)"),
                failing(R"(\s*FAIL (\S+)\s.*)"), views(R"(\s*FAIL (\S+)\s+\d.*% of pixels.*)");
            for (const std::string& line : sample.lines) {
                std::smatch m;
                if (line.find("open TODOs in this lab") != std::string::npos ||
                    std::regex_match(line, std::regex(R"(\d+ passed, \d+ failed)"))) {
                    EXPECT_NE(printed.find(trimmed(line)), std::string::npos)
                        << "the guide shows\n  " << line << "\nthe check printed\n"
                        << printed;
                } else if (std::regex_match(line, m, todo)) {
                    EXPECT_NE(printed.find(stage.id + "/" + m[1].str()), std::string::npos)
                        << "the guide shows\n  " << line << "\nthe check printed\n"
                        << printed;
                } else if (line.find(" cases; first failure: ") != std::string::npos) {
                    EXPECT_NE(printed.find(trimmed(line)), std::string::npos)
                        << "the guide shows\n  " << line << "\nthe check printed\n"
                        << printed;
                } else if (std::regex_match(line, m, views)) {
                    EXPECT_NE(printed.find("FAIL " + m[1].str() + " "), std::string::npos)
                        << "the guide shows view " << m[1] << " failing\n"
                        << printed;
                }
            }
            ++samples;
        }
    }
    EXPECT_GE(samples, 6) << "the guides' samples of an untouched lab";
}
