// raylab-labgen: makes labs/<stage>/ from solution/ so that a lab can never
// drift from its solution. For instructors; students get the generated files.
//
//   raylab-labgen                 regenerate labs/ (the guided level) for every stage
//   raylab-labgen --check         exit 1 and list the files that differ
//   raylab-labgen --level open --labs DIR   write the open level's labs to DIR
//   raylab-labgen --solved DIR    write a fully solved copy laid out like labs/
//   raylab-labgen --count         the lines of code students write, per stage and level
//
// A lab for stage N holds every shader file stage N's program includes, except
// the framework's: the files of solution/N/ in lab form (TODO stubs), the files
// of earlier stages in solved form, and the guide (README.md, from
// solution/N/guide.md at the level, its "How you are graded" written from the
// stage's "grading" in stage.json so that the points students read are the
// points they get). The pictures (expected.png, ...) are hand-made: they stay
// in labs/ and are copied from there to another --labs folder.
#include "error.h"
#include "lab_files.h"
#include "lab_folder.h"
#include "paths.h"
#include "stage_catalog.h"
#include "stage_grading.h"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <fstream>
#include <map>
#include <set>

using namespace raylab;
namespace fs = std::filesystem;

namespace {

bool isShaderFile(const fs::path& p) {
    const std::string e = p.extension().string();
    return e == ".glsl" || e == ".frag" || e == ".vert" || e == ".geom";
}

void writeFile(const fs::path& file, const std::string& text) {
    fs::create_directories(file.parent_path());
    fs::path tmp = file;
    tmp += ".tmp";
    {
        std::ofstream out(tmp, std::ios::binary);
        out << text;
        if (!out) throw Error("cannot write " + tmp.string());
    }
    fs::rename(tmp, file);
}

std::string readIfExists(const fs::path& file) {
    std::error_code ec;
    return fs::is_regular_file(file, ec) ? readTextFile(file) : std::string("\x01missing");
}

// The lines of code students write, per stage and level (lab_markers.h).
void printCounts() {
    std::printf("%-16s %7s %5s\n", "stage", "guided", "open");
    int guided = 0, open = 0;
    for (const StageInfo& stage : allStages()) {
        int g = 0, o = 0;
        for (const auto& [name, file] : labFileSources(stage)) {
            if (!file.own) continue;
            const std::string text = readTextFile(file.source);
            g += studentCodeLines(text, Level::Guided);
            o += studentCodeLines(text, Level::Open);
        }
        std::printf("%-16s %7d %5d\n", stage.id.c_str(), g, o);
        guided += g;
        open += o;
    }
    std::printf("%-16s %7d %5d\n", "all", guided, open);
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"Derives labs/ from solution/ (the //@solution ... //@end markers)."};
    bool check = false, count = false;
    std::string labsDir, solvedDir, levelName = "guided";
    app.add_flag("--check", check,
                 "do not write; exit 1 when the labs differ from what solution/ gives");
    app.add_option("--labs", labsDir, "the labs folder to write or check (default: labs/)");
    app.add_option("--level", levelName,
                   "guided (labs/: the algorithm's structure given, a few lines per TODO) or "
                   "open (whole functions from their contracts)")
        ->capture_default_str();
    app.add_option("--solved", solvedDir,
                   "write a fully solved copy of the labs to this folder instead");
    app.add_flag("--count", count, "print the lines of code students write per stage and level");
    CLI11_PARSE(app, argc, argv);

    try {
        if (count) {
            printCounts();
            return 0;
        }
        const Level level = parseLevel(levelName);
        const bool solved = !solvedDir.empty();
        const fs::path projectLabs = projectRoot() / "labs";
        const fs::path root = solved            ? fs::path(solvedDir)
                              : labsDir.empty() ? projectLabs
                                                : fs::path(labsDir);
        std::error_code ec;
        if (level == Level::Open && fs::equivalent(root, projectLabs, ec))
            throw Error("labs/ holds the guided level; write the open level elsewhere "
                        "(--level open --labs DIR)");
        const bool copyPictures = !solved && !fs::equivalent(root, projectLabs, ec);
        int drift = 0;
        for (const StageInfo& stage : allStages()) {
            // A solved copy has no guides.
            auto files =
                solved ? labFiles(stage, MarkedForm::Solved) : labFolderFiles(stage, level);
            const fs::path dir = root / stage.id;
            std::set<std::string> stale;
            if (fs::is_directory(dir, ec))
                for (const auto& e : fs::directory_iterator(dir))
                    if (isShaderFile(e.path()) && !files.count(e.path().filename().string()))
                        stale.insert(e.path().filename().string());
            if (copyPictures)
                for (const auto& [name, from] : labPictures(projectLabs / stage.id, level))
                    files[name] = readTextFile(from);
            for (const auto& [name, text] : files) {
                if (check) {
                    if (readIfExists(dir / name) != text) {
                        std::printf("differs: %s (regenerate with raylab-labgen)\n",
                                    (dir / name).c_str());
                        ++drift;
                    }
                } else {
                    writeFile(dir / name, text);
                }
            }
            for (const std::string& name : stale) {
                if (check) {
                    std::printf("not generated from solution/: %s\n", (dir / name).c_str());
                    ++drift;
                } else {
                    fs::remove(dir / name);
                }
            }
            if (!check) std::printf("labgen: wrote %zu files to %s\n", files.size(), dir.c_str());
        }
        if (check) {
            std::printf(drift ? "labgen: %d files drifted from solution/\n"
                              : "labgen: the labs match solution/\n",
                        drift);
            return drift ? 1 : 0;
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "raylab-labgen: error: %s\n", e.what());
        return 2;
    }
    return 0;
}
