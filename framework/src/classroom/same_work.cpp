#include "same_work.h"

#include "atomic_file.h"
#include "error.h"
#include "grade_stage.h"
#include "paths.h"
#include "stage_sources.h"

#include <sodium.h>

#include <algorithm>

namespace raylab {

namespace fs = std::filesystem;

namespace {

// The regular files under DIR, sorted; none when a link or anything but a
// file or folder is there.
std::optional<std::vector<fs::path>> plainFiles(const fs::path& dir) {
    std::vector<fs::path> files;
    std::error_code ec;
    for (fs::recursive_directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
        const fs::file_type type = it->symlink_status(ec).type();
        if (type == fs::file_type::regular) files.push_back(it->path());
        else if (type != fs::file_type::directory) return std::nullopt;
    }
    if (ec) return std::nullopt;
    std::sort(files.begin(), files.end());
    return files;
}

bool namesAny(const std::string& text, const std::vector<std::string>& names) {
    for (const std::string& n : names)
        if (!n.empty() && text.find(n) != std::string::npos) return true;
    return false;
}

}  // namespace

std::optional<std::string> sameWorkKey(const StageInfo& stage, const fs::path& labRoot) {
    std::string material;
    // Each folder's files as "folder/name", their sizes and contents.
    auto addFolder = [&](const std::string& id) {
        const std::optional<std::vector<fs::path>> files = plainFiles(labRoot / id);
        if (!files) return false;
        for (const fs::path& f : *files) {
            const std::string content = readTextFile(f);  // throws: graded on its own
            material += id + "/" + f.lexically_relative(labRoot / id).generic_string() + '\0' +
                        std::to_string(content.size()) + '\0' + content;
        }
        return true;
    };
    try {
        if (!addFolder(stage.id)) return std::nullopt;
        // The earlier folders of the student's that grading reads (those
        // of the note on an earlier slip too, stage_sources.h): whole.
        const StageSources own = labSources(stage, labRoot, MissingLabFiles::FromHandedOutLab);
        for (const OwnEarlierStage& earlier : ownEarlierStagesRead(stage, own)) {
            material += std::string("\0earlier\0", 9);
            if (!addFolder(earlier.id)) return std::nullopt;
        }
    } catch (const std::exception&) { return std::nullopt; }
    if (sodium_init() < 0) return std::nullopt;
    unsigned char digest[crypto_generichash_BYTES];
    crypto_generichash(digest, sizeof digest,
                       reinterpret_cast<const unsigned char*>(material.data()), material.size(),
                       nullptr, 0);
    char hex[2 * sizeof digest + 1];
    return std::string(sodium_bin2hex(hex, sizeof hex, digest, sizeof digest));
}

std::optional<StageResult> copySameWork(const StageResult& leader, const fs::path& out,
                                        const std::string& from, const std::string& to,
                                        const std::vector<std::string>& names) {
    const fs::path fromDir = studentFolder(out, from) / leader.stage;
    const fs::path toDir = studentFolder(out, to) / leader.stage;
    // The leader's image paths, moved to TO's folder.
    const std::string fromPrefix = fs::path(fromDir).lexically_relative(out).generic_string() + "/",
                      toPrefix = fs::path(toDir).lexically_relative(out).generic_string() + "/";
    StageResult r = leader;
    // No child graded this copy: it took no time and no memory (so that
    // `raylab grade --estimate` counts the sharing it saw in its sample).
    r.seconds = 0;
    r.peakMb = 0;
    auto moved = [&](std::string& path) {
        if (path.rfind(fromPrefix, 0) == 0) path = toPrefix + path.substr(fromPrefix.size());
    };
    for (CheckResult& c : r.checks) {
        moved(c.studentImage);
        moved(c.diffImage);
        moved(c.referenceImage);
    }
    std::string texts = r.message + "\n" + r.lateNote;
    for (const CheckResult& c : r.checks)
        texts += "\n" + c.output + "\n" + c.studentImage + "\n" + c.diffImage;
    std::error_code ec;
    if (fs::is_regular_file(fromDir / "log.txt", ec))
        texts += "\n" + readTextFile(fromDir / "log.txt");
    if (namesAny(texts, names)) return std::nullopt;
    fs::remove_all(toDir, ec);
    fs::create_directories(toDir.parent_path(), ec);
    fs::copy(fromDir, toDir, fs::copy_options::recursive, ec);
    if (ec) {
        fs::remove_all(toDir, ec);
        return std::nullopt;
    }
    if (fs::is_regular_file(toDir / "result.json", ec))
        writeTextFileAtomic(toDir / "result.json", stageResultToJson(r));
    return r;
}

}  // namespace raylab
