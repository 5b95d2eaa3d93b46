#include "core/progress.h"

#include <unistd.h>
#include <algorithm>
#include <cstdio>

namespace rayset {

ProgressBar::ProgressBar(std::string label, bool enabled)
    : label_(std::move(label)),
      enabled_(enabled && ::isatty(STDERR_FILENO)),
      start_(std::chrono::steady_clock::now()),
      last_(start_) {}

ProgressBar::~ProgressBar() { done(); }

void ProgressBar::update(double fraction) {
    if (!enabled_) return;
    auto now = std::chrono::steady_clock::now();
    if (drawn_ && now - last_ < std::chrono::milliseconds(100)) return;
    last_ = now;
    drawn_ = true;
    fraction = std::clamp(fraction, 0.0, 1.0);
    constexpr int width = 30;
    int filled = static_cast<int>(fraction * width);
    double elapsed = std::chrono::duration<double>(now - start_).count();
    std::fprintf(stderr, "\r%s [%.*s%*s] %5.1f%% %6.1fs", label_.c_str(), filled,
                 "==============================", width - filled, "", 100 * fraction, elapsed);
    std::fflush(stderr);
}

void ProgressBar::done() {
    if (!enabled_ || !drawn_) return;
    update(1.0);
    std::fputc('\n', stderr);
    drawn_ = false;
    enabled_ = false;
}

}  // namespace rayset
