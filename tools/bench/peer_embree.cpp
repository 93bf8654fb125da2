#include "tools/bench/peer_embree.h"

#include <embree3/rtcore.h>

#include <chrono>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "runtime/backend/cpu_parallel_for.h"

namespace kdpm::bench {

struct EmbreePeer::State {
    RTCDevice device = nullptr;
    RTCScene scene = nullptr;
    std::vector<float> vertices;
};

bool embree_available() { return true; }

EmbreePeer::EmbreePeer(std::span<const float> triangle_vertices, int threads) : state_(std::make_unique<State>()) {
    std::string config = "threads=" + std::to_string(threads);
    state_->device = rtcNewDevice(config.c_str());
    if (!state_->device) throw std::runtime_error("Embree: cannot create a device");
    state_->vertices.assign(triangle_vertices.begin(), triangle_vertices.end());
}

EmbreePeer::~EmbreePeer() {
    if (state_->scene) rtcReleaseScene(state_->scene);
    if (state_->device) rtcReleaseDevice(state_->device);
}

double EmbreePeer::build_ms(EmbreeBuildQuality quality) {
    const RTCBuildQuality q = quality == EmbreeBuildQuality::high ? RTC_BUILD_QUALITY_HIGH : RTC_BUILD_QUALITY_MEDIUM;
    if (state_->scene) rtcReleaseScene(state_->scene);
    const std::size_t tris = state_->vertices.size() / 9;
    auto start = std::chrono::steady_clock::now();
    RTCScene scene = rtcNewScene(state_->device);
    rtcSetSceneBuildQuality(scene, q);
    RTCGeometry geom = rtcNewGeometry(state_->device, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* vb = static_cast<float*>(
        rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), tris * 3));
    auto* ib = static_cast<unsigned*>(
        rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), tris));
    for (std::size_t i = 0; i < tris * 9; ++i) vb[i] = state_->vertices[i];
    for (std::size_t i = 0; i < tris * 3; ++i) ib[i] = static_cast<unsigned>(i);
    rtcSetGeometryBuildQuality(geom, q);
    rtcCommitGeometry(geom);
    rtcAttachGeometry(scene, geom);
    rtcReleaseGeometry(geom);
    rtcCommitScene(scene);
    auto end = std::chrono::steady_clock::now();
    state_->scene = scene;
    return std::chrono::duration<double, std::milli>(end - start).count();
}

void EmbreePeer::intersect(std::span<const PeerRay> rays, std::span<PeerHit> hits) const {
    RTCScene scene = state_->scene;
    cpu_parallel_for(rays.size(), [&](std::uint64_t i) {
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        RTCRayHit rh{};
        const PeerRay& r = rays[i];
        rh.ray.org_x = r.origin[0];
        rh.ray.org_y = r.origin[1];
        rh.ray.org_z = r.origin[2];
        rh.ray.dir_x = r.direction[0];
        rh.ray.dir_y = r.direction[1];
        rh.ray.dir_z = r.direction[2];
        rh.ray.tnear = 0.0f;
        rh.ray.tfar = std::numeric_limits<float>::infinity();
        rh.ray.mask = ~0u;
        rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
        rtcIntersect1(scene, &context, &rh);
        hits[i] = rh.hit.geomID == RTC_INVALID_GEOMETRY_ID
                      ? PeerHit{std::numeric_limits<float>::infinity(), 0xffffffffu}
                      : PeerHit{rh.ray.tfar, rh.hit.primID};
    }, 256);
}

void EmbreePeer::intersect16(std::span<const PeerRay> rays, std::uint32_t width, std::uint32_t height,
                             std::span<PeerHit> hits) const {
    constexpr std::uint32_t kSide = 4;  // 4x4 pixels per packet
    RTCScene scene = state_->scene;
    const std::uint32_t tiles_x = (width + kSide - 1) / kSide, tiles_y = (height + kSide - 1) / kSide;
    cpu_parallel_for(static_cast<std::uint64_t>(tiles_x) * tiles_y, [&](std::uint64_t tile) {
        const std::uint32_t x0 = static_cast<std::uint32_t>(tile % tiles_x) * kSide;
        const std::uint32_t y0 = static_cast<std::uint32_t>(tile / tiles_x) * kSide;
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
        alignas(64) RTCRayHit16 rh{};  // RTCRay16 needs 64-byte alignment
        alignas(64) int valid[16];
        std::size_t pixel[16];
        for (std::uint32_t j = 0; j < 16; ++j) {
            const std::uint32_t x = x0 + j % kSide, y = y0 + j / kSide;
            valid[j] = x < width && y < height ? -1 : 0;
            pixel[j] = valid[j] ? static_cast<std::size_t>(y) * width + x : 0;
            const PeerRay& r = rays[pixel[j]];
            rh.ray.org_x[j] = r.origin[0];
            rh.ray.org_y[j] = r.origin[1];
            rh.ray.org_z[j] = r.origin[2];
            rh.ray.dir_x[j] = r.direction[0];
            rh.ray.dir_y[j] = r.direction[1];
            rh.ray.dir_z[j] = r.direction[2];
            rh.ray.tnear[j] = 0.0f;
            rh.ray.tfar[j] = std::numeric_limits<float>::infinity();
            rh.ray.mask[j] = ~0u;
            rh.hit.geomID[j] = RTC_INVALID_GEOMETRY_ID;
        }
        rtcIntersect16(valid, scene, &context, &rh);
        for (std::uint32_t j = 0; j < 16; ++j) {
            if (!valid[j]) continue;
            hits[pixel[j]] = rh.hit.geomID[j] == RTC_INVALID_GEOMETRY_ID
                                 ? PeerHit{std::numeric_limits<float>::infinity(), 0xffffffffu}
                                 : PeerHit{rh.ray.tfar[j], rh.hit.primID[j]};
        }
    }, 16);
}

}  // namespace kdpm::bench
