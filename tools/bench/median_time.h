#pragma once
// Median wall time of repeated runs: robust against the noise of a shared machine.
#include <algorithm>
#include <chrono>
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

}  // namespace kdpm::bench
