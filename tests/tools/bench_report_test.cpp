// kdpm-bench's report: each target is checked where its figures are, with the verdict the issue
// states: the report's k = 32 frame for every scene the report measured, and the paired ratios
// (median_ratio) rather than the quotient of the medians beside them.
#include <catch2/catch.hpp>

#include <string>

#include "tools/bench/bench_report.h"

using namespace kdpm::bench;

namespace {

SceneBenchResult with_k32_frame(const std::string& scene, double ms) {
    SceneBenchResult r;
    r.name = scene;
    FrameTable f;
    f.label = "2 threads";
    f.ray_tracing_ms = 20.0;
    f.with_gather_ms[32] = ms;
    r.frames.push_back(f);
    return r;
}

}  // namespace

TEST_CASE("kdpm-bench checks the report's k=32 frame on Sponza and on the Conference room", "[tools][bench]") {
    const std::string conference_missed = format_report({with_k32_frame("conference", 200.0)}, true);
    CHECK_THAT(conference_missed,
               Catch::Contains("- ray tracing + k=32 gather, 2 threads: 200.0 ms (target <= 197 ms, the report's GPU): MISSED"));
    const std::string conference_met = format_report({with_k32_frame("conference", 190.0)}, true);
    CHECK_THAT(conference_met,
               Catch::Contains("- ray tracing + k=32 gather, 2 threads: 190.0 ms (target <= 197 ms, the report's GPU): met"));
    const std::string sponza = format_report({with_k32_frame("sponza", 150.0)}, true);
    CHECK_THAT(sponza, Catch::Contains("150.0 ms (target <= 121 ms, the report's GPU): MISSED"));
    // The report has no figures for the Cornell box: no target line.
    CHECK_THAT(format_report({with_k32_frame("cornell-box", 150.0)}, true), !Catch::Contains("the report's GPU"));
}

TEST_CASE("kdpm-bench's ratio column and verdicts read the paired ratios", "[tools][bench]") {
    SceneBenchResult r = with_k32_frame("cornell-box", 100.0);
    PeerFigures& p = r.peers;
    p.embree = true;
    // Medians 30 / 20 ms (1.50x), but the pairs' own ratios have the median 0.95x.
    p.rays = {30.0, 20.0, 0.95};
    // A row whose pairs were not measured shows no verdict.
    p.shoot = {10.0, 10.0, 0.0};
    r.quality.rays = {11.0, 10.0, 1.08};
    const std::string out = format_report({r}, true);
    CHECK_THAT(out, Catch::Contains("| 30.0 | 20.0 | 0.95x | <= 1 | met |"));
    CHECK_THAT(out, Catch::Contains("| photon shooting, kdpm / Embree photon tracer | 10.0 | 10.0 | - | <= 1.5 | - |"));
    CHECK_THAT(out, Catch::Contains("| 11.0 | 10.0 | 1.08x | <= 1.05 | MISSED |"));
    CHECK_THAT(out, Catch::Contains("the median of the ratios of passes run in pairs"));
}

