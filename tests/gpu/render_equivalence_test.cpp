// Frames of every mode on both backends, from the same scene and photon map. Tolerance, stated:
// the mean absolute difference at most 1e-4 of the mean value, and at least 99.9% of the values
// within 1e-3 of their own size (plus 1e-6 of the mean). Intersection, traversal and the photon
// search agree bit for bit (--fmad=false), so what remains is the last-place rounding of
// transcendental functions (host glibc vs. CUDA libdevice), which can flip a grazing shadow ray.
// The first-hit AOVs (depth, triangle) must be identical, and so must the density view.
#include <catch2/catch.hpp>

#include <cmath>

#include "runtime/render/renderer.h"
#include "tests/gpu/gpu_scenes.h"

using namespace kdpm;

namespace {

struct Difference {
    double mean_abs = 0, max_abs = 0, mean_value = 0, within = 0;  // within: fraction inside tolerance
};

Difference compare(const std::vector<float>& expected, const std::vector<float>& got) {
    Difference d;
    REQUIRE(expected.size() == got.size());
    REQUIRE(!expected.empty());
    for (float v : expected) d.mean_value += std::fabs(v);
    d.mean_value /= static_cast<double>(expected.size());
    std::size_t ok = 0;
    for (std::size_t i = 0; i < expected.size(); ++i) {
        const double diff = std::fabs(static_cast<double>(got[i]) - expected[i]);
        d.mean_abs += diff;
        d.max_abs = std::max(d.max_abs, diff);
        ok += diff <= 1e-3 * std::fabs(expected[i]) + 1e-6 * d.mean_value;
    }
    d.mean_abs /= static_cast<double>(expected.size());
    d.within = static_cast<double>(ok) / static_cast<double>(expected.size());
    return d;
}

RenderSettings settings_for(RenderMode mode, std::uint32_t w, std::uint32_t h) {
    RenderSettings s;
    s.mode = mode;
    s.width = w;
    s.height = h;
    s.light_samples = 4;
    s.aovs.depth = s.aovs.triangle = s.aovs.normal = s.aovs.position = true;
    return s;
}

// For modes whose rays may take another branch on the device (cosf/sinf differ in the last place
// between glibc and libdevice): the images agree in the mean (0.5 %) and on a share `within` of
// their values; the first hits, and their depths where `same_depth`, agree exactly.
void check_agree_in_the_mean(const RenderResult& expected, const RenderResult& got, double within, bool same_depth) {
    const Difference d = compare(expected.linear.rgb, got.linear.rgb);
    double mean_got = 0;
    for (float v : got.linear.rgb) mean_got += std::fabs(v);
    mean_got /= static_cast<double>(got.linear.rgb.size());
    INFO("mean value " << d.mean_value << " (CUDA " << mean_got << "), mean |diff| " << d.mean_abs
                       << ", within tolerance " << d.within * 100 << "%");
    CHECK(d.mean_value > 0.0);
    CHECK(mean_got == Approx(d.mean_value).epsilon(0.005));
    CHECK(d.within >= within);
    CHECK(got.aovs.triangle == expected.aovs.triangle);
    if (same_depth) CHECK(got.aovs.depth == expected.aovs.depth);
}

}  // namespace

TEST_CASE("CUDA renders every mode like the CPU, within the stated tolerance", "[gpu][render]") {
    auto scene = test::build_gpu_test_scene("cornell-box", 100000);
    Renderer cpu(scene.views, BackendKind::cpu);
    Renderer cuda(scene.views, BackendKind::cuda);
    for (RenderMode mode : {RenderMode::photons, RenderMode::direct_photons, RenderMode::direct}) {
        INFO("mode " << render_mode_name(mode));
        const RenderSettings s = settings_for(mode, 96, 80);
        const RenderResult expected = cpu.render(s);
        const RenderResult got = cuda.render(s);
        const Difference d = compare(expected.linear.rgb, got.linear.rgb);
        INFO("mean value " << d.mean_value << ", mean |diff| " << d.mean_abs << ", max |diff| " << d.max_abs
                           << ", within tolerance " << d.within * 100 << "%");
        CHECK(d.mean_value > 0.0);
        CHECK(d.mean_abs <= 1e-4 * d.mean_value);
        CHECK(d.within >= 0.999);
        CHECK(got.aovs.triangle == expected.aovs.triangle);
        CHECK(got.aovs.depth == expected.aovs.depth);
    }
}

TEST_CASE("CUDA frames repeat exactly across sizes (the frame arrays are reused)", "[gpu][render]") {
    auto scene = test::build_gpu_test_scene("cornell-box", 50000);
    Renderer cuda(scene.views, BackendKind::cuda);
    const RenderSettings small = settings_for(RenderMode::direct_photons, 64, 48);
    const RenderResult first = cuda.render(small);
    const RenderResult larger = cuda.render(settings_for(RenderMode::direct_photons, 160, 120));
    const RenderResult again = cuda.render(small);
    CHECK(larger.linear.width == 160);
    CHECK(larger.linear.height == 120);
    CHECK(again.linear.rgb == first.linear.rgb);
    CHECK(again.aovs.triangle == first.aovs.triangle);
}

