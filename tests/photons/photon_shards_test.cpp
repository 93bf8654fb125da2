#include <catch2/catch.hpp>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "builders/photons/photon_shards.h"
#include "formats/format_error.h"
#include "runtime/photons/photon_shooter.h"
#include "tests/photons/shooting_scenes.h"
#include "tests/support/file_contents.h"
#include "tests/support/run_command.h"
#include "tests/support/temp_dir.h"

using namespace kdpm;

namespace {

// The Cornell box's .kdg, built once per test into `dir`.
std::string cornell_kdg(const test::TempDir& dir, const std::string& extra = "") {
    auto kdg = (dir / ("cornell" + std::to_string(extra.size()) + ".kdg")).string();
    auto card = test::source_path("scenes/cornell-box/cornell-box.json");
    auto r = test::run_tool("kdpm-build-geometry " + card + " -o " + kdg + " --quiet" + extra);
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
    return kdg;
}

std::string shoot(const std::string& kdg, const std::filesystem::path& out, const std::string& options) {
    auto r = test::run_tool("kdpm-shoot-photons " + kdg + " -o " + out.string() + " --quiet " + options);
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
    return out.string();
}

std::size_t lines(const std::string& s) { return static_cast<std::size_t>(std::count(s.begin(), s.end(), '\n')); }

}  // namespace

TEST_CASE("Uneven shards merge into the single run's file byte for byte, in any order", "[photons][shards][tools]") {
    test::TempDir dir;
    const auto kdg = cornell_kdg(dir);
    const auto whole = shoot(kdg, dir / "whole.kdph", "-n 4000 --bounces 5 --seed 7");
    std::vector<std::string> parts = {shoot(kdg, dir / "a.kdph", "-n 4000 --bounces 5 --seed 7 --paths 0:1000"),
                                      shoot(kdg, dir / "b.kdph", "-n 4000 --bounces 5 --seed 7 --paths 1000:1037 --threads 1"),
                                      shoot(kdg, dir / "c.kdph", "-n 4000 --bounces 5 --seed 7 --paths 1037:4000")};
    for (const auto& p : parts) CHECK(test::run_tool("kdpm-validate " + p).exit_code == 0);
    // A shard's bytes are not the whole run's: the test below can tell them apart.
    CHECK(test::file_contents(parts[0]) != test::file_contents(whole));

    std::sort(parts.begin(), parts.end());
    int order = 0;
    do {
        auto merged = dir / ("merged" + std::to_string(order++) + ".kdph");
        auto r = test::run_tool("kdpm-merge-photons " + parts[0] + " " + parts[1] + " " + parts[2] + " -o " + merged.string());
        INFO(r.output);
        REQUIRE(r.exit_code == 0);
        CHECK_THAT(r.output, Catch::Contains("3 shards") && Catch::Contains("4000 paths"));
        CHECK(test::file_contents(merged) == test::file_contents(whole));
    } while (std::next_permutation(parts.begin(), parts.end()));
    CHECK(order == 6);
    CHECK(test::run_tool("kdpm-validate " + (dir / "merged0.kdph").string()).exit_code == 0);

    // One shard that covers every path is the whole run too.
    auto one = shoot(kdg, dir / "one.kdph", "-n 4000 --bounces 5 --seed 7 --paths 0:4000");
    CHECK(test::file_contents(one) == test::file_contents(whole));
}

