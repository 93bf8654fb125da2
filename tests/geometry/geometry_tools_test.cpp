// kdpm-build-geometry end to end, and corrupt .kdg files refused by kdpm-validate and GeometryFile.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>

#include "builders/geometry/geometry_file_builder.h"
#include "builders/geometry/sah/sah_kd_builder.h"
#include "formats/format_error.h"
#include "runtime/geometry/geometry_file.h"
#include "tests/geometry/random_scenes.h"
#include "tests/support/run_command.h"
#include "tests/support/temp_dir.h"

using namespace kdpm;
namespace fs = std::filesystem;

namespace {

std::vector<std::uint8_t> read_bytes(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
}

void write_bytes(const fs::path& p, const std::vector<std::uint8_t>& b) {
    std::ofstream out(p, std::ios::binary);
    out.write(reinterpret_cast<const char*>(b.data()), static_cast<std::streamsize>(b.size()));
}

bool one_line(const std::string& s) { return !s.empty() && s.find('\n') == s.size() - 1; }

// kdpm-validate and GeometryFile (with checksums) must both refuse the file.
void check_refused(const fs::path& p) {
    const auto r = test::run_tool("kdpm-validate " + p.string());
    CHECK(r.exit_code == 1);
    CHECK(one_line(r.output));
    CHECK_THROWS_AS(GeometryFile::open(p), FormatError);
}

}  // namespace

TEST_CASE("kdpm-build-geometry builds the shipped card and kdpm-validate accepts it", "[geometry][tools]") {
    test::TempDir dir;
    const fs::path out = dir / "cornell.kdg";
    const auto build = test::run_tool("kdpm-build-geometry " + test::source_path("scenes/cornell-box/cornell-box.json") +
                                      " -o " + out.string());
    REQUIRE(build.exit_code == 0);
    CHECK(one_line(build.output));
    CHECK(build.output.find("32 triangles") != std::string::npos);
    const auto quiet = test::run_tool("kdpm-build-geometry --quiet --threads 1 " +
                                      test::source_path("scenes/cornell-box/cornell-box.json") + " --output " +
                                      (dir / "q.kdg").string());
    CHECK(quiet.exit_code == 0);
    CHECK(quiet.output.empty());
    CHECK(read_bytes(out) == read_bytes(dir / "q.kdg"));
    const auto v = test::run_tool("kdpm-validate --exhaustive " + out.string());
    CHECK(v.exit_code == 0);
    const GeometryFile f = GeometryFile::open(out);
    CHECK(f.info().triangle_count == 32);
    CHECK(f.lights().size() == 2);
    CHECK(f.metadata().tool == "kdpm-build-geometry");
    CHECK(f.metadata().source_hash.size() == 16);
}

TEST_CASE("kdpm-build-geometry refuses bad input with one line and writes nothing", "[geometry][tools]") {
    test::TempDir dir;
    {
        std::ofstream bad(dir / "bad.ply");
        bad << "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nend_header\n1 2\n";
    }
    const fs::path out = dir / "out.kdg";
    const auto r = test::run_tool("kdpm-build-geometry " + (dir / "bad.ply").string() + " -o " + out.string());
    CHECK(r.exit_code == 1);
    CHECK(one_line(r.output));
    CHECK(r.output.rfind("kdpm-build-geometry: error:", 0) == 0);
    CHECK_FALSE(fs::exists(out));
    const auto missing = test::run_tool("kdpm-build-geometry " + (dir / "none.obj").string() + " -o " + out.string());
    CHECK(missing.exit_code == 1);
    CHECK(one_line(missing.output));
    CHECK_FALSE(fs::exists(out));
    const auto absurd = test::run_tool("kdpm-build-geometry x.obj -o y.kdg --empty-bonus 7");
    CHECK(absurd.exit_code == 2);
    const auto quality = test::run_tool("kdpm-build-geometry x.obj -o y.kdg --quality best");
    CHECK(quality.exit_code == 2);
    CHECK(quality.output.find("fast or high") != std::string::npos);
    const auto clip = test::run_tool("kdpm-build-geometry x.obj -o y.kdg --quality fast --clip-below -1");
    CHECK(clip.exit_code == 2);
    CHECK(one_line(clip.output));
    CHECK(clip.output.find("clip-below") != std::string::npos);
}

