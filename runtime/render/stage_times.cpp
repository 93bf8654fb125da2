#include "runtime/render/stage_times.h"

#include <cstdio>

namespace kdpm {

namespace {
void row(std::string& out, const char* name, double ms) {
    char line[64];
    std::snprintf(line, sizeof line, "  %-16s %10.2f\n", name, ms);
    out += line;
}
}  // namespace

std::string format_stage_table(const StageTimes& t, double load_ms) {
    std::string out = "  stage                    ms\n";
    if (load_ms > 0) row(out, "load", load_ms);
    row(out, "ray tracing", t.ray_tracing_ms);
    row(out, "photon gather", t.photon_gather_ms);
    row(out, "shading", t.shading_ms);
    row(out, "post", t.post_ms);
    if (t.transfer_ms > 0) row(out, "buffers+copies", t.transfer_ms);
    row(out, "total (frame)", t.total_ms());
    if (t.cache_points > 0) {
        char line[128];
        std::snprintf(line, sizeof line, "  irradiance cache: gather rays at %llu records for %llu diffuse points\n",
                      static_cast<unsigned long long>(t.cache_records), static_cast<unsigned long long>(t.cache_points));
        out += line;
        if (t.cache_records_kept > 0) {
            std::snprintf(line, sizeof line, "  irradiance cache: %llu records kept from earlier frames\n",
                          static_cast<unsigned long long>(t.cache_records_kept));
            out += line;
        }
    }
    return out;
}

}  // namespace kdpm
