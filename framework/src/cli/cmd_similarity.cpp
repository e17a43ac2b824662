// `raylab similarity --submissions DIR --out DIR`: which students' code is
// suspiciously alike, stage by stage. Only what students wrote counts: each
// student's own files of a stage (the ones its lab hands out in lab form)
// are compared with every other student's, and the lab as handed out at the
// course's level is the template (boilerplate), so the code everyone was
// given never makes two students alike. The detector is copydetect (PyPI,
// tools/similarity/similarity.py; the choice is explained with figures in
// docs/grading.md): names replaced by placeholders, comments and layout
// dropped, fingerprints independent of the order of functions. OUT gets
// pairs.csv (every pair's scores) and one report per stage with the flagged
// pairs side by side, or nothing at all.
#include "child_process.h"
#include "command.h"
#include "error.h"
#include "handout_folder.h"
#include "lab_files.h"
#include "paths.h"
#include "stage_list.h"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <sstream>

#include <unistd.h>

namespace raylab {

namespace fs = std::filesystem;

namespace {

// Below it, independent solutions of the open labs; above it, every planted
// copy (tests/similarity: docs/grading.md has the figures).
constexpr double kDefaultThreshold = 0.85;

struct SimilarityOptions {
    std::string submissions, out, stages, level = "guided";
    double threshold = kDefaultThreshold;
};

void writeText(const fs::path& file, const std::string& text) {
    fs::create_directories(file.parent_path());
    std::ofstream out(file, std::ios::binary);
    out << text;
    if (!out) throw Error("cannot write " + file.string());
}

// The stage's own files (those students write in) from FILES, in name
// order, one after the other; empty when none is there.
std::string ownCode(const StageInfo& stage,
                    const std::function<std::string(const std::string&)>& file) {
    std::string code;
    for (const auto& [name, source] : labFileSources(stage)) {
        if (!source.own) continue;
        const std::string text = file(name);
        if (!text.empty()) code += "// file " + name + "\n" + text + "\n";
    }
    return code;
}

// The Python that has copydetect: the project's virtual environment
// (install.sh makes it), else the system's python3.
std::string python() {
    const fs::path venv = projectRoot() / "tools" / "similarity" / ".venv" / "bin" / "python";
    std::error_code ec;
    return fs::exists(venv, ec) ? venv.string() : "python3";
}

int cmdSimilarity(const SimilarityOptions& o) {
    const Level level = parseLevel(o.level);
    if (!(o.threshold > 0.0 && o.threshold <= 1.0))
        throw Error("--threshold must be a share above 0 and at most 1 (e.g. 0.5)");
    const fs::path submissions = o.submissions;
    std::error_code ec;
    if (!fs::is_directory(submissions, ec))
        throw Error("--submissions " + o.submissions + ": not a folder");
    std::vector<std::string> students;
    for (const auto& e : fs::directory_iterator(submissions))
        if (e.is_directory() && e.path().filename().string()[0] != '.')
            students.push_back(e.path().filename().string());
    std::sort(students.begin(), students.end());
    if (students.size() < 2)
        throw Error("--submissions " + o.submissions +
                    ": fewer than two student folders, nothing to compare");
    std::vector<const StageInfo*> stages;
    if (o.stages.empty())
        for (const StageInfo& s : allStages()) stages.push_back(&s);
    else stages = parseStageList(o.stages);
    const fs::path out = newOutputFolder(o.out);

    const fs::path work =
        fs::temp_directory_path() / ("raylab-similarity-" + std::to_string(getpid()));
    struct Cleanup {
        fs::path dir;
        ~Cleanup() {
            std::error_code e;
            fs::remove_all(dir, e);
        }
    } cleanup{work};
    int compared = 0;
    for (const StageInfo* stage : stages) {
        const auto handedOut = labFiles(*stage, MarkedForm::Lab, level);
        const fs::path dir = work / stage->id;
        writeText(dir / "base" / "handed-out.glsl", ownCode(*stage, [&](const std::string& n) {
                      return handedOut.count(n) ? handedOut.at(n) : std::string();
                  }));
        int withCode = 0;
        for (const std::string& student : students) {
            const fs::path folder = submissions / student / stage->id;
            const std::string code = ownCode(*stage, [&](const std::string& n) {
                return fs::is_regular_file(folder / n, ec) ? readTextFile(folder / n)
                                                           : std::string();
            });
            if (code.empty()) continue;
            writeText(dir / "students" / (student + ".glsl"), code);
            ++withCode;
        }
        compared += withCode >= 2 ? 1 : 0;
    }
    if (compared == 0)
        throw Error("no stage has the files of two students or more under " + o.submissions +
                    " (one folder per student, laid out like labs/)");

    int flagged = 0;
    writeWhole(out, "the similarity report", [&](const fs::path& to) {
        const fs::path log = work / "detector.log";
        char threshold[32];
        std::snprintf(threshold, sizeof threshold, "%g", o.threshold);
        Child detector({python(), (projectRoot() / "tools/similarity/similarity.py").string(),
                        "--work", work.string(), "--out", to.string(), "--threshold", threshold},
                       log, {600.0, 0});
        const ChildOutcome& done = detector.wait();
        if (done.exitCode != 0)
            throw Error("the detector failed (" + done.describe() + "): " + lastLogLine(log));
        flagged = std::atoi(lastLogLine(log).c_str());
    });
    std::printf("raylab similarity: %d pair%s at or above %g of shared code (%zu students, %d "
                "stage%s compared at the %s level); every pair's scores in %s, the flagged "
                "side by side in %s/<stage>.html\n",
                flagged, flagged == 1 ? "" : "s", o.threshold, students.size(), compared,
                compared == 1 ? "" : "s", levelName(level), (out / "pairs.csv").c_str(),
                out.c_str());
    return 0;
}

}  // namespace

Command similarityCommand() {
    return {"similarity",
            "compare what students wrote, stage by stage, and flag pairs that share too much "
            "code (copydetect; the handed-out code does not count)",
            [](CLI::App& cmd) {
                auto o = std::make_shared<SimilarityOptions>();
                cmd.add_option("--submissions", o->submissions,
                               "folder with one subfolder per student, each laid out like labs/")
                    ->required();
                cmd.add_option("--out", o->out,
                               "the folder to write: pairs.csv and <stage>.html (new, or empty)")
                    ->required();
                cmd.add_option("--stages", o->stages,
                               "the stages to compare, as handout takes them (default: all)");
                cmd.add_option("--level", o->level,
                               "the level of the labs handed out (their code is the template): "
                               "guided or open")
                    ->capture_default_str();
                cmd.add_option("--threshold", o->threshold,
                               "flag a pair when either student's share of code found in the "
                               "other's reaches this")
                    ->capture_default_str();
                return std::function<int()>([=] { return cmdSimilarity(*o); });
            }};
}

}  // namespace raylab
