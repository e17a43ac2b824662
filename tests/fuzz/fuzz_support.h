#pragma once
// Shared by the fuzz targets: a private temporary folder per fuzzer process
// (made once, removed at exit) and a helper that writes a file into it.
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>
#include <unistd.h>

namespace raylab::fuzz {

namespace fs = std::filesystem;

// mkdtemp under $TMPDIR (or /tmp): a fresh folder only this process writes to.
inline const fs::path& scratchDir() {
    static const fs::path dir = [] {
        const char* tmp = std::getenv("TMPDIR");
        std::string pattern = std::string(tmp && *tmp ? tmp : "/tmp") + "/raylab-fuzz-XXXXXX";
        if (!mkdtemp(pattern.data())) std::abort();
        std::atexit([] {
            std::error_code ec;
            fs::remove_all(scratchDir(), ec);
        });
        return fs::path(pattern);
    }();
    return dir;
}

inline void writeBytes(const fs::path& file, const std::uint8_t* data, std::size_t size) {
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), std::streamsize(size));
    if (!out) std::abort();  // the harness itself failed, not the code under test
}

}  // namespace raylab::fuzz
