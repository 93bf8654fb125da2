// Feeds arbitrary text to the scene card reader, applied to a one-triangle scene: any crash,
// hang or sanitizer report is a bug. KDPM_FUZZ_SEED=DIR writes seed cards and exits.
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <string>

#include "builders/geometry/scene.h"
#include "builders/geometry/scene_card.h"
#include "formats/format_error.h"

namespace {

kdpm::Scene one_triangle() {
    kdpm::Scene s;
    const float a[3] = {0, 0, 0}, b[3] = {1, 0, 0}, c[3] = {0, 1, 0};
    s.triangles.push_back(kdpm::make_triangle(a, b, c, 0, 0));
    s.materials.push_back(kdpm::MaterialRecord{{0.8f, 0.8f, 0.8f}, 0, {}, 1.0f, {}, 0, {}, 0});
    return s;
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    if (const char* dir = std::getenv("KDPM_FUZZ_SEED")) {
        const char* cards[] = {
            R"({"mesh": "m.obj", "up": "z", "photons": 1000, "bounces": 4, "k": 64})",
            (R"({"mesh": "m.obj", "camera": {"eye": [0,1,3.9], "lookat": [0,1,0], "up": [0,1,0], "vfov": 40,)"
             R"( "width": 64, "height": 48}})"),
            R"({"mesh": "m.obj", "lights": [{"p0": [0,2,0], "e1": [1,0,0], "e2": [0,0,1], "radiance": [5,5,5]}]})",
        };
        int i = 0;
        for (const char* card : cards) std::ofstream(std::string(dir) + "/seed" + std::to_string(i++) + ".json") << card;
        std::exit(0);
    }
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const kdpm::Scene base = one_triangle();
    kdpm::Scene scene = base;
    try {
        kdpm::apply_scene_card(std::string(reinterpret_cast<const char*>(data), size), "fuzz.json", scene);
    } catch (const kdpm::FormatError&) {
    }
    return 0;
}