TEST_CASE("kdpm-merge-photons refuses shards of different runs, gaps and overlaps, and writes nothing",
          "[photons][shards][tools]") {
    test::TempDir dir;
    const auto kdg = cornell_kdg(dir);
    const auto other_scene = cornell_kdg(dir, " --max-depth 6");
    const std::string run = "-n 3000 --bounces 4 --seed 1";
    auto a = shoot(kdg, dir / "a.kdph", run + " --paths 0:1000");
    auto b = shoot(kdg, dir / "b.kdph", run + " --paths 1000:2000");
    auto c = shoot(kdg, dir / "c.kdph", run + " --paths 2000:3000");
    auto b_overlap = shoot(kdg, dir / "bo.kdph", run + " --paths 900:2000");
    auto b_scene = shoot(other_scene, dir / "bs.kdph", run + " --paths 1000:2000");
    auto b_seed = shoot(kdg, dir / "bd.kdph", "-n 3000 --bounces 4 --seed 2 --paths 1000:2000");
    auto b_total = shoot(kdg, dir / "bn.kdph", "-n 3001 --bounces 4 --seed 1 --paths 1000:2000");
    auto b_bounces = shoot(kdg, dir / "bb.kdph", "-n 3000 --bounces 3 --seed 1 --paths 1000:2000");
    auto whole = shoot(kdg, dir / "whole.kdph", run);

    struct Case {
        std::string name, inputs, reason;
    };
    const std::vector<Case> cases = {
        {"different scenes", a + " " + b_scene + " " + c, "different scenes"},
        {"different seeds", a + " " + b_seed + " " + c, "different seeds"},
        {"different photon totals", a + " " + b_total + " " + c, "different photon totals"},
        {"different bounces", a + " " + b_bounces + " " + c, "different bounce limits"},
        {"a gap at the start", b + " " + c, "paths 0:1000 are in no shard"},
        {"a gap inside", a + " " + c, "paths 1000:2000 are in no shard"},
        {"a gap at the end", a + " " + b, "paths 2000:3000 are in no shard"},
        {"an overlap", a + " " + b_overlap + " " + c, "overlap (paths 900:1000)"},
        {"a shard given twice", a + " " + b + " " + b + " " + c, "overlap (paths 1000:2000)"},
        {"a whole run and a shard", whole + " " + b, "overlap"},
    };
    const auto out = dir / "out.kdph";
    for (const auto& k : cases) {
        SECTION(k.name) {
            auto r = test::run_tool("kdpm-merge-photons " + k.inputs + " -o " + out.string());
            INFO(r.output);
            CHECK(r.exit_code == 1);
            CHECK(lines(r.output) == 1);
            CHECK_THAT(r.output, Catch::StartsWith("kdpm-merge-photons: error:") && Catch::Contains(k.reason));
            CHECK_FALSE(std::filesystem::exists(out));
        }
    }
    SECTION("an existing output is left as it was") {
        std::ofstream(out) << "previous";
        CHECK(test::run_tool("kdpm-merge-photons " + a + " " + c + " -o " + out.string()).exit_code == 1);
        CHECK(test::file_contents(out) == "previous");
    }
    SECTION("the output may not be a shard") {
        auto r = test::run_tool("kdpm-merge-photons " + a + " " + b + " " + c + " -o " + b);
        CHECK(r.exit_code == 1);
        CHECK_THAT(r.output, Catch::Contains("is one of the shards"));
    }
    SECTION("no shards, no output, or a file that is not photon hits") {
        CHECK(test::run_tool("kdpm-merge-photons -o " + out.string()).exit_code == 2);
        CHECK(test::run_tool("kdpm-merge-photons " + a).exit_code == 1);
        auto wrong = test::run_tool("kdpm-merge-photons " + a + " " + kdg + " -o " + out.string());
        CHECK(wrong.exit_code == 1);
        CHECK(lines(wrong.output) == 1);
        CHECK_FALSE(std::filesystem::exists(out));
    }
    SECTION("kdpm-build-photons refuses a shard, and builds the merged file") {
        auto r = test::run_tool("kdpm-build-photons " + b + " -o " + (dir / "b.kdp").string());
        CHECK(r.exit_code == 1);
        CHECK_THAT(r.output, Catch::Contains("is a shard (paths 1000:2000 of 3000)"));
        CHECK_FALSE(std::filesystem::exists(dir / "b.kdp"));
        REQUIRE(test::run_tool("kdpm-merge-photons " + c + " " + a + " " + b + " -o " + out.string() + " --quiet").exit_code == 0);
        CHECK(test::run_tool("kdpm-build-photons " + out.string() + " -o " + (dir / "m.kdp").string() + " --quiet").exit_code == 0);
    }
}

TEST_CASE("kdpm-shoot-photons --paths needs BEGIN < END <= N", "[photons][shards][tools]") {
    test::TempDir dir;
    const auto kdg = cornell_kdg(dir);
    const auto out = (dir / "p.kdph").string();
    for (const char* bad : {"5:4", "7:7", "abc", "5", "-1:5", "1:x", ":5", "5:", "1:2:3", "+1:5",
                            "99999999999999999999999:1"}) {
        INFO(bad);
        auto r = test::run_tool("kdpm-shoot-photons " + kdg + " -n 100 --paths " + bad + " -o " + out);
        CHECK(r.exit_code == 2);
        CHECK(lines(r.output) == 1);
    }
    auto beyond = test::run_tool("kdpm-shoot-photons " + kdg + " -n 100 --paths 50:101 -o " + out);
    CHECK(beyond.exit_code == 1);
    CHECK_THAT(beyond.output, Catch::Contains("ends beyond the 100 photon paths"));
    CHECK_FALSE(std::filesystem::exists(out));
    auto last = test::run_tool("kdpm-shoot-photons " + kdg + " -n 100 --paths 99:100 -o " + out);
    INFO(last.output);
    CHECK(last.exit_code == 0);
    CHECK_THAT(last.output, Catch::Contains("paths 99:100 of 100 emitted"));
}

