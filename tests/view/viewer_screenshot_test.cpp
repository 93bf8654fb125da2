// kdpm-view end to end: under xvfb-run it renders the Cornell box for a few frames and saves a
// screenshot that must match kdpm-render's image for the same camera and settings. Skips (WARN)
// when xvfb-run is missing or no X server starts, or when the build has no scene tools.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include <OpenImageIO/imageio.h>

#include "tests/support/run_command.h"
#include "tests/support/temp_dir.h"

using namespace kdpm;
namespace fs = std::filesystem;

namespace {

// Under the asan preset, LeakSanitizer would fail the viewer for allocations that Mesa, X11 and
// GLFW keep until exit; the viewer's own parts are leak-checked by the unit tests.
const std::string kViewerEnv = "ASAN_OPTIONS=detect_leaks=0 ";

bool have_xvfb_run() { return test::run_shell("command -v xvfb-run").exit_code == 0; }

bool have_tools() {
    for (const char* t : {"kdpm-view", "kdpm-render", "kdpm-build-geometry", "kdpm-shoot-photons", "kdpm-build-photons"})
        if (!fs::exists(test::tool_path(t))) return false;
    return fs::exists(test::source_path("scenes/cornell-box/cornell-box.json"));
}

struct Pixels {
    int width = 0, height = 0;
    std::vector<float> rgb;
};

Pixels read_rgb(const fs::path& path) {
    Pixels p;
    auto in = OIIO::ImageInput::open(path.string());
    REQUIRE(in);
    const OIIO::ImageSpec& spec = in->spec();
    p.width = spec.width;
    p.height = spec.height;
    REQUIRE(spec.nchannels >= 3);
    std::vector<float> all(static_cast<std::size_t>(p.width) * p.height * spec.nchannels);
    REQUIRE(in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, all.data()));
    for (std::size_t i = 0; i < static_cast<std::size_t>(p.width) * p.height; ++i)
        for (int c = 0; c < 3; ++c) p.rgb.push_back(all[i * spec.nchannels + c]);
    return p;
}

double mean_abs_difference(const Pixels& a, const Pixels& b) {
    double sum = 0.0;
    for (std::size_t i = 0; i < a.rgb.size(); ++i) sum += std::fabs(a.rgb[i] - b.rgb[i]);
    return sum / static_cast<double>(a.rgb.size());
}

// Standard deviation of the values: a blank (or single-colour) image has none.
double spread(const Pixels& p) {
    double mean = 0.0, sq = 0.0;
    for (float v : p.rgb) mean += v;
    mean /= static_cast<double>(p.rgb.size());
    for (float v : p.rgb) sq += (v - mean) * (v - mean);
    return std::sqrt(sq / static_cast<double>(p.rgb.size()));
}

// Xvfb could not start (or no display could be opened): the environment, not the viewer.
bool display_unavailable(const test::CommandResult& r) {
    return r.output.find("no display available") != std::string::npos ||
           r.output.find("Xvfb failed to start") != std::string::npos ||
           r.output.find("cannot open an OpenGL") != std::string::npos;
}

}  // namespace

