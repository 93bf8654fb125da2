// The shipped textured scene (scenes/textured-quad): a quad filling the frame whose map_Kd is a
// red/green checker of 4x4 squares (16x16 texels) repeated twice each way. Rendered with direct
// light and with the path tracer, every one of the 8x8 squares shows the colour of its square
// of the texture, the texture's top-left square in the image's top-left corner; pixels wider
// than the texels read coarser mip levels; photons bounce off the texture's colour.
#include <catch2/catch.hpp>

#include <cmath>

#include "builders/geometry/geometry_file_builder.h"
#include "builders/geometry/scene_card.h"
#include "runtime/geometry/geometry_file.h"
#include "runtime/photons/photon_shooter.h"
#include "runtime/render/renderer.h"
#include "tests/support/run_command.h"

using namespace kdpm;

namespace {

// Red where the square's column plus its row counted from the top of checker.ppm is even.
bool red_square(std::uint32_t square_x, std::uint32_t square_y) { return (square_x + square_y) % 2 == 0; }

void check_checker(const Image& image, std::uint32_t size) {
    const std::uint32_t square = size / 8;
    std::uint32_t right = 0;
    for (std::uint32_t sy = 0; sy < 8; ++sy)
        for (std::uint32_t sx = 0; sx < 8; ++sx) {
            const std::uint32_t px = sx * square + square / 2, py = sy * square + square / 2;  // row 0 on top
            const float* rgb = &image.rgb[(std::size_t{py} * size + px) * 3];
            INFO("square " << sx << ", " << sy << ": " << rgb[0] << " " << rgb[1] << " " << rgb[2]);
            CHECK(rgb[0] + rgb[1] > 0.01f);  // lit
            CHECK(rgb[2] == 0.0f);           // neither texel colour has blue
            // A sample anywhere in the pixel reads texels of its square only.
            const bool red = rgb[0] > 0.0f && rgb[1] == 0.0f, green = rgb[1] > 0.0f && rgb[0] == 0.0f;
            CHECK((red_square(sx, sy) ? red : green));
            right += red_square(sx, sy) ? red : green;
        }
    CHECK(right == 64);
}

// The shipped textured quad built into a .kdg in memory, with its scene and file kept alive for
// the views the renderer reads.
struct BuiltTexturedQuad {
    Scene scene = load_scene_input(test::source_path("scenes/textured-quad/textured-quad.json"));
    GeometryFile file = GeometryFile::from_bytes(build_geometry_file(scene, KdBuildParams{}).writer.bytes(),
                                                 "textured-quad.kdg");
    SceneViews views() const {
        SceneViews v;
        v.geometry = file.view();
        v.camera = file.camera();
        return v;
    }
};

}  // namespace

TEST_CASE("the textured quad renders its checker in direct light and in the path tracer", "[texture][render]") {
    const BuiltTexturedQuad quad;
    REQUIRE(quad.scene.warnings.empty());
    REQUIRE(quad.scene.textures.size() == 1);
    Renderer renderer(quad.views(), BackendKind::cpu);
    const std::uint32_t size = 64;
    RenderSettings settings;
    settings.width = settings.height = size;
    settings.mode = RenderMode::direct;
    settings.light_samples = 4;
    check_checker(renderer.render(settings).linear, size);
    settings.mode = RenderMode::path;
    settings.spp = 4;
    check_checker(renderer.render(settings).linear, size);
}

TEST_CASE("camera rays filter the texture over their pixel: a checker finer than the pixels averages out", "[texture][render]") {
    const BuiltTexturedQuad quad;
    Renderer renderer(quad.views(), BackendKind::cpu);
    // 3 x 3 pixels over 32 x 32 texels (8 x 8 squares): each pixel covers 10.7 x 10.7 texels, so
    // it reads mip levels 3 and 4, which are uniform (0.5, 0.5, 0) (a level-3 texel averages
    // 2 x 2 squares); level 0 at the pixel centres would read one square's colour.
    RenderSettings settings;
    settings.width = settings.height = 3;
    settings.mode = RenderMode::direct;
    const Image image = renderer.render(settings).linear;
    for (std::size_t p = 0; p < 9; ++p) {
        const float r = image.rgb[p * 3], g = image.rgb[p * 3 + 1];
        INFO("pixel " << p << ": " << r << " " << g);
        CHECK(r > 0.01f);
        CHECK(std::fabs(r - g) < 1e-3f * (r + g));
    }
}

TEST_CASE("photons bounce off the texture's colour", "[texture][photons]") {
    // The textured quad (red and green texels, no blue) under a white ceiling above its light:
    // every photon that reaches the ceiling bounced off the quad, so it carries no blue power
    // (with the material's grey Kd it would).
    Scene scene = load_scene_input(test::source_path("scenes/textured-quad/textured-quad.json"));
    REQUIRE(scene.textures.size() == 1);
    MaterialRecord white{};
    for (float& c : white.diffuse) c = 0.8f;
    white.ior = 1.0f;
    scene.materials.push_back(white);
    const auto ceiling_material = static_cast<std::uint32_t>(scene.materials.size() - 1);
    const float z = 1.5f, a[3] = {-5, -5, z}, b[3] = {6, -5, z}, c[3] = {6, 6, z}, d[3] = {-5, 6, z};
    // Facing down, onto the quad.
    scene.triangles.push_back(make_triangle(a, c, b, ceiling_material, static_cast<std::uint32_t>(scene.triangles.size())));
    scene.triangles.push_back(make_triangle(a, d, c, ceiling_material, static_cast<std::uint32_t>(scene.triangles.size())));
    scene.uvs.resize(scene.triangles.size());
    if (!scene.normals.empty()) scene.normals.resize(scene.triangles.size());
    GeometryBuild build = build_geometry_file(scene, KdBuildParams{});
    const GeometryFile file = GeometryFile::from_bytes(build.writer.bytes(), "textured-room.kdg");
    ShootOptions options;
    options.photons = 16384;
    options.max_bounces = 1;
    const ShotPhotons shot = shoot_photons(file.view(), options);
    std::uint32_t on_ceiling = 0, reddish = 0, greenish = 0;
    for (const PhotonHit& h : shot.hits) {
        if (h.position[2] < 1.0f) continue;
        ++on_ceiling;
        CHECK(h.power[2] == 0.0f);
        reddish += h.power[0] > h.power[1];
        greenish += h.power[1] > h.power[0];
    }
    CHECK(on_ceiling > 200);
    // Half the quad is red, half green.
    CHECK(reddish > on_ceiling / 3);
    CHECK(greenish > on_ceiling / 3);
}
