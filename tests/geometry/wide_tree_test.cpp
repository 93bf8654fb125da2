// The wide tree of geometry.wide (format 1.2): the walk over it finds brute force's closest hits
// with both box tests (AVX2 and lane by lane), the builder collapses the kd-tree into it, the
// validator refuses a corrupt one with its fault named, and files without it still trace.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <functional>
#include <limits>
#include <random>
#include <set>
#include <vector>

#include "builders/geometry/scene_card.h"
#include "formats/container_writer.h"
#include "formats/format_error.h"
#include "formats/section_ids.h"
#include "runtime/geometry/wide_traversal.h"
#include "tests/geometry/geometry_check.h"
#include "tests/geometry/random_scenes.h"
#include "tests/support/run_command.h"

using namespace kdpm;

namespace {

bool same_bits(const Hit& a, const Hit& b) { return std::memcmp(&a, &b, sizeof(Hit)) == 0; }

// Rays where the two box tests' walks differ in any bit, or either disagrees with brute force
// (as count_mismatches judges it).
int wide_mismatches(const GeometryView& g, const std::vector<Ray>& rays) {
    REQUIRE(g.wide != nullptr);
    int bad = 0;
    for (const Ray& r : rays) {
        const Hit scalar = wide_detail::scalar::closest_hit(g, r);
        const bool scalar_any = wide_detail::scalar::occluded(g, r);
#if defined(KDPM_WIDE_AVX2)
        if (cpu_has_avx2()) {
            bad += !same_bits(scalar, wide_detail::avx2::closest_hit(g, r));
            bad += scalar_any != wide_detail::avx2::occluded(g, r);
        }
#endif
        const Hit b = closest_hit_brute_force(g, r);
        if (scalar.found() != b.found() || scalar_any != b.found()) {
            ++bad;
            UNSCOPED_INFO("ray " << r.origin.x << "," << r.origin.y << "," << r.origin.z << " dir " << r.direction.x
                                 << "," << r.direction.y << "," << r.direction.z << ": wide " << scalar.found() << " t "
                                 << scalar.t << " any " << scalar_any << ", brute force " << b.found() << " t " << b.t
                                 << " triangle " << b.triangle);
            continue;
        }
        if (b.found() && scalar.t != b.t && std::fabs(scalar.t - b.t) > 1e-5f * std::fabs(b.t)) ++bad;
    }
    return bad;
}

// The file's bytes with its geometry.wide records changed by `edit` (the other sections as they
// are, checksums made anew), or without the section and as format 1.1 when edit is empty.
std::vector<std::uint8_t> with_wide(const std::vector<std::uint8_t>& bytes,
                                    const std::function<void(std::vector<WideNode>&)>& edit) {
    const ContainerReader r = ContainerReader::from_bytes(bytes, "in.kdg");
    ContainerWriter w(FileKind::geometry);
    if (!edit) w.set_version(1, 1);
    w.set_metadata(r.metadata());
    for (const SectionEntry& e : r.sections()) {
        if (e.id == section::metadata) continue;
        const auto data = r.section_bytes(e);
        if (e.id != section::geo_wide) {
            w.add_raw(e.id, static_cast<ElementType>(e.element_type), e.element_size, e.count, data.data());
            continue;
        }
        if (!edit) continue;
        std::vector<WideNode> wide(e.count);
        std::memcpy(wide.data(), data.data(), data.size());
        edit(wide);
        w.add(section::geo_wide, ElementType::record, wide);
    }
    return w.bytes();
}

std::string refusal(const std::vector<std::uint8_t>& bytes, bool exhaustive) {
    try {
        ValidationOptions o;
        o.exhaustive = exhaustive;
        validate_file(ContainerReader::from_bytes(bytes, "bad.kdg"), o);
    } catch (const FormatError& e) {
        return e.what();
    }
    return "";
}

// The first slot of the first node that is inner (want_inner) or a leaf.
std::pair<std::uint32_t, std::uint32_t> find_slot(const std::vector<WideNode>& wide, bool want_inner) {
    for (std::uint32_t i = 0; i < wide.size(); ++i)
        for (std::uint32_t j = 0; j < kWideWidth; ++j)
            if (wide[i].count[j] != 0 && (wide[i].count[j] == kWideInner) == want_inner) return {i, j};
    FAIL("no such slot");
    return {0, 0};
}

}  // namespace

TEST_CASE("the wide walk finds brute force's closest hits with both box tests", "[geometry][traversal][wide]") {
    const KdBuildParams p = test::quality_params(GENERATE(KdBuildQuality::high, KdBuildQuality::fast));
    INFO("quality: " << quality_name(p.quality));
    for (const auto& tris : {test::random_soup(60, 1, 0.3f), test::random_soup(3000, 2, 0.05f)}) {
        const auto bytes = test::build_bytes(scene_from_triangles(tris), p);
        const GeometryFile file = GeometryFile::from_bytes(bytes, "soup.kdg");
        CHECK(wide_mismatches(file.view(), test::random_rays(20000, 31)) == 0);
        CHECK(wide_mismatches(file.view(), test::random_rays(5000, 32, -3.0f, 4.0f)) == 0);
    }
#if defined(KDPM_WIDE_AVX2)
    if (!cpu_has_avx2()) WARN("this CPU lacks AVX2: only the lane-by-lane box test was run");
#endif
}

