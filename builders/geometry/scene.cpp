#include "builders/geometry/scene.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "formats/math_constants.h"
#include "formats/format_error.h"
#include "formats/triangle_clip.h"

namespace kdpm {

namespace {

void cross(const float (&a)[3], const float (&b)[3], float (&out)[3]) {
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
}

float length(const float (&a)[3]) { return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]); }

}  // namespace

TriangleRecord make_triangle(const float (&a)[3], const float (&b)[3], const float (&c)[3], std::uint32_t material,
                             std::uint32_t source_index) {
    TriangleRecord t{};
    for (int i = 0; i < 3; ++i) {
        t.v0[i] = a[i];
        t.e1[i] = b[i] - a[i];
        t.e2[i] = c[i] - a[i];
    }
    t.material = material;
    t.source_index = source_index;
    return t;
}

AreaLightRecord make_parallelogram_light(const float (&p0)[3], const float (&e1)[3], const float (&e2)[3],
                                         const float (&radiance)[3]) {
    AreaLightRecord l{};
    float n[3];
    cross(e1, e2, n);
    for (int i = 0; i < 3; ++i) l.p0[i] = p0[i], l.e1[i] = e1[i], l.e2[i] = e2[i], l.radiance[i] = radiance[i];
    l.shape = static_cast<std::uint32_t>(LightShape::parallelogram);
    l.triangle = 0xffffffffu;
    l.area = length(n);
    l.power = kPi * l.area * (radiance[0] + radiance[1] + radiance[2]) / 3.0f;
    return l;
}

void add_emissive_triangle_lights(Scene& scene) {
    for (std::uint32_t i = 0; i < scene.triangles.size(); ++i) {
        const TriangleRecord& t = scene.triangles[i];
        if (t.material >= scene.materials.size() || !triangle_is_usable(t)) continue;
        const float(&e)[3] = scene.materials[t.material].emission;
        if (!(e[0] > 0.0f || e[1] > 0.0f || e[2] > 0.0f)) continue;
        AreaLightRecord l{};
        float n[3];
        cross(t.e1, t.e2, n);
        for (int k = 0; k < 3; ++k) l.p0[k] = t.v0[k], l.e1[k] = t.e1[k], l.e2[k] = t.e2[k], l.radiance[k] = e[k];
        l.shape = static_cast<std::uint32_t>(LightShape::triangle);
        l.triangle = i;
        l.area = 0.5f * length(n);
        l.power = kPi * l.area * (e[0] + e[1] + e[2]) / 3.0f;
        scene.lights.push_back(l);
    }
}

void check_scene_extent(const Scene& scene) {
    for (const TriangleRecord& t : scene.triangles) {
        float v[3][3];
        triangle_vertices(t, v);
        for (const auto& p : v)
            for (float x : p)
                if (std::isfinite(x) && std::fabs(x) > kMaxSceneCoordinate) {
                    char text[160];
                    std::snprintf(text, sizeof text,
                                  "the scene reaches coordinate %g, beyond %g where surface areas overflow a float: "
                                  "scale it down", x, kMaxSceneCoordinate);
                    throw FormatError(text);
                }
    }
}

void frame_camera(Scene& scene) {
    float lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    bool any = false;
    for (const TriangleRecord& t : scene.triangles) {
        if (!triangle_is_usable(t)) continue;
        float v[3][3];
        triangle_vertices(t, v);
        for (auto& p : v)
            for (int a = 0; a < 3; ++a) lo[a] = std::min(lo[a], p[a]), hi[a] = std::max(hi[a], p[a]);
        any = true;
    }
    if (!any)
        for (int a = 0; a < 3; ++a) lo[a] = -1.0f, hi[a] = 1.0f;
    frame_camera_on(scene, lo, hi);
}

void frame_camera_on(Scene& scene, const float (&lo)[3], const float (&hi)[3]) {
    float center[3], radius = 0.0f;
    for (int a = 0; a < 3; ++a) {
        center[a] = 0.5f * (lo[a] + hi[a]);
        radius += (hi[a] - lo[a]) * (hi[a] - lo[a]);
    }
    radius = std::max(0.5f * std::sqrt(radius), 1e-3f);
    const float vfov = 45.0f;
    const float distance = radius / std::sin(0.5f * vfov * kPi / 180.0f);
    // Look at the front: along -z for y up, along +y for z up, along -z for x up.
    float back[3] = {0, 0, 1};
    if (scene.up_axis == 2) back[0] = 0, back[1] = -1, back[2] = 0;
    CameraRecord& c = scene.camera;
    for (int a = 0; a < 3; ++a) {
        c.eye[a] = center[a] + distance * back[a];
        c.lookat[a] = center[a];
        c.up[a] = a == static_cast<int>(scene.up_axis) ? 1.0f : 0.0f;
    }
    c.vfov_degrees = vfov;
    if (c.width == 0) c.width = 512;
    if (c.height == 0) c.height = 512;
    scene.has_camera = true;
}

}  // namespace kdpm
