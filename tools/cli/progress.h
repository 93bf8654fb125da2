#pragma once
// A progress bar on stderr for long work. Draws only when stderr is a terminal and the tool
// was not given --quiet; safe to update from several threads; redraws at most ~10 times a second.
#include <atomic>
#include <chrono>
#include <mutex>
#include <string>

namespace kdpm::cli {

class Progress {
public:
    Progress(std::string label, bool quiet);
    ~Progress();
    void update(double fraction);  // 0..1
    void finish();
    bool enabled() const { return enabled_; }

private:
    void draw(double fraction);
    std::string label_;
    bool enabled_;
    bool finished_ = false;
    std::mutex mutex_;
    std::chrono::steady_clock::time_point last_draw_{};
    std::chrono::steady_clock::time_point start_;
};

// True when messages meant for a person should be printed (a terminal and not --quiet).
bool interactive(bool quiet);

}  // namespace kdpm::cli
