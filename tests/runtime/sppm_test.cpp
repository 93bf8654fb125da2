// Progressive photon mapping (--mode sppm) against the path-traced reference on the Cornell box:
// the direct part alone, the bounce limit, the mean radiance, and the relative error falling
// as passes grow; and the tool's refusal of bad pass counts.
#include <catch2/catch.hpp>

#include <algorithm>
#include <string>

#include "runtime/render/renderer.h"
#include "runtime/render/scene_loader.h"
#include "tests/runtime/image_stats.h"
#include "tests/support/run_command.h"
#include "tests/support/temp_dir.h"

using namespace kdpm;
using kdpm::test::mean_of;
using kdpm::test::relative_mse;

namespace {

// The Cornell box's .kdg, built by the tool (no photon map: sppm shoots its own photons).
struct CornellBox {
    test::TempDir dir;
    std::string kdg = (dir / "cb.kdg").string();
    CornellBox() {
        auto r = test::run_tool("kdpm-build-geometry " + test::source_path("scenes/cornell-box/cornell-box.json") +
                                " -o " + kdg + " --quiet");
        INFO(r.output);
        REQUIRE(r.exit_code == 0);
    }
};

RenderSettings small_frame(RenderMode mode) {
    RenderSettings s;
    s.mode = mode;
    s.width = s.height = 32;
    s.light_samples = 4;
    return s;
}

}  // namespace

TEST_CASE("SPPM on the Cornell box converges to the path-traced reference", "[render][sppm][cornell]") {
    CornellBox box;
    LoadedScene scene = LoadedScene::load(box.kdg, std::nullopt);
    Renderer renderer(scene.views(), BackendKind::cpu);
    auto sppm = [&](std::uint32_t passes, std::uint32_t max_bounces) {
        RenderSettings s = small_frame(RenderMode::sppm);
        s.passes = passes;
        s.max_bounces = max_bounces;
        s.photons_per_pass = 4096;
        return renderer.render(s).linear;
    };
    // Equal camera samples where means are compared: the jitter is a function of (pixel, sample)
    // alone, so both modes see the same rays and the bright emitter's edges do not differ.
    auto path = [&](std::uint32_t spp, std::uint32_t max_bounces) {
        RenderSettings s = small_frame(RenderMode::path);
        s.spp = spp;
        s.max_bounces = max_bounces;
        return renderer.render(s).linear;
    };
    auto direct = [&](std::uint32_t spp) {
        RenderSettings s = small_frame(RenderMode::direct);
        s.spp = spp;
        return renderer.render(s).linear;
    };

    SECTION("one bounce is the direct light: no photon is gathered") {
        const double s1 = mean_of(sppm(16, 1)), d = mean_of(direct(16));
        INFO("sppm, one bounce " << s1 << "; direct " << d);
        CHECK(s1 == Approx(d).epsilon(0.005));
    }

    SECTION("the photons add the indirect light of the path tracer with the same bounce limit") {
        const double d = mean_of(direct(64));
        for (std::uint32_t bounces : {2u, 0u}) {
            const double s = mean_of(sppm(64, bounces)), p = mean_of(path(64, bounces));
            INFO("max bounces " << bounces << ": sppm " << s << ", path " << p << ", direct " << d);
            CHECK(s == Approx(p).epsilon(0.015));
            CHECK(s - d == Approx(p - d).epsilon(0.08));  // the indirect part alone
            CHECK(s > d * 1.1);
        }
    }

    SECTION("the relative error against a converged reference falls as passes grow") {
        const Image reference = path(1024, 0);
        double previous = 1e30;
        for (std::uint32_t passes : {4u, 16u, 64u}) {
            const double error = relative_mse(sppm(passes, 0), reference);
            INFO(passes << " passes: relMSE " << error << " (previous " << previous << ")");
            CHECK(error < previous * 0.7);
            previous = error;
        }
        CHECK(previous < 0.05);
    }
}

TEST_CASE("kdpm-render refuses bad sppm options in one line", "[render][sppm][cli]") {
    CornellBox box;
    const std::string out = " --backend cpu -o " + (box.dir / "s.png").string();
    for (const std::string options :
         {"--mode sppm --passes 0", "--mode sppm --passes -3", "--mode sppm --passes many", "--mode sppm --passes",
          "--mode path --passes 4", "--mode sppm --photons-per-pass 0", "--mode sppm --sppm-radius -1",
          "--mode sppm --photons-per-pass 2147483647"}) {
        auto r = test::run_tool("kdpm-render " + box.kdg + " " + options + out);
        INFO(options << "\n" << r.output);
        CHECK(r.exit_code != 0);
        CHECK(std::count(r.output.begin(), r.output.end(), '\n') == 1);
        CHECK(!std::filesystem::exists(box.dir / "s.png"));
    }
    auto ok = test::run_tool("kdpm-render " + box.kdg + " --mode sppm --passes 2 --width 8 --height 8 --quiet" + out);
    INFO(ok.output);
    CHECK(ok.exit_code == 0);
    CHECK(ok.output.empty());
    CHECK(std::filesystem::exists(box.dir / "s.png"));
}
