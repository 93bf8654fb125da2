#include "builders/geometry/sah/sah_kd_builder.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <memory>
#include <stdexcept>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>
#include <tbb/parallel_reduce.h>

#include "builders/geometry/sah/binned_split.h"
#include "builders/geometry/sah/kd_tree_stats.h"
#include "builders/geometry/sah/sah_cost.h"
#include "builders/geometry/sah/sah_events.h"
#include "formats/repeated_triangles.h"
#include "formats/stable_radix_sort.h"
#include "formats/triangle_clip.h"

namespace kdpm {

namespace {

using namespace sah_detail;

// A node is either exact (sorted events) or, in the upper levels of a fast build, binned (each
// triangle's bounds clipped to the cell, no events).
struct NodeInput {
    AxisBox cell{};
    std::vector<std::uint32_t> tris;  // global triangle indices, ascending
    std::vector<Event> ev[3];         // exact: sorted, per axis
    bool binned = false;
    std::vector<AxisBox> boxes;       // binned: clipped bounds, parallel to tris
    void release() {
        std::vector<std::uint32_t>().swap(tris);
        for (auto& e : ev) std::vector<Event>().swap(e);
        std::vector<AxisBox>().swap(boxes);
    }
    // Empty, as a fresh one, but keeping the arrays' memory for the next node.
    void reuse() {
        tris.clear();
        for (auto& e : ev) e.clear();
        boxes.clear();
        binned = false;
    }
};

struct Split {
    int axis = -1;  // -1: make a leaf
    float pos = 0.0f;
    bool planar_left = true;
    // Exact splits: no triangle goes to that side (an empty-space cut), so the other child is the
    // node itself, events and all.
    bool empty_left = false, empty_right = false;
};

// A subtree in file layout with node and leaf indices relative to its own arrays.
// With each node, the area of its cell and its depth, for the tree's statistics (measure_kd_tree's,
// taken while the pieces are built on all threads).
struct Flat {
    std::vector<KdNode> nodes;
    std::vector<std::uint32_t> leaf;
    std::vector<float> area;            // box_area of each node's cell
    std::vector<std::uint32_t> depth;  // of each node
};

// Large nodes are split into pieces whose subtrees are built in parallel; the choice depends on
// the triangle count only, so the piece structure (and the file) does not depend on threads.
struct Piece {
    bool is_split = false;
    Split split;
    float area = 0.0f;  // a split's cell
    std::unique_ptr<Piece> below, above;
    Flat flat;
};

constexpr std::size_t kParallelThreshold = 4096;

class Builder {
public:
    Builder(std::span<const TriangleRecord> tris, const KdBuildParams& params,
            const std::function<void(double)>& progress)
        : tris_(tris), params_(params), progress_(progress) {}

