#include "framework/render/progress_bar.h"

#include <cstdio>
#include <unistd.h>

namespace rtlab {

static constexpr int kBarWidth = 40;

ProgressBar::ProgressBar(std::string label, size_t total)
    : label_(std::move(label)), total_(total), enabled_(isatty(STDERR_FILENO) == 1 && total > 0) {}

ProgressBar::~ProgressBar() {
    if (enabled_ && drawnPercent_ >= 0) std::fputs("\r\033[K", stderr);  // leave the line clean
}

void ProgressBar::advance() {
    if (!enabled_) return;
    std::lock_guard lock(mutex_);
    ++done_;
    int percent = static_cast<int>(100 * done_ / total_);
    if (percent == drawnPercent_) return;  // redraw only when the figure changes
    drawnPercent_ = percent;
    draw();
}

void ProgressBar::draw() const {
    int filled = drawnPercent_ * kBarWidth / 100;
    std::string bar(static_cast<size_t>(filled), '#');
    bar.resize(kBarWidth, '.');
    std::fprintf(stderr, "\r%s [%s] %3d%%", label_.c_str(), bar.c_str(), drawnPercent_);
    std::fflush(stderr);
}

}  // namespace rtlab
