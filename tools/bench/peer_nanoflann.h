#pragma once
// nanoflann, a peer for kdpm-bench only: its kd-tree k-nearest queries over the same photon
// positions and query points as kdpm's gather.
#include <cstdint>
#include <memory>
#include <span>

namespace kdpm::bench {

class NanoflannPeer {
public:
    NanoflannPeer(std::span<const float> x, std::span<const float> y, std::span<const float> z);
    ~NanoflannPeer();
    double build_ms() const { return build_ms_; }
    // For each query point (3 floats), finds the k nearest photons; writes the squared distance
    // of the k-th nearest into kth_distance2 (a checksum of the work, and a cross-check).
    void knn(std::span<const float> queries, int k, std::span<float> kth_distance2) const;

private:
    struct State;
    std::unique_ptr<State> state_;
    double build_ms_ = 0;
};

}  // namespace kdpm::bench