    KdTree build() {
        KdTree tree;
        NodeInput root;
        std::size_t taken = 0;
        const AxisBox bounds = start_root(root, taken, tree.repeated_triangles);
        // Every triangle taken counts, also one that clips to nothing (which the root leaves out).
        limits_ = KdDepthLimits::of(params_, taken);
        tree.limits = limits_;
        root_volume_ = volume(bounds);
        if (params_.quality == KdBuildQuality::high) to_exact(root);

        std::unique_ptr<Piece> piece = build_piece(std::move(root), 0);
        tree.bounds = bounds;
        emit(*piece, tree.nodes, tree.leaf_indices);
        tree.stats = statistics(*piece, tree.nodes.size(), bounds);
        if (progress_) progress_(1.0);
        return tree;
    }

private:
    // The root: every usable triangle but repeated copies (repeated_triangles), each clipped to
    // the root cell, their bounds, in binned form (a fast build's upper levels; a high build
    // turns it into events). Returns the root cell, with the number of triangles taken and of
    // the copies left out.
    //
    // Three passes over the triangles, the first two on all threads: their keys and the cell
    // together, then each clipped to the cell while one thread files the keys. Copies do not
    // change the cell (each equals a triangle the tree takes), so neither waits for the filing;
    // the first two run on all threads because on one they would hold up a fast build.
    AxisBox start_root(NodeInput& root, std::size_t& taken, std::uint64_t& repeated_count) const {
        const std::size_t count = tris_.size();
        std::vector<std::uint64_t> keys(count);
        AxisBox none;
        for (int a = 0; a < 3; ++a) none.lo[a] = INFINITY, none.hi[a] = -INFINITY;
        auto join = [](AxisBox x, const AxisBox& y) {
            for (int a = 0; a < 3; ++a) x.lo[a] = std::min(x.lo[a], y.lo[a]), x.hi[a] = std::max(x.hi[a], y.hi[a]);
            return x;
        };
        // min and max do not depend on the order, so neither does the cell.
        AxisBox cell = tbb::parallel_reduce(
            tbb::blocked_range<std::size_t>(0, count, 4096), none,
            [&](const tbb::blocked_range<std::size_t>& r, AxisBox box) {
                for (std::size_t i = r.begin(); i != r.end(); ++i) {
                    keys[i] = triangle_key(tris_[i]);
                    if (keys[i] != kUnusableTriangleKey) box = join(box, triangle_bounds(tris_[i]));
                }
                return box;
            },
            join);
        if (!(cell.lo[0] <= cell.hi[0])) cell = AxisBox{{0, 0, 0}, {0, 0, 0}};  // no usable triangle

        std::vector<bool> repeated;
        std::vector<AxisBox> boxes(count);
        std::vector<std::uint8_t> inside(count);
        auto clip_to_cell = [&](const tbb::blocked_range<std::size_t>& r) {
            for (std::size_t i = r.begin(); i != r.end(); ++i) {
                inside[i] = 0;
                if (keys[i] == kUnusableTriangleKey) continue;
                double v[3][3];
                triangle_vertices(tris_[i], v);
                inside[i] = clip_triangle_to_box(v, cell, boxes[i]);
            }
        };
        tbb::parallel_invoke([&] { repeated = repeated_triangles(tris_, keys); },
                             [&] { tbb::parallel_for(tbb::blocked_range<std::size_t>(0, count, 4096), clip_to_cell); });
        taken = 0;
        repeated_count = 0;
        for (std::size_t i = 0; i < count; ++i) {
            if (repeated[i]) {
                ++repeated_count;
            } else if (keys[i] != kUnusableTriangleKey) {
                ++taken;
                if (inside[i]) root.tris.push_back(static_cast<std::uint32_t>(i)), root.boxes.push_back(boxes[i]);
            }
        }
        if (taken > kLocalMask) throw std::runtime_error("too many triangles for one kd-tree");
        root.cell = cell;
        root.binned = true;
        return cell;
    }

    // Leaves binned mode: events from the clipped bounds, sorted, as the exact build keeps them.
    static void to_exact(NodeInput& in) {
        if (!in.binned) return;
        for (auto& e : in.ev) e.reserve(2 * in.tris.size());
        for (std::size_t i = 0; i < in.boxes.size(); ++i) add_events(in.boxes[i], static_cast<std::uint32_t>(i), in.ev);
        if (in.tris.size() > kParallelThreshold)
            tbb::parallel_invoke([&] { sort_events(in.ev[0]); }, [&] { sort_events(in.ev[1]); },
                                 [&] { sort_events(in.ev[2]); });
        else
            for (auto& e : in.ev) sort_events(e);
        std::vector<AxisBox>().swap(in.boxes);
        in.binned = false;
    }

    bool wants_binning(const NodeInput& in, std::uint32_t depth) const {
        const std::size_t n = in.tris.size();
        return in.binned && n >= params_.exact_below && n > static_cast<std::size_t>(std::max(params_.leaf_size, 0)) &&
               limits_.may_split(depth, n);
    }

