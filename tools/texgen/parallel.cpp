#include "parallel.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace raylab::texgen {

void forEachRow(int rows, const std::function<void(int)>& row) {
    const int threads =
        std::max(1, std::min(rows, static_cast<int>(std::thread::hardware_concurrency())));
    // Rows are handed out one at a time: rows near the poles or a face's
    // corner cost more than others, so fixed blocks would leave cores idle.
    std::atomic<int> next{0};
    std::exception_ptr failure;
    std::mutex failureLock;
    auto work = [&] {
        try {
            for (int y = next++; y < rows; y = next++) row(y);
        } catch (...) {
            std::lock_guard<std::mutex> lock(failureLock);
            if (!failure) failure = std::current_exception();
            next = rows;  // the others stop after their current row
        }
    };
    std::vector<std::thread> pool;
    for (int i = 1; i < threads; ++i) pool.emplace_back(work);
    work();
    for (std::thread& t : pool) t.join();
    if (failure) std::rethrow_exception(failure);
}

}  // namespace raylab::texgen
