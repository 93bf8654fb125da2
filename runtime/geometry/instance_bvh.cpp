#include "runtime/geometry/instance_bvh.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "runtime/geometry/affine.h"

namespace kdpm {
namespace {

constexpr int kBins = 16;
// Below this depth splits are at the median, which halves the count: the depth stays bounded.
constexpr std::uint32_t kSahDepth = 64;

struct Bounds {
    float lo[3] = {std::numeric_limits<float>::infinity(), std::numeric_limits<float>::infinity(),
                   std::numeric_limits<float>::infinity()};
    float hi[3] = {-std::numeric_limits<float>::infinity(), -std::numeric_limits<float>::infinity(),
                   -std::numeric_limits<float>::infinity()};
    void grow(const WorldBox& b) {
        for (int a = 0; a < 3; ++a) lo[a] = std::min(lo[a], b.lo[a]), hi[a] = std::max(hi[a], b.hi[a]);
    }
    void grow(const Bounds& b) {
        for (int a = 0; a < 3; ++a) lo[a] = std::min(lo[a], b.lo[a]), hi[a] = std::max(hi[a], b.hi[a]);
    }
    double area() const {
        if (!(lo[0] <= hi[0])) return 0.0;
        const double x = hi[0] - lo[0], y = hi[1] - lo[1], z = hi[2] - lo[2];
        return x * y + y * z + z * x;
    }
};

float centre(const WorldBox& b, int axis) { return 0.5f * (b.lo[axis] + b.hi[axis]); }

class Builder {
public:
    Builder(std::span<const WorldBox> boxes) : boxes_(boxes) {
        order_.resize(boxes.size());
        for (std::uint32_t i = 0; i < order_.size(); ++i) order_[i] = i;
        nodes_.reserve(2 * boxes.size());
    }

    std::vector<InstanceNode> build() {
        if (boxes_.empty()) return {};
        nodes_.emplace_back();
        make(0, 0, static_cast<std::uint32_t>(order_.size()), 0);
        return std::move(nodes_);
    }

private:
    void make(std::uint32_t node, std::uint32_t begin, std::uint32_t end, std::uint32_t depth) {
        Bounds box, centres;
        for (std::uint32_t i = begin; i < end; ++i) {
            const WorldBox& b = boxes_[order_[i]];
            box.grow(b);
            WorldBox c{};
            for (int a = 0; a < 3; ++a) c.lo[a] = c.hi[a] = centre(b, a);
            centres.grow(c);
        }
        InstanceNode& n = nodes_[node];
        for (int a = 0; a < 3; ++a) n.lo[a] = box.lo[a], n.hi[a] = box.hi[a];
        if (end - begin == 1) {
            n.first = order_[begin];
            n.count = 1;
            return;
        }
        const std::uint32_t mid = split(begin, end, centres, depth);
        const auto first = static_cast<std::uint32_t>(nodes_.size());
        nodes_[node].first = first;
        nodes_[node].count = 0;
        nodes_.emplace_back();
        nodes_.emplace_back();
        make(first, begin, mid, depth + 1);
        make(first + 1, mid, end, depth + 1);
    }

    // The split of [begin, end): the cheapest binned SAH plane over the centres' longest axes,
    // or the median of the longest axis (deep levels, or centres that all coincide).
    std::uint32_t split(std::uint32_t begin, std::uint32_t end, const Bounds& centres, std::uint32_t depth) {
        int axis = 0;
        for (int a = 1; a < 3; ++a)
            if (centres.hi[a] - centres.lo[a] > centres.hi[axis] - centres.lo[axis]) axis = a;
        const float extent = centres.hi[axis] - centres.lo[axis];
        auto* first = order_.data() + begin;
        auto* last = order_.data() + end;
        auto median = [&] {
            const std::uint32_t mid = begin + (end - begin) / 2;
            std::nth_element(first, order_.data() + mid, last, [&](std::uint32_t x, std::uint32_t y) {
                const float cx = centre(boxes_[x], axis), cy = centre(boxes_[y], axis);
                return cx < cy || (cx == cy && x < y);
            });
            return mid;
        };
        if (depth >= kSahDepth || !(extent > 0.0f)) return median();

        Bounds bin_box[kBins];
        std::uint32_t bin_count[kBins] = {};
        const float scale = kBins / extent;
        auto bin_of = [&](std::uint32_t i) {
            const int b = static_cast<int>((centre(boxes_[i], axis) - centres.lo[axis]) * scale);
            return std::clamp(b, 0, kBins - 1);
        };
        for (std::uint32_t i = begin; i < end; ++i) {
            const int b = bin_of(order_[i]);
            bin_box[b].grow(boxes_[order_[i]]);
            ++bin_count[b];
        }
        double right_area[kBins];
        std::uint32_t right_count[kBins];
        Bounds acc;
        std::uint32_t count = 0;
        for (int b = kBins - 1; b > 0; --b) {
            acc.grow(bin_box[b]);
            count += bin_count[b];
            right_area[b] = acc.area();
            right_count[b] = count;
        }
        Bounds left;
        std::uint32_t left_count = 0;
        double best = std::numeric_limits<double>::infinity();
        int best_plane = -1;
        for (int b = 1; b < kBins; ++b) {
            left.grow(bin_box[b - 1]);
            left_count += bin_count[b - 1];
            if (left_count == 0 || right_count[b] == 0) continue;
            const double cost = left.area() * left_count + right_area[b] * right_count[b];
            if (cost < best) best = cost, best_plane = b;
        }
        if (best_plane < 0) return median();
        auto* mid = std::partition(first, last, [&](std::uint32_t i) { return bin_of(i) < best_plane; });
        return static_cast<std::uint32_t>(mid - order_.data());
    }

    std::span<const WorldBox> boxes_;
    std::vector<std::uint32_t> order_;
    std::vector<InstanceNode> nodes_;
};

}  // namespace

WorldBox placed_bounds(const GeometryInfo& object, const Affine& world_from_object) {
    WorldBox w{};
    for (int a = 0; a < 3; ++a) w.lo[a] = std::numeric_limits<float>::infinity(), w.hi[a] = -w.lo[a];
    for (int corner = 0; corner < 8; ++corner) {
        const glm::vec3 p((corner & 1) ? object.bounds_max[0] : object.bounds_min[0],
                          (corner & 2) ? object.bounds_max[1] : object.bounds_min[1],
                          (corner & 4) ? object.bounds_max[2] : object.bounds_min[2]);
        const glm::vec3 q = apply_point(world_from_object, p);
        for (int a = 0; a < 3; ++a) w.lo[a] = std::min(w.lo[a], q[a]), w.hi[a] = std::max(w.hi[a], q[a]);
    }
    // Rounding in the map: widen by a relative 2^-20 of the box's own scale, so no mapped triangle
    // pokes out of it (the walk's box test assumes the box holds its instance).
    float scale = 0.0f;
    for (int a = 0; a < 3; ++a) scale = std::max({scale, std::fabs(w.lo[a]), std::fabs(w.hi[a]), w.hi[a] - w.lo[a]});
    const float margin = scale * (1.0f / 1048576.0f);
    for (int a = 0; a < 3; ++a) w.lo[a] -= margin, w.hi[a] += margin;
    return w;
}

std::vector<InstanceNode> build_instance_bvh(std::span<const WorldBox> boxes) { return Builder(boxes).build(); }

}  // namespace kdpm
