// raylab-classgen: writes a class of 30 submissions, each a copy of labs/,
// and what grading them must give. For instructors trying `raylab grade`
// and for its test (tests/e2e/grade_class_test.cpp).
//
//   raylab-classgen OUTDIR    -> OUTDIR/submissions/<student>/, OUTDIR/expected.json
//   raylab-classgen --help
//
// The class: 2 pristine solutions, 3 untouched labs, one that submitted
// stages 01-03 only, one that did 01-04, the broken submissions of
// tests/grading/broken/ (each on top of a solution), and the rest of the
// 30 (14 today) sharing every mistake of tests/mistakes/ (at most one per
// stage each: a stage can have as many mistakes as there are such students).
// expected.json: {student: {stage: "100" | "<100" | "not submitted" | "status:A|B"}}.
#include "child_process.h"
#include "error.h"
#include "paths.h"
#include "stage_catalog.h"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <map>

using namespace raylab;
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

struct Change {
    std::string stage, file;
    json replace;
    std::string source;  // the JSON file it came from
};

void apply(const fs::path& labRoot, const Change& c) {
    const fs::path file = labRoot / c.stage / c.file;
    std::string text = readTextFile(file);
    for (const auto& pair : c.replace) {
        const std::string from = pair[0], to = pair[1];
        auto at = text.find(from);
        if (at == std::string::npos)
            throw Error(c.source + ": text not found in " + displayPath(file) + ": " + from);
        text.replace(at, from.size(), to);
    }
    std::ofstream(file) << text;
}

std::vector<std::pair<fs::path, json>> specs(const fs::path& dir) {
    std::vector<std::pair<fs::path, json>> out;
    for (const auto& e : fs::recursive_directory_iterator(dir))
        if (e.path().extension() == ".json")
            out.emplace_back(e.path(), json::parse(readTextFile(e.path())));
    std::sort(out.begin(), out.end(),
              [](const auto& a, const auto& b) { return a.first < b.first; });
    return out;
}

// The stages after the first N, in course order.
std::vector<std::string> laterThan(const std::vector<std::string>& stages, std::size_t n) {
    return stages.size() > n ? std::vector<std::string>(stages.begin() + long(n), stages.end())
                             : std::vector<std::string>{};
}

void copyTree(const fs::path& from, const fs::path& to) {
    fs::copy(from, to, fs::copy_options::recursive);
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{
        "Writes a generated class of 30 submissions (OUTDIR/submissions/<student>/, each a "
        "copy of labs/ with some stages done, mistakes made or broken) and what grading "
        "them must give (OUTDIR/expected.json), to try `raylab grade` on."};
    std::string outDir;
    app.add_option("OUTDIR", outDir, "a new folder (or one without submissions/ in it)")
        ->required()
        ->check([](const std::string& v) {
            return !v.empty() && v[0] == '-' ? "OUTDIR may not start with '-' (an option?)" : "";
        });
    CLI11_PARSE(app, argc, argv);
    try {
        const fs::path out = outDir;
        const fs::path subs = out / "submissions";
        if (fs::exists(subs)) throw Error(subs.string() + " exists already");
        fs::create_directories(subs);
        const fs::path solved = out / "solved";
        fs::remove_all(solved);
        // execv, not a shell: any folder name works.
        Child labgen({(executablePath().parent_path() / "raylab-labgen").string(), "--solved",
                      solved.string()},
                     out / "labgen.log", ChildLimits{600.0, 0});
        if (labgen.wait().exitCode != 0)
            throw Error("raylab-labgen --solved failed (" + labgen.outcome().describe() +
                        "); see " + (out / "labgen.log").string());
        fs::remove(out / "labgen.log");

        std::vector<std::string> stages;
        for (const StageInfo& s : allStages()) stages.push_back(s.id);
        json expected;
        auto expectAll = [&](const std::string& student, const std::string& value) {
            for (const std::string& s : stages) expected[student][s] = value;
        };
        auto solvedStudent = [&](const std::string& name) {
            copyTree(solved, subs / name);
            expectAll(name, "100");
        };

        for (int i = 1; i <= 2; ++i) solvedStudent("pristine-" + std::to_string(i));
        for (int i = 1; i <= 3; ++i) {
            std::string name = "untouched-" + std::to_string(i);
            copyTree(projectRoot() / "labs", subs / name);
            expectAll(name, "<100");
        }
        // By position in the course, not by stage number: the first three
        // stages submitted, then the first four finished.
        solvedStudent("submitted-01-03-only");
        for (const std::string& s : laterThan(stages, 3)) {
            fs::remove_all(subs / "submitted-01-03-only" / s);
            expected["submitted-01-03-only"][s] = "not submitted";
        }
        solvedStudent("finished-01-04");
        for (const std::string& s : laterThan(stages, 4)) {
            fs::remove_all(subs / "finished-01-04" / s);
            copyTree(projectRoot() / "labs" / s, subs / "finished-01-04" / s);
            expected["finished-01-04"][s] = "<100";
        }

        for (const auto& [file, spec] : specs(projectRoot() / "tests" / "grading" / "broken")) {
            std::string name = "broken-" + file.stem().string();
            solvedStudent(name);
            apply(subs / name, {spec["stage"], spec["file"], spec["replace"], displayPath(file)});
            std::string status = spec["expect_status"];
            expected[name][spec["stage"].get<std::string>()] =
                status == "graded" ? "<100" : "status:" + status;
        }

        // Mistakes: the remaining students, each mistake once, never two in one
        // stage of a student.
        const int mistakeStudents = 30 - int(expected.size());
        std::vector<std::vector<Change>> assigned(std::size_t(std::max(mistakeStudents, 1)));
        std::vector<std::pair<fs::path, json>> mistakes;
        for (const StageInfo& s : allStages())
            if (fs::is_directory(projectRoot() / s.mistakes))
                for (auto& m : specs(projectRoot() / s.mistakes)) mistakes.push_back(std::move(m));
        for (const auto& [file, spec] : mistakes) {
            Change c{spec["stage"], spec["file"], spec["replace"], displayPath(file)};
            std::size_t best = assigned.size();
            for (std::size_t k = 0; k < assigned.size(); ++k) {
                bool stageFree = std::none_of(assigned[k].begin(), assigned[k].end(),
                                              [&](const Change& x) { return x.stage == c.stage; });
                if (stageFree &&
                    (best == assigned.size() || assigned[k].size() < assigned[best].size()))
                    best = k;
            }
            if (best == assigned.size())
                throw Error("too many mistakes in stage " + c.stage + " for " +
                            std::to_string(assigned.size()) + " students");
            assigned[best].push_back(c);
        }
        for (std::size_t k = 0; k < assigned.size(); ++k) {
            char name[32];
            std::snprintf(name, sizeof name, "mistakes-%02zu", k + 1);
            solvedStudent(name);
            for (const Change& c : assigned[k]) {
                apply(subs / name, c);
                expected[name][c.stage] = "<100";
                expected[name]["_mistakes"].push_back(c.source);
            }
        }
        fs::remove_all(solved);
        std::ofstream(out / "expected.json") << expected.dump(1) << "\n";
        std::printf("raylab-classgen: %zu submissions in %s, expectations in %s\n", expected.size(),
                    subs.c_str(), (out / "expected.json").c_str());
        return 0;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "raylab-classgen: error: %s\n", e.what());
        return 2;
    }
}