TEST_CASE("shoot_photons over path ranges gives the whole run's hits, shard by shard", "[photons][shards]") {
    GeometryFile scene = test::closed_box(0.7f, true);
    ShootOptions whole_options;
    whole_options.photons = 3000;
    whole_options.max_bounces = 6;
    whole_options.seed = 11;
    const ShotPhotons whole = shoot_photons(scene.view(), whole_options);
    REQUIRE(whole.info.caustic_count > 0);

    std::vector<PhotonHit> joined;
    std::uint64_t rays = 0;
    // Cuts off the batch grid, with a one-path shard.
    for (auto [begin, end] : {std::pair<std::uint64_t, std::uint64_t>{0, 1234}, {1234, 1235}, {1235, 3000}}) {
        ShootOptions part = whole_options;
        part.path_begin = begin;
        part.path_end = end;
        const ShotPhotons shot = shoot_photons(scene.view(), part);
        CHECK(shot.info.emitted_count == 3000);
        for (const auto& h : shot.hits) CHECK((h.path >= begin && h.path < end));
        joined.insert(joined.end(), shot.hits.begin(), shot.hits.end());
        rays += shot.rays;
    }
    REQUIRE(joined.size() == whole.hits.size());
    CHECK(std::memcmp(joined.data(), whole.hits.data(), joined.size() * sizeof(PhotonHit)) == 0);
    CHECK(rays == whole.rays);

    for (auto [begin, end] : {std::pair<std::uint64_t, std::uint64_t>{5, 5}, {6, 5}, {0, 3001}, {3000, 3001}}) {
        ShootOptions bad = whole_options;
        bad.path_begin = begin;
        bad.path_end = end;
        CHECK_THROWS_AS(shoot_photons(scene.view(), bad), std::invalid_argument);
    }
}

TEST_CASE("A .kdph's path range: its metadata, else every path", "[photons][shards]") {
    PhotonHitsInfo info{};
    info.emitted_count = 500;
    Metadata m;
    CHECK(photon_hits_path_range(m, info) == PathRange{0, 500});
    m.parameters[kPathsParameter] = "100:250";
    CHECK(photon_hits_path_range(m, info) == PathRange{100, 250});
    m.parameters[kPathsParameter] = "100:501";
    CHECK_THROWS_AS(photon_hits_path_range(m, info), FormatError);
    m.parameters[kPathsParameter] = "garbage";
    CHECK_THROWS_AS(photon_hits_path_range(m, info), FormatError);
    CHECK(path_range_text({3, 18446744073709551615ull}) == "3:18446744073709551615");
    CHECK(parse_path_range("3:18446744073709551615", ~0ull) == PathRange{3, ~0ull});
}

TEST_CASE("Merging refuses a shard whose photons lie outside its path range", "[photons][shards]") {
    auto shard = [](std::string name, PathRange r, std::vector<std::uint32_t> paths) {
        PhotonShard s;
        s.name = std::move(name);
        s.paths = r;
        s.set.info.emitted_count = 10;
        for (auto p : paths) {
            PhotonHit h{};
            h.path = p;
            s.set.hits.push_back(h);
        }
        s.metadata.tool = "kdpm-shoot-photons";
        s.metadata.parameters[kPathsParameter] = path_range_text(r);
        return s;
    };
    CHECK_NOTHROW(merge_photon_shards({shard("a", {0, 5}, {0, 0, 4}), shard("b", {5, 10}, {5, 9})}));
    auto merged = merge_photon_shards({shard("b", {5, 10}, {5, 9}), shard("a", {0, 5}, {0, 3})});
    REQUIRE(merged.set.hits.size() == 4);
    CHECK(merged.set.hits[1].path == 3);
    CHECK(merged.set.hits[2].path == 5);
    CHECK(merged.metadata.parameters.at(kPathsParameter) == "0:10");
    CHECK_THROWS_WITH(merge_photon_shards({shard("a", {0, 5}, {0, 5}), shard("b", {5, 10}, {})}),
                      Catch::Contains("a holds a photon of path 5 outside its paths 0:5"));
    CHECK_THROWS_WITH(merge_photon_shards({shard("a", {0, 5}, {3, 2}), shard("b", {5, 10}, {})}),
                      Catch::Contains("out of path order"));
}
