#include "tools/bench/peer_embree_photons.h"

#include <embree3/rtcore.h>

#include <stdexcept>
#include <string>

#include "runtime/geometry/ray.h"
#include "runtime/photons/shoot_on_cpu.h"

namespace kdpm::bench {
namespace {

// rtcIntersect1 as trace_photon_path's closest-hit query. Embree's primID indexes the triangles
// in g's order and its u, v weight v1 and v2, as kdpm's Hit does.
struct EmbreeClosestHit {
    RTCScene scene = nullptr;

    Hit operator()(const GeometryView&, const Ray& ray) const {
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        RTCRayHit rh{};
        rh.ray.org_x = ray.origin.x;
        rh.ray.org_y = ray.origin.y;
        rh.ray.org_z = ray.origin.z;
        rh.ray.dir_x = ray.direction.x;
        rh.ray.dir_y = ray.direction.y;
        rh.ray.dir_z = ray.direction.z;
        rh.ray.tnear = ray.tmin;
        rh.ray.tfar = ray.tmax;
        rh.ray.mask = ~0u;
        rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
        rtcIntersect1(scene, &context, &rh);
        if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return miss(ray.tmax);
        return Hit{rh.ray.tfar, rh.hit.primID, rh.hit.u, rh.hit.v};
    }
};

void attach_triangles(RTCDevice device, RTCScene scene, const GeometryView& g) {
    const std::size_t tris = g.triangle_count;
    RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* vb = static_cast<float*>(
        rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), tris * 3));
    auto* ib = static_cast<unsigned*>(
        rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), tris));
    // The corners as kdpm's intersection test sees them: v0, v0 + e1, v0 + e2.
    for (std::size_t t = 0; t < tris; ++t) {
        const TriangleRecord& r = g.triangles[t];
        for (int a = 0; a < 3; ++a) {
            vb[9 * t + a] = r.v0[a];
            vb[9 * t + 3 + a] = r.v0[a] + r.e1[a];
            vb[9 * t + 6 + a] = r.v0[a] + r.e2[a];
        }
        for (int c = 0; c < 3; ++c) ib[3 * t + c] = static_cast<unsigned>(3 * t + c);
    }
    rtcSetGeometryBuildQuality(geom, RTC_BUILD_QUALITY_HIGH);
    rtcCommitGeometry(geom);
    rtcAttachGeometry(scene, geom);
    rtcReleaseGeometry(geom);
}

}  // namespace

struct EmbreePhotonTracer::State {
    GeometryView geometry;
    RTCDevice device = nullptr;
    RTCScene scene = nullptr;

    ~State() {
        if (scene) rtcReleaseScene(scene);
        if (device) rtcReleaseDevice(device);
    }
};

EmbreePhotonTracer::EmbreePhotonTracer(const GeometryView& g, int threads) : state_(std::make_unique<State>()) {
    state_->geometry = g;
    const std::string config = "threads=" + std::to_string(threads);
    state_->device = rtcNewDevice(config.c_str());
    if (!state_->device) throw std::runtime_error("Embree: cannot create a device");
    state_->scene = rtcNewScene(state_->device);
    rtcSetSceneBuildQuality(state_->scene, RTC_BUILD_QUALITY_HIGH);
    if (g.triangle_count > 0) attach_triangles(state_->device, state_->scene, g);  // else every ray misses
    rtcCommitScene(state_->scene);
    if (rtcGetDeviceError(state_->device) != RTC_ERROR_NONE) throw std::runtime_error("Embree: the BVH build failed");
}

EmbreePhotonTracer::~EmbreePhotonTracer() = default;

ShotPhotons EmbreePhotonTracer::shoot(const ShootOptions& options) const {
    return shoot_photons_on_cpu(state_->geometry, options, EmbreeClosestHit{state_->scene}, {}, PathOrder::depth_first);
}

}  // namespace kdpm::bench
