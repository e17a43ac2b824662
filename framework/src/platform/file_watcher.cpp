#include "file_watcher.h"

namespace raylab {

std::filesystem::file_time_type FileWatcher::stampOf(const std::filesystem::path& file) {
    std::error_code ec;
    auto stamp = std::filesystem::last_write_time(file, ec);
    return ec ? std::filesystem::file_time_type::min() : stamp;
}

void FileWatcher::watch(const std::vector<std::filesystem::path>& files) {
    entries_.clear();
    for (const auto& f : files) entries_.push_back({f, stampOf(f)});
}

bool FileWatcher::changed() {
    bool any = false;
    for (Entry& e : entries_) {
        auto now = stampOf(e.file);
        if (now != e.stamp) {
            e.stamp = now;
            any = true;
        }
    }
    return any;
}

}  // namespace raylab