    // Distributes a binned node's triangles to its children in fixed chunks that run in parallel:
    // the same sides as split_node, straddling triangles clipped to each child cell, both lists
    // kept in ascending order.
    void split_binned(const NodeInput& in, const BinnedSplit& s, NodeInput& left, NodeInput& right) const {
        constexpr std::uint8_t kInLeft = 1, kInRight = 2;
        constexpr std::size_t kChunk = 4096;
        const std::size_t n = in.tris.size();
        const int k = s.axis;
        const float p = s.pos;
        left.cell = in.cell;
        right.cell = in.cell;
        left.cell.hi[k] = p;
        right.cell.lo[k] = p;
        left.binned = right.binned = true;
        std::vector<std::uint8_t> side(n);
        std::vector<AxisBox> lbox(n), rbox(n);
        const std::size_t chunks = (n + kChunk - 1) / kChunk;
        std::vector<std::size_t> lcount(chunks + 1, 0), rcount(chunks + 1, 0);
        auto each_chunk = [&](auto&& body) {
            tbb::parallel_for(tbb::blocked_range<std::size_t>(0, chunks, 1), [&](const tbb::blocked_range<std::size_t>& r) {
                for (std::size_t c = r.begin(); c != r.end(); ++c) body(c, c * kChunk, std::min(n, (c + 1) * kChunk));
            });
        };
        each_chunk([&](std::size_t c, std::size_t begin, std::size_t end) {
            std::size_t nl = 0, nr = 0;
            for (std::size_t i = begin; i < end; ++i) {
                const AxisBox& b = in.boxes[i];
                std::uint8_t sd = 0;
                if (b.lo[k] == b.hi[k]) {
                    sd = (b.lo[k] < p || (b.lo[k] == p && s.planar_left)) ? kInLeft : kInRight;
                } else if (b.hi[k] <= p) {
                    sd = kInLeft;
                } else if (b.lo[k] >= p) {
                    sd = kInRight;
                } else {
                    double v[3][3];
                    triangle_vertices(tris_[in.tris[i]], v);
                    bool meets_left, meets_right;
                    clip_triangle_to_children(v, in.cell, k, p, meets_left, lbox[i], meets_right, rbox[i]);
                    if (meets_left) sd |= kInLeft;
                    if (meets_right) sd |= kInRight;
                }
                if (sd == kInLeft) lbox[i] = b;
                if (sd == kInRight) rbox[i] = b;
                side[i] = sd;
                nl += (sd & kInLeft) != 0;
                nr += (sd & kInRight) != 0;
            }
            lcount[c + 1] = nl;
            rcount[c + 1] = nr;
        });
        for (std::size_t c = 0; c < chunks; ++c) lcount[c + 1] += lcount[c], rcount[c + 1] += rcount[c];
        left.tris.resize(lcount[chunks]);
        left.boxes.resize(lcount[chunks]);
        right.tris.resize(rcount[chunks]);
        right.boxes.resize(rcount[chunks]);
        each_chunk([&](std::size_t c, std::size_t begin, std::size_t end) {
            std::size_t il = lcount[c], ir = rcount[c];
            for (std::size_t i = begin; i < end; ++i) {
                if (side[i] & kInLeft) left.tris[il] = in.tris[i], left.boxes[il++] = lbox[i];
                if (side[i] & kInRight) right.tris[ir] = in.tris[i], right.boxes[ir++] = rbox[i];
            }
        });
    }

    static double volume(const AxisBox& b) {
        return static_cast<double>(b.hi[0] - b.lo[0]) * (b.hi[1] - b.lo[1]) * (b.hi[2] - b.lo[2]);
    }

