// `raylab web-bundle --stages 01-03 --out DIR`: the page as a static folder a
// course hosts for its students (any web server; no raylab server): the
// page and its WebAssembly core, the released stages' labs exactly as
// `raylab handout` gives them, the framework's shaders, the scenes and their
// pictures, and, for the released stages only, their stage.json (data, no
// code), the check views' reference pictures, the function checks' expected
// values and harness GLSL, and the shader variants. Of a stage the released
// ones build on and the bundle does not release it holds the stage.json
// (the folders and files the later stage reads) and, with --carry own, the
// folder as handed out (so that the page opens before a student brings in
// their own); nothing of a later stage. No solution code: not solution/'s
// files, not the variant files that stand in for a file students write
// (web/tools/serve.mjs keeps the same ones back), no page test API. The
// folder appears whole or not at all.
#include "atomic_file.h"
#include "command.h"
#include "course_file.h"
#include "error.h"
#include "function_checks.h"
#include "function_tables.h"
#include "handout.h"
#include "handout_folder.h"
#include "paths.h"
#include "stage_list.h"
#include "stage_sources.h"

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <set>

namespace raylab {

namespace fs = std::filesystem;

namespace {

void copyTree(const fs::path& from, const fs::path& to) {
    fs::create_directories(to.parent_path());
    fs::copy(from, to, fs::copy_options::recursive);
}

// Whether students write FILE as stage STAGE reads it: its solved form (the
// newest of STAGE's chain in solution/) has regions a lab takes away. A
// variant file standing in for such a file is that file solved; one standing
// in for a provided file (surface_at.glsl with meshes) is not.
bool studentsWrite(const std::string& stage, const std::string& file) {
    std::error_code ec;
    for (const StageInfo* at = &findStage(stage);; at = &findStage(at->buildsOn)) {
        if (fs::is_regular_file(at->folder() / file, ec)) {
            const std::string text = readTextFile(at->folder() / file);
            return text.find("//@solution") != std::string::npos ||
                   text.find("//@open") != std::string::npos;
        }
        if (at->buildsOn.empty()) return false;
    }
}

// framework/shaders/ with the variant folders of STAGES only, and without
// the variant files that hold solved code (studentsWrite).
void copyFrameworkShaders(const fs::path& to, const std::set<std::string>& stages) {
    const fs::path from = projectRoot() / "framework" / "shaders";
    for (const fs::directory_entry& e : fs::recursive_directory_iterator(from)) {
        if (!e.is_regular_file()) continue;
        const fs::path rel = e.path().lexically_relative(from);
        auto part = rel.begin();
        if (part->string() == "variants") {
            if (std::distance(rel.begin(), rel.end()) != 4) continue;
            const std::string stage = std::next(part, 2)->string();
            if (!stages.count(stage) || studentsWrite(stage, rel.filename().string())) continue;
        }
        fs::create_directories((to / rel).parent_path());
        fs::copy_file(e.path(), to / rel);
    }
}

// The stages PLAN's stages build on that PLAN does not release, in course order.
std::vector<const StageInfo*> earlierStages(const std::vector<HandoutStage>& plan) {
    std::set<std::string> released, seen;
    for (const HandoutStage& h : plan) released.insert(h.stage->id);
    for (const HandoutStage& h : plan)
        for (const StageInfo* at = h.stage; !at->buildsOn.empty();) {
            at = &findStage(at->buildsOn);
            if (!released.count(at->id)) seen.insert(at->id);
        }
    std::vector<const StageInfo*> out;
    for (const StageInfo& s : allStages())
        if (seen.count(s.id)) out.push_back(&s);
    return out;
}

// web/function_tables.json with the tables of PLAN's stages' checks only.
std::string releasedFunctionTables(const std::vector<HandoutStage>& plan) {
    std::vector<const FunctionSpec*> specs;
    for (const HandoutStage& h : plan)
        for (const FunctionSpec* spec : functionSpecsFor(*h.stage))
            if (std::find(specs.begin(), specs.end(), spec) == specs.end()) specs.push_back(spec);
    // No checks at all: an empty table, not every one (functionTablesJson's default).
    return specs.empty() ? "{\"functions\": {}}\n" : functionTablesJson(specs);
}

// web/tools/write_catalog.mjs for the bundle: its stages, no solutions.
void writeCatalog(const fs::path& root, const std::vector<HandoutStage>& plan) {
    std::string ids;
    for (const HandoutStage& h : plan) ids += (ids.empty() ? "" : ",") + h.stage->id;
    const std::string script = (projectRoot() / "web" / "tools" / "write_catalog.mjs").string();
    const pid_t pid = fork();
    if (pid == 0) {
        execlp("node", "node", script.c_str(), "--root", root.c_str(), "--stages", ids.c_str(),
               "--no-solutions", "--bundle", static_cast<char*>(nullptr));
        std::perror("raylab web-bundle: cannot run node");
        _exit(127);
    }
    int status = 0;
    if (pid < 0 || waitpid(pid, &status, 0) < 0 || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
        throw Error("web/tools/write_catalog.mjs failed (is Node.js installed? bash install.sh)");
}

const char* const kIndex =
    "<!doctype html>\n<meta charset=\"utf-8\">\n<title>RayLab</title>\n"
    "<meta http-equiv=\"refresh\" content=\"0; url=web/\">\n<a href=\"web/\">RayLab</a>\n";

int cmdWebBundle(const std::string& list, const std::string& outDir, const std::string& carryName,
                 const std::string& courseFile, const std::string& levelName) {
    const Carry carry = parseCarry(carryName);
    const Level level = parseLevel(levelName);
    const CourseSettings course =
        courseFile.empty() ? CourseSettings{} : readCourseFile(courseFile);
    const std::vector<HandoutStage> plan = planHandout(parseStageList(list), carry);
    checkHandoutSources(plan, defaultLabRoot());
    const fs::path root = projectRoot();
    std::error_code ec;
    for (const char* built : {"web/dist/app/main.js", "web/dist/core/raylab_core.js"})
        if (!fs::is_regular_file(root / built, ec))
            throw Error(std::string(built) +
                        " is missing: build the page first (npm --prefix web run build)");
    const std::vector<const StageInfo*> earlier = earlierStages(plan);
    std::set<std::string> stages;  // the released ones and those they build on
    for (const HandoutStage& h : plan) stages.insert(h.stage->id);
    for (const StageInfo* s : earlier) stages.insert(s->id);
    const fs::path out = newOutputFolder(outDir);
    writeWhole(out, "the bundle", [&](const fs::path& temp) {
        fs::create_directories(temp / "labs");
        writeHandoutFolder(plan, defaultLabRoot(), temp / "labs", "", course, level);
        if (carry == Carry::Own && !earlier.empty()) {
            // The earlier stages' folders as handed out: the page opens and
            // checks on them until the student brings in their own.
            const fs::path before = temp / "earlier";
            fs::create_directories(before);
            writeHandoutFolder(planHandout(earlier, Carry::Own), defaultLabRoot(), before, "",
                               course, level);
            for (const StageInfo* s : earlier) fs::rename(before / s->id, temp / "labs" / s->id);
            fs::remove_all(before);
        }
        for (const char* file :
             {"web/index.html", "web/page.css", "web/guide.html", "web/guide.css"})
            copyTree(root / file, temp / file);
        writeTextFileAtomic(temp / "web" / "function_tables.json", releasedFunctionTables(plan));
        for (const char* dir :
             {"web/dist", "web/shaders", "assets/scenes", "assets/textures", "assets/meshes"})
            copyTree(root / dir, temp / dir);
        // The page's test API stays at home (tests drive the dev page).
        for (const fs::directory_entry& e : fs::directory_iterator(temp / "web/dist/app"))
            if (e.path().filename().string().rfind("test_api.", 0) == 0) fs::remove(e.path());
        copyFrameworkShaders(temp / "framework" / "shaders", stages);
        // The stage.json of the released stages and those they build on (the
        // core reads the course from them; data, no code), the released
        // stages' reference pictures.
        for (const StageInfo& s : allStages())
            if (stages.count(s.id))
                copyTree(s.folder() / "stage.json", temp / "solution" / s.id / "stage.json");
        for (const HandoutStage& h : plan)
            copyTree(root / "tests" / "reference" / h.stage->id,
                     temp / "tests" / "reference" / h.stage->id);
        writeTextFileAtomic(temp / "index.html", kIndex);
        writeCatalog(temp, plan);
    });
    std::string ids;
    for (const HandoutStage& h : plan) ids += (ids.empty() ? "" : ", ") + h.stage->id;
    std::printf("raylab web-bundle: wrote %s (%s): host it with any web server, e.g. "
                "python3 -m http.server --directory %s; no solution of a stage it holds\n",
                out.c_str(), ids.c_str(), out.c_str());
    return 0;
}

}  // namespace

Command webBundleCommand() {
    return {"web-bundle",
            "write the web page with the released stages' labs as a static folder for students "
            "(any web server), with no solution of a stage it holds",
            [](CLI::App& cmd) {
                auto stages = std::make_shared<std::string>();
                auto out = std::make_shared<std::string>();
                auto carry = std::make_shared<std::string>("own");
                auto course = std::make_shared<std::string>();
                auto level = std::make_shared<std::string>("guided");
                cmd.add_option("--stages", *stages,
                               "the released stages, as raylab handout takes them (01-03, "
                               "01,02,f1, all)")
                    ->required();
                cmd.add_option("--out", *out, "the folder to write (new, or empty)")->required();
                cmd.add_option("--carry", *carry,
                               "earlier stages this bundle does not release: own or solved (as "
                               "raylab handout)")
                    ->capture_default_str();
                cmd.add_option("--course", *course,
                               "a course file (docs/grading.md): the guides show its weights");
                cmd.add_option("--level", *level, "guided or open (as raylab handout)")
                    ->capture_default_str();
                return std::function<int()>(
                    [=] { return cmdWebBundle(*stages, *out, *carry, *course, *level); });
            }};
}

}  // namespace raylab
