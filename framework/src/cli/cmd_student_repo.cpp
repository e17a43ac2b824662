// `raylab student-repo --stages 01-03 --out DIR`: a repository students clone
// and build, for working natively (their own editor, the window at their
// GPU's speed, the debug views, raylab trace), with no answer of any stage:
// the framework without the reference tracer, the checks' references and
// stand-ins, the bench and the instructors' commands (student_release.h);
// the released stages' labs as `raylab handout` gives them; and, as the
// page's bundle ships them, the released stages' reference pictures and
// function tables (course/) and the stage.json of the stages they use
// (solution/<id>/stage.json: data, no code). Its raylab checks against
// those. Run again on that folder with more stages, it adds their labs and
// renews everything of the course's, and never touches a lab folder that is
// there: committed, that is a change students pull and merge cleanly.
#include "atomic_file.h"
#include "command.h"
#include "course_file.h"
#include "error.h"
#include "gl_context.h"
#include "handout.h"
#include "handout_folder.h"
#include "lab_folder.h"
#include "paths.h"
#include "release_assets.h"
#include "stage_list.h"
#include "stage_sources.h"
#include "student_release.h"
#include "view_renderers.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <set>

namespace raylab {

namespace fs = std::filesystem;

namespace {

using json = nlohmann::json;

// What a student repository records of itself.
constexpr const char* kManifest = "course/student-repo.json";

// The command-line files of a student build (framework/src/cli/CMakeLists.txt's
// RAYLAB_STUDENT list); the others are the instructors'.
const std::set<std::string> kStudentCli = {"CMakeLists.txt",
                                           "cmd_check.cpp",
                                           "cmd_compare.cpp",
                                           "cmd_render.cpp",
                                           "cmd_run.cpp",
                                           "cmd_shader.cpp",
                                           "cmd_stages.cpp",
                                           "cmd_trace.cpp",
                                           "command.h",
                                           "command_options.cpp",
                                           "command_options.h",
                                           "commands.cpp",
                                           "commands.h",
                                           "main.cpp",
                                           "viewer_window.cpp",
                                           "viewer_window.h",
                                           "viewer_window_none.cpp"};

// framework/src's folders a student repository leaves out: the reference
// tracer (every stage's answers in C++), the bench that runs it, the page's
// WebAssembly bindings (the page is not built there), the instructors'
// reports.
const std::set<std::string> kLeftOut = {"raytrace/reference", "bench", "wasm", "grading/report"};

// Of the class workflow and grading modules, a student build compiles the
// checks' sandbox and the function checks' harness (their CMakeLists.txt).
const std::set<std::string> kStudentGrading = {
    "classroom/CMakeLists.txt",  "classroom/check_sandbox.cpp", "classroom/check_sandbox.h",
    "classroom/grade_options.h", "grading/CMakeLists.txt",      "grading/function_harness.cpp",
    "grading/function_harness.h"};

bool leftOut(const fs::path& rel) {
    const std::string r = rel.generic_string();
    for (const std::string& dir : kLeftOut)
        if (r == dir || r.rfind(dir + "/", 0) == 0) return true;
    if (rel.parent_path() == "cli") return !kStudentCli.count(rel.filename().string());
    if (rel.parent_path() == "classroom" || rel.parent_path() == "grading")
        return !kStudentGrading.count(r);
    // The fur functions in double precision and the silhouette count
    // (TODO f3.a's answer): references of the fur checks.
    return rel.parent_path() == "fur/mesh" &&
           (rel.stem() == "fur_reference" || rel.stem() == "silhouette");
}

// framework/ as a student repository holds it.
void writeFramework(const fs::path& to, const std::set<std::string>& stages) {
    const fs::path from = projectRoot() / "framework";
    fs::create_directories(to / "src");
    fs::copy_file(from / "CMakeLists.txt", to / "CMakeLists.txt");
    for (const fs::directory_entry& e : fs::recursive_directory_iterator(from / "src")) {
        if (!e.is_regular_file()) continue;
        const fs::path rel = e.path().lexically_relative(from / "src");
        if (leftOut(rel)) continue;
        fs::create_directories((to / "src" / rel).parent_path());
        const std::string ext = rel.extension().string();
        if (ext == ".cpp" || ext == ".h")
            writeTextFileAtomic(to / "src" / rel,
                                withoutReferences(readTextFile(e.path()), displayPath(e.path())));
        else fs::copy_file(e.path(), to / "src" / rel);
    }
    copyFrameworkShaders(to / "shaders", stages);
}

std::string releasedIds(const std::vector<HandoutStage>& plan, const char* separator) {
    std::string out;
    for (const HandoutStage& h : plan) out += (out.empty() ? "" : separator) + h.stage->id;
    return out;
}

// The check views of PLAN's stages as the lab as handed out draws them for
// grading (the earlier stages solved; at the course's level), into
// TO/<stage>/<view>.png: the score's handed-out rule (stage_score.h) reads
// them in a student repository, which has no earlier stage's solution to
// draw them with. At the check's size, with the stage's own scenes.
void writeHandedOutPictures(const fs::path& to, const std::vector<HandoutStage>& plan) {
    auto context = createHeadlessContext(Backend::Auto);
    for (const HandoutStage& h : plan) {
        const StageInfo& stage = *h.stage;
        ViewRenderers handedOut(stage, labSources(stage, handedOutLabRoot()), "", 160, 120,
                                SceneTransform{});
        fs::create_directories(to / stage.id);
        for (const CheckView& view : stage.checkViews)
            writePngAtomic(handedOut.render(view), to / stage.id / (view.name + ".png"));
    }
}

// Everything of the course's (not the students' labs) into ROOT; the labs
// as handed out into HANDOUT (the new stages' folders are taken from it).
void writeCourse(const fs::path& root, const fs::path& handout,
                 const std::vector<HandoutStage>& plan, Carry carry, Level level,
                 const CourseSettings& course) {
    const fs::path src = projectRoot();
    std::set<std::string> stages;  // the released ones and those they build on
    for (const HandoutStage& h : plan) stages.insert(h.stage->id);
    for (const StageInfo* s : earlierStages(plan)) stages.insert(s->id);

    fs::copy_file(src / "CMakeLists.txt", root / "CMakeLists.txt");
    const fs::path templates = src / "framework" / "student_repo";
    std::string readme = readTextFile(templates / "README.md");
    const std::string mark = "{{stages}}";
    readme.replace(readme.find(mark), mark.size(), releasedIds(plan, ", "));
    writeTextFileAtomic(root / "README.md", readme);
    fs::copy_file(templates / "install.sh", root / "install.sh");
    fs::copy_file(templates / "gitignore", root / ".gitignore");
    writeFramework(root / "framework", stages);
    copyReleasedAssets(root, plan, true);
    for (const StageInfo& s : allStages())
        if (stages.count(s.id))
            copyTree(s.folder() / "stage.json", root / "solution" / s.id / "stage.json");
    fs::create_directories(root / "course" / "references");
    for (const HandoutStage& h : plan)
        copyTree(src / "tests" / "reference" / h.stage->id,
                 root / "course" / "references" / h.stage->id);
    writeTextFileAtomic(root / "course" / "function_tables.json", releasedFunctionTables(plan));
    writeHandedOutPictures(root / "course" / "handed-out", plan);
    // The labs as handed out (a file missing from a student's folder is read
    // from here, as grading does).
    fs::create_directories(handout);
    writeHandoutFolder(plan, defaultLabRoot(), handout, "", course, level, SolutionText::LeaveOut);
    copyTree(handout, root / "course" / "handout");
    json stagesJson = json::array();
    for (const HandoutStage& h : plan) stagesJson.push_back(h.stage->id);
    writeTextFileAtomic(root / kManifest, json{{"stages", stagesJson},
                                               {"level", level == Level::Open ? "open" : "guided"},
                                               {"carry", carry == Carry::Own ? "own" : "solved"}}
                                                  .dump(2) +
                                              "\n");
}

// What the course writes at the top of a student repository; the rest (labs/
// but its README.md) is the students'.
const std::vector<std::string> kCoursePaths = {"CMakeLists.txt", "README.md", "install.sh",
                                               ".gitignore",     "framework", "assets",
                                               "solution",       "course"};

int cmdStudentRepo(const std::string& list, const std::string& outDir, const std::string& carryName,
                   const std::string& courseFile, const std::string& levelName) {
    const Carry carry = parseCarry(carryName);
    const Level level = parseLevel(levelName);
    setHandedOutLevel(level);  // the handed-out pictures at the course's level
    const CourseSettings course =
        courseFile.empty() ? CourseSettings{} : readCourseFile(courseFile);
    const std::vector<HandoutStage> plan = planHandout(parseStageList(list), carry);
    checkHandoutSources(plan, defaultLabRoot());
    for (const HandoutStage& h : plan)
        if (!fs::is_directory(projectRoot() / "tests" / "reference" / h.stage->id))
            throw Error("tests/reference/" + h.stage->id +
                        " is missing: the student repository ships the check views' pictures");
    std::error_code ec;
    const fs::path existing(outDir);
    if (!fs::is_regular_file(existing / kManifest, ec)) {
        const fs::path out = newOutputFolder(outDir);
        writeWhole(out, "the student repository", [&](const fs::path& temp) {
            const fs::path handout = temp / ".handout";
            writeCourse(temp, handout, plan, carry, level, course);
            fs::rename(handout, temp / "labs");
        });
        std::printf("raylab student-repo: wrote %s (%s): commit it and give students the "
                    "clone address; no answer of any stage\n",
                    out.c_str(), releasedIds(plan, ", ").c_str());
        return 0;
    }

    // A release more into an existing repository: every stage it has stays.
    const json before = json::parse(readTextFile(existing / kManifest));
    std::set<std::string> now;
    for (const HandoutStage& h : plan) now.insert(h.stage->id);
    for (const json& id : before.at("stages"))
        if (!now.count(id.get<std::string>()))
            throw Error("--stages " + list + ": " + displayPath(existing) + " already releases " +
                        id.get<std::string>() + "; a release adds stages and takes none away");
    // Written beside the repository first (never inside it, where git would see it).
    fs::path whole = fs::absolute(existing).lexically_normal();
    if (whole.filename().empty()) whole = whole.parent_path();  // "repo/"
    const fs::path temp = whole.parent_path() / (whole.filename().string() + ".raylab-new");
    fs::remove_all(temp, ec);
    try {
        fs::create_directories(temp);
        const fs::path handout = temp / ".handout";
        writeCourse(temp, handout, plan, carry, level, course);
        // Every course path replaced; the students' lab folders left alone.
        for (const std::string& p : kCoursePaths) {
            fs::remove_all(existing / p);
            fs::rename(temp / p, existing / p);
        }
        fs::create_directories(existing / "labs");
        std::vector<std::string> added;
        for (const HandoutStage& h : plan)
            if (!fs::exists(existing / "labs" / h.stage->id)) {
                fs::rename(handout / h.stage->id, existing / "labs" / h.stage->id);
                added.push_back(h.stage->id);
            }
        fs::copy_file(handout / "README.md", existing / "labs" / "README.md",
                      fs::copy_options::overwrite_existing);
        fs::remove_all(temp);
        std::string addedList;
        for (const std::string& a : added) addedList += (addedList.empty() ? "" : ", ") + a;
        std::printf("raylab student-repo: updated %s (%s): new labs %s; no lab folder that was "
                    "there changed\n",
                    existing.c_str(), releasedIds(plan, ", ").c_str(),
                    addedList.empty() ? "none" : addedList.c_str());
    } catch (...) {
        fs::remove_all(temp, ec);
        throw;
    }
    return 0;
}

}  // namespace

Command studentRepoCommand() {
    return {"student-repo",
            "write (or add a release to) a repository for students to clone and build, with the "
            "released stages' labs and no answer of any stage",
            [](CLI::App& cmd) {
                auto o = std::make_shared<ReleaseOptions>();
                addReleaseOptions(
                    cmd, *o,
                    "the repository's folder: new or empty, or a student repository written before "
                    "(the new stages' labs are added)");
                return std::function<int()>([=] {
                    return cmdStudentRepo(o->stages, o->out, o->carry, o->course, o->level);
                });
            }};
}

}  // namespace raylab
