#include "grader/engine/parallel_jobs.h"

#include <algorithm>
#include <atomic>
#include <thread>
#include <vector>

namespace rtlab::grader {

size_t compileThreads() {
    return std::clamp<size_t>(std::thread::hardware_concurrency(), 1, 4);
}

void runInParallel(size_t count, size_t threads, const std::function<void(size_t)>& job) {
    std::atomic<size_t> next{0};
    auto takeJobs = [&] {
        for (size_t i; (i = next++) < count;) job(i);
    };
    std::vector<std::thread> helpers;
    for (size_t t = 1; t < std::min(threads, count); ++t) helpers.emplace_back(takeJobs);
    takeJobs();
    for (std::thread& helper : helpers) helper.join();
}

}  // namespace rtlab::grader
