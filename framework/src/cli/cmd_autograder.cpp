// `raylab autograder --out DIR`: DIR/autograder.zip for Gradescope. At the
// zip's root: setup.sh (installs what the headless build needs and builds
// RayLab with -DRAYLAB_WINDOW=OFF), run_autograder (runs `raylab gradescope`)
// and raylab-autograder.json (the stages, the secret seed, what students see
// when); beside them the RayLab sources the build and grading need. The zip
// is made by Debian's `zip` in a staging folder and renamed into place, so
// DIR never holds a partial bundle.
#include "atomic_file.h"
#include "child_process.h"
#include "command.h"
#include "commands.h"
#include "error.h"
#include "grade_report.h"
#include "paths.h"
#include "stage_catalog.h"
#include "upload_grading.h"

#include <nlohmann/json.hpp>

#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <random>

namespace raylab {

namespace fs = std::filesystem;

namespace {

struct BundleOptions {
    std::string outDir;
    std::string stages;  // empty: every stage
    unsigned seed = 0;
    bool seedGiven = false;
    std::string visibility = "visible";
    std::string testVisibility = "visible";
    std::string seededVisibility = "after_due_date";
    std::string stdoutVisibility = "hidden";
    double timeoutSeconds = 60.0;
    long memoryMb = 2048;
    std::string level = "guided";
};

// What the bundle carries of the tree: what CMake configures (the top
// CMakeLists.txt adds framework/ and tools/) and what grading reads.
const char* const kBundledFolders[] = {"framework", "tools", "assets", "labs", "solution"};

// Regular files under DIR, relative to ROOT; hidden files, links and
// leftovers of atomic writes (*.tmp*) are not part of the sources.
void listFiles(const fs::path& root, const fs::path& dir, std::vector<fs::path>& out) {
    for (fs::recursive_directory_iterator it(root / dir), end; it != end; ++it) {
        const std::string name = it->path().filename().string();
        const bool hidden =
            name.empty() || name[0] == '.' || name.find(".tmp") != std::string::npos;
        if (hidden || it->is_symlink()) {
            if (it->is_directory()) it.disable_recursion_pending();
            continue;
        }
        if (it->is_regular_file()) out.push_back(fs::relative(it->path(), root));
    }
}

bool onPath(const std::string& program) {
    const char* path = std::getenv("PATH");
    std::string dirs = path ? path : "/usr/bin:/bin";
    for (std::size_t at = 0; at <= dirs.size();) {
        std::size_t end = dirs.find(':', at);
        if (end == std::string::npos) end = dirs.size();
        const fs::path candidate = fs::path(dirs.substr(at, end - at)) / program;
        if (::access(candidate.c_str(), X_OK) == 0) return true;
        at = end + 1;
    }
    return false;
}

int cmdAutograder(const BundleOptions& o) {
    // Everything that can be wrong with the request fails before anything is written.
    if (o.outDir.empty()) throw Error("--out is required");
    std::vector<std::string> ids;
    if (o.stages.empty())
        for (const StageInfo& s : allStages()) ids.push_back(s.id);
    else ids = stageList(o.stages);
    for (const auto& [option, value] :
         {std::pair<const char*, std::string>{"--visibility", o.visibility},
          {"--test-visibility", o.testVisibility},
          {"--seeded-visibility", o.seededVisibility},
          {"--stdout-visibility", o.stdoutVisibility}})
        if (!isGradescopeVisibility(value))
            throw Error(std::string(option) +
                        " must be visible, hidden, after_due_date or "
                        "after_published (not '" +
                        value + "')");
    if (!(o.timeoutSeconds > 0.0) || o.timeoutSeconds > 3600.0)
        throw Error("--timeout must be between 0 and 3600 seconds");
    if (o.memoryMb != 0 && (o.memoryMb < 256 || o.memoryMb > 1 << 20))
        throw Error("--memory-mb must be 0 (no limit) or 256..1048576");
    parseLevel(o.level);  // an unknown level is refused before anything is written
    if (!onPath("zip")) throw Error("the zip program is missing (Debian: apt-get install zip)");
    const fs::path root = projectRoot();
    for (const char* script : {"tools/grader/setup.sh", "tools/grader/run_autograder"})
        if (!fs::is_regular_file(root / script))
            throw Error("no " + std::string(script) + " in " + root.string());
    const unsigned seed = o.seedGiven ? o.seed : std::random_device{}();

    const fs::path out = o.outDir;
    std::error_code ec;
    const bool madeOut = !fs::exists(out, ec);
    fs::create_directories(out, ec);
    if (ec || !fs::is_directory(out))
        throw Error("--out '" + o.outDir + "': cannot create the folder");
    const std::string pid = std::to_string(::getpid());
    const fs::path staging = out / (".autograder-staging-" + pid);
    const fs::path tmpZip = out / (".autograder-" + pid + ".zip");
    const fs::path log = out / (".autograder-" + pid + ".log");
    const fs::path zip = out / "autograder.zip";
    auto cleanUp = [&] {
        std::error_code ignored;
        fs::remove_all(staging, ignored);
        fs::remove(tmpZip, ignored);
        fs::remove(log, ignored);
    };
    std::size_t count = 0;
    try {
        std::vector<fs::path> files = {"CMakeLists.txt"};
        for (const char* dir : kBundledFolders) listFiles(root, dir, files);
        for (const fs::path& f : files) {
            fs::create_directories((staging / f).parent_path());
            fs::copy_file(root / f, staging / f);
        }
        // Gradescope's two files at the zip's root (the same scripts as in
        // tools/grader/, which the PrairieLearn image runs too).
        for (const char* script : {"setup.sh", "run_autograder"}) {
            fs::copy_file(root / "tools" / "grader" / script, staging / script);
            fs::permissions(staging / script, fs::perms::owner_all | fs::perms::group_read |
                                                  fs::perms::group_exec | fs::perms::others_read |
                                                  fs::perms::others_exec);
        }
        nlohmann::ordered_json config{{"stages", ids},
                                      {"seed", seed},
                                      {"visibility", o.visibility},
                                      {"test_visibility", o.testVisibility},
                                      {"seeded_visibility", o.seededVisibility},
                                      {"stdout_visibility", o.stdoutVisibility},
                                      {"timeout_s", o.timeoutSeconds},
                                      {"memory_mb", o.memoryMb},
                                      {"level", o.level}};
        writeTextFileAtomic(staging / "raylab-autograder.json", config.dump(2) + "\n");
        count = files.size() + 3;

        Child child({"/bin/sh", "-c", "cd \"$1\" && exec zip -q -r -X \"$2\" .", "sh",
                     staging.string(), fs::absolute(tmpZip).string()},
                    log, ChildLimits{300.0, 0});
        const ChildOutcome& done = child.wait();
        if (done.exitCode != 0 || !fs::is_regular_file(tmpZip))
            throw Error("zip failed (" + done.describe() + "): " + lastLogLine(log));
        fs::rename(tmpZip, zip);
    } catch (const fs::filesystem_error& e) {
        cleanUp();
        if (madeOut) fs::remove(out, ec);
        throw Error(std::string("cannot make the bundle: ") + e.what());
    } catch (...) {
        cleanUp();
        if (madeOut) fs::remove(out, ec);
        throw;
    }
    cleanUp();
    std::string list;
    for (const std::string& id : ids) list += (list.empty() ? "" : ",") + id;
    std::printf("raylab autograder: wrote %s (%zu files, %.1f MB)\n"
                "  stages %s, seed %u (keep it secret: `raylab grade --seed %u` gives the same "
                "scores), seeded views %s\n"
                "  upload it as the assignment's autograder (Ubuntu 22.04 base image)\n",
                zip.c_str(), count, double(fs::file_size(zip)) / (1024.0 * 1024.0), list.c_str(),
                seed, seed, o.seededVisibility.c_str());
    return 0;
}

}  // namespace

Command autograderCommand() {
    return {
        "autograder",
        "write a Gradescope autograder bundle (DIR/autograder.zip: setup.sh, run_autograder, the "
        "sources, the secret seed)",
        [](CLI::App& cmd) {
            auto o = std::make_shared<BundleOptions>();
            cmd.add_option("--out", o->outDir, "folder for autograder.zip")->required();
            cmd.add_option("--stages", o->stages,
                           "the stages the assignment grades, e.g. 01,02 (default: all)");
            CLI::Option* seed = cmd.add_option(
                "--seed", o->seed,
                "seed of the extra camera views, kept in the bundle (default: a random "
                "one, printed)");
            cmd.add_option("--seeded-visibility", o->seededVisibility,
                           "when students see the seeded views' tests: visible, hidden, "
                           "after_due_date, after_published")
                ->capture_default_str();
            cmd.add_option("--test-visibility", o->testVisibility,
                           "when students see the other tests (check views, function and count "
                           "checks)")
                ->capture_default_str();
            cmd.add_option("--visibility", o->visibility,
                           "Gradescope's visibility of the whole result")
                ->capture_default_str();
            cmd.add_option("--stdout-visibility", o->stdoutVisibility,
                           "when students see the autograder's log")
                ->capture_default_str();
            cmd.add_option("--timeout", o->timeoutSeconds, "seconds per stage")
                ->capture_default_str();
            cmd.add_option("--memory-mb", o->memoryMb, "address-space limit per stage, MB")
                ->capture_default_str();
            cmd.add_option("--level", o->level,
                           "the level of the labs handed out: guided or open (raylab handout "
                           "--level)")
                ->capture_default_str();
            return std::function<int()>([=] {
                o->seedGiven = seed->count() > 0;
                return cmdAutograder(*o);
            });
        }};
}

}  // namespace raylab
