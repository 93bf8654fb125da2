#pragma once
// nanoflann's kd-tree over the same photon positions: the reference the gather benchmark
// compares the kNN kernel with.
#include <cstdint>
#include <memory>
#include <vector>

#include <nanoflann.hpp>

namespace kdpm::photon_tools {

struct PointCloud {
    std::vector<float> x, y, z;
    std::size_t kdtree_get_point_count() const { return x.size(); }
    float kdtree_get_pt(std::size_t i, std::size_t d) const { return d == 0 ? x[i] : (d == 1 ? y[i] : z[i]); }
    template <class Box>
    bool kdtree_get_bbox(Box&) const {
        return false;
    }
};

using NanoflannTree =
    nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<float, PointCloud>, PointCloud, 3, std::uint32_t>;

}  // namespace kdpm::photon_tools