    Split find_split(const NodeInput& in, std::uint32_t depth) const {
        Split best;
        const std::uint32_t n = static_cast<std::uint32_t>(in.tris.size());
        if (n == 0 || n <= static_cast<std::uint32_t>(std::max(params_.leaf_size, 0)) || !limits_.may_split(depth, n))
            return best;
        const float area = box_area(in.cell);
        if (!(area > 0.0f)) return best;
        float best_cost = params_.intersection_cost * static_cast<float>(n);
        for (int k = 0; k < 3; ++k) {
            const float lo = in.cell.lo[k], hi = in.cell.hi[k];
            if (!(hi > lo)) continue;
            const std::vector<Event>& e = in.ev[k];
            const SplitCostAxis axis_terms = split_cost_axis(in.cell, area, k);
            const std::size_t m = e.size();
            std::uint32_t nl = 0, nr = n;
            std::size_t i = 0;
            while (i < m) {
                const std::uint32_t pb = e[i].pos_bits();
                // The group's events counted by type in one loop: its only branch is where the
                // position changes (three loops, one per type, would mispredict at each change).
                // Ends and planars in the two halves of one register; an array of counts in
                // memory would make every event wait for the store of the one before.
                static constexpr std::uint64_t kIncrement[3] = {1, std::uint64_t{1} << 32, 0};  // by EventType
                const std::size_t group = i;
                std::uint64_t ends_planar = 0;
                do {
                    ends_planar += kIncrement[e[i].type()];
                    ++i;
                } while (i < m && e[i].pos_bits() == pb);
                const auto ends = static_cast<std::uint32_t>(ends_planar);
                const auto planar = static_cast<std::uint32_t>(ends_planar >> 32);
                const std::uint32_t starts = static_cast<std::uint32_t>(i - group) - ends - planar;
                const float p = from_order_bits(pb);
                nr -= planar + ends;
                if (p > lo && p < hi) {
                    const SplitCost c = sah_split_cost(params_, axis_terms, p, nl, planar, nr);
                    if (c.cost < best_cost) {
                        best_cost = c.cost;
                        best = Split{k, p, c.planar_left, nl + (c.planar_left ? planar : 0) == 0,
                                     nr + (c.planar_left ? 0 : planar) == 0};
                    }
                }
                nl += starts + planar;
            }
        }
        return best;
    }

    // Per-thread scratch of split_node, reused to keep small nodes free of allocations.
    struct Scratch {
        std::vector<std::uint8_t> side;
        std::vector<std::uint32_t> lmap, rmap;
        std::vector<Event> fresh_l[3], fresh_r[3];
        std::vector<Event> one_sided_l, one_sided_r;
        std::vector<AxisBox> box;
    };

