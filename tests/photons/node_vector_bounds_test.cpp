// Per-node boxes of the photons' decoded vectors (bound_node_vectors) and the surface filter's
// rejects_node: a box holds every vector below its node, a node is ruled out only when no photon
// below it passes the filter, and k-nearest estimates that skip ruled-out nodes are the same bit
// for bit.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>
#include <vector>

#include "runtime/photons/irradiance_lookup.h"
#include "runtime/photons/node_vector_bounds.h"
#include "runtime/photons/radiance_estimate.h"
#include "tests/photons/decoded_photon_views.h"

using namespace kdpm;
using test::DecodedPhotonViews;

namespace {

// The indices of the photons below `node`.
void photons_below(const PhotonMapView& map, std::uint32_t node, std::vector<std::uint32_t>& out) {
    std::vector<std::uint32_t> todo{node};
    while (!todo.empty()) {
        const std::uint32_t i = todo.back();
        todo.pop_back();
        const KdNode n = map.nodes[i];
        if (n.is_leaf()) {
            for (std::uint32_t p = n.first(); p < n.first() + n.count(); ++p) out.push_back(p);
        } else {
            todo.push_back(i + 1);
            todo.push_back(n.above_child());
        }
    }
}

glm::vec3 random_point(std::mt19937& rng) {
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    const float x = u(rng), y = u(rng);
    return glm::vec3(x, y, u(rng));
}

glm::vec3 random_unit(std::mt19937& rng) {
    std::normal_distribution<float> g;
    for (;;) {
        const glm::vec3 v(g(rng), g(rng), g(rng));
        const float l = std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
        if (l > 1e-3f) return v / l;
    }
}

}  // namespace

TEST_CASE("A node's vector boxes hold the decoded vectors of every photon below it", "[photons][bounds]") {
    const DecodedPhotonViews views(6000, 71);
    const PhotonMapView& map = views.bounded;
    REQUIRE(views.bounds.size() == std::size_t{map.node_count} * kVectorBoundFloats);
    const std::uint64_t n = map.photon_count;
    std::uint32_t empty_leaves = 0;
    for (std::uint32_t node = 0; node < map.node_count; ++node) {
        const float* box = map.vector_bounds + std::uint64_t{node} * kVectorBoundFloats;
        CHECK(box[11] == 0.0f);
        CHECK(box[15] == 0.0f);
        std::vector<std::uint32_t> below;
        photons_below(map, node, below);
        if (below.empty()) {
            ++empty_leaves;
            CHECK(box[0] > box[4]);  // an empty box
            CHECK(box[kMaxBounceAt] == -1.0f);
            continue;
        }
        std::uint32_t max_bounce = 0, common = kPhotonKnownFlags;
        for (std::uint32_t p : below) {
            max_bounce = std::max(max_bounce, photon_bounce(map.flags[p]));
            common &= map.flags[p];
        }
        REQUIRE(box[kMaxBounceAt] == static_cast<float>(max_bounce));
        REQUIRE(box[kCommonFlagsAt] == static_cast<float>(common));
        for (std::uint32_t c = 0; c < 6; ++c) {
            const std::uint32_t lo = c < 3 ? c : 8 + (c - 3);
            float least = INFINITY, most = -INFINITY;
            for (std::uint32_t p : below) {
                least = std::fmin(least, map.unpacked[c * n + p]);
                most = std::fmax(most, map.unpacked[c * n + p]);
            }
            // Exactly the least and greatest component: the boxes are tight.
            REQUIRE(box[lo] == least);
            REQUIRE(box[lo + 4] == most);
        }
    }
    INFO("empty leaves " << empty_leaves);
    PhotonMapView none;
    CHECK(bound_node_vectors(none).empty());
}

