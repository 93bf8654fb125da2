// The parallel steps of a large photon node give exactly what their sequential versions give,
// on more photons than one chunk, with ties, coincident points and both signed zeros.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstring>
#include <numeric>
#include <vector>

#include "builders/photons/large_node.h"
#include "runtime/backend/thread_limit.h"
#include "tests/photons/synthetic_photons.h"

using namespace kdpm;
using namespace kdpm::photon_build;

namespace {

bool same_bits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }

struct Cloud {
    std::vector<float> axis[3];
    std::vector<std::uint32_t> idx;
    // The photons in index order, as the builder moves them.
    std::vector<PhotonRecord> records() const {
        std::vector<PhotonRecord> r;
        for (std::uint32_t i : idx) r.push_back({{axis[0][i], axis[1][i], axis[2][i]}, i});
        return r;
    }
};

std::vector<std::uint32_t> indices(const std::vector<PhotonRecord>& r) {
    std::vector<std::uint32_t> out;
    for (const PhotonRecord& p : r) out.push_back(p.index);
    return out;
}

// Synthetic photons, in a shuffled index order; the x minimum is a +0 met first and a -0 met
// last, so a bounds scan must keep the +0.
Cloud cloud(std::uint32_t n, std::uint32_t seed) {
    const PhotonHitSet set = test::synthetic_photons(n, seed);
    Cloud c;
    for (int a = 0; a < 3; ++a)
        for (const PhotonHit& h : set.hits) c.axis[a].push_back(h.position[a]);
    float lowest = *std::min_element(c.axis[0].begin(), c.axis[0].end());
    for (float& x : c.axis[0]) x = x - lowest + 1.0f;  // all above 0 but the two below
    c.idx.resize(n);
    std::iota(c.idx.begin(), c.idx.end(), 0u);
    for (std::uint32_t i = n - 1; i > 0; --i) std::swap(c.idx[i], c.idx[(i * 2654435761u) % (i + 1)]);
    c.axis[0][c.idx[0]] = 0.0f;       // met first, in the first chunk
    c.axis[0][c.idx[n - 1]] = -0.0f;  // met last, in the last chunk
    return c;
}

}  // namespace

TEST_CASE("parallel large-node steps equal the sequential ones", "[photons][builder]") {
    const std::uint32_t n = 3 * kLargeNode + 12345;
    Cloud c = cloud(n, 9);
    const std::vector<PhotonRecord> p = c.records();
    ThreadLimit limit(2);

    const Cell seq = photon_bounds(p.data(), n), par = parallel_photon_bounds(p.data(), n);
    for (int a = 0; a < 3; ++a) {
        CHECK(same_bits(seq.lo[a], par.lo[a]));
        CHECK(same_bits(seq.hi[a], par.hi[a]));
    }

    Cell cell = seq;
    for (int a = 0; a < 3; ++a) cell.lo[a] -= 1.0f, cell.hi[a] += 1.0f;
    for (float radius : {0.01f, 0.3f}) {
        const SplitChoice s = choose_vvh_split(p.data(), n, cell, radius, 16);
        const SplitChoice q = parallel_vvh_split(p.data(), n, cell, radius, 16);
        CHECK(s.make_leaf == q.make_leaf);
        CHECK(s.axis == q.axis);
        CHECK(same_bits(s.position, q.position));
    }

    for (int axis = 0; axis < 3; ++axis) {
        // A plane at an existing coordinate: ties go above, as in the builder.
        const float plane = c.axis[axis][c.idx[n / 2]];
        std::vector<std::uint32_t> expected = c.idx;
        std::vector<PhotonRecord> got = p;
        const float* coord = c.axis[axis].data();
        const auto mid = std::stable_partition(expected.begin(), expected.end(),
                                               [&](std::uint32_t i) { return coord[i] < plane; });
        const std::uint32_t below = parallel_stable_partition(got.data(), n, axis, plane);
        CHECK(below == static_cast<std::uint32_t>(mid - expected.begin()));
        CHECK(indices(got) == expected);
    }
}