    // Distributes the node's triangles and events to its children. Triangles on one side keep
    // their (already sorted) events; straddling triangles are clipped to each child cell (in a
    // fast build's nodes below clip_below, their bounds are cut at the plane instead) and their
    // fresh events are sorted and merged in, in the same pass.
    void split_node(NodeInput& in, const Split& s, NodeInput& left, NodeInput& right) const {
        if (s.empty_left || s.empty_right) {
            // What the general case below would produce, without touching the events.
            NodeInput& full = s.empty_left ? right : left;
            NodeInput& empty = s.empty_left ? left : right;
            // Swapped rather than moved: `in` is spent, and full's arrays may be reused memory.
            full.tris.swap(in.tris);
            for (int a = 0; a < 3; ++a) full.ev[a].swap(in.ev[a]);
            full.cell = empty.cell = in.cell;
            left.cell.hi[s.axis] = s.pos;
            right.cell.lo[s.axis] = s.pos;
            return;
        }
        enum : std::uint8_t { kBoth = 0, kLeft = 1, kRight = 2 };
        thread_local Scratch scratch;
        const std::size_t n = in.tris.size();
        const int k = s.axis;
        const float p = s.pos;
        const bool cut_boxes = params_.quality == KdBuildQuality::fast && n < params_.clip_below;
        std::vector<std::uint8_t>& side = scratch.side;
        side.assign(n, kBoth);
        const std::uint32_t pb = order_bits(p);
        for (const Event& e : in.ev[k]) {
            const EventType t = e.type();
            const std::uint32_t eb = e.pos_bits();
            if (t == kEnd && eb <= pb) side[e.local()] = kLeft;
            else if (t == kStart && eb >= pb) side[e.local()] = kRight;
            else if (t == kPlanar) side[e.local()] = (eb < pb || (eb == pb && s.planar_left)) ? kLeft : kRight;
        }
        left.cell = in.cell;
        right.cell = in.cell;
        left.cell.hi[k] = p;
        right.cell.lo[k] = p;
        // The crossing triangles' bounds as their events give them (clipped in the nodes above).
        std::vector<AxisBox>& box = scratch.box;
        if (cut_boxes) {
            box.resize(n);
            for (int a = 0; a < 3; ++a)
                for (const Event& e : in.ev[a]) {
                    const std::uint32_t i = e.local();
                    if (side[i] != kBoth) continue;
                    const EventType t = e.type();
                    if (t != kEnd) box[i].lo[a] = e.pos();
                    if (t != kStart) box[i].hi[a] = e.pos();
                }
        }

        std::vector<std::uint32_t>& lmap = scratch.lmap;
        std::vector<std::uint32_t>& rmap = scratch.rmap;
        // Never shrunk: a larger node after a smaller one would zero the difference again.
        if (lmap.size() < n) lmap.resize(n), rmap.resize(n);
        for (int a = 0; a < 3; ++a) scratch.fresh_l[a].clear(), scratch.fresh_r[a].clear();
        std::size_t n_left = 0, n_right = 0;
        for (std::size_t i = 0; i < n; ++i) n_left += side[i] != kRight, n_right += side[i] != kLeft;
        left.tris.reserve(n_left);
        right.tris.reserve(n_right);
        for (std::size_t i = 0; i < n; ++i) {
            const std::uint32_t g = in.tris[i];
            if (side[i] == kLeft) {
                lmap[i] = static_cast<std::uint32_t>(left.tris.size());
                left.tris.push_back(g);
            } else if (side[i] == kRight) {
                rmap[i] = static_cast<std::uint32_t>(right.tris.size());
                right.tris.push_back(g);
            } else {
                AxisBox lb, rb;
                bool meets_left = true, meets_right = true;
                if (cut_boxes) {
                    // Conservative: the triangle may be listed in a child it only comes near.
                    lb = rb = box[i];
                    lb.hi[k] = p;
                    rb.lo[k] = p;
                } else {
                    double v[3][3];
                    triangle_vertices(tris_[g], v);
                    clip_triangle_to_children(v, in.cell, k, p, meets_left, lb, meets_right, rb);
                }
                if (meets_left) {
                    lmap[i] = static_cast<std::uint32_t>(left.tris.size());
                    left.tris.push_back(g);
                    add_events(lb, lmap[i], scratch.fresh_l);
                }
                if (meets_right) {
                    rmap[i] = static_cast<std::uint32_t>(right.tris.size());
                    right.tris.push_back(g);
                    add_events(rb, rmap[i], scratch.fresh_r);
                }
            }
        }
        for (int a = 0; a < 3; ++a) {
            std::vector<Event>& fl = scratch.fresh_l[a];
            std::vector<Event>& fr = scratch.fresh_r[a];
            sort_events(fl);
            sort_events(fr);
            // The one-sided triangles' events, in order, split by side without a branch on the
            // side (which is data-dependent): each event is written to both lists and counted in
            // the one it belongs to; a slot it is not counted in is overwritten by the next one.
            const std::vector<Event>& ev = in.ev[a];
            const std::size_t m = ev.size();
            std::vector<Event>& one_l = scratch.one_sided_l;
            std::vector<Event>& one_r = scratch.one_sided_r;
            if (one_l.size() < m + 1) one_l.resize(m + 1), one_r.resize(m + 1);
            Event* ol = one_l.data();
            Event* orr = one_r.data();
            std::size_t nl = 0, nr = 0;
            const std::uint8_t* side_of = side.data();
            const std::uint32_t* lm = lmap.data();
            const std::uint32_t* rm = rmap.data();
            for (std::size_t j = 0; j < m; ++j) {
                const Event e = ev[j];
                const std::uint32_t i = e.local();
                const std::uint8_t sd = side_of[i];
                ol[nl] = e.with_local(lm[i]);
                orr[nr] = e.with_local(rm[i]);
                nl += sd == kLeft;
                nr += sd == kRight;
            }
            // Merged with the straddlers' fresh events (sorted above); none is equal to a
            // one-sided event (their triangles differ), so the order is operator<'s.
            std::vector<Event>& el = left.ev[a];
            std::vector<Event>& er = right.ev[a];
            el.resize(nl + fl.size());
            er.resize(nr + fr.size());
            std::merge(ol, ol + nl, fl.begin(), fl.end(), el.begin());
            std::merge(orr, orr + nr, fr.begin(), fr.end(), er.begin());
        }
    }