TEST_CASE("kdpm-view screenshot of the Cornell box matches kdpm-render", "[view][e2e]") {
    if (!have_tools()) {
        WARN("kdpm-view or the scene tools are not built, or scenes/cornell-box is missing: skipped");
        return;
    }
    if (!have_xvfb_run()) {
        WARN("xvfb-run not found (Debian package xvfb): skipped");
        return;
    }
    test::TempDir dir;
    const std::string kdg = (dir / "cornell.kdg").string(), kdph = (dir / "cornell.kdph").string(),
                      kdp = (dir / "cornell.kdp").string();
    auto r = test::run_tool("kdpm-build-geometry " + test::source_path("scenes/cornell-box/cornell-box.json") +
                            " -o " + kdg + " --quiet");
    REQUIRE(r.exit_code == 0);
    // Fewer photons than the card's 262,144 keep the test fast; the comparison does not care.
    r = test::run_tool("kdpm-shoot-photons " + kdg + " --photons 40000 -o " + kdph + " --quiet");
    REQUIRE(r.exit_code == 0);
    r = test::run_tool("kdpm-build-photons " + kdph + " -o " + kdp + " --quiet");
    REQUIRE(r.exit_code == 0);

    const std::string common = " --width 160 --height 160 --k 32 --backend cpu";
    const fs::path reference = dir / "render.png", screenshot = dir / "view.png";
    // The viewer's one sample per pixel is one sppm pass.
    for (const std::string mode : {"photons", "direct", "sppm"}) {
        INFO("mode " << mode);
        const std::string passes = mode == "sppm" ? " --passes 1" : "";
        r = test::run_tool("kdpm-render " + kdg + " " + kdp + common + " --mode " + mode + passes + " -o " +
                           reference.string() + " --quiet");
        REQUIRE(r.exit_code == 0);
        r = test::run_shell(kViewerEnv + "xvfb-run -a " + test::tool_path("kdpm-view") + " " + kdg + " " + kdp + common + " --mode " + mode +
                  " --frames 2 --spp 1 --screenshot " + screenshot.string() + " --quiet");
        if (r.exit_code != 0 && display_unavailable(r)) {
            WARN("no X server could be started under xvfb-run: skipped (" << r.output << ")");
            return;
        }
        INFO(r.output);
        REQUIRE(r.exit_code == 0);
        REQUIRE(fs::exists(screenshot));
        const Pixels view = read_rgb(screenshot), ref = read_rgb(reference);
        REQUIRE(view.width == 160);
        REQUIRE(view.height == 160);
        REQUIRE(ref.width == view.width);
        REQUIRE(ref.height == view.height);
        CHECK(spread(view) > 0.05);  // not blank
        // Same renderer, camera and post-processing: equal up to 8-bit rounding.
        CHECK(mean_abs_difference(view, ref) < 0.004);
        fs::remove(screenshot);
    }
    // Refinement to 4 samples: frames of 1, 1 and 2 new samples folded into the shown image give
    // kdpm-render's 4-sample image; a fourth frame, past the cap, renders all 4 afresh.
    for (const std::string frames : {"3", "4"}) {
        INFO("frames " << frames);
        r = test::run_tool("kdpm-render " + kdg + " " + kdp + common + " --mode photons --spp 4 -o " + reference.string() +
                           " --quiet");
        REQUIRE(r.exit_code == 0);
        r = test::run_shell(kViewerEnv + "xvfb-run -a " + test::tool_path("kdpm-view") + " " + kdg + " " + kdp + common +
                            " --mode photons --frames " + frames + " --spp 4 --screenshot " + screenshot.string() +
                            " --quiet");
        INFO(r.output);
        REQUIRE(r.exit_code == 0);
        const Pixels view = read_rgb(screenshot), ref = read_rgb(reference);
        REQUIRE(ref.width == view.width);
        CHECK(mean_abs_difference(view, ref) < 0.004);
        fs::remove(screenshot);
    }
}

