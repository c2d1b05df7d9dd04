// A progress bar on stderr, drawn only when stderr is a terminal, so logs and pipes stay clean.
// advance() may be called from any thread.
#pragma once

#include <cstddef>
#include <mutex>
#include <string>

namespace rtlab {

class ProgressBar {
public:
    ProgressBar(std::string label, size_t total);
    ~ProgressBar();
    ProgressBar(const ProgressBar&) = delete;
    ProgressBar& operator=(const ProgressBar&) = delete;

    void advance();

private:
    void draw() const;

    std::string label_;
    size_t total_;
    size_t done_ = 0;
    int drawnPercent_ = -1;
    bool enabled_;
    std::mutex mutex_;
};

}  // namespace rtlab
