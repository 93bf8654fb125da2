#include <catch2/catch.hpp>

#include <cstring>
#include <random>

#include "builders/photons/photon_tree_builder.h"
#include "builders/photons/photon_tree_writer.h"
#include "formats/container_reader.h"
#include "formats/section_ids.h"
#include "formats/tree_validation.h"
#include "runtime/photons/photon_map_file.h"
#include "tests/photons/synthetic_photons.h"
#include "tests/support/error_text.h"

using namespace kdpm;

namespace {

void validate_bytes(const std::vector<std::uint8_t>& bytes) {
    auto reader = ContainerReader::from_bytes(bytes, "x");
    validate_file(reader, ValidationOptions{});
}

// Rewrites a tree file with one section's bytes altered (checksums stay consistent, so only
// the structural checks can catch it).
template <class Edit>
std::vector<std::uint8_t> tampered_tree(const BuiltPhotonTree& original, Edit edit) {
    BuiltPhotonTree t = original;
    edit(t);
    ContainerWriter w(FileKind::photon_tree);
    add_photon_tree_sections(w, PhotonMapKind::global, t);
    w.set_metadata(Metadata{});
    return w.bytes();
}

}  // namespace

TEST_CASE("Photon hit files with broken contents are rejected", "[photons][corrupt]") {
    auto good = test::synthetic_photons(500, 8);
    auto bytes_of = [](const PhotonHitSet& s) { return photon_hits_writer(s, Metadata{}).bytes(); };
    CHECK_NOTHROW(validate_bytes(bytes_of(good)));

    auto bad = good;
    bad.hits[10].position[0] = std::nanf("");
    CHECK_THROWS_AS(validate_bytes(bytes_of(bad)), FormatError);
    bad = good;
    bad.hits[3].power[1] = -1.0f;
    CHECK_THROWS_AS(validate_bytes(bytes_of(bad)), FormatError);
    bad = good;
    bad.hits[3].direction[0] = 3.0f;
    CHECK_THROWS_AS(validate_bytes(bytes_of(bad)), FormatError);
    bad = good;
    bad.hits[3].flags = make_photon_flags(9, false);  // beyond max_bounces 4
    CHECK_THROWS_AS(validate_bytes(bytes_of(bad)), FormatError);
    bad = good;
    bad.info.stored_count += 1;
    CHECK_THROWS_AS(validate_bytes(bytes_of(bad)), FormatError);
    bad = good;
    bad.info.caustic_count += 1;
    CHECK_THROWS_AS(validate_bytes(bytes_of(bad)), FormatError);
    bad = good;
    bad.hits[7].position[2] = bad.info.bounds_max[2] + 1.0f;
    CHECK_THROWS_AS(validate_bytes(bytes_of(bad)), FormatError);
}

TEST_CASE("Photon tree files with broken structure are rejected", "[photons][corrupt]") {
    auto set = test::synthetic_photons(3000, 9);
    auto tree = build_photon_tree(set.hits, PhotonTreeOptions{}, 3000, 4);
    CHECK_NOTHROW(validate_bytes(tampered_tree(tree, [](BuiltPhotonTree&) {})));

    auto first_inner = [](const BuiltPhotonTree& t) {
        for (std::size_t i = 0; i < t.nodes.size(); ++i)
            if (!t.nodes[i].is_leaf()) return i;
        return std::size_t{0};
    };
    auto first_leaf = [](const BuiltPhotonTree& t) {
        for (std::size_t i = 0; i < t.nodes.size(); ++i)
            if (t.nodes[i].is_leaf() && t.nodes[i].count() > 0) return i;
        return std::size_t{0};
    };
    std::vector<std::pair<const char*, std::vector<std::uint8_t>>> cases = {
        {"above child out of range", tampered_tree(tree, [&](BuiltPhotonTree& t) {
             auto& n = t.nodes[first_inner(t)];
             n = KdNode::inner(n.axis(), n.split(), 1u << 29);
         })},
        {"above child pointing back", tampered_tree(tree, [&](BuiltPhotonTree& t) {
             auto& n = t.nodes[first_inner(t)];
             n = KdNode::inner(n.axis(), n.split(), 0);
         })},
        {"leaf count too large", tampered_tree(tree, [&](BuiltPhotonTree& t) {
             t.nodes[first_leaf(t)] = KdNode::leaf(t.nodes[first_leaf(t)].first(), 1u << 28);
         })},
        {"photon moved out of its cell", tampered_tree(tree, [&](BuiltPhotonTree& t) {
             t.x[t.nodes[first_leaf(t)].first()] = t.info.bounds_max[0];
             t.x.back() = t.info.bounds_min[0];
         })},
        {"non-finite position", tampered_tree(tree, [&](BuiltPhotonTree& t) { t.y[5] = std::nanf(""); })},
        {"photon count mismatch", tampered_tree(tree, [&](BuiltPhotonTree& t) { t.flags.pop_back(); })},
        {"unknown flags", tampered_tree(tree, [&](BuiltPhotonTree& t) { t.flags[2] |= 0x80000000u; })},
        {"wrong statistics", tampered_tree(tree, [&](BuiltPhotonTree& t) { t.info.leaf_count += 1; })},
        {"too deep", tampered_tree(tree, [&](BuiltPhotonTree& t) { t.info.max_depth = 1000; })},
    };
    for (auto& [what, bytes] : cases) {
        INFO(what);
        CHECK_THROWS_AS(validate_bytes(bytes), FormatError);
        CHECK_THROWS_AS(PhotonMapFile::from_bytes(bytes, "bad.kdp"), FormatError);
    }
}

