#include "grade_items.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <thread>
#include <vector>

namespace raylab {

namespace fs = std::filesystem;

bool runPool(std::size_t count, int jobs,
             const std::function<std::unique_ptr<Child>(std::size_t)>& start,
             const std::function<void(std::size_t, const ChildOutcome&)>& done,
             const std::function<bool()>& interrupted) {
    std::vector<std::pair<std::size_t, std::unique_ptr<Child>>> running;
    std::size_t next = 0;
    while (next < count || !running.empty()) {
        if (interrupted()) return false;
        while (next < count && int(running.size()) < jobs) {
            std::size_t job = next++;
            if (auto child = start(job)) running.emplace_back(job, std::move(child));
        }
        bool any = false;
        for (auto it = running.begin(); it != running.end();) {
            if (!it->second->poll()) {
                ++it;
                continue;
            }
            any = true;
            done(it->first, it->second->outcome());
            it = running.erase(it);
        }
        if (!any) std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    return true;
}

std::string lastLines(const fs::path& log, int count) {
    std::ifstream in(log);
    std::vector<std::string> lines;
    for (std::string line; std::getline(in, line);)
        if (!line.empty()) lines.push_back(line);
    std::string out;
    for (std::size_t i = lines.size() > std::size_t(count) ? lines.size() - std::size_t(count) : 0;
         i < lines.size(); ++i)
        out += lines[i] + "\n";
    return out;
}

StageResult failedItem(const StageInfo& stage, const ChildOutcome& o, const fs::path& log,
                       const GradeOptions& g) {
    StageResult r;
    r.stage = stage.id;
    r.seconds = o.seconds;
    char limit[160];
    if (o.timedOut) {
        r.status = "timed out";
        std::snprintf(limit, sizeof limit,
                      "stopped after %.0f s (--timeout): an endless loop, or a shader that takes "
                      "minutes to compile?",
                      g.timeoutSeconds);
        r.message = limit;
    } else if (o.exitCode == 3) {
        r.status = "out of memory";
        r.message =
            "ran out of memory (--memory-mb " + std::to_string(g.memoryMb) + "): a huge array?";
    } else if (o.signal) {
        r.status = "crashed";
        r.message = o.describe() +
                    " (a crash in the shader compiler or driver, or memory beyond --memory-mb " +
                    std::to_string(g.memoryMb) + ")";
    } else {
        r.status = "error";
        r.message = o.describe();
    }
    std::string tail = lastLines(log, 5);
    if (!tail.empty()) r.message += "\nlast lines of its log:\n" + tail;
    return r;
}

Progress::Progress(std::size_t total) : total_(total), tty_(isatty(2)) {}

void Progress::working(const std::string& student, const std::string& stage) {
    if (!tty_) return;
    const int width = 30;
    int filled = int(double(width) * double(finished_) / double(std::max<std::size_t>(total_, 1)));
    std::fprintf(stderr, "\r[%s%s] %zu/%zu  grading %-20.20s %-14s",
                 std::string(std::size_t(filled), '#').c_str(),
                 std::string(std::size_t(width - filled), '.').c_str(), finished_, total_,
                 student.c_str(), stage.c_str());
    std::fflush(stderr);
}

void Progress::done(const std::string& student, const StageResult& r) {
    ++finished_;
    if (tty_) {
        if (finished_ == total_) std::fprintf(stderr, "\r%-90s\r", "");
    } else {
        std::fprintf(
            stderr, "  [%zu/%zu] %s %s: %s\n", finished_, total_, student.c_str(), r.stage.c_str(),
            r.status == "graded" ? (std::to_string(int(std::lround(r.score))) + "/100").c_str()
                                 : r.status.c_str());
    }
    std::fflush(stderr);
}

}  // namespace raylab
