#include "tools/photons/primary_hits.h"

#include "runtime/backend/cpu_parallel_for.h"
#include "runtime/geometry/scene_traversal.h"
#include "runtime/render/camera.h"

namespace kdpm::photon_tools {

std::vector<SurfacePoint> primary_hits(const GeometryFile& geometry, std::uint32_t width, std::uint32_t height) {
    const PinholeCamera camera = PinholeCamera::from_record(geometry.camera(), width, height, 1);
    const GeometryView& g = geometry.view();

    std::vector<SurfacePoint> pixels(static_cast<std::size_t>(width) * height);
    std::vector<std::uint8_t> hit(pixels.size(), 0);
    cpu_parallel_for(pixels.size(), [&](std::uint64_t i) {
        const CameraRay c = camera.ray(static_cast<std::uint32_t>(i % width), static_cast<std::uint32_t>(i / width), 0);
        const Ray ray{c.origin, 0.0f, c.direction, 3.402823466e38f};
        const Hit h = closest_hit(g, ray);
        if (!h.found()) return;
        pixels[i] = surface_at(g, ray, h);
        hit[i] = 1;
    });
    std::vector<SurfacePoint> out;
    for (std::size_t i = 0; i < pixels.size(); ++i)
        if (hit[i]) out.push_back(pixels[i]);
    return out;
}

}  // namespace kdpm::photon_tools
