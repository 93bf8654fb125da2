#pragma once
// Wall-clock time of each stage of a frame, in milliseconds, and the table the tools print
// (same rows as the report's: ray tracing, photon gather, shading, post-processing, total).
#include <chrono>
#include <cstdint>
#include <string>

namespace kdpm {

struct StageTimes {
    double ray_tracing_ms = 0;
    double photon_gather_ms = 0;
    double shading_ms = 0;
    double post_ms = 0;
    double transfer_ms = 0;  // frame buffer allocation and copies (CUDA: to and from the device)
    // Final gathering with the irradiance cache: records made in this frame (points that sent
    // gather rays), diffuse points shaded from the cache, and records kept from earlier frames
    // (RenderSettings::keep_irradiance_cache); 0 without the cache.
    std::uint64_t cache_records = 0, cache_points = 0, cache_records_kept = 0;
    double total_ms() const { return ray_tracing_ms + photon_gather_ms + shading_ms + post_ms + transfer_ms; }
};

// Rows "stage  ms" including load time (0 or negative: row left out) and the total.
std::string format_stage_table(const StageTimes& t, double load_ms);

class StopWatch {
public:
    StopWatch() : start_(std::chrono::steady_clock::now()) {}
    // Milliseconds since construction or the last lap.
    double lap_ms() {
        auto now = std::chrono::steady_clock::now();
        double ms = std::chrono::duration<double, std::milli>(now - start_).count();
        start_ = now;
        return ms;
    }

private:
    std::chrono::steady_clock::time_point start_;
};

}  // namespace kdpm
