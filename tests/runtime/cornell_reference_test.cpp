// The shipped Cornell box rendered at 64x64 (direct light, CPU) against a stored reference,
// within a tolerance: small changes of the tree or of sampling move a few pixels a little,
// a broken camera, normal, material or light changes many pixels a lot.
//
// Regenerate the reference (after checking the new image by eye) from the repository root:
//   build/bin/kdpm-build-geometry scenes/cornell-box/cornell-box.json -o /tmp/cb.kdg
//   build/bin/kdpm-render /tmp/cb.kdg --mode direct --width 64 --height 64 --backend cpu
//       -o tests/data/cornell_box_direct_64.png   (one command line)
#include <catch2/catch.hpp>

#include <cmath>

#include <OpenImageIO/imageio.h>

#include "tests/support/run_command.h"
#include "tests/support/temp_dir.h"

using namespace kdpm;

namespace {

std::vector<float> read_rgb(const std::string& path, int& w, int& h) {
    auto in = OIIO::ImageInput::open(path);
    REQUIRE(in);
    w = in->spec().width;
    h = in->spec().height;
    REQUIRE(in->spec().nchannels == 3);
    std::vector<float> px(static_cast<std::size_t>(w) * h * 3);
    REQUIRE(in->read_image(0, 0, 0, 3, OIIO::TypeDesc::FLOAT, px.data()));
    return px;
}

}  // namespace

TEST_CASE("the Cornell box at 64x64 matches the stored reference image", "[render][reference]") {
    test::TempDir dir;
    auto kdg = dir / "cb.kdg", png = dir / "cb.png";
    auto b = test::run_tool("kdpm-build-geometry " + test::source_path("scenes/cornell-box/cornell-box.json") +
                            " -o " + kdg.string() + " --quiet");
    INFO(b.output);
    REQUIRE(b.exit_code == 0);
    auto r = test::run_tool("kdpm-render " + kdg.string() + " --mode direct --width 64 --height 64 --backend cpu -o " +
                            png.string() + " --quiet");
    INFO(r.output);
    REQUIRE(r.exit_code == 0);

    int w = 0, h = 0, rw = 0, rh = 0;
    auto got = read_rgb(png.string(), w, h);
    auto ref = read_rgb(test::source_path("tests/data/cornell_box_direct_64.png"), rw, rh);
    REQUIRE(w == rw);
    REQUIRE(h == rh);
    double sum = 0;
    std::size_t far_off = 0;
    for (std::size_t i = 0; i < got.size(); ++i) {
        const double d = std::fabs(got[i] - ref[i]);
        sum += d;
        far_off += d > 0.1;
    }
    const double mean = sum / static_cast<double>(got.size());
    INFO("mean difference " << mean << ", values off by more than 0.1: " << far_off);
    CHECK(mean < 0.01);
    CHECK(far_off < got.size() / 100);
}
