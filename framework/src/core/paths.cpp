#include "paths.h"

#include "error.h"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>

namespace raylab {

namespace {

bool looksLikeRoot(const fs::path& dir) {
    std::error_code ec;
    return fs::is_directory(dir / "framework" / "shaders", ec) &&
           fs::is_directory(dir / "solution", ec);
}

fs::path findRoot() {
    if (const char* env = std::getenv("RAYLAB_ROOT"); env && *env) {
        if (!looksLikeRoot(env))
            throw Error(std::string("RAYLAB_ROOT=") + env +
                        " is not a RayLab tree (no framework/shaders or solution/)");
        return fs::weakly_canonical(env);
    }
    std::error_code ec;
    fs::path exe = fs::read_symlink("/proc/self/exe",
                                    ec);  // not executablePath(): no error here, fall through
    if (!ec) {
        for (fs::path dir = exe.parent_path(); !dir.empty(); dir = dir.parent_path()) {
            if (looksLikeRoot(dir)) return dir;
            if (dir == dir.root_path()) break;
        }
    }
#ifdef RAYLAB_SOURCE_DIR
    if (looksLikeRoot(RAYLAB_SOURCE_DIR)) return RAYLAB_SOURCE_DIR;
#endif
    throw Error("cannot find the RayLab tree (framework/shaders, solution/): set RAYLAB_ROOT");
}

}  // namespace

fs::path executablePath() {
    std::error_code ec;
    fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    if (ec) throw Error("cannot find this program's executable (/proc/self/exe): " + ec.message());
    return exe;
}

const fs::path& projectRoot() {
    static const fs::path root = findRoot();
    return root;
}

std::string displayPath(const fs::path& p) {
    std::error_code ec;
    fs::path abs = fs::weakly_canonical(p, ec);
    if (ec) return p.string();
    fs::path rel = abs.lexically_relative(projectRoot());
    if (!rel.empty() && *rel.begin() != "..") return rel.string();
    return p.string();
}

std::string readTextFile(const fs::path& p) {
    std::error_code ec;
    if (fs::is_directory(p, ec)) throw Error("cannot read " + displayPath(p) + ": is a directory");
    std::ifstream in(p, std::ios::binary);
    if (!in) throw Error("cannot read " + displayPath(p) + ": " + std::strerror(errno));
    std::ostringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

}  // namespace raylab