    std::unique_ptr<Piece> build_piece(NodeInput&& in, std::uint32_t depth) {
        auto piece = std::make_unique<Piece>();
        // A split piece: its children's subtrees built in parallel.
        auto split_into = [&](const Split& s, NodeInput& left, NodeInput& right) {
            in.release();
            piece->is_split = true;
            piece->split = s;
            piece->area = box_area(in.cell);
            tbb::parallel_invoke([&] { piece->below = build_piece(std::move(left), depth + 1); },
                                 [&] { piece->above = build_piece(std::move(right), depth + 1); });
            return std::move(piece);
        };
        if (wants_binning(in, depth)) {
            const BinnedSplit s = find_binned_split(in.boxes, in.cell, params_);
            if (s.axis >= 0) {
                NodeInput left, right;
                split_binned(in, s, left, right);
                return split_into(Split{s.axis, s.pos, s.planar_left}, left, right);
            }
        }
        to_exact(in);
        if (in.tris.size() > kParallelThreshold) {
            const Split s = find_split(in, depth);
            if (s.axis >= 0) {
                NodeInput left, right;
                split_node(in, s, left, right);
                return split_into(s, left, right);
            }
        }
        build_flat(in, depth, piece->flat);
        return piece;
    }

    // A subtree on one thread, depth first. The children's inputs are this thread's arrays for
    // their depth, reused from node to node because fresh ones for every node spend the build's
    // time in malloc and free; the trees are byte-identical.
    void build_flat(NodeInput& in, std::uint32_t depth, Flat& out) {
        const Split s = find_split(in, depth);
        if (s.axis < 0) {
            make_leaf(in, depth, out);
            return;
        }
        // A build_flat call runs to its end on its thread (nothing inside it waits on other
        // tasks), so a depth's pair is never in use twice at a time.
        thread_local std::vector<std::array<NodeInput, 2>> by_depth(kMaxKdTreeDepth + 1);
        NodeInput& left = by_depth[depth + 1][0];
        NodeInput& right = by_depth[depth + 1][1];
        left.reuse();
        right.reuse();
        split_node(in, s, left, right);
        const std::size_t index = out.nodes.size();
        out.nodes.push_back(KdNode{});
        out.area.push_back(box_area(in.cell));
        out.depth.push_back(depth);
        build_flat(left, depth + 1, out);
        out.nodes[index] = KdNode::inner(s.axis, s.pos, checked_index(out.nodes.size()));
        build_flat(right, depth + 1, out);
    }

    void make_leaf(const NodeInput& in, std::uint32_t depth, Flat& out) {
        out.nodes.push_back(KdNode::leaf(checked_index(out.leaf.size()), checked_index(in.tris.size())));
        out.area.push_back(box_area(in.cell));
        out.depth.push_back(depth);
        out.leaf.insert(out.leaf.end(), in.tris.begin(), in.tris.end());
        if (progress_ && root_volume_ > 0.0) {
            const double done = done_volume_.fetch_add(volume(in.cell)) + volume(in.cell);
            progress_(std::min(0.99, done / root_volume_));
        }
    }