TEST_CASE("A NaN vector leaves its nodes' boxes unbounded, ruled out by no filter", "[photons][bounds]") {
    const DecodedPhotonViews views(3000, 73);
    PhotonMapView map = views.unpacked;
    std::vector<float> vectors = views.vectors;
    // Photon 0 lies in the first leaf on the root's below path; its direction's x becomes NaN.
    vectors[0] = NAN;
    map.unpacked = vectors.data();
    const std::vector<float> bounds = bound_node_vectors(map);
    map.vector_bounds = bounds.data();
    std::uint32_t node = 0;
    std::vector<std::uint32_t> path;
    while (true) {
        path.push_back(node);
        const KdNode k = map.nodes[node];
        if (k.is_leaf()) break;
        node = node + 1;  // below children hold the first photons
    }
    REQUIRE(map.nodes[node].first() == 0);
    for (std::uint32_t i : path) {
        CHECK(std::isinf(bounds[i * kVectorBoundFloats + 0]));
        CHECK(std::isinf(bounds[i * kVectorBoundFloats + 4]));
        // A direction test alone (no cosine): the NaN photon passes it whatever the normal, as
        // exact_from decides (a NaN sum is not "from behind"), so no node above it may go.
        for (const glm::vec3 normal : {glm::vec3(1, 0, 0), glm::vec3(-1, 0, 0), glm::vec3(0, 0, 1)}) {
            const SurfacePhotonFilter filter(map, normal, -1.0f, 0, 0);
            REQUIRE(filter(0));
            CHECK_FALSE(filter.rejects_node(i));
        }
    }
}

TEST_CASE("A node is ruled out only when the filter refuses every photon below it", "[photons][bounds]") {
    const DecodedPhotonViews views(8000, 75);
    const PhotonMapView& map = views.bounded;
    std::mt19937 rng(77);
    std::vector<std::vector<std::uint32_t>> below(map.node_count);
    for (std::uint32_t node = 0; node < map.node_count; ++node) photons_below(map, node, below[node]);
    std::uint64_t rejected = 0, asked = 0, leaves_rejected = 0, by_flags = 0;
    for (int trial = 0; trial < 72; ++trial) {
        // Axis normals (the synthetic walls') and random ones; cosines from none to the strictest.
        const glm::vec3 normal = trial < 6 ? glm::vec3(trial % 3 == 0, trial % 3 == 1, trial % 3 == 2) *
                                                 (trial < 3 ? 1.0f : -1.0f)
                                           : random_unit(rng);
        const float cosines[] = {-1.0f, 0.0f, 0.7f, 0.95f};
        const float min_cos = cosines[trial % 4];
        // Bounce and flag rules as the modes set them: none, direct hits skipped, caustics too.
        const std::uint32_t min_bounce = (trial / 4) % 3;
        const std::uint32_t exclude = (trial / 12) % 2 ? kPhotonCaustic : 0u;
        const SurfacePhotonFilter filter(map, normal, min_cos, min_bounce, exclude),
            vectors_only(map, normal, min_cos, 0, 0);
        REQUIRE(filter.node_test);
        for (std::uint32_t node = 0; node < map.node_count; ++node) {
            ++asked;
            if (!filter.rejects_node(node)) continue;
            ++rejected;
            by_flags += !vectors_only.rejects_node(node);
            leaves_rejected += map.nodes[node].is_leaf();
            for (std::uint32_t p : below[node]) {
                INFO("trial " << trial << " node " << node << " photon " << p);
                REQUIRE_FALSE(filter(p));
            }
        }
    }
    // Whole walls face away from most normals: many nodes go, leaves and inner ones.
    CHECK(rejected > asked / 10);
    CHECK(leaves_rejected > 0);
    CHECK(leaves_rejected < rejected);
    CHECK(by_flags > 0);
}

