// The panel's "copy as command line" gives kdpm-render options that reproduce the view exactly.
#include <catch2/catch.hpp>

#include <cstring>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "runtime/render/camera_override.h"
#include "runtime/view/camera_command_line.h"
#include "tools/cli/args.h"
#include "tools/cli/camera_override.h"

using namespace kdpm;

TEST_CASE("camera command line reads back to the same camera, bit for bit", "[view][camera]") {
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> coord(-1e4f, 1e4f), angle(1.0f, 170.0f);
    for (int i = 0; i < 200; ++i) {
        CameraRecord c{};
        for (int k = 0; k < 3; ++k) {
            c.eye[k] = coord(rng);
            c.lookat[k] = coord(rng) * 1e-3f;
            c.up[k] = coord(rng);
        }
        c.vfov_degrees = angle(rng);
        c.width = 64;
        c.height = 48;

        std::vector<std::string> words = {"kdpm-render"};
        std::istringstream line(camera_command_line(c));
        for (std::string w; line >> w;) words.push_back(w);
        REQUIRE(words.size() == 1 + 3 * 4 + 2);
        std::vector<char*> argv;
        for (auto& w : words) argv.push_back(w.data());
        CameraOverride parsed;
        cli::Args args("kdpm-render", "test");
        cli::add_camera_options(args, parsed);
        args.parse(static_cast<int>(argv.size()), argv.data());

        CameraRecord start{};
        start.eye[2] = 1.0f;
        start.up[1] = 1.0f;
        start.vfov_degrees = 30.0f;
        start.width = 64;
        start.height = 48;
        const CameraRecord back = parsed.applied_to(start);
        INFO(camera_command_line(c));
        CHECK(std::memcmp(&back, &c, sizeof c) == 0);
    }
}