    static std::uint32_t checked_index(std::size_t i) {
        if (i > KdNode::kMaxIndex) throw std::runtime_error("kd-tree too large for 30-bit node indices");
        return static_cast<std::uint32_t>(i);
    }

    // Where a flat piece's nodes and leaf indices go in the file's arrays.
    struct FlatPlace {
        const Flat* flat;
        std::size_t node_base, leaf_base;
    };

    // Lays the pieces out depth first: each split becomes an inner node, each flat piece gets its
    // ranges, copied afterwards (emit) when the arrays have their final size.
    static void place(const Piece& piece, std::vector<KdNode>& nodes, std::size_t& leaf_end,
                      std::vector<FlatPlace>& flats) {
        if (piece.is_split) {
            const std::size_t index = nodes.size();
            nodes.push_back(KdNode{});
            place(*piece.below, nodes, leaf_end, flats);
            nodes[index] = KdNode::inner(piece.split.axis, piece.split.pos, checked_index(nodes.size()));
            place(*piece.above, nodes, leaf_end, flats);
            return;
        }
        flats.push_back({&piece.flat, nodes.size(), leaf_end});
        nodes.resize(nodes.size() + piece.flat.nodes.size());
        leaf_end += piece.flat.leaf.size();
    }

    // measure_kd_tree's statistics from the areas and depths the pieces kept: the same sums in the
    // same (node) order, so the same bits, without walking the tree again on one thread, which
    // would hold up a fast build. The tests hold the two equal.
    KdTreeStats statistics(const Piece& root, std::size_t node_count, const AxisBox& bounds) const {
        if (node_count == 0) return KdTreeStats{};
        TreeStatsSum sum;
        auto add = [&](const Piece& piece, auto&& self) -> void {
            if (piece.is_split) {
                sum.inner(piece.area);
                self(*piece.below, self);
                self(*piece.above, self);
                return;
            }
            const Flat& f = piece.flat;
            for (std::size_t i = 0; i < f.nodes.size(); ++i) {
                const KdNode& n = f.nodes[i];
                if (n.is_leaf()) sum.leaf(n.count(), f.area[i], f.depth[i]);
                else sum.inner(f.area[i]);
            }
        };
        add(root, add);
        return sum.finish(node_count, bounds, params_);
    }

    static std::size_t node_total(const Piece& piece) {
        return piece.is_split ? 1 + node_total(*piece.below) + node_total(*piece.above) : piece.flat.nodes.size();
    }

    // The whole tree in file layout; the flat pieces (nearly all of it) are copied in parallel.
    static void emit(const Piece& root, std::vector<KdNode>& nodes, std::vector<std::uint32_t>& leaf) {
        std::vector<FlatPlace> flats;
        std::size_t leaf_end = 0;
        nodes.reserve(node_total(root));
        place(root, nodes, leaf_end, flats);
        leaf.resize(leaf_end);
        tbb::parallel_for(std::size_t{0}, flats.size(), [&](std::size_t f) {
            const FlatPlace& at = flats[f];
            KdNode* out = nodes.data() + at.node_base;
            for (const KdNode& n : at.flat->nodes) {
                *out++ = n.is_leaf() ? KdNode::leaf(checked_index(n.first() + at.leaf_base), n.count())
                                     : KdNode::inner(n.axis(), n.split(), checked_index(n.above_child() + at.node_base));
            }
            std::copy(at.flat->leaf.begin(), at.flat->leaf.end(), leaf.begin() + static_cast<std::ptrdiff_t>(at.leaf_base));
        });
    }

    std::span<const TriangleRecord> tris_;
    KdBuildParams params_;
    const std::function<void(double)>& progress_;
    KdDepthLimits limits_{};
    double root_volume_ = 0.0;
    std::atomic<double> done_volume_{0.0};
};

}  // namespace

KdTree build_sah_kd_tree(std::span<const TriangleRecord> triangles, const KdBuildParams& params,
                         const std::function<void(double)>& progress) {
    return Builder(triangles, params, progress).build();
}

}  // namespace kdpm
