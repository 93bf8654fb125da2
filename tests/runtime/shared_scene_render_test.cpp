// The real scenes through the whole pipeline at a small size (skipped without ../shared/scenes):
// both lighting modes must agree on the overall brightness, since they split the same light
// differently (all from photons, or direct by shadow rays + indirect and caustics from photons).
#include <catch2/catch.hpp>

#include <filesystem>

#include <OpenImageIO/imageio.h>

#include "tests/support/run_command.h"
#include "tests/support/temp_dir.h"

using namespace kdpm;

namespace {

double mean_radiance(const std::string& exr) {
    auto in = OIIO::ImageInput::open(exr);
    REQUIRE(in);
    const auto& spec = in->spec();
    std::vector<float> px(static_cast<std::size_t>(spec.width) * spec.height * spec.nchannels);
    REQUIRE(in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, px.data()));
    double sum = 0;
    for (std::size_t i = 0; i < px.size(); i += static_cast<std::size_t>(spec.nchannels))
        sum += px[i] + px[i + 1] + px[i + 2];
    return sum / (3.0 * spec.width * spec.height);
}

void render_both_modes(const std::string& card) {
    test::TempDir dir;
    const std::string kdg = (dir / "s.kdg").string(), kdph = (dir / "s.kdph").string(), kdp = (dir / "s.kdp").string();
    auto run = [](const std::string& command) {
        auto r = test::run_tool(command);
        INFO(command << "\n" << r.output);
        REQUIRE(r.exit_code == 0);
    };
    run("kdpm-build-geometry " + test::source_path(card) + " -o " + kdg + " --quiet");
    run("kdpm-shoot-photons " + kdg + " -o " + kdph + " --photons 60000 --quiet");
    run("kdpm-build-photons " + kdph + " -o " + kdp + " --quiet");
    double mean[2];
    const char* modes[2] = {"photons", "direct+photons"};
    for (int m = 0; m < 2; ++m) {
        const std::string exr = (dir / (std::string("m") + std::to_string(m) + ".exr")).string();
        run("kdpm-render " + kdg + " " + kdp + " --mode " + modes[m] + " --width 48 --light-samples 4 --backend cpu -o " +
            exr + " --quiet");
        mean[m] = mean_radiance(exr);
    }
    INFO(card << ": mean radiance photons " << mean[0] << ", direct+photons " << mean[1]);
    CHECK(mean[0] > 0.0);
    CHECK(mean[0] == Approx(mean[1]).epsilon(0.1));
}

}  // namespace

TEST_CASE("Sponza renders with the same brightness in both lighting modes", "[render][shared]") {
    if (test::shared_scenes_dir().empty()) {
        WARN("../shared/scenes not found (set KDPM_SCENES): skipped");
        return;
    }
    render_both_modes("scenes/sponza/sponza.json");
}

TEST_CASE("Conference renders with the same brightness in both lighting modes", "[render][shared]") {
    if (test::shared_scenes_dir().empty()) {
        WARN("../shared/scenes not found (set KDPM_SCENES): skipped");
        return;
    }
    render_both_modes("scenes/conference/conference.json");
}
