#include "tools/bench/peer_nanoflann.h"

#include <nanoflann.hpp>

#include <chrono>
#include <vector>

#include "runtime/backend/cpu_parallel_for.h"

namespace kdpm::bench {
namespace {

struct PhotonCloud {
    std::span<const float> x, y, z;
    std::size_t kdtree_get_point_count() const { return x.size(); }
    float kdtree_get_pt(std::size_t i, std::size_t dim) const { return dim == 0 ? x[i] : dim == 1 ? y[i] : z[i]; }
    template <class Box>
    bool kdtree_get_bbox(Box&) const { return false; }
};

using Tree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<float, PhotonCloud>, PhotonCloud, 3,
                                                 std::uint32_t>;

}  // namespace

struct NanoflannPeer::State {
    PhotonCloud cloud;
    std::unique_ptr<Tree> tree;
};

NanoflannPeer::NanoflannPeer(std::span<const float> x, std::span<const float> y, std::span<const float> z)
    : state_(std::make_unique<State>()) {
    state_->cloud = {x, y, z};
    auto start = std::chrono::steady_clock::now();
    state_->tree = std::make_unique<Tree>(3, state_->cloud, nanoflann::KDTreeSingleIndexAdaptorParams(10));
    state_->tree->buildIndex();
    build_ms_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

NanoflannPeer::~NanoflannPeer() = default;

void NanoflannPeer::knn(std::span<const float> queries, int k, std::span<float> kth_distance2) const {
    const Tree& tree = *state_->tree;
    cpu_parallel_for(queries.size() / 3, [&](std::uint64_t q) {
        std::uint32_t index[256];
        float dist2[256];
        nanoflann::KNNResultSet<float, std::uint32_t> result(static_cast<std::size_t>(k));
        result.init(index, dist2);
        tree.findNeighbors(result, &queries[q * 3], nanoflann::SearchParams());
        kth_distance2[q] = result.size() ? dist2[result.size() - 1] : 0.0f;
    }, 64);
}

}  // namespace kdpm::bench
