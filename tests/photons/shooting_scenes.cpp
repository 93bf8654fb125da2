#include "tests/photons/shooting_scenes.h"

#include "builders/geometry/geometry_file_builder.h"

namespace kdpm::test {
namespace {

MaterialRecord diffuse(float rho) {
    MaterialRecord m{};
    m.kind = static_cast<std::uint32_t>(MaterialKind::diffuse);
    m.diffuse[0] = m.diffuse[1] = m.diffuse[2] = rho;
    return m;
}

void add_quad(Scene& s, const float (&a)[3], const float (&b)[3], const float (&c)[3], const float (&d)[3],
              std::uint32_t material) {
    s.triangles.push_back(make_triangle(a, b, c, material, static_cast<std::uint32_t>(s.triangles.size())));
    s.triangles.push_back(make_triangle(a, c, d, material, static_cast<std::uint32_t>(s.triangles.size())));
}

GeometryFile file_of(const Scene& scene) {
    auto build = build_geometry_file(scene, KdBuildParams{});
    auto bytes = build.writer.bytes();
    return GeometryFile::from_bytes(bytes, "scene.kdg");
}

}  // namespace

namespace {

Scene box_scene(float rho, bool mirror_floor) {
    Scene s;
    s.materials.push_back(diffuse(rho));
    MaterialRecord mirror{};
    mirror.kind = static_cast<std::uint32_t>(MaterialKind::mirror);
    mirror.specular[0] = mirror.specular[1] = mirror.specular[2] = 1.0f;
    s.materials.push_back(mirror);
    const float p[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 0, 1}, {0, 1, 0}, {1, 1, 0}, {1, 1, 1}, {0, 1, 1}};
    add_quad(s, p[0], p[1], p[2], p[3], mirror_floor ? 1 : 0);  // floor
    add_quad(s, p[4], p[7], p[6], p[5], 0);                      // ceiling
    add_quad(s, p[0], p[4], p[5], p[1], 0);                      // z = 0
    add_quad(s, p[3], p[2], p[6], p[7], 0);                      // z = 1
    add_quad(s, p[0], p[3], p[7], p[4], 0);                      // x = 0
    add_quad(s, p[1], p[5], p[6], p[2], 0);                      // x = 1
    return s;
}

}  // namespace

GeometryFile closed_box(float rho, bool mirror_floor) {
    Scene s = box_scene(rho, mirror_floor);
    const float l0[3] = {0.4f, 0.9f, 0.4f}, e1[3] = {0.2f, 0, 0}, e2[3] = {0, 0, 0.2f}, radiance[3] = {10, 5, 2};
    s.lights.push_back(make_parallelogram_light(l0, e1, e2, radiance));
    return file_of(s);
}

GeometryFile closed_box_two_lights(float rho) {
    Scene s = box_scene(rho, false);
    const float a0[3] = {0.15f, 0.9f, 0.4f}, a1[3] = {0.2f, 0, 0}, a2[3] = {0, 0, 0.2f}, white[3] = {1, 1, 1};
    const float b0[3] = {0.7f, 0.1f, 0.45f}, b1[3] = {0, 0, 0.1f}, b2[3] = {0.1f, 0, 0}, bright[3] = {12, 12, 12};
    s.lights.push_back(make_parallelogram_light(a0, a1, a2, white));
    s.lights.push_back(make_parallelogram_light(b0, b1, b2, bright));
    return file_of(s);
}

GeometryFile closed_box_with_glass_cube(float rho) {
    Scene s = box_scene(rho, true);
    MaterialRecord glass{};
    glass.kind = static_cast<std::uint32_t>(MaterialKind::glass);
    glass.ior = 1.5f;
    glass.transmission[0] = glass.transmission[1] = glass.transmission[2] = 1.0f;
    const auto material = static_cast<std::uint32_t>(s.materials.size());
    s.materials.push_back(glass);
    // Clear of the floor: no coplanar faces, whose ties two intersectors may break differently.
    const float lo = 0.35f, hi = 0.65f, bottom = 0.05f, top = 0.35f;
    const float p[8][3] = {{lo, bottom, lo}, {hi, bottom, lo}, {hi, bottom, hi}, {lo, bottom, hi},
                           {lo, top, lo},    {hi, top, lo},    {hi, top, hi},    {lo, top, hi}};
    add_quad(s, p[0], p[3], p[2], p[1], material);  // bottom
    add_quad(s, p[4], p[5], p[6], p[7], material);  // top
    add_quad(s, p[0], p[1], p[5], p[4], material);
    add_quad(s, p[3], p[7], p[6], p[2], material);
    add_quad(s, p[0], p[4], p[7], p[3], material);
    add_quad(s, p[1], p[2], p[6], p[5], material);
    const float l0[3] = {0.4f, 0.9f, 0.4f}, e1[3] = {0.2f, 0, 0}, e2[3] = {0, 0, 0.2f}, radiance[3] = {10, 5, 2};
    s.lights.push_back(make_parallelogram_light(l0, e1, e2, radiance));
    return file_of(s);
}

GeometryFile floor_under_small_light(float h) {
    Scene s;
    s.materials.push_back(diffuse(0.0f));
    const float a[3] = {-1000, 0, -1000}, b[3] = {1000, 0, -1000}, c[3] = {1000, 0, 1000}, d[3] = {-1000, 0, 1000};
    add_quad(s, a, b, c, d, 0);
    const float l0[3] = {-0.005f, h, -0.005f}, e1[3] = {0.01f, 0, 0}, e2[3] = {0, 0, 0.01f}, radiance[3] = {1, 1, 1};
    s.lights.push_back(make_parallelogram_light(l0, e1, e2, radiance));
    return file_of(s);
}

}  // namespace kdpm::test
