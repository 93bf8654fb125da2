// kdpm-render's photon estimate options end to end: --filter cone, --disc F and --gather radius
// reach the gather kernel (the image changes) and, on the Cornell box's flat walls, estimate the
// same radiance as the default (k nearest, box filter, sphere); bad values give an error.
#include <catch2/catch.hpp>

#include <filesystem>
#include <string>
#include <vector>

#include <OpenImageIO/imageio.h>

#include "tests/support/run_command.h"
#include "tests/support/temp_dir.h"

using namespace kdpm;

namespace {

std::vector<float> read_rgb(const std::filesystem::path& p) {
    auto in = OIIO::ImageInput::open(p.string());
    REQUIRE(in);
    const OIIO::ImageSpec spec = in->spec();
    std::vector<float> px(static_cast<std::size_t>(spec.width) * spec.height * 3);
    REQUIRE(in->read_image(0, 0, 0, 3, OIIO::TypeDesc::FLOAT, px.data()));
    return px;
}

double mean(const std::vector<float>& v) {
    double s = 0.0;
    for (float x : v) s += x;
    return s / static_cast<double>(v.size());
}

}  // namespace

TEST_CASE("kdpm-render's cone filter, disc search and fixed radius change the photon estimate but not its mean", "[render][tools]") {
    test::TempDir dir;
    const std::string kdg = (dir / "scene.kdg").string(), kdph = (dir / "scene.kdph").string(),
                      kdp = (dir / "scene.kdp").string();
    for (const std::string& step :
         {"kdpm-build-geometry " + test::source_path("scenes/cornell-box/cornell-box.json") + " -o " + kdg + " --quiet",
          "kdpm-shoot-photons " + kdg + " -n 50000 -o " + kdph, "kdpm-build-photons " + kdph + " -o " + kdp}) {
        auto r = test::run_tool(step);
        INFO(step << "\n" << r.output);
        REQUIRE(r.exit_code == 0);
    }
    auto render = [&](const std::string& name, const std::string& options) {
        const auto out = dir / (name + ".exr");
        auto r = test::run_tool("kdpm-render " + kdg + " " + kdp + " --mode photons --width 24 --height 24 --k 64 " +
                                "--backend cpu --quiet " + options + " -o " + out.string());
        INFO(options << "\n" << r.output);
        REQUIRE(r.exit_code == 0);
        return read_rgb(out);
    };
    const auto box = render("box", ""), cone = render("cone", "--filter cone"), disc = render("disc", "--disc 8"),
               radius = render("radius", "--gather radius");
    CHECK(render("box_named", "--filter box --gather knn") == box);
    CHECK(cone != box);
    CHECK(disc != box);
    CHECK(radius != box);
    CHECK(mean(cone) == Approx(mean(box)).epsilon(0.1));
    CHECK(mean(disc) == Approx(mean(box)).epsilon(0.1));
    CHECK(mean(radius) == Approx(mean(box)).epsilon(0.1));

    for (const std::string bad : {"--filter gauss", "--disc -1", "--gather all", "--gather radius --max-radius 0"}) {
        auto r = test::run_tool("kdpm-render " + kdg + " " + kdp + " --backend cpu " + bad + " -o " +
                                (dir / "bad.png").string());
        INFO(bad << "\n" << r.output);
        CHECK(r.exit_code != 0);
        CHECK(r.output.find("error") != std::string::npos);
        CHECK_FALSE(std::filesystem::exists(dir / "bad.png"));
    }
}
