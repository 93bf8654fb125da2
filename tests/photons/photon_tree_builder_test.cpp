#include <catch2/catch.hpp>

#include <algorithm>

#include "builders/photons/photon_tree_builder.h"
#include "builders/photons/photon_tree_writer.h"
#include "formats/tree_validation.h"
#include "runtime/backend/thread_limit.h"
#include "runtime/photons/photon_map_file.h"
#include "tests/photons/synthetic_photons.h"

using namespace kdpm;

namespace {

ContainerWriter tree_file(const BuiltPhotonTree& t) {
    ContainerWriter w(FileKind::photon_tree);
    add_photon_tree_sections(w, PhotonMapKind::global, t);
    Metadata m;
    m.tool = "test";
    w.set_metadata(m);
    return w;
}

}  // namespace

TEST_CASE("Both builders put every photon in exactly one leaf and pass the validator", "[photons][builder]") {
    auto set = test::synthetic_photons(20000, 3);
    for (auto builder : {PhotonTreeBuilder::vvh, PhotonTreeBuilder::balanced})
        for (std::uint32_t leaf : {1u, 8u, 64u}) {
            PhotonTreeOptions options;
            options.builder = builder;
            options.leaf_size = leaf;
            auto t = build_photon_tree(set.hits, options, 20000, 4);
            INFO("builder " << static_cast<int>(builder) << " leaf size " << leaf);
            // The reorder is a permutation carrying each photon's data along.
            auto sorted = t.source;
            std::sort(sorted.begin(), sorted.end());
            for (std::uint32_t i = 0; i < sorted.size(); ++i) REQUIRE(sorted[i] == i);
            for (std::uint32_t i = 0; i < t.x.size(); ++i) {
                REQUIRE(t.x[i] == set.hits[t.source[i]].position[0]);
                REQUIRE(t.flags[i] == set.hits[t.source[i]].flags);
            }
            CHECK(t.info.max_depth <= kMaxPhotonTreeDepth);
            // A leaf may exceed the leaf size only when its photons all coincide.
            for (const KdNode& n : t.nodes) {
                if (!n.is_leaf() || n.count() <= leaf) continue;
                for (std::uint32_t p = n.first(); p < n.first() + n.count(); ++p)
                    REQUIRE((t.x[p] == t.x[n.first()] && t.y[p] == t.y[n.first()] && t.z[p] == t.z[n.first()]));
            }
            auto bytes = tree_file(t).bytes();
            auto file = PhotonMapFile::from_bytes(bytes, "tree.kdp");  // validates
            CHECK(file.view().photon_count == set.hits.size());
        }
}

TEST_CASE("Many coincident photons still give a valid tree", "[photons][builder]") {
    auto set = test::synthetic_photons(1, 1);
    std::vector<PhotonHit> same(5000, set.hits[0]);
    for (auto builder : {PhotonTreeBuilder::vvh, PhotonTreeBuilder::balanced}) {
        PhotonTreeOptions options;
        options.builder = builder;
        auto t = build_photon_tree(same, options, 1, 4);
        auto bytes = tree_file(t).bytes();
        CHECK_NOTHROW(PhotonMapFile::from_bytes(bytes, "same.kdp"));
    }
}

TEST_CASE("The photon tree does not depend on the thread count", "[photons][builder]") {
    // More photons than a large node, so that the root is split in parallel chunks.
    auto set = test::synthetic_photons(150000, 4);
    for (auto builder : {PhotonTreeBuilder::vvh, PhotonTreeBuilder::balanced}) {
        PhotonTreeOptions options;
        options.builder = builder;
        std::vector<std::uint8_t> one, two;
        {
            ThreadLimit limit(1);
            one = tree_file(build_photon_tree(set.hits, options)).bytes();
        }
        {
            ThreadLimit limit(2);
            two = tree_file(build_photon_tree(set.hits, options)).bytes();
        }
        CHECK(one == two);
    }
}