TEST_CASE("the wide walk finds brute force's hits at the kd planes' edge cases", "[geometry][traversal][wide]") {
    const auto bytes = test::build_bytes(scene_from_triangles(test::grid_scene(false)));
    const GeometryFile file = GeometryFile::from_bytes(bytes, "grid.kdg");
    // Origins on split planes and on triangle edges, directions with zero components (the box
    // test's 1/d), and short segments ending on a plane.
    std::vector<Ray> rays;
    const glm::vec3 origins[] = {{0.25f, 0.25f, 0.5f}, {0.5f, 0.25f, 0.25f}, {0.125f, 0.375f, 0.5f},
                                 {0.0f, 0.0f, 0.0f},   {0.25f, 0.25f, 0.0f}, {0.375f, 0.125f, 0.0f}};
    const glm::vec3 dirs[] = {{0, 0, 1},  {0, 0, -1}, {0, 1, 0},           {0, -1, 0},
                              {1, 0, 0},  {-1, 0, 0}, {0.3f, 0.0f, -1.0f}, {0.0f, 0.2f, 1.0f}};
    for (const glm::vec3& o : origins)
        for (const glm::vec3& d : dirs)
            for (float tmax : {1e30f, 0.25f, 0.5f}) rays.push_back(Ray{o, 0.0f, d, tmax});
    std::mt19937 rng(4);
    std::uniform_int_distribution<int> cell(0, 8);
    for (int k = 0; k < 3000; ++k) {  // from grid points, straight along an axis or not
        const glm::vec3 o(cell(rng) * 0.125f, cell(rng) * 0.125f, cell(rng) * 0.125f);
        glm::vec3 d(0.0f);
        d[k % 3] = k % 2 ? 1.0f : -1.0f;
        if (k % 5 == 0) d[(k + 1) % 3] = 0.01f * static_cast<float>(cell(rng));
        rays.push_back(Ray{o, 0.0f, d, 1e30f});
    }
    CHECK(wide_mismatches(file.view(), rays) == 0);
}

TEST_CASE("the wide walk finds grazing hits from far outside the scene", "[geometry][traversal][wide]") {
    // Rays from 10^3 scene sizes away aimed at triangle vertices and edge points: the slab test's
    // roundings there exceed the boxes' margin, and only the exit slack keeps the boxes entered
    // (without it 9 of these rays miss). From 10^4 away the triangle test's own roundings put
    // hits outside the triangle's bounds (a hit 0.8 units off its aim point); no box holds those.
    const auto tris = test::random_soup(2000, 16, 0.05f);
    const auto bytes = test::build_bytes(scene_from_triangles(tris));
    const GeometryFile file = GeometryFile::from_bytes(bytes, "soup.kdg");
    std::mt19937 rng(17);
    std::normal_distribution<float> gauss(0.0f, 1.0f);
    std::vector<Ray> rays;
    for (const TriangleRecord& t : tris) {
        for (float w : {0.0f, 0.5f, 1.0f}) {
            const glm::vec3 target = glm::vec3(t.v0[0], t.v0[1], t.v0[2]) + w * glm::vec3(t.e1[0], t.e1[1], t.e1[2]);
            const glm::vec3 away = 1000.0f * glm::normalize(glm::vec3(gauss(rng), gauss(rng), gauss(rng)));
            rays.push_back(Ray{target + away, 0.0f, -away, 1e30f});
        }
    }
    CHECK(wide_mismatches(file.view(), rays) == 0);
}

TEST_CASE("the wide walk finds brute force's hits on the shipped Cornell box", "[geometry][traversal][wide]") {
    const Scene scene = load_scene_input(test::source_path("scenes/cornell-box/cornell-box.json"));
    const auto bytes = test::build_bytes(scene);
    const GeometryFile file = GeometryFile::from_bytes(bytes, "cornell-box.kdg");
    CHECK(wide_mismatches(file.view(), test::random_rays(40000, 7, -0.99f, 1.99f)) == 0);
}

TEST_CASE("the wide tree collapses the kd-tree and holds each of its leaves once", "[geometry][wide]") {
    const Scene scene = scene_from_triangles(test::random_soup(5000, 9, 0.03f));
    const auto build = build_geometry_file(scene, KdBuildParams{});
    const auto bytes = build.writer.bytes();
    const GeometryFile file = GeometryFile::from_bytes(bytes, "soup.kdg");
    const GeometryView& g = file.view();
    REQUIRE(g.wide != nullptr);
    std::set<std::uint32_t> kd_leaves, slots;
    for (std::uint32_t i = 0; i < g.node_count; ++i)
        if (g.nodes[i].is_leaf() && g.nodes[i].count() > 0) kd_leaves.insert(g.nodes[i].first());
    std::size_t used = 0;
    for (std::uint32_t i = 0; i < g.wide_node_count; ++i) {
        used += wide_used_slots(g.wide[i]);
        for (std::uint32_t j = 0; j < kWideWidth; ++j)
            if (g.wide[i].count[j] != 0 && g.wide[i].count[j] != kWideInner)
                CHECK(slots.insert(g.wide[i].child[j]).second);
    }
    CHECK(slots == kd_leaves);  // a high-quality build's leaves all meet their cells
    // Three kd levels and more per wide node, and their empty leaves gone.
    CHECK(g.wide_node_count * 8 < g.node_count);
    CHECK(static_cast<double>(used) / g.wide_node_count > 3.0);
    const Metadata meta = file.metadata();
    CHECK(meta.statistics.at("wide_nodes") == g.wide_node_count);
}

