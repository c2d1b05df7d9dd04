#include "fast/task_pool.h"

#include <algorithm>

#if defined(__linux__)
#include <sched.h>
#endif

namespace rtlab {

int availableCpus() {
#if defined(__linux__)
    cpu_set_t set;
    if (sched_getaffinity(0, sizeof set, &set) == 0) return std::max(1, CPU_COUNT(&set));
#endif
    return std::max(1u, std::thread::hardware_concurrency());
}

TaskPool::TaskPool(int threads) {
    for (int i = 1; i < threads; ++i) workers_.emplace_back([this] { workerLoop(); });
}

TaskPool::~TaskPool() {
    {
        std::lock_guard lock(mutex_);
        stopping_ = true;
    }
    wake_.notify_all();
    for (std::thread& worker : workers_) worker.join();
}

void TaskPool::run(std::function<void()> task, std::atomic<int>& pending) {
    pending.fetch_add(1, std::memory_order_relaxed);
    if (workers_.empty()) {
        task();
        pending.fetch_sub(1, std::memory_order_release);
        return;
    }
    {
        std::lock_guard lock(mutex_);
        tasks_.push_back({std::move(task), &pending});
    }
    wake_.notify_one();
}

bool TaskPool::runOne() {
    Task task;
    {
        std::lock_guard lock(mutex_);
        if (tasks_.empty()) return false;
        task = std::move(tasks_.back());
        tasks_.pop_back();
    }
    task.work();
    task.pending->fetch_sub(1, std::memory_order_release);
    return true;
}

void TaskPool::waitFor(const std::atomic<int>& pending) {
    while (pending.load(std::memory_order_acquire) > 0)
        if (!runOne()) std::this_thread::yield();  // the last tasks run elsewhere: a short wait
}

void TaskPool::workerLoop() {
    for (;;) {
        Task task;
        {
            std::unique_lock lock(mutex_);
            wake_.wait(lock, [this] { return stopping_ || !tasks_.empty(); });
            if (tasks_.empty()) return;  // stopping, and nothing left
            task = std::move(tasks_.back());
            tasks_.pop_back();
        }
        task.work();
        task.pending->fetch_sub(1, std::memory_order_release);
    }
}

}  // namespace rtlab