TEST_CASE("A photon exactly at the filter's cosine keeps its leaf", "[photons][bounds]") {
    const DecodedPhotonViews views(16000, 79);  // over 300 leaves of the default VVH tree
    const PhotonMapView& map = views.bounded;
    const std::uint64_t n = map.photon_count;
    std::mt19937 rng(81);
    std::uint32_t tried = 0;
    for (std::uint32_t node = 0; node < map.node_count && tried < 300; ++node) {
        const KdNode leaf = map.nodes[node];
        if (!leaf.is_leaf() || leaf.count() == 0) continue;
        ++tried;
        // A normal a photon of this leaf meets at exactly the filter's threshold, computed as the
        // filter computes it: the photon passes, so its leaf must stay.
        const std::uint32_t p = leaf.first() + static_cast<std::uint32_t>(rng() % leaf.count());
        const float d[3] = {map.unpacked[p], map.unpacked[n + p], map.unpacked[2 * n + p]};
        const float s[3] = {map.unpacked[3 * n + p], map.unpacked[4 * n + p], map.unpacked[5 * n + p]};
        const glm::vec3 normal(-d[0], -d[1], -d[2]);  // facing the photon's arrival
        const float threshold = s[0] * normal.x + s[1] * normal.y + s[2] * normal.z;
        if (!(threshold > -1.0f)) continue;
        const SurfacePhotonFilter filter(map, normal, threshold, 0, 0);
        REQUIRE(filter(p));
        REQUIRE_FALSE(filter.rejects_node(node));
    }
    CHECK(tried == 300);
}

TEST_CASE("Radiance estimates that skip ruled-out nodes equal those that scan them", "[photons][bounds]") {
    const DecodedPhotonViews views(20000, 83);
    std::mt19937 rng(85);
    static KnnHeap heap;
    std::uint32_t lit = 0;
    for (int q = 0; q < 600; ++q) {
        const glm::vec3 pos = random_point(rng);
        const glm::vec3 normal = q % 3 == 0 ? random_unit(rng) : glm::vec3(0, q % 3 == 1 ? 1 : -1, 0);
        RadianceEstimateParams params;
        params.k = q % 4 == 0 ? 8 : (q % 4 == 1 ? 64 : 32);
        params.min_normal_cos = q % 5 == 0 ? -1.0f : 0.7f;
        params.cone_filter = q % 6 == 1;
        params.min_bounce = q % 7 == 2 ? 1 : 0;
        params.exclude_flags = q % 9 == 4 ? kPhotonCaustic : 0u;
        params.max_radius = q % 8 == 3 ? 0.1f : 0.0f;
        const float hint = q % 2 ? 0.05f : 0.0f;
        const RadianceEstimate a = estimate_radiance(views.unpacked, pos, normal, glm::vec3(0.5f), params, heap, hint);
        const RadianceEstimate b = estimate_radiance(views.bounded, pos, normal, glm::vec3(0.5f), params, heap, hint);
        INFO("query " << q);
        test::require_same_estimate(a, b);
        lit += a.count > 0;
    }
    CHECK(lit > 200);
}

TEST_CASE("Irradiance lookups that skip ruled-out nodes find the same photon", "[photons][bounds]") {
    const DecodedPhotonViews views(12000, 87);
    std::vector<PrecomputedIrradiance> values(views.unpacked.photon_count);
    for (std::uint32_t p = 0; p < views.unpacked.photon_count; ++p)
        values[p] = PrecomputedIrradiance{{static_cast<float>(p), 0.0f, 1.0f}};
    const IrradianceMapView plain{views.unpacked, values.data()}, bounded{views.bounded, values.data()};
    std::mt19937 rng(89);
    static KnnHeap heap;
    std::uint32_t found = 0;
    for (int q = 0; q < 800; ++q) {
        const glm::vec3 pos = random_point(rng);
        const glm::vec3 normal = q % 2 ? random_unit(rng) : glm::vec3(0, 0, q % 4 == 0 ? 1 : -1);
        const float limit = q % 3 == 0 ? 0.0f : 0.2f;
        glm::vec3 a(-1.0f), b(-2.0f);
        const bool in_a = lookup_irradiance(plain, pos, normal, limit, 0.7f, 0.0f, heap, a);
        const bool in_b = lookup_irradiance(bounded, pos, normal, limit, 0.7f, 0.0f, heap, b);
        INFO("query " << q);
        REQUIRE(in_a == in_b);
        if (in_a) REQUIRE(a == b);
        found += in_a;
    }
    CHECK(found > 200);
}
