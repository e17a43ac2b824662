// `raylab web-bundle --stages 01-03 --out DIR`: the page as a static folder a
// course hosts for its students (any web server; no raylab server): the
// page and its WebAssembly core, the released stages' labs exactly as
// `raylab handout` gives them, the framework's shaders, the scenes and their
// pictures, each stage's stage.json (data, no code), the check views'
// reference pictures and the function checks' expected values, which the
// page's Check compares with. No solution code:
// not solution/'s files, not the variant files that stand in for a file
// students write (web/tools/serve.mjs keeps the same ones back). The folder
// appears whole or not at all.
#include "atomic_file.h"
#include "command.h"
#include "course_file.h"
#include "error.h"
#include "handout.h"
#include "handout_folder.h"
#include "paths.h"
#include "stage_list.h"
#include "stage_sources.h"

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>

namespace raylab {

namespace fs = std::filesystem;

namespace {

void copyTree(const fs::path& from, const fs::path& to) {
    fs::create_directories(to.parent_path());
    fs::copy(from, to, fs::copy_options::recursive);
}

// framework/shaders/ without the variant files that hold solved code: a
// variant file standing in for a file of labs/<stage>/ is that file solved.
void copyFrameworkShaders(const fs::path& to) {
    const fs::path from = projectRoot() / "framework" / "shaders";
    std::error_code ec;
    for (const fs::directory_entry& e : fs::recursive_directory_iterator(from)) {
        if (!e.is_regular_file()) continue;
        const fs::path rel = e.path().lexically_relative(from);
        auto part = rel.begin();
        if (part->string() == "variants" && std::distance(rel.begin(), rel.end()) == 4) {
            const std::string stage = std::next(part, 2)->string();
            if (fs::exists(defaultLabRoot() / stage / rel.filename(), ec)) continue;
        }
        fs::create_directories((to / rel).parent_path());
        fs::copy_file(e.path(), to / rel);
    }
}

// web/tools/write_catalog.mjs for the bundle: its stages, no solutions.
void writeCatalog(const fs::path& root, const std::vector<HandoutStage>& plan) {
    std::string ids;
    for (const HandoutStage& h : plan) ids += (ids.empty() ? "" : ",") + h.stage->id;
    const std::string script = (projectRoot() / "web" / "tools" / "write_catalog.mjs").string();
    const pid_t pid = fork();
    if (pid == 0) {
        execlp("node", "node", script.c_str(), "--root", root.c_str(), "--stages", ids.c_str(),
               "--no-solutions", static_cast<char*>(nullptr));
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
    const fs::path out = newOutputFolder(outDir);
    writeWhole(out, "the bundle", [&](const fs::path& temp) {
        fs::create_directories(temp / "labs");
        writeHandoutFolder(plan, defaultLabRoot(), temp / "labs", "", course, level);
        for (const char* file : {"web/index.html", "web/page.css", "web/function_tables.json"})
            copyTree(root / file, temp / file);
        for (const char* dir :
             {"web/dist", "web/shaders", "assets/scenes", "assets/textures", "assets/meshes"})
            copyTree(root / dir, temp / dir);
        copyFrameworkShaders(temp / "framework" / "shaders");
        // Every stage.json (the core reads the course from them; data, no
        // code), the released stages' reference pictures.
        for (const StageInfo& s : allStages())
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
