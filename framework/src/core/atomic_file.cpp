#include "atomic_file.h"

#include "error.h"
#include "paths.h"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <unistd.h>

namespace raylab {

namespace fs = std::filesystem;

namespace {

// Writes all of TEXT to FD, retrying short writes and EINTR; returns 0 or errno.
int writeAll(int fd, const std::string& text) {
    const char* p = text.data();
    std::size_t left = text.size();
    while (left > 0) {
        ssize_t n = ::write(fd, p, left);
        if (n < 0) {
            if (errno == EINTR) continue;
            return errno;
        }
        p += n;
        left -= std::size_t(n);
    }
    return 0;
}

}  // namespace

void writeTextFileAtomic(const fs::path& file, const std::string& text) {
    const std::string what = "cannot write " + displayPath(file) + ": ";
    std::error_code ec;
    const fs::path dir = file.parent_path().empty() ? fs::path(".") : file.parent_path();
    if (!fs::is_directory(dir, ec))
        throw Error(what + "folder " + displayPath(dir) + " does not exist");
    if (file.filename().empty()) throw Error(what + "not a file name");

    fs::path tmp = file;
    tmp += ".tmp-" + std::to_string(::getpid());
    int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
    if (fd < 0) throw Error(what + std::strerror(errno));

    int err = writeAll(fd, text);
    if (err == 0 && ::fsync(fd) != 0 && errno != EINVAL && errno != EROFS)
        err = errno;  // EINVAL: fs without fsync
    if (::close(fd) != 0 && err == 0) err = errno;
    if (err == 0 && ::rename(tmp.c_str(), file.c_str()) != 0) err = errno;
    if (err != 0) {
        ::unlink(tmp.c_str());
        throw Error(what + std::strerror(err));
    }
}

}  // namespace raylab
