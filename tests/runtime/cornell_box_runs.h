#pragma once
// The shipped Cornell box built by the tools in a temporary folder and rendered by kdpm-render
// (CPU, linear EXR), for tests that compare the lighting modes on it.
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include <OpenImageIO/imageio.h>

#include "tests/support/run_command.h"
#include "tests/support/temp_dir.h"

namespace kdpm::test {

// The RGB channels of an image file, row by row.
inline std::vector<float> read_exr(const std::string& path) {
    auto in = OIIO::ImageInput::open(path);
    REQUIRE(in);
    const int w = in->spec().width, h = in->spec().height, n = in->spec().nchannels;
    std::vector<float> px(static_cast<std::size_t>(w) * h * n);
    REQUIRE(in->read_image(0, 0, 0, n, OIIO::TypeDesc::FLOAT, px.data()));
    std::vector<float> rgb;
    for (std::size_t i = 0; i < px.size(); i += n)
        for (int c = 0; c < 3; ++c) rgb.push_back(px[i + c]);
    return rgb;
}

// The shipped Cornell box built by the tools in a temporary folder, rendered at 32x32 by
// kdpm-render (CPU, linear EXR).
struct CornellBoxRuns {
    TempDir dir;
    const std::string kdg = (dir / "cb.kdg").string(), kdph = (dir / "cb.kdph").string();

    CornellBoxRuns() {
        run("kdpm-build-geometry " + source_path("scenes/cornell-box/cornell-box.json") + " -o " + kdg +
            " --quiet");
    }
    static std::string run(const std::string& command) {
        auto r = run_tool(command);
        INFO(command << "\n" << r.output);
        REQUIRE(r.exit_code == 0);
        return r.output;
    }
    // The card's photon map: bounces 0..4.
    void shoot_photons() { run("kdpm-shoot-photons " + kdg + " -n 200000 -o " + kdph + " --quiet"); }
    std::string build_photons(const std::string& name, const std::string& options = "") {
        const std::string kdp = (dir / name).string();
        run("kdpm-build-photons " + kdph + " -o " + kdp + " --quiet" + options);
        return kdp;
    }
    // `inputs`: the .kdg, then the .kdp when the mode needs one.
    std::vector<float> render(const std::string& inputs, const std::string& options, const std::string& name) {
        const std::string exr = (dir / (name + ".exr")).string();
        run("kdpm-render " + inputs + " " + options + " --width 32 --height 32 --backend cpu --quiet --tonemap none -o " +
            exr);
        return read_exr(exr);
    }
    std::vector<float> render(const std::string& options, const std::string& name) { return render(kdg, options, name); }
};

}  // namespace kdpm::test
