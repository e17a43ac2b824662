#pragma once
// Notices when any of a set of files changes on disk (shader hot reload).
#include <filesystem>
#include <vector>

namespace raylab {

class FileWatcher {
public:
    void watch(const std::vector<std::filesystem::path>& files);
    // True once for every change of a modification time (or a file vanishing).
    bool changed();

private:
    struct Entry {
        std::filesystem::path file;
        std::filesystem::file_time_type stamp;
    };
    static std::filesystem::file_time_type stampOf(const std::filesystem::path& file);
    std::vector<Entry> entries_;
};

}  // namespace raylab
