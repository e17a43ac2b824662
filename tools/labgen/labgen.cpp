// raylab-labgen: makes labs/<stage>/ from solution/ so that a lab can never
// drift from its solution. For instructors; students get the generated files.
//
//   raylab-labgen                 regenerate labs/ for every available stage
//   raylab-labgen --check         exit 1 and list the files that differ
//   raylab-labgen --solved DIR    write a fully solved copy laid out like labs/
//
// A lab for stage N holds every shader file stage N's program includes, except
// the framework's: the files of solution/N/ in lab form (TODO stubs), the files
// of earlier stages in solved form. Hand-written files (README.md, images) are
// left alone, except the guide's "How you are graded" (between its
// <!-- grading --> markers), written from the stage's "grading" in
// stage.json so that the points students read are the points they get.
#include "error.h"
#include "lab_files.h"
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

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"Derives labs/ from solution/ (the //@solution ... //@end markers)."};
    bool check = false;
    std::string labsDir = (projectRoot() / "labs").string();
    std::string solvedDir;
    app.add_flag("--check", check,
                 "do not write; exit 1 when labs/ differs from what solution/ gives");
    app.add_option("--labs", labsDir, "the labs folder to write or check")->capture_default_str();
    app.add_option("--solved", solvedDir,
                   "write a fully solved copy of the labs to this folder instead");
    CLI11_PARSE(app, argc, argv);

    try {
        const bool solved = !solvedDir.empty();
        const fs::path root = solved ? fs::path(solvedDir) : fs::path(labsDir);
        int drift = 0;
        for (const StageInfo& stage : allStages()) {
            auto files = labFiles(stage, solved ? MarkedForm::Solved : MarkedForm::Lab);
            const fs::path dir = root / stage.id;
            std::set<std::string> stale;
            std::error_code ec;
            if (fs::is_directory(dir, ec))
                for (const auto& e : fs::directory_iterator(dir))
                    if (isShaderFile(e.path()) && !files.count(e.path().filename().string()))
                        stale.insert(e.path().filename().string());
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
            // The guide's grading section (only in labs/: a solved copy has no guides).
            if (!solved && fs::is_regular_file(dir / "README.md", ec)) {
                const std::string guide = readTextFile(dir / "README.md");
                const std::string text = withGradingSection(guide, stage, stage.grading);
                if (check && text != guide) {
                    std::printf("differs: %s's \"How you are graded\" (regenerate with "
                                "raylab-labgen)\n",
                                (dir / "README.md").c_str());
                    ++drift;
                } else if (!check && text != guide) {
                    writeFile(dir / "README.md", text);
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
                              : "labgen: labs/ matches solution/\n",
                        drift);
            return drift ? 1 : 0;
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "raylab-labgen: error: %s\n", e.what());
        return 2;
    }
    return 0;
}
