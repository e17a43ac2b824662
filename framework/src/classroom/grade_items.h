#pragma once
// Running a class's items (grade_class.cpp): the pool of child processes,
// the progress line, and what a child that left no result means.
#include "child_process.h"
#include "grade_options.h"
#include "grade_result.h"
#include "stage_catalog.h"

#include <filesystem>
#include <functional>
#include <memory>
#include <string>

namespace raylab {

// Runs COUNT jobs with at most JOBS children at once. START(i) starts job i
// and returns its child, or nullptr when the job needed none (it is then
// finished already). DONE(i, outcome) runs when child i has ended. Returns
// false when INTERRUPTED() says so; the running children are then killed
// (~Child).
bool runPool(std::size_t count, int jobs,
             const std::function<std::unique_ptr<Child>(std::size_t)>& start,
             const std::function<void(std::size_t, const ChildOutcome&)>& done,
             const std::function<bool()>& interrupted);

// LOG's last COUNT lines that are not empty, each ending in a newline.
std::string lastLines(const std::filesystem::path& log, int count);

// What a child that left no result means.
StageResult failedItem(const StageInfo& stage, const ChildOutcome& o,
                       const std::filesystem::path& log, const GradeOptions& g);

// On a terminal: a bar and the item now under work; in a log: a line per
// finished item.
class Progress {
public:
    explicit Progress(std::size_t total);
    void working(const std::string& student, const std::string& stage);
    void done(const std::string& student, const StageResult& r);

private:
    std::size_t total_, finished_ = 0;
    bool tty_;
};

}  // namespace raylab