TEST_CASE("kdpm-view --panel shows the control panel over the image, and only there", "[view][e2e][panel]") {
    if (!have_tools() || !have_xvfb_run()) {
        WARN("kdpm-view, the scene tools or xvfb-run are missing: skipped");
        return;
    }
    test::TempDir dir;
    const std::string kdg = (dir / "cornell.kdg").string();
    REQUIRE(test::run_tool("kdpm-build-geometry " + test::source_path("scenes/cornell-box/cornell-box.json") +
                           " -o " + kdg + " --quiet").exit_code == 0);
    const fs::path plain = dir / "plain.png", panel = dir / "panel.png";
    const std::string common = test::tool_path("kdpm-view") + " " + kdg +
                               " --width 480 --height 360 --mode direct --light-samples 2 --backend cpu --frames 1 --quiet";
    auto r = test::run_shell(kViewerEnv + "xvfb-run -a " + common + " --screenshot " + plain.string());
    if (r.exit_code != 0 && display_unavailable(r)) {
        WARN("no X server could be started under xvfb-run: skipped (" << r.output << ")");
        return;
    }
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
    r = test::run_shell(kViewerEnv + "xvfb-run -a " + common + " --panel --screenshot " + panel.string());
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
    const Pixels a = read_rgb(plain), b = read_rgb(panel);
    REQUIRE(a.width == 480);
    REQUIRE(b.width == a.width);
    REQUIRE(b.height == a.height);
    // Mean difference inside a box: the panel sits at the top left, the rest is the image.
    auto box_difference = [&](int x0, int y0, int x1, int y1) {
        double sum = 0.0;
        for (int y = y0; y < y1; ++y)
            for (int x = x0; x < x1; ++x)
                for (int c = 0; c < 3; ++c) {
                    const std::size_t i = (static_cast<std::size_t>(y) * a.width + x) * 3 + c;
                    sum += std::fabs(a.rgb[i] - b.rgb[i]);
                }
        return sum / (3.0 * (x1 - x0) * (y1 - y0));
    };
    CHECK(box_difference(12, 12, 200, 120) > 0.05);
    CHECK(box_difference(370, 200, 480, 360) < 0.004);
}

TEST_CASE("kdpm-view refuses bad input with a one-line error", "[view][e2e]") {
    if (!fs::exists(test::tool_path("kdpm-view"))) {
        WARN("kdpm-view is not built (no GLFW or OpenGL): skipped");
        return;
    }
    test::TempDir dir;
    auto r = test::run_tool("kdpm-view " + (dir / "missing.kdg").string() + " --frames 1");
    CHECK(r.exit_code == 1);
    CHECK(r.output.rfind("kdpm-view: error:", 0) == 0);
    CHECK(std::count(r.output.begin(), r.output.end(), '\n') == 1);

    const fs::path junk = dir / "junk.kdg";
    {
        std::FILE* f = std::fopen(junk.c_str(), "wb");
        REQUIRE(f);
        std::fputs("not a kdpm file at all, just some words that are long enough to look like a header", f);
        std::fclose(f);
    }
    r = test::run_tool("kdpm-view " + junk.string() + " --frames 1");
    CHECK(r.exit_code == 1);
    CHECK(r.output.rfind("kdpm-view: error:", 0) == 0);

    r = test::run_tool("kdpm-view " + junk.string() + " --k 100000");
    CHECK(r.exit_code == 2);
    r = test::run_tool("kdpm-view " + junk.string() + " --width 0");
    CHECK(r.exit_code == 2);
    r = test::run_tool("kdpm-view " + junk.string() + " --mode sideways");
    CHECK(r.exit_code == 2);
}

TEST_CASE("kdpm-view without a display says so in one line", "[view][e2e]") {
    if (!have_tools()) {
        WARN("kdpm-view or the scene tools are not built, or scenes/cornell-box is missing: skipped");
        return;
    }
    test::TempDir dir;
    const std::string kdg = (dir / "cornell.kdg").string();
    REQUIRE(test::run_tool("kdpm-build-geometry " + test::source_path("scenes/cornell-box/cornell-box.json") +
                           " -o " + kdg + " --quiet").exit_code == 0);
    auto r = test::run_shell(kViewerEnv + "env -u DISPLAY -u WAYLAND_DISPLAY " + test::tool_path("kdpm-view") + " " + kdg +
                   " --frames 1 --quiet");
    CHECK(r.exit_code == 1);
    CHECK(r.output.rfind("kdpm-view: error: no display available", 0) == 0);
    CHECK(std::count(r.output.begin(), r.output.end(), '\n') == 1);
}
