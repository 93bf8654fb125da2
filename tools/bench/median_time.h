#pragma once
// Median wall time of repeated runs: robust against the noise of a shared machine.
#include <algorithm>
#include <chrono>
#include <cstddef>
#include <utility>
#include <vector>

namespace kdpm::bench {

template <class F>
double median_ms(int repetitions, F&& run) {
    std::vector<double> times;
    for (int i = 0; i < std::max(1, repetitions); ++i) {
        auto start = std::chrono::steady_clock::now();
        run();
        times.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
    }
    std::sort(times.begin(), times.end());
    return times[times.size() / 2];
}

inline double median_of(std::vector<double> v) {
    if (v.empty()) return 0.0;
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

// A ratio of two stages timed in pairs (each of our passes right beside the peer's): the median
// of the per-pair ratios. The host's speed drifts by tens of percent within a run; a pair sees one
// speed, so its ratio cancels the drift, where the ratio of the two medians can take a slow stretch
// that fell on more of one side's passes than the other's. Pairs with a time <= 0 are skipped;
// 0 when none is left.
inline double median_ratio(const std::vector<double>& ours, const std::vector<double>& peer) {
    std::vector<double> ratios;
    for (std::size_t i = 0; i < ours.size() && i < peer.size(); ++i)
        if (ours[i] > 0.0 && peer[i] > 0.0) ratios.push_back(ours[i] / peer[i]);
    return median_of(std::move(ratios));
}

// Two stages timed in pairs: each side's median time, and their ratio as median_ratio gives it
// (what the verdicts read). A stage timed without its peer has only ours_ms.
struct PairedTimes {
    double ours_ms = 0, peer_ms = 0;
    double ratio = 0;  // 0: no pair was timed
};

inline PairedTimes paired_times(const std::vector<double>& ours, const std::vector<double>& peer) {
    return {median_of(ours), median_of(peer), median_ratio(ours, peer)};
}

}  // namespace kdpm::bench