TEST_CASE("kdpm-build-geometry --quality: both are exact, recorded, and identical across thread counts",
          "[geometry][tools]") {
    test::TempDir dir;
    // A soup as OBJ, large enough for the fast build to bin its upper levels.
    {
        std::ofstream obj(dir / "soup.obj");
        std::uint32_t v = 0;
        for (const TriangleRecord& t : test::random_soup(12000, 43, 0.05f)) {
            for (int c = 0; c < 3; ++c) {
                const float* e = c == 0 ? nullptr : c == 1 ? t.e1 : t.e2;
                obj << "v";
                for (int a = 0; a < 3; ++a) obj << ' ' << t.v0[a] + (e ? e[a] : 0.0f);
                obj << '\n';
            }
            obj << "f " << v + 1 << ' ' << v + 2 << ' ' << v + 3 << '\n';
            v += 3;
        }
    }
    const std::string mesh = (dir / "soup.obj").string();
    std::map<std::string, std::vector<std::uint8_t>> files;
    for (const std::string quality : {"fast", "high"}) {
        for (const std::string threads : {"1", "2"}) {
            const fs::path out = dir / (quality + threads + ".kdg");
            const auto r = test::run_tool("kdpm-build-geometry " + mesh + " -o " + out.string() + " --quiet --quality " +
                                          quality + " --exact-below 512 --threads " + threads);
            REQUIRE(r.exit_code == 0);
            files[quality + threads] = read_bytes(out);
        }
        INFO("quality: " << quality);
        CHECK(files[quality + "1"] == files[quality + "2"]);
        const auto v = test::run_tool("kdpm-validate --exhaustive " + (dir / (quality + "1.kdg")).string());
        CHECK(v.exit_code == 0);
        CHECK(GeometryFile::open(dir / (quality + "1.kdg")).metadata().parameters.at("quality") == quality);
    }
    CHECK(files["fast1"] != files["high1"]);
    const Metadata fast = GeometryFile::open(dir / "fast1.kdg").metadata();
    CHECK(fast.parameters.at("exact_below") == "512");
    CHECK(fast.parameters.at("clip_below") == std::to_string(KdBuildParams{}.clip_below));
    // Clipping everywhere is another tree, exact too.
    const fs::path clipped = dir / "clipped.kdg";
    REQUIRE(test::run_tool("kdpm-build-geometry " + mesh + " -o " + clipped.string() +
                           " --quiet --quality fast --exact-below 512 --clip-below 0")
                .exit_code == 0);
    CHECK(read_bytes(clipped) != files["fast1"]);
    CHECK(test::run_tool("kdpm-validate --exhaustive " + clipped.string()).exit_code == 0);
    CHECK(GeometryFile::open(clipped).metadata().parameters.at("clip_below") == "0");
}

TEST_CASE("corrupt geometry files are refused", "[geometry][tools]") {
    test::TempDir dir;
    const Scene scene = scene_from_triangles(test::random_soup(300, 41));
    const auto good = build_geometry_file(scene, KdBuildParams{}).writer.bytes();
    write_bytes(dir / "good.kdg", good);
    REQUIRE(test::run_tool("kdpm-validate --exhaustive " + (dir / "good.kdg").string()).exit_code == 0);

    SECTION("bit flips") {
        for (std::size_t offset : {std::size_t{3}, std::size_t{200}, good.size() / 2, good.size() - 10}) {
            auto bytes = good;
            bytes[offset] ^= 0x10;
            write_bytes(dir / "flip.kdg", bytes);
            INFO("offset " << offset);
            check_refused(dir / "flip.kdg");
        }
    }
    SECTION("truncation") {
        for (std::size_t size : {std::size_t{0}, std::size_t{50}, good.size() / 2, good.size() - 1}) {
            write_bytes(dir / "short.kdg", std::vector<std::uint8_t>(good.begin(), good.begin() + static_cast<std::ptrdiff_t>(size)));
            check_refused(dir / "short.kdg");
        }
    }
    SECTION("bad indices with valid checksums") {
        const KdTree tree = build_sah_kd_tree(scene.triangles, KdBuildParams{});
        REQUIRE(tree.nodes.size() > 3);
        KdTree bad_leaf = tree;
        bad_leaf.leaf_indices.at(0) = 300;
        KdTree bad_child = tree;
        bad_child.nodes[0] = KdNode::inner(bad_child.nodes[0].axis(), bad_child.nodes[0].split(), 100000);
        KdTree cycle = tree;
        cycle.nodes[0] = KdNode::inner(cycle.nodes[0].axis(), cycle.nodes[0].split(), 1);
        KdTree bad_split = tree;
        bad_split.nodes[0] = KdNode::inner(bad_split.nodes[0].axis(), 1e9f, bad_split.nodes[0].above_child());
        Scene bad_material = scene;
        bad_material.triangles[5].material = 9;
        // The walk's first fault is named: the root's children, node 1 twice, the root's split.
        int i = 0;
        struct Case {
            const Scene* scene;
            const KdTree* tree;
            const char* message;
        };
        for (const Case& c : {Case{&scene, &bad_leaf, "leaf index 0 names triangle 300"},
                              Case{&scene, &bad_child, "node 0 has a child index out of range"},
                              Case{&scene, &cycle, "node 1 is reached twice"},
                              Case{&scene, &bad_split, "node 0 splits outside its cell"},
                              Case{&bad_material, &tree, "triangle 5 has material index out of range"}}) {
            const fs::path p = dir / ("bad" + std::to_string(i++) + ".kdg");
            assemble_geometry_file(*c.scene, *c.tree, KdBuildParams{}).write(p);
            INFO(p.string());
            check_refused(p);
            CHECK_THROWS_AS(GeometryFile::open(p), FormatError);
            CHECK_THROWS_WITH(GeometryFile::open(p), Catch::Contains(c.message));
        }
    }
}

TEST_CASE("a file missing leaf coverage fails only the exhaustive check", "[geometry][tools]") {
    test::TempDir dir;
    const Scene scene = scene_from_triangles(test::random_soup(300, 42));
    KdTree tree = build_sah_kd_tree(scene.triangles, KdBuildParams{});
    // Drop one triangle from the first non-empty leaf by pointing it at the previous index.
    for (KdNode& n : tree.nodes)
        if (n.is_leaf() && n.count() > 1) {
            n = KdNode::leaf(n.first(), n.count() - 1);
            break;
        }
    assemble_geometry_file(scene, tree, KdBuildParams{}).write(dir / "hole.kdg");
    CHECK(test::run_tool("kdpm-validate " + (dir / "hole.kdg").string()).exit_code == 0);
    CHECK(test::run_tool("kdpm-validate --exhaustive " + (dir / "hole.kdg").string()).exit_code == 1);
}
