// LoadedScene opens the photon file on a second thread beside the geometry: what it loads and
// which error it reports must be what opening them one after the other gives.
#include <catch2/catch.hpp>

#include <fstream>
#include <string>
#include <vector>

#include "runtime/render/scene_loader.h"
#include "tests/support/error_text.h"
#include "tests/support/file_contents.h"
#include "tests/support/run_command.h"
#include "tests/support/temp_dir.h"

using namespace kdpm;

namespace {

std::string load_error(const std::filesystem::path& kdg, const std::filesystem::path& kdp) {
    return test::error_text([&] { (void)LoadedScene::load(kdg, kdp); });
}

std::vector<std::uint8_t> read_bytes(const std::filesystem::path& path) {
    const std::string text = test::file_contents(path);
    return {text.begin(), text.end()};
}

void write_bytes(const std::filesystem::path& path, const std::vector<std::uint8_t>& bytes) {
    std::ofstream out(path, std::ios::binary);
    out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
}

}  // namespace

TEST_CASE("a scene loads both files and reports the geometry's error first", "[render][load][corrupt]") {
    test::TempDir dir;
    const auto kdg = dir / "box.kdg", kdp = dir / "box.kdp", bad_kdp = dir / "bad.kdp", bad_kdg = dir / "bad.kdg";
    auto r = test::run_tool("kdpm-build-geometry " + test::source_path("scenes/cornell-box/cornell-box.json") +
                            " -o " + kdg.string() + " --quiet");
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
    // Over a megabyte, so that the photon file's own checks also use their second thread.
    const auto kdph = dir / "box.kdph";
    r = test::run_tool("kdpm-shoot-photons " + kdg.string() + " -n 40000 -o " + kdph.string() + " --quiet");
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
    r = test::run_tool("kdpm-build-photons " + kdph.string() + " -o " + kdp.string() + " --quiet");
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
    const std::vector<std::uint8_t> photons = read_bytes(kdp);
    REQUIRE(photons.size() > (std::size_t{1} << 20));
    std::vector<std::uint8_t> damaged = photons;
    damaged[damaged.size() / 2] ^= 0x10;
    write_bytes(bad_kdp, damaged);
    std::vector<std::uint8_t> geometry = read_bytes(kdg);
    geometry[geometry.size() / 2] ^= 0x10;
    write_bytes(bad_kdg, geometry);

    const LoadedScene scene = LoadedScene::load(kdg, kdp);
    CHECK(scene.views().photons.present);
    CHECK(scene.views().photons.global.photon_count > 0);
    CHECK(scene.views().geometry.triangle_count > 0);

    for (int run = 0; run < 3; ++run) {
        const std::string photon_error = load_error(kdg, bad_kdp);
        INFO(photon_error);
        CHECK_THAT(photon_error, Catch::Contains("bad.kdp") && Catch::Contains("corrupt"));
        const std::string both = load_error(bad_kdg, bad_kdp);
        INFO(both);
        CHECK_THAT(both, Catch::Contains("bad.kdg"));
        CHECK(both.find("bad.kdp") == std::string::npos);
        const std::string missing = load_error(dir / "missing.kdg", bad_kdp);
        INFO(missing);
        CHECK_THAT(missing, Catch::Contains("missing.kdg"));
    }
}
