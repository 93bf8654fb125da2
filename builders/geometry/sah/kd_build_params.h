#pragma once
// Parameters of the SAH geometry kd-tree build (Wald & Havran 2006), with the defaults used by
// kdpm-build-geometry. All of them are recorded in the file's metadata.
#include <cstdint>
#include <optional>
#include <string_view>

namespace kdpm {

// high: the exact O(N log N) sweep with perfect splits in every node.
// fast: binned SAH (Shevtsov et al. 2007; Hunt et al. 2006) in nodes of at least `exact_below`
// triangles, binned in parallel inside the node; the exact sweep below that size, where nodes of
// fewer than `clip_below` triangles hand a triangle that crosses the split plane to both children
// with its bounds (as the nodes above clipped them) cut at the plane instead of clipping the
// triangle. Binned nodes always clip.
enum class KdBuildQuality : std::uint8_t { high, fast };

std::string_view quality_name(KdBuildQuality q);
std::optional<KdBuildQuality> parse_quality(std::string_view name);

struct KdBuildParams {
    float traversal_cost = 1.0f;     // K_T: cost of stepping through one inner node
    float intersection_cost = 1.0f;  // K_I: cost of one ray/triangle test (four are tested at once)
    float empty_bonus = 0.2f;        // split cost is scaled by (1 - bonus) when one side is empty
    int max_depth = 0;               // 0: automatic, 8 + 1.3 log2(N), capped below kMaxKdTreeDepth
    int leaf_size = 0;               // nodes with at most this many triangles become leaves unsplit
    KdBuildQuality quality = KdBuildQuality::high;
    std::uint32_t exact_below = 4096;  // fast: nodes with fewer triangles use the exact sweep
    std::uint32_t clip_below = 12;     // fast: exact-sweep nodes with fewer triangles cut boxes, not triangles
};

// Nodes of at most this many triangles (four SIMD groups of a leaf test) stop splitting at the
// small-node depth; in a fast build, nodes of at most kFastSmallLeafTriangles (eight groups).
inline constexpr std::uint32_t kSmallLeafTriangles = 16;
inline constexpr std::uint32_t kFastSmallLeafTriangles = 32;

// The depth limits a build of `triangles` triangles uses. Automatically, 8 + 1.3 log2(triangles)
// for every node, and 4 + log2(triangles) for nodes of at most kSmallLeafTriangles: below it the
// sweep still finds splits it rates cheaper, but trees with them trace no faster and have many
// more nodes (README). A fast build stops two levels sooner, 2 + log2(triangles), for nodes of
// at most kFastSmallLeafTriangles: fewer nodes again for a little more SAH cost (README). An
// explicit max_depth is a plain limit for every node.
struct KdDepthLimits {
    std::uint32_t max_depth;        // no node at this depth (or deeper) is split
    std::uint32_t small_depth;      // nor one of at most small_triangles triangles from this depth on
    std::uint32_t small_triangles;  // what counts as a small node
    static KdDepthLimits of(const KdBuildParams& params, std::uint64_t triangles);
    // Whether a node of n triangles at `depth` may be split.
    bool may_split(std::uint32_t depth, std::uint64_t n) const {
        return depth < max_depth && (depth < small_depth || n > small_triangles);
    }
};

}  // namespace kdpm
