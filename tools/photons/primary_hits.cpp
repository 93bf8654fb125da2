#include "tools/photons/primary_hits.h"

#include <cmath>

#include <glm/geometric.hpp>

#include "runtime/backend/cpu_parallel_for.h"
#include "runtime/geometry/kd_traversal.h"
#include "runtime/shading/constants.h"

namespace kdpm::photon_tools {

std::vector<SurfacePoint> primary_hits(const GeometryFile& geometry, std::uint32_t width, std::uint32_t height) {
    const CameraRecord& cam = geometry.camera();
    const glm::vec3 eye(cam.eye[0], cam.eye[1], cam.eye[2]);
    const glm::vec3 forward = glm::normalize(glm::vec3(cam.lookat[0], cam.lookat[1], cam.lookat[2]) - eye);
    const glm::vec3 right = glm::normalize(glm::cross(forward, glm::vec3(cam.up[0], cam.up[1], cam.up[2])));
    const glm::vec3 up = glm::cross(right, forward);
    const float tan_half = std::tan(0.5f * cam.vfov_degrees * kPi / 180.0f);
    const float aspect = static_cast<float>(width) / static_cast<float>(height);
    const GeometryView& g = geometry.view();

    std::vector<SurfacePoint> pixels(static_cast<std::size_t>(width) * height);
    std::vector<std::uint8_t> hit(pixels.size(), 0);
    cpu_parallel_for(pixels.size(), [&](std::uint64_t i) {
        const float px = (2.0f * ((i % width) + 0.5f) / width - 1.0f) * aspect * tan_half;
        const float py = (1.0f - 2.0f * ((i / width) + 0.5f) / height) * tan_half;
        const glm::vec3 dir = glm::normalize(forward + px * right + py * up);
        const Ray ray{eye, 0.0f, dir, 3.402823466e38f};
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
