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
#include "release_assets.h"
#include "stage_list.h"
#include "stage_sources.h"
#include "student_release.h"

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <set>

namespace raylab {

namespace fs = std::filesystem;

namespace {

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
        // The guides as a student repository has them (without what needs the
        // solution: `--solution`, `--reference`): a bundle's reader is a student.
        writeHandoutFolder(plan, defaultLabRoot(), temp / "labs", "", course, level,
                           SolutionText::LeaveOut);
        if (carry == Carry::Own && !earlier.empty()) {
            // The earlier stages' folders as handed out: the page opens and
            // checks on them until the student brings in their own.
            const fs::path before = temp / "earlier";
            fs::create_directories(before);
            writeHandoutFolder(planHandout(earlier, Carry::Own), defaultLabRoot(), before, "",
                               course, level, SolutionText::LeaveOut);
            for (const StageInfo* s : earlier) fs::rename(before / s->id, temp / "labs" / s->id);
            fs::remove_all(before);
        }
        for (const char* file :
             {"web/index.html", "web/page.css", "web/guide.html", "web/guide.css"})
            copyTree(root / file, temp / file);
        writeTextFileAtomic(temp / "web" / "function_tables.json", releasedFunctionTables(plan));
        for (const char* dir : {"web/dist", "web/shaders"}) copyTree(root / dir, temp / dir);
        copyReleasedAssets(temp, plan, false);
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
                auto o = std::make_shared<ReleaseOptions>();
                addReleaseOptions(cmd, *o, "the folder to write (new, or empty)");
                return std::function<int()>(
                    [=] { return cmdWebBundle(o->stages, o->out, o->carry, o->course, o->level); });
            }};
}

}  // namespace raylab
