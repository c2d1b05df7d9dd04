// A few threads that share a stack of tasks, for the builders of fast/: a task may add more
// tasks, and whoever waits for a group of tasks works on queued ones meanwhile, so no thread
// idles while there is work and nested waits cannot deadlock.
//
// Deliberately small: the wide BVH's builder hands out subtrees of thousands of primitives and
// the binning of big nodes, a few hundred tasks per build, so one mutex is no bottleneck.
#pragma once

#include <atomic>
#include <condition_variable>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace rtlab {

// The CPUs this process may run on (its affinity mask: 1 under `taskset -c 0`).
int availableCpus();

class TaskPool {
public:
    // threads - 1 workers; the thread that waits is the other one. With threads <= 1 every
    // task runs at once, on the thread that adds it.
    explicit TaskPool(int threads);
    ~TaskPool();
    TaskPool(const TaskPool&) = delete;
    TaskPool& operator=(const TaskPool&) = delete;

    int threads() const { return static_cast<int>(workers_.size()) + 1; }

    // Runs task on some thread; pending is incremented now and decremented once it has run.
    void run(std::function<void()> task, std::atomic<int>& pending);
    // Returns once pending is 0, running queued tasks (of any group) in the meantime.
    void waitFor(const std::atomic<int>& pending);

private:
    struct Task {
        std::function<void()> work;
        std::atomic<int>* pending;
    };
    bool runOne();  // runs the newest queued task; false when there is none
    void workerLoop();

    std::mutex mutex_;
    std::condition_variable wake_;
    std::vector<Task> tasks_;  // a stack: the newest task is the smallest and warmest
    bool stopping_ = false;
    std::vector<std::thread> workers_;
};

}  // namespace rtlab
