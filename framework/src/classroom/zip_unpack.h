#pragma once
// A zip a student uploaded, unpacked for grading with Debian's libzip.
// Uploads are untrusted: an entry may not leave the folder (an absolute
// path, "..", a symbolic link), and the whole archive has a size and a file
// limit, so that a zip bomb stops with a one-line cause instead of filling
// the disk. Nothing is left behind when unpacking fails.
#include <cstdint>
#include <filesystem>
#include <string>

namespace raylab {

struct ZipLimits {
    std::uint64_t maxBytes = 64ull << 20;  // uncompressed, all entries together
    std::size_t maxEntries = 4096;
};

// Unpacks ZIPFILE into INTO (created; must not exist). Throws Error("NAME:
// why") on a damaged archive or an entry that breaks the rules above.
void unpackZip(const std::filesystem::path& zipFile, const std::filesystem::path& into,
               const ZipLimits& limits = {});

bool isZipFile(const std::filesystem::path& file);  // by its first bytes, not its name

}  // namespace raylab