TEST_CASE("a corrupt geometry.wide is refused with its fault named", "[geometry][wide][hostile]") {
    const auto good = test::build_bytes(scene_from_triangles(test::random_soup(2000, 12, 0.05f)));
    REQUIRE(refusal(good, true).empty());
    const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
    struct Case {
        const char* what;
        std::function<void(std::vector<WideNode>&)> edit;
        const char* message;
    };
    const Case cases[] = {
        {"a child pointing back at the root",
         [](std::vector<WideNode>& w) {
             auto [n, j] = find_slot(w, true);
             w[n].child[j] = 0;
         },
         "has a child index out of range"},
        {"a child past the end",
         [](std::vector<WideNode>& w) {
             auto [n, j] = find_slot(w, true);
             w[n].child[j] = static_cast<std::uint32_t>(w.size());
         },
         "has a child index out of range"},
        {"a NaN box", [&](std::vector<WideNode>& w) { w[0].lo[1][0] = nan; }, "not finite and ordered"},
        {"a box larger than its parent's",
         [](std::vector<WideNode>& w) {
             auto [n, j] = find_slot(w, true);
             w[w[n].child[j]].hi[0][0] += 1.0f;
         },
         "outside its parent's"},
        {"a leaf slot that is no kd leaf",
         [](std::vector<WideNode>& w) {
             auto [n, j] = find_slot(w, false);
             w[n].count[j] += 1;
         },
         "is not a leaf of geometry.nodes"},
        {"one kd leaf in two slots",
         [](std::vector<WideNode>& w) {
             auto [n, j] = find_slot(w, false);
             for (std::uint32_t m = 0; m < w.size(); ++m)
                 for (std::uint32_t k = 0; k < kWideWidth; ++k)
                     if ((m != n || k != j) && w[m].count[k] != 0 && w[m].count[k] != kWideInner) {
                         w[m].child[k] = w[n].child[j];
                         w[m].count[k] = w[n].count[j];
                         return;
                     }
             FAIL("no second leaf slot");
         },
         "is the slot of two wide nodes"},
        {"an empty slot with a box",
         [&](std::vector<WideNode>& w) {
             for (WideNode& n : w)
                 for (std::uint32_t j = 0; j < kWideWidth; ++j)
                     if (n.count[j] == 0) {
                         n.lo[0][j] = 0.0f;
                         return;
                     }
             FAIL("no empty slot");
         },
         "is empty but has a box"},
        {"a node nobody points at",
         [&](std::vector<WideNode>& w) { w.push_back(w.back()); },
         "not reachable from the root"},
    };
    for (const Case& c : cases) {
        INFO(c.what);
        const std::string why = refusal(with_wide(good, c.edit), false);
        CHECK_THAT(why, Catch::Contains("geometry.wide") && Catch::Contains(c.message));
        CHECK(why.find('\n') == std::string::npos);
    }
    (void)inf;

    SECTION("a leaf box too small for its triangles fails only the exhaustive check") {
        const auto shrunk = with_wide(good, [](std::vector<WideNode>& w) {
            auto [n, j] = find_slot(w, false);
            for (int a = 0; a < 3; ++a) {
                const float mid = 0.5f * (w[n].lo[a][j] + w[n].hi[a][j]);
                w[n].lo[a][j] = w[n].hi[a][j] = mid;
            }
        });
        CHECK(refusal(shrunk, false).empty());
        CHECK_THAT(refusal(shrunk, true), Catch::Contains("does not hold triangle"));
    }
}

TEST_CASE("a format 1.1 file without the wide tree loads and traces with the binary walk", "[geometry][wide]") {
    const auto tris = test::random_soup(1500, 14, 0.05f);
    const auto current = test::build_bytes(scene_from_triangles(tris));
    const auto old = with_wide(current, {});
    const ContainerReader r = ContainerReader::from_bytes(old, "old.kdg");
    CHECK(r.header().version_minor == 1);
    REQUIRE(refusal(old, true).empty());
    const GeometryFile file = GeometryFile::from_bytes(old, "old.kdg");
    CHECK(file.view().wide == nullptr);
    const GeometryFile now = GeometryFile::from_bytes(current, "new.kdg");
    CHECK(now.view().wide != nullptr);
    const auto rays = test::random_rays(5000, 15);
    CHECK(test::count_mismatches(file.view(), rays) == 0);
    int differ = 0;
    for (const Ray& ray : rays) differ += !same_bits(closest_hit(file.view(), ray), closest_hit_kd(now.view(), ray));
    CHECK(differ == 0);
}