TEST_CASE("the photon density view gives the same densities on CUDA as on the CPU", "[gpu][density]") {
    auto scene = test::build_gpu_test_scene("cornell-box", 50000);
    Renderer cpu(scene.views, BackendKind::cpu);
    Renderer cuda(scene.views, BackendKind::cuda);
    const RenderResult frame = cpu.render(settings_for(RenderMode::direct, 64, 64));
    for (std::uint32_t k : {1u, 32u, 256u}) {
        INFO("k = " << k);
        const std::vector<float> expected = cpu.photon_density(frame.aovs.position, frame.aovs.normal, k);
        const std::vector<float> got = cuda.photon_density(frame.aovs.position, frame.aovs.normal, k);
        REQUIRE(expected.size() == 64u * 64u);
        double total = 0;
        for (float v : expected) total += v;
        CHECK(total > 0.0);
        CHECK(got == expected);
    }
}

// A path continues from every bounce, so one flipped grazing decision changes the rest of its
// path, not one shadow ray: the images agree in the mean (0.5%) and on most values, not to 1e-4.
TEST_CASE("CUDA path-traces like the CPU, within the path tracer's tolerance", "[gpu][render][path]") {
    auto scene = test::build_gpu_test_scene("cornell-box", 1000);
    Renderer cpu(scene.views, BackendKind::cpu);
    Renderer cuda(scene.views, BackendKind::cuda);
    RenderSettings s = settings_for(RenderMode::path, 96, 80);
    s.spp = 4;
    const RenderResult expected = cpu.render(s);
    const RenderResult got = cuda.render(s);
    check_agree_in_the_mean(expected, got, 0.95, true);
}

// SPPM shoots its photons on the device each pass; their directions use cosf/sinf, which may
// differ in the last place between glibc and CUDA (photon_shooter.h), so a few photons land
// elsewhere: the images agree in the mean and on most values, as the path tracer's do.
TEST_CASE("CUDA renders progressive photon mapping like the CPU", "[gpu][render][sppm]") {
    auto scene = test::build_gpu_test_scene("cornell-box", 1000);
    Renderer cpu(scene.views, BackendKind::cpu);
    Renderer cuda(scene.views, BackendKind::cuda);
    RenderSettings s = settings_for(RenderMode::sppm, 96, 80);
    s.passes = 8;
    s.photons_per_pass = 50000;
    const RenderResult expected = cpu.render(s);
    const RenderResult got = cuda.render(s);
    check_agree_in_the_mean(expected, got, 0.9, true);
}

// Gather rays leave in cosine-distributed directions (cosf/sinf, last-place differences between
// glibc and libdevice), so, like paths, a few of them may go elsewhere: the path tracer's tolerance.
TEST_CASE("CUDA final-gathers like the CPU, with the precomputed irradiance and without",
          "[gpu][render][final-gather]") {
    auto scene = test::build_gpu_test_scene("cornell-box", 50000);
    REQUIRE(scene.views.photons.irradiance.present());
    SceneViews without = scene.views;
    without.photons.irradiance = IrradianceMapView{};
    for (const SceneViews* views : {&scene.views, &without}) {
        INFO((views == &without ? "without" : "with") << " the precomputed irradiance");
        Renderer cpu(*views, BackendKind::cpu);
        Renderer cuda(*views, BackendKind::cuda);
        RenderSettings s = settings_for(RenderMode::final_gather, 96, 80);
        s.gather_rays = 8;
        s.irradiance_cache = false;  // the cache runs on the CPU backend only
        const RenderResult expected = cpu.render(s);
        const RenderResult got = cuda.render(s);
        check_agree_in_the_mean(expected, got, 0.95, false);
    }
}

// The textured quad (its checker read by OpenImageIO, or by kdpm's PPM reader in the bundle):
// texture lookups, mip levels from the camera footprint and the textured photon bounces run on
// the device from the uploaded texture sections.
TEST_CASE("CUDA renders the textured quad like the CPU, in every mode", "[gpu][render][texture]") {
    auto scene = test::build_gpu_test_scene("textured-quad", 20000);
    REQUIRE(scene.views.geometry.texture_count == 1);
    Renderer cpu(scene.views, BackendKind::cpu);
    Renderer cuda(scene.views, BackendKind::cuda);
    for (std::uint32_t size : {64u, 3u}) {  // 3 x 3: pixels wider than the texels read coarser levels
        for (RenderMode mode : {RenderMode::photons, RenderMode::direct_photons, RenderMode::direct}) {
            INFO("mode " << render_mode_name(mode) << ", " << size << " pixels");
            const RenderSettings s = settings_for(mode, size, size);
            const Difference d = compare(cpu.render(s).linear.rgb, cuda.render(s).linear.rgb);
            INFO("mean value " << d.mean_value << ", mean |diff| " << d.mean_abs << ", within " << d.within * 100 << "%");
            CHECK(d.mean_value > 0.0);
            CHECK(d.mean_abs <= 1e-4 * d.mean_value);
            CHECK(d.within >= 0.999);
        }
    }
}
