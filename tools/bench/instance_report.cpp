#include "tools/bench/instance_bench.h"
#include "tools/bench/text_table.h"

namespace kdpm::bench {

std::string format_instance_figures(const std::string& scene, const InstanceFigures& f, bool md) {
    if (!f.measured) return "";
    auto row = [](std::string label, const PairedTimes& t, double target) -> std::vector<std::string> {
        const std::string r = t.ratio > 0 ? fmt("%.2fx", t.ratio) : "-";
        return {std::move(label), fmt("%.2f", t.ours_ms), fmt("%.2f", t.peer_ms), r, fmt("<= %.2f", target),
                t.ratio > 0 && t.ratio <= target ? "met" : "MISSED"};
    };
    Table t{{"instances of " + scene + ", primary rays, all threads (ms)", "scene", "object alone", "ratio", "target", "verdict"}, {}};
    t.rows.push_back(row("1 instance as it is", f.one_as_is, 1.00 * 1.02));
    t.rows.push_back(row(fmt("1 instance moved (%.4f same triangle)", f.moved_same_hits), f.one_moved, 1.00 * 1.02));
    t.rows.push_back(row(fmt("%llu instances, camera in the middle one", (unsigned long long)f.instances), f.grid_inside, 2.0));
    t.rows.push_back(row(fmt("%llu instances seen whole (framed camera)", (unsigned long long)f.instances), f.grid_overview, 2.0));
    Table o{{"instanced grid: files and build", "value"}, {}};
    o.rows.push_back({"instances / triangles placed", fmt("%llu / %.3g", (unsigned long long)f.instances, double(f.placed_triangles))});
    o.rows.push_back({"object .kdg bytes / scene .kdg bytes per instance",
                      fmt("%llu / %.1f", (unsigned long long)f.object_bytes, double(f.scene_bytes) / double(f.instances))});
    o.rows.push_back({"scene build from its card (ms)", fmt("%.1f", f.scene_build_ms)});
    if (f.object_build_ms > 0)
        o.rows.push_back({"object + scene build / object build (target <= 1.1)",
                          fmt("%.3f: %s", (f.object_build_ms + f.scene_build_ms) / f.object_build_ms,
                              f.object_build_ms + f.scene_build_ms <= 1.1 * f.object_build_ms ? "met" : "MISSED")});
    o.rows.push_back({"scene load: object, placements, BVH, lights (ms)", fmt("%.1f", f.load_ms)});
    o.rows.push_back({"run-time memory per instance (bytes)", fmt("%.0f", f.runtime_bytes_per_instance)});
    return t.render(md) + "(1.00x targets read met within 2 %, the pairs' noise)\n\n" + o.render(md);
}

}  // namespace kdpm::bench