TEST_CASE("Random byte damage to a photon tree never crashes the loader", "[photons][corrupt]") {
    auto set = test::synthetic_photons(400, 10);
    auto tree = build_photon_tree(set.hits, PhotonTreeOptions{}, 400, 4);
    auto good = tampered_tree(tree, [](BuiltPhotonTree&) {});
    std::mt19937 rng(12);
    int rejected = 0;
    for (int trial = 0; trial < 300; ++trial) {
        auto bytes = good;
        int flips = 1 + trial % 4;
        for (int f = 0; f < flips; ++f) bytes[rng() % bytes.size()] ^= static_cast<std::uint8_t>(1u << (rng() % 8));
        if (trial % 5 == 0) bytes.resize(rng() % bytes.size());
        try {
            PhotonMapFile::from_bytes(bytes, "fuzz.kdp");
        } catch (const FormatError&) {
            ++rejected;
        }
    }
    CHECK(rejected == 300);  // checksums catch every flip and truncation
}

TEST_CASE("A large photon tree file reports its first fault as a small one does", "[photons][corrupt]") {
    // Over a megabyte: the checksums run beside the structural checks (tree_validation.cpp).
    auto set = test::synthetic_photons(60000, 13);
    auto tree = build_photon_tree(set.hits, PhotonTreeOptions{}, 60000, 4);
    const auto good = tampered_tree(tree, [](BuiltPhotonTree&) {});
    REQUIRE(good.size() > (std::size_t{1} << 20));
    CHECK_NOTHROW(validate_bytes(good));
    auto message = [](const std::vector<std::uint8_t>& bytes) { return test::error_text([&] { validate_bytes(bytes); }); };

    // Checksums consistent: the structural fault is named.
    const auto moved = tampered_tree(tree, [](BuiltPhotonTree& t) { t.x.back() = t.info.bounds_min[0] - 1.0f; });
    const std::string structural = message(moved);
    INFO(structural);
    CHECK_THAT(structural, Catch::Contains("lies outside the cell of leaf"));

    // The same damage written over the good file's bytes: both passes fail, the checksum is named.
    auto damaged = good;
    auto reader = ContainerReader::from_bytes(good, "x");
    const SectionEntry* xs = reader.find(photon_tree_section(PhotonMapKind::global, ptree_field_x));
    REQUIRE(xs != nullptr);
    const float outside = tree.info.bounds_min[0] - 1.0f;
    std::memcpy(damaged.data() + xs->offset + xs->byte_size - sizeof(float), &outside, sizeof outside);
    const std::string m = message(damaged);
    CHECK_THAT(m, Catch::Contains("is corrupt (checksum"));
    INFO(m);
    CHECK(m.find("lies outside") == std::string::npos);
}

TEST_CASE("A photon tree's cells are closed at the root's upper bounds and open at splits", "[photons][corrupt]") {
    auto set = test::synthetic_photons(3000, 21);
    const auto tree = build_photon_tree(set.hits, PhotonTreeOptions{}, 3000, 4);
    REQUIRE(!tree.nodes[0].is_leaf());
    auto coords = [](BuiltPhotonTree& t, int axis) -> std::vector<float>& { return axis == 0 ? t.x : axis == 1 ? t.y : t.z; };
    auto largest = [&](const BuiltPhotonTree& t, int axis, std::size_t end) {
        auto& c = coords(const_cast<BuiltPhotonTree&>(t), axis);
        return static_cast<std::size_t>(std::max_element(c.begin(), c.begin() + static_cast<std::ptrdiff_t>(end)) - c.begin());
    };
    auto outcome = [&](int axis, std::size_t photon, float value) {
        return test::error_text([&] {
            validate_bytes(tampered_tree(tree, [&](BuiltPhotonTree& t) { coords(t, axis)[photon] = value; }));
        });
    };
    for (int a = 0; a < 3; ++a) {
        INFO("axis " << a);
        // The photon furthest up the axis lies in a leaf bounded above by the root's bounds.
        const std::size_t top = largest(tree, a, tree.x.size());
        const float bound = tree.info.bounds_max[a];
        CHECK(outcome(a, top, bound) == "accepted");
        CHECK_THAT(outcome(a, top, std::nextafter(bound, HUGE_VALF)), Catch::Contains("lies outside the cell"));
    }
    // The root's below subtree holds the photons before its above subtree's first leaf; its
    // furthest photon along the split axis lies in a leaf bounded above by the root's split.
    const KdNode root = tree.nodes[0];
    std::uint32_t node = root.above_child();
    while (!tree.nodes[node].is_leaf()) ++node;  // pre-order: the first leaf below the above child
    const std::size_t below_end = tree.nodes[node].first();
    REQUIRE(below_end > 0);
    const std::size_t edge = largest(tree, root.axis(), below_end);
    CHECK(outcome(root.axis(), edge, std::nextafter(root.split(), -HUGE_VALF)) == "accepted");
    CHECK_THAT(outcome(root.axis(), edge, root.split()), Catch::Contains("lies outside the cell"));
}
