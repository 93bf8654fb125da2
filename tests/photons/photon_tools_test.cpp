#include <catch2/catch.hpp>

#include <fstream>
#include <iterator>

#include "runtime/photons/photon_map_file.h"
#include "tests/support/file_contents.h"
#include "tests/photons/synthetic_photons.h"
#include "tests/support/run_command.h"
#include "tests/support/temp_dir.h"

using namespace kdpm;

TEST_CASE("kdpm-build-photons writes a valid tree whatever the thread count", "[photons][tools]") {
    test::TempDir dir;
    auto hits = dir / "p.kdph";
    test::write_photon_hits_file(test::synthetic_photons(40000, 5), hits);
    for (const char* builder : {"", " --balanced"}) {
        auto one = dir / "one.kdp", two = dir / "two.kdp";
        auto r1 = test::run_tool("kdpm-build-photons " + hits.string() + " -o " + one.string() + " --threads 1" + builder);
        auto r2 = test::run_tool("kdpm-build-photons " + hits.string() + " --output " + two.string() +
                                 " --threads 2 --quiet" + builder);
        INFO(r1.output << r2.output);
        REQUIRE(r1.exit_code == 0);
        REQUIRE(r2.exit_code == 0);
        CHECK_THAT(r1.output, Catch::Contains("40000 photons") || Catch::Contains("photons ("));
        CHECK(r2.output.empty());
        CHECK(test::file_contents(one) == test::file_contents(two));
        CHECK(test::run_tool("kdpm-validate " + one.string()).exit_code == 0);
        auto file = PhotonMapFile::open(one);
        CHECK(file.has_map(PhotonMapKind::caustic));
        CHECK(file.info(PhotonMapKind::caustic).photon_count > 0);
    }
}

TEST_CASE("kdpm-build-photons refuses bad input in one line", "[photons][tools]") {
    test::TempDir dir;
    auto out = dir / "out.kdp";
    auto missing = test::run_tool("kdpm-build-photons " + (dir / "none.kdph").string() + " -o " + out.string());
    CHECK(missing.exit_code == 1);
    CHECK_THAT(missing.output, Catch::StartsWith("kdpm-build-photons: error:"));

    auto hits = dir / "p.kdph";
    test::write_photon_hits_file(test::synthetic_photons(1000, 5), hits);
    auto bytes = test::file_contents(hits);
    bytes[bytes.size() / 2] ^= 0x40;
    auto bad = dir / "bad.kdph";
    std::ofstream(bad, std::ios::binary) << bytes;
    auto corrupt = test::run_tool("kdpm-build-photons " + bad.string() + " -o " + out.string());
    CHECK(corrupt.exit_code == 1);
    CHECK(std::count(corrupt.output.begin(), corrupt.output.end(), '\n') == 1);
    CHECK_FALSE(std::filesystem::exists(out));

    // A .kdp given where hits are expected: the wrong kind.
    CHECK(test::run_tool("kdpm-build-photons " + hits.string() + " -o " + out.string()).exit_code == 0);
    auto wrong = test::run_tool("kdpm-build-photons " + out.string() + " -o " + (dir / "x.kdp").string());
    CHECK(wrong.exit_code == 1);

    CHECK(test::run_tool("kdpm-build-photons " + hits.string() + " -o " + out.string() + " --leaf-size 0").exit_code == 2);
    CHECK(test::run_tool("kdpm-build-photons " + hits.string()).exit_code == 1);
}

TEST_CASE("The Cornell box goes through kdpm-shoot-photons and kdpm-build-photons", "[photons][tools]") {
    test::TempDir dir;
    auto kdg = (dir / "cornell.kdg").string();
    auto card = test::source_path("scenes/cornell-box/cornell-box.json");
    REQUIRE(test::run_tool("kdpm-build-geometry " + card + " -o " + kdg + " --quiet").exit_code == 0);
    auto one = dir / "one.kdph", two = dir / "two.kdph";
    auto r1 = test::run_tool("kdpm-shoot-photons " + kdg + " -n 20000 --bounces 4 -o " + one.string() + " --threads 1");
    auto r2 = test::run_tool("kdpm-shoot-photons " + kdg + " -n 20000 --bounces 4 -o " + two.string() +
                             " --threads 2 --quiet");
    INFO(r1.output << r2.output);
    REQUIRE(r1.exit_code == 0);
    REQUIRE(r2.exit_code == 0);
    CHECK_THAT(r1.output, Catch::Contains("20000 emitted") && Catch::Contains("rays"));
    CHECK(test::file_contents(one) == test::file_contents(two));
    CHECK(test::run_tool("kdpm-validate " + one.string()).exit_code == 0);
    auto kdp = (dir / "cornell.kdp").string();
    REQUIRE(test::run_tool("kdpm-build-photons " + one.string() + " -o " + kdp + " --quiet").exit_code == 0);
    CHECK(test::run_tool("kdpm-validate " + kdp).exit_code == 0);
    auto file = PhotonMapFile::open(kdp);
    CHECK(file.info().photon_count > 20000);  // direct hits plus bounces
    CHECK(file.info().emitted_count == 20000);

    CHECK(test::run_tool("kdpm-shoot-photons " + kdg + " -n 0 -o " + one.string()).exit_code == 2);
    auto wrong = test::run_tool("kdpm-shoot-photons " + one.string() + " -o " + two.string());
    CHECK(wrong.exit_code == 1);
    CHECK_THAT(wrong.output, Catch::StartsWith("kdpm-shoot-photons: error:"));
}

TEST_CASE("Sponza and Conference go through the photon pipeline when present", "[photons][tools][scenes]") {
    if (test::shared_scenes_dir().empty()) {
        WARN("../shared/scenes not found (set KDPM_SCENES): skipping Sponza and Conference");
        return;
    }
    test::TempDir dir;
    for (const char* card : {"scenes/sponza/sponza.json", "scenes/conference/conference.json"}) {
        INFO(card);
        auto kdg = (dir / "scene.kdg").string(), kdph = (dir / "scene.kdph").string(), kdp = (dir / "scene.kdp").string();
        auto geo = test::run_tool("kdpm-build-geometry " + test::source_path(card) + " -o " + kdg + " --quiet");
        if (geo.exit_code != 0) {
            WARN(std::string(card) + ": geometry not built (" + geo.output + "), skipping");
            continue;
        }
        auto shot = test::run_tool("kdpm-shoot-photons " + kdg + " -n 20000 -o " + kdph + " --quiet");
        INFO(shot.output);
        REQUIRE(shot.exit_code == 0);
        REQUIRE(test::run_tool("kdpm-build-photons " + kdph + " -o " + kdp + " --quiet").exit_code == 0);
        CHECK(test::run_tool("kdpm-validate " + kdph).exit_code == 0);
        CHECK(test::run_tool("kdpm-validate " + kdp).exit_code == 0);
        CHECK(PhotonMapFile::open(kdp).info().photon_count > 10000);
    }
}
