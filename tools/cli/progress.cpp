#include "tools/cli/progress.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>

namespace kdpm::cli {

bool interactive(bool quiet) { return !quiet && ::isatty(STDERR_FILENO); }

Progress::Progress(std::string label, bool quiet)
    : label_(std::move(label)), enabled_(interactive(quiet)), start_(std::chrono::steady_clock::now()) {}

Progress::~Progress() { finish(); }

void Progress::update(double fraction) {
    if (!enabled_) return;
    auto now = std::chrono::steady_clock::now();
    std::unique_lock lock(mutex_, std::try_to_lock);
    if (!lock.owns_lock() || finished_) return;
    if (now - last_draw_ < std::chrono::milliseconds(100)) return;
    last_draw_ = now;
    draw(fraction);
}

void Progress::draw(double fraction) {
    fraction = std::clamp(fraction, 0.0, 1.0);
    constexpr int width = 30;
    int filled = static_cast<int>(fraction * width);
    double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    std::fprintf(stderr, "\r%s [%.*s%*s] %3d%% %.1fs", label_.c_str(), filled, "==============================",
                 width - filled, "", static_cast<int>(fraction * 100), secs);
    std::fflush(stderr);
}

void Progress::finish() {
    if (!enabled_) return;
    std::lock_guard lock(mutex_);
    if (finished_) return;
    finished_ = true;
    draw(1.0);
    std::fputc('\n', stderr);
}

}  // namespace kdpm::cli
