#pragma once
// Embree 3, a peer for kdpm-bench only (never linked by the toolchain or runtime): its
// BVH builds (high and medium quality), rtcIntersect1 and rtcIntersect16 packets over the same
// triangles and rays as kdpm.
#include <cstdint>
#include <memory>
#include <span>

namespace kdpm::bench {

struct PeerRay {
    float origin[3];
    float direction[3];
};

struct PeerHit {
    float t;                  // +inf for a miss
    std::uint32_t triangle;   // index into the triangle list, 0xffffffff for a miss
};

enum class EmbreeBuildQuality { medium, high };

class EmbreePeer {
public:
    // vertices: 9 floats per triangle (v0, v1, v2). threads: Embree's worker count.
    EmbreePeer(std::span<const float> triangle_vertices, int threads);
    ~EmbreePeer();
    // Builds (again) with RTC_BUILD_QUALITY_HIGH or _MEDIUM and returns the time.
    double build_ms(EmbreeBuildQuality quality = EmbreeBuildQuality::high);
    // Traces one ray per element with rtcIntersect1 through the last build, in parallel over
    // `threads` (oneTBB).
    void intersect(std::span<const PeerRay> rays, std::span<PeerHit> hits) const;
    // The same with rtcIntersect16: rays are a width x height image in row-major order, traced
    // as one coherent 16-ray packet per 4x4 pixel tile (edge tiles masked), tiles in parallel.
    void intersect16(std::span<const PeerRay> rays, std::uint32_t width, std::uint32_t height,
                     std::span<PeerHit> hits) const;

private:
    struct State;
    std::unique_ptr<State> state_;
};

bool embree_available();

}  // namespace kdpm::bench
