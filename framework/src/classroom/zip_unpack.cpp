#include "zip_unpack.h"

#include "error.h"

#include <zip.h>

#include <fstream>
#include <memory>
#include <vector>

namespace raylab {

namespace fs = std::filesystem;

namespace {

struct ZipCloser {
    void operator()(zip_t* z) const { zip_discard(z); }
};
struct FileCloser {
    void operator()(zip_file_t* f) const { zip_fclose(f); }
};

// A relative path of plain names, or empty when the entry may not be written.
fs::path safeRelative(const std::string& name) {
    if (name.empty() || name[0] == '/' || name[0] == '\\' || name.find('\\') != std::string::npos ||
        name.find(':') != std::string::npos)
        return {};
    fs::path out;
    for (const fs::path& part : fs::path(name)) {
        const std::string p = part.string();
        if (p == "..") return {};
        if (p.empty() || p == ".") continue;
        out /= part;
    }
    return out;
}

bool isSymlinkEntry(zip_t* z, zip_uint64_t i) {
    zip_uint8_t os = 0;
    zip_uint32_t attributes = 0;
    if (zip_file_get_external_attributes(z, i, 0, &os, &attributes) != 0) return false;
    const unsigned mode = attributes >> 16;
    return os == ZIP_OPSYS_UNIX && (mode & 0170000u) == 0120000u;
}

}  // namespace

bool isZipFile(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    char magic[4] = {};
    in.read(magic, 4);
    return in.gcount() == 4 && magic[0] == 'P' && magic[1] == 'K' &&
           ((magic[2] == 3 && magic[3] == 4) || (magic[2] == 5 && magic[3] == 6));
}

void unpackZip(const fs::path& zipFile, const fs::path& into, const ZipLimits& limits) {
    const std::string label = zipFile.filename().string();
    int err = 0;
    // No ZIP_CHECKCONS: libzip 1.7 (Debian 12, Ubuntu 22.04) then refuses the
    // zips macOS's Finder makes (local and central headers differ); every
    // entry's name, kind and size is checked here instead.
    std::unique_ptr<zip_t, ZipCloser> z(zip_open(zipFile.c_str(), ZIP_RDONLY, &err));
    if (!z) {
        zip_error_t e;
        zip_error_init_with_code(&e, err);
        const std::string why = zip_error_strerror(&e);
        zip_error_fini(&e);
        throw Error(label + ": not a readable zip (" + why + ")");
    }
    const zip_int64_t count = zip_get_num_entries(z.get(), 0);
    if (count < 0 || std::size_t(count) > limits.maxEntries)
        throw Error(label + ": more than " + std::to_string(limits.maxEntries) + " entries");
    // Check every entry before writing anything.
    std::uint64_t total = 0;
    std::vector<std::pair<zip_uint64_t, fs::path>> files;
    std::vector<fs::path> folders;
    for (zip_uint64_t i = 0; i < zip_uint64_t(count); ++i) {
        zip_stat_t st;
        zip_stat_init(&st);
        if (zip_stat_index(z.get(), i, 0, &st) != 0 || !(st.valid & ZIP_STAT_NAME))
            throw Error(label + ": entry " + std::to_string(i) + " cannot be read");
        const std::string name = st.name;
        const fs::path rel = safeRelative(name);
        if (rel.empty() && !name.empty() && name != "/" && name != "./")
            throw Error(label + ": " + name + " would be written outside the upload");
        if (isSymlinkEntry(z.get(), i))
            throw Error(label + ": " + name + " is a symbolic link (links are not accepted)");
        if (!name.empty() && name.back() == '/') {
            if (!rel.empty()) folders.push_back(rel);
            continue;
        }
        if (!(st.valid & ZIP_STAT_SIZE)) throw Error(label + ": " + name + " has no size");
        total += st.size;
        if (total > limits.maxBytes)
            throw Error(label + ": more than " + std::to_string(limits.maxBytes >> 20) +
                        " MB unpacked");
        files.emplace_back(i, rel);
    }
    if (fs::exists(into)) throw Error(into.string() + " exists already");
    try {
        fs::create_directories(into);
        for (const fs::path& f : folders) fs::create_directories(into / f);
        std::vector<char> buffer(1 << 16);
        std::uint64_t unpacked = 0;
        for (const auto& [index, rel] : files) {
            std::unique_ptr<zip_file_t, FileCloser> in(zip_fopen_index(z.get(), index, 0));
            if (!in)
                throw Error(label + ": " + rel.string() + " cannot be read (" +
                            zip_strerror(z.get()) + ")");
            zip_stat_t st;
            zip_stat_init(&st);
            zip_stat_index(z.get(), index, 0, &st);
            fs::create_directories((into / rel).parent_path());
            std::ofstream out(into / rel, std::ios::binary | std::ios::trunc);
            std::uint64_t written = 0;
            for (;;) {
                const zip_int64_t n = zip_fread(in.get(), buffer.data(), buffer.size());
                if (n < 0) throw Error(label + ": " + rel.string() + " is damaged");
                if (n == 0) break;
                written += std::uint64_t(n);
                unpacked += std::uint64_t(n);
                // The sizes in the directory were checked; the data must agree.
                if (written > st.size)
                    throw Error(label + ": " + rel.string() + " holds more than its entry says");
                if (unpacked > limits.maxBytes)
                    throw Error(label + ": more than " + std::to_string(limits.maxBytes >> 20) +
                                " MB unpacked");
                out.write(buffer.data(), std::streamsize(n));
            }
            if (!out) throw Error("cannot write " + (into / rel).string());
        }
    } catch (...) {
        std::error_code ec;
        fs::remove_all(into, ec);
        throw;
    }
}

}  // namespace raylab
