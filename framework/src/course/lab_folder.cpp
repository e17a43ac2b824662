#include "lab_folder.h"

#include "error.h"
#include "lab_files.h"
#include "paths.h"

#include <cstdlib>
#include <fstream>
#include <sstream>

#include <unistd.h>

namespace raylab {

namespace {

std::string trimmedLine(const std::string& s) {
    const std::size_t a = s.find_first_not_of(" \t\r"), b = s.find_last_not_of(" \t\r");
    return a == std::string::npos ? std::string() : s.substr(a, b - a + 1);
}

// A guide's pair of marker lines "<!-- NAME -->" and "<!-- /NAME -->" for
// one of two NAMES, not nested in itself.
struct MarkedBlock {
    const char* names[2];
    bool section;      // "the guided section" in messages; else "<!-- NAME -->"
    std::string name;  // the one open; empty when none is
    int line = 0;      // where it opened

    bool open() const { return !name.empty(); }
    std::string shown() const { return section ? name + " section" : "<!-- " + name + " -->"; }
    // Whether T is one of the markers (then taken); FAIL(N, WHY) when misplaced.
    template <class Fail>
    bool take(const std::string& t, int n, Fail fail) {
        for (const char* candidate : names) {
            if (t == "<!-- " + std::string(candidate) + " -->") {
                if (open())
                    fail(n,
                         t + " inside the " + shown() + " opened on line " + std::to_string(line));
                name = candidate, line = n;
                return true;
            }
            if (t == "<!-- /" + std::string(candidate) + " -->") {
                if (name != candidate)
                    fail(n,
                         t + " closes no " + (section ? "section" : "block") + " opened before it");
                name.clear();
                return true;
            }
        }
        return false;
    }
    // At the end of the guide: FAIL when one is still open.
    template <class Fail>
    void close(Fail fail) const {
        if (open()) fail(line, "<!-- " + name + " --> not closed with <!-- /" + name + " -->");
    }
};

}  // namespace

std::string guideAtLevel(const std::string& source, Level level, const std::string& file,
                         SolutionText solution) {
    auto fail = [&](int n, const std::string& what) -> void {
        throw Error(file + ":" + std::to_string(n) + ": " + what);
    };
    // The level section we are in (none: shared), and the with-solution or
    // without-solution block (which may hold level sections or sit in one).
    MarkedBlock section{{"guided", "open"}, true},
        block{{"with-solution", "without-solution"}, false};
    std::string out;
    std::istringstream in(source);
    std::string line;
    for (int n = 1; std::getline(in, line); ++n) {
        const std::string t = trimmedLine(line);
        if (section.take(t, n, fail) || block.take(t, n, fail)) continue;
        if (t.rfind("#", 0) == 0) {
            if (section.open())
                fail(n, "a heading inside the " + section.shown() +
                            ": headings are shared by both levels (one outline)");
            if (block.open())
                fail(n, "a heading inside " + block.shown() +
                            ": a student repository's guide keeps the outline");
        }
        const bool kept =
            !block.open() || (block.name == "with-solution") == (solution == SolutionText::Keep);
        if ((!section.open() || section.name == levelName(level)) && kept) out += line + "\n";
    }
    section.close(fail);
    block.close(fail);
    return out;
}

std::map<std::string, std::filesystem::path> labPictures(const std::filesystem::path& dir,
                                                         Level level) {
    namespace fs = std::filesystem;
    const std::string openSuffix = "-open.png";
    std::map<std::string, fs::path> pictures, openOnes;
    std::error_code ec;
    for (const fs::directory_entry& e : fs::directory_iterator(dir, ec)) {
        const std::string name = e.path().filename().string(), ext = e.path().extension().string();
        const bool shader = ext == ".glsl" || ext == ".frag" || ext == ".vert" || ext == ".geom";
        if (!e.is_regular_file() || shader || name == "README.md") continue;
        const bool openOnly =
            name.size() > openSuffix.size() &&
            name.compare(name.size() - openSuffix.size(), openSuffix.size(), openSuffix) == 0;
        if (!openOnly) pictures[name] = e.path();
        else openOnes[name.substr(0, name.size() - openSuffix.size()) + ".png"] = e.path();
    }
    if (level == Level::Open)
        for (const auto& [name, path] : openOnes) pictures[name] = path;
    return pictures;
}

std::string stageGuide(const StageInfo& stage, Level level, const StageGrading& grading,
                       SolutionText solution) {
    const std::filesystem::path source = stage.folder() / "guide.md";
    return withGradingSection(
        guideAtLevel(readTextFile(source), level, displayPath(source), solution), stage, grading);
}

std::map<std::string, std::string> labFolderFiles(const StageInfo& stage, Level level,
                                                  SolutionText solution) {
    std::map<std::string, std::string> files = labFiles(stage, MarkedForm::Lab, level);
    std::error_code ec;  // a stage without a guide yet (just added) has no README.md
    if (std::filesystem::is_regular_file(stage.folder() / "guide.md", ec))
        files["README.md"] = stageGuide(stage, level, stage.grading, solution);
    return files;
}

namespace {

constexpr const char* kLevelVariable = "RAYLAB_LEVEL";
// The open labs' folder, written once by the process that sets the level and
// read by its child processes (a grading run's one per submission and stage).
constexpr const char* kOpenLabsVariable = "RAYLAB_OPEN_LABS";

// The open labs' temporary folder, removed when the process that wrote it ends.
struct OpenLabs {
    std::filesystem::path root;
    bool written = false;  // by this process (a child only reads its parent's)
    ~OpenLabs() {
        std::error_code ec;
        if (written) std::filesystem::remove_all(root, ec);
    }
};

}  // namespace

void setHandedOutLevel(Level level) {
    setenv(kLevelVariable, levelName(level), 1);
    if (level == Level::Open) handedOutLabRoot();  // written once, here, for the children too
}

Level handedOutLevel() {
    const char* value = std::getenv(kLevelVariable);
    if (!value || !*value) return Level::Guided;
    try {
        return parseLevel(value);
    } catch (const Error& e) { throw Error(std::string(kLevelVariable) + ": " + e.what()); }
}

std::filesystem::path handedOutLabRoot() {
    namespace fs = std::filesystem;
#ifdef RAYLAB_STUDENT_BUILD
    // A student repository: labs/ is the student's work; the labs as they
    // were handed out (at the repository's level) are kept apart.
    return projectRoot() / "course" / "handout";
#endif
    if (handedOutLevel() == Level::Guided) return projectRoot() / "labs";
    static OpenLabs labs;
    std::error_code ec;
    const char* inherited = std::getenv(kOpenLabsVariable);
    if (labs.root.empty() && inherited && *inherited && fs::is_directory(inherited, ec))
        labs.root = inherited;
    if (labs.root.empty()) {
        const fs::path root =
            fs::temp_directory_path() / ("raylab-open-labs-" + std::to_string(getpid()));
        fs::remove_all(root);
        for (const StageInfo& stage : allStages())
            for (const auto& [name, text] : labFiles(stage, MarkedForm::Lab, Level::Open)) {
                fs::create_directories(root / stage.id);
                std::ofstream out(root / stage.id / name, std::ios::binary);
                out << text;
                if (!out) throw Error("cannot write " + (root / stage.id / name).string());
            }
        labs.root = root;
        labs.written = true;
        setenv(kOpenLabsVariable, root.c_str(), 1);
    }
    return labs.root;
}

}  // namespace raylab