TEST_CASE("kdpm-bench shows CUDA's frames and shot beside the CPU's only where a device measured them", "[tools][bench]") {
    SceneBenchResult r = with_k32_frame("sponza", 100.0);
    r.shoot_ms[2] = 150.0;
    ModeFrames& m = r.mode_frames;
    m.width = m.height = 512;
    m.threads = 2;
    m.viewer_threads = 2;
    m.viewer_frame_ms = 125.0;
    m.rows.push_back({"photons", "k=32", 130.0, 0.0, 1});
    m.rows.push_back({"sppm", "4 passes", 800.0, 0.0, 4});
    const std::string cpu_only = format_report({r}, true);
    CHECK_THAT(cpu_only, !Catch::Contains("CUDA"));
    CHECK_THAT(cpu_only, Catch::Contains("| photons | k=32 | 130.0 | 7.69 |  |"));
    CHECK_THAT(cpu_only, !Catch::Contains("viewer refinement"));  // not measured
    m.refinement_resumed_ms = 1000.0;
    m.refinement_fresh_ms = 1900.0;
    CHECK_THAT(format_report({r}, true),
               Catch::Contains("- viewer refinement to 8 spp once the camera stops (photons, k=32), 2 threads: 1000 ms "
                               "with each step resumed and folded in, 1900 ms with a fresh render per step (0.53x)"));

    r.shoot_cuda_ms = 12.5;
    m.rows[0].cuda_frame_ms = 4.0;
    m.rows[1].cuda_frame_ms = 40.0;
    m.viewer_cuda_frame_ms = 8.0;
    const std::string both = format_report({r}, true);
    CHECK_THAT(both, Catch::Contains("| photon shooting, CUDA (ms) | 12.5 |"));
    CHECK_THAT(both, Catch::Contains("| CUDA frame (ms) | CUDA frames/s | CUDA per pass (ms) |"));
    CHECK_THAT(both, Catch::Contains("| photons | k=32 | 130.0 | 7.69 |  | 4.00 | 250.00 |  |"));
    // The per-pass column divides by the passes on each backend.
    CHECK_THAT(both, Catch::Contains("| sppm | 4 passes | 800.0 | 1.25 | 200.0 | 40.0 | 25.00 | 10.0 |"));
    CHECK_THAT(both, Catch::Contains("- viewer frame, rendered on CUDA (composed on the CPU): 8.0 ms, 125.0 frames/s"));
    // The two-core target stays the CPU's.
    CHECK_THAT(both, Catch::Contains("2 threads: 125.0 ms, 8.0 frames/s (target >= 8 frames/s): met"));

    // A device that failed part way says why under the table.
    m.rows[1].cuda_frame_ms = 0.0;
    m.cuda_note = "CUDA frames stopped: CUDA kernel execution: out of memory";
    const std::string stopped = format_report({r}, true);
    CHECK_THAT(stopped, Catch::Contains("| sppm | 4 passes | 800.0 | 1.25 | 200.0 | - | - |  |"));
    CHECK_THAT(stopped, Catch::Contains("- CUDA frames stopped: CUDA kernel execution: out of memory"));
}

TEST_CASE("kdpm-bench's instance rows judge each ratio against its target", "[tools][bench][instances]") {
    SceneBenchResult r = with_k32_frame("sponza", 100.0);
    CHECK_THAT(format_report({r}, false), !Catch::Contains("instances of sponza"));  // not measured: no rows
    InstanceFigures& f = r.instances;
    f.measured = true;
    f.instances = 10000;
    f.placed_triangles = 10000ull * 66454;
    f.object_build_ms = 1000.0;
    f.scene_build_ms = 150.0;  // 1.15x the object's build alone
    f.object_bytes = 10000000, f.scene_bytes = 640000;
    f.one_as_is = {20.0, 20.1, 0.995};
    f.one_moved = {25.0, 20.0, 1.25};
    f.grid_inside = {39.0, 20.0, 1.95};
    f.grid_overview = {60.0, 20.0, 3.0};
    const std::string text = format_report({r}, false);
    auto line = [&](const std::string& label) {  // the row's line, its columns one space apart
        const std::size_t at = text.find(label);
        if (at == std::string::npos) return std::string("absent");
        std::string l = text.substr(at, text.find('\n', at) - at), squeezed;
        for (char ch : l)
            if (ch != ' ' || squeezed.empty() || squeezed.back() != ' ') squeezed += ch;
        return squeezed;
    };
    CHECK(line("1 instance as it is") == "1 instance as it is 20.00 20.10 0.99x <= 1.02 met ");
    CHECK_THAT(line("1 instance moved"), Catch::EndsWith("1.25x <= 1.02 MISSED "));
    CHECK_THAT(line("10000 instances, camera"), Catch::EndsWith("1.95x <= 2.00 met "));
    CHECK_THAT(line("10000 instances seen whole"), Catch::EndsWith("3.00x <= 2.00 MISSED "));
    CHECK_THAT(text, Catch::Contains("1.150: MISSED"));
    CHECK_THAT(text, Catch::Contains("64.0"));  // scene bytes per instance
}
