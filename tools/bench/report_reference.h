#pragma once
// The report's timing table ("Global Illumination Effects", 2010; GTX 275, 512x512, 262,144
// photons, up to 4 bounces, about 675,000 stored): printed beside kdpm's own figures.
#include <array>
#include <optional>
#include <string_view>

namespace kdpm::bench {

inline constexpr std::array<int, 8> kReportK{2, 4, 8, 16, 32, 64, 128, 256};

struct ReportFigures {
    double ray_tracing_ms;
    std::array<double, 8> ray_tracing_and_gather_ms;  // for kReportK
};

// The report measured Sponza (76k triangles) and the Conference room (282k); none for others.
inline std::optional<ReportFigures> report_figures(std::string_view scene) {
    if (scene == "sponza") return ReportFigures{26, {33, 36, 47, 67, 121, 264, 634, 1541}};
    if (scene == "conference") return ReportFigures{26, {50, 54, 68, 107, 197, 399, 856, 1977}};
    return std::nullopt;
}

}  // namespace kdpm::bench
