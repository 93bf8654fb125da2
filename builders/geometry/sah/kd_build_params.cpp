#include "builders/geometry/sah/kd_build_params.h"

#include <algorithm>
#include <cmath>

#include "formats/geometry_layout.h"

namespace kdpm {

KdDepthLimits KdDepthLimits::of(const KdBuildParams& params, std::uint64_t triangles) {
    const std::uint32_t cap = kMaxKdTreeDepth - 4;
    if (params.max_depth > 0) {
        const std::uint32_t limit = std::min<std::uint32_t>(static_cast<std::uint32_t>(params.max_depth), cap);
        return {limit, limit, kSmallLeafTriangles};
    }
    const double log2_n = std::log2(static_cast<double>(std::max<std::uint64_t>(triangles, 1)));
    const std::uint32_t limit = std::min<std::uint32_t>(static_cast<std::uint32_t>(std::lround(8.0 + 1.3 * log2_n)), cap);
    const bool fast = params.quality == KdBuildQuality::fast;
    const double small_base = fast ? 2.0 : 4.0;
    const std::uint32_t small = static_cast<std::uint32_t>(std::lround(small_base + log2_n));
    return {limit, std::min<std::uint32_t>(small, limit), fast ? kFastSmallLeafTriangles : kSmallLeafTriangles};
}

std::string_view quality_name(KdBuildQuality q) { return q == KdBuildQuality::fast ? "fast" : "high"; }

std::optional<KdBuildQuality> parse_quality(std::string_view name) {
    if (name == "high") return KdBuildQuality::high;
    if (name == "fast") return KdBuildQuality::fast;
    return std::nullopt;
}

}  // namespace kdpm
