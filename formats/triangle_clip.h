#pragma once
// Triangle against axis-aligned box: the bounds of their intersection (Sutherland–Hodgman on the
// six box planes). The SAH builder uses it for perfect splits, the validator for leaf coverage;
// sharing it keeps "the triangle overlaps this cell" the same question for both.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

#include "formats/geometry_layout.h"

namespace kdpm {

struct AxisBox {
    float lo[3];
    float hi[3];
};

// A triangle the tree can hold: finite coordinates and non-zero area (in float arithmetic).
inline bool triangle_is_usable(const TriangleRecord& t) {
    for (int i = 0; i < 3; ++i)
        if (!std::isfinite(t.v0[i]) || !std::isfinite(t.e1[i]) || !std::isfinite(t.e2[i])) return false;
    const float cx = t.e1[1] * t.e2[2] - t.e1[2] * t.e2[1];
    const float cy = t.e1[2] * t.e2[0] - t.e1[0] * t.e2[2];
    const float cz = t.e1[0] * t.e2[1] - t.e1[1] * t.e2[0];
    return cx != 0.0f || cy != 0.0f || cz != 0.0f;
}

// The three vertices of a stored triangle, in float (for framing and display only: v0 + e1
// rounds). The tree uses the exact double form below.
inline void triangle_vertices(const TriangleRecord& t, float (&v)[3][3]) {
    for (int i = 0; i < 3; ++i) {
        v[0][i] = t.v0[i];
        v[1][i] = t.v0[i] + t.e1[i];
        v[2][i] = t.v0[i] + t.e2[i];
    }
}

// The exact vertices of the triangle the intersection test sees (v0 + e1 is exact in double).
inline void triangle_vertices(const TriangleRecord& t, double (&v)[3][3]) {
    for (int i = 0; i < 3; ++i) {
        v[0][i] = t.v0[i];
        v[1][i] = static_cast<double>(t.v0[i]) + t.e1[i];
        v[2][i] = static_cast<double>(t.v0[i]) + t.e2[i];
    }
}

// The float next to f toward -infinity / +infinity (std::nextafter's result for a float that is
// not NaN and not already that infinity), from its bits: nextafter is a library call, and the
// builder rounds bounds outward for every clipped triangle.
inline float float_below(float f) {
    std::uint32_t u;
    std::memcpy(&u, &f, sizeof u);
    u = (u & 0x7fffffffu) == 0 ? 0x80000001u : (u & 0x80000000u) ? u + 1 : u - 1;
    std::memcpy(&f, &u, sizeof f);
    return f;
}
inline float float_above(float f) {
    std::uint32_t u;
    std::memcpy(&u, &f, sizeof u);
    u = (u & 0x7fffffffu) == 0 ? 0x00000001u : (u & 0x80000000u) ? u - 1 : u + 1;
    std::memcpy(&f, &u, sizeof f);
    return f;
}

// Float bounds that contain the double interval [lo, hi]: rounded outward.
inline float round_down(double x) {
    float f = static_cast<float>(x);
    return static_cast<double>(f) > x ? float_below(f) : f;
}
inline float round_up(double x) {
    float f = static_cast<float>(x);
    return static_cast<double>(f) < x ? float_above(f) : f;
}

// Rounding the bounds of a triangle to float. To nearest by default, so that triangles sharing
// a vertex share its bound exactly (outward rounding would scatter split candidates one ulp
// apart and breed needless sliver cells); half an ulp there only touches a sliver along an
// edge. But on an axis where the triangle is nearly flat (it spans fewer than ~1000 ulps), half
// an ulp is a sizeable part of the triangle, so there the bounds are rounded outward.
struct BoundRounding {
    bool outward[3];
};

// The spacing of floats around x (within a factor of 2: the power of two of its exponent times
// 2^-23), by bit manipulation: nextafter is a library call and this runs for every clip.
inline double float_spacing(double x) {
    const float f = std::fabs(static_cast<float>(x));
    std::uint32_t bits;
    std::memcpy(&bits, &f, sizeof bits);
    bits &= 0x7f800000u;
    float power;
    std::memcpy(&power, &bits, sizeof power);
    return std::max(static_cast<double>(power) * 0x1p-23, 1.4e-45);
}

// From the triangle's per-axis bounds lo/hi, where a caller has them already.
inline BoundRounding bound_rounding(const double (&lo)[3], const double (&hi)[3]) {
    BoundRounding r;
    for (int a = 0; a < 3; ++a)
        r.outward[a] = hi[a] - lo[a] < 1024.0 * float_spacing(std::max(std::fabs(lo[a]), std::fabs(hi[a])));
    return r;
}

inline BoundRounding bound_rounding(const double (&v)[3][3]) {
    double lo[3], hi[3];
    for (int a = 0; a < 3; ++a) {
        lo[a] = std::min(v[0][a], std::min(v[1][a], v[2][a]));
        hi[a] = std::max(v[0][a], std::max(v[1][a], v[2][a]));
    }
    return bound_rounding(lo, hi);
}

// `slack` bounds the error of x; outward rounding also when it is not far below the spacing
// (never for no slack: the spacing is positive, so that case skips working it out).
inline float bound_down(double x, double slack, bool outward) {
    return outward || (slack > 0.0 && slack >= 0.25 * float_spacing(x)) ? round_down(x - slack) : static_cast<float>(x);
}
inline float bound_up(double x, double slack, bool outward) {
    return outward || (slack > 0.0 && slack >= 0.25 * float_spacing(x)) ? round_up(x + slack) : static_cast<float>(x);
}

// Float bounds of a usable triangle (rounded as above).
inline AxisBox triangle_bounds(const TriangleRecord& t) {
    double v[3][3];
    triangle_vertices(t, v);
    const BoundRounding r = bound_rounding(v);
    AxisBox b;
    for (int a = 0; a < 3; ++a) {
        b.lo[a] = bound_down(std::min(v[0][a], std::min(v[1][a], v[2][a])), 0.0, r.outward[a]);
        b.hi[a] = bound_up(std::max(v[0][a], std::max(v[1][a], v[2][a])), 0.0, r.outward[a]);
    }
    return b;
}

namespace clip_detail {

// A polygon being clipped: the triangle cut by the planes so far, and a bound on the rounding
// error of its points per axis.
struct ClipPolygon {
    double buf[2][9][3];  // the points in buf[cur]; each plane adds at most one vertex: 3 + 6
    int cur = 0;
    int n = 3;
    double slack[3] = {0.0, 0.0, 0.0};
    const double (*points() const)[3] { return buf[cur]; }
    // A copy of the points and their error only (what clipping goes on from).
    ClipPolygon copy() const {
        ClipPolygon c;
        c.n = n;
        for (int i = 0; i < n; ++i)
            for (int a = 0; a < 3; ++a) c.buf[0][i][a] = buf[cur][i][a];
        for (int a = 0; a < 3; ++a) c.slack[a] = slack[a];
        return c;
    }
};

// Cuts the polygon by the planes of box on axes [a_begin, a_end) (Sutherland–Hodgman), skipping
// the planes that the triangle's bounds lo/hi do not cross.
inline void clip_axes(ClipPolygon& poly, const AxisBox& box, const double (&lo)[3], const double (&hi)[3], int a_begin,
                      int a_end) {
    constexpr double kRound = 4.0 * 2.220446049250313e-16;  // a few double ulps per operation
    for (int a = a_begin; a < a_end && poly.n > 0; ++a) {
        for (int side = 0; side < 2 && poly.n > 0; ++side) {
            const double plane = side == 0 ? box.lo[a] : box.hi[a];
            if (side == 0 ? lo[a] >= plane : hi[a] <= plane) continue;  // nothing to cut
            const double (*in)[3] = poly.buf[poly.cur];
            double (*res)[3] = poly.buf[poly.cur ^ 1];
            const double* slack = poly.slack;
            double new_slack[3] = {slack[0], slack[1], slack[2]};
            const int n = poly.n;
            int m = 0;
            for (int i = 0; i < n; ++i) {
                const double* p = in[i];
                const double* q = in[i + 1 < n ? i + 1 : 0];
                const bool p_in = side == 0 ? p[a] >= plane : p[a] <= plane;
                const bool q_in = side == 0 ? q[a] >= plane : q[a] <= plane;
                if (p_in && m < 9) {
                    for (int k = 0; k < 3; ++k) res[m][k] = p[k];
                    ++m;
                }
                if (p_in != q_in && m < 9) {
                    const double d = q[a] - p[a];
                    const double t = (plane - p[a]) / d;
                    const double t_err = (kRound * (std::fabs(plane) + std::fabs(p[a])) + 2.0 * slack[a]) / std::fabs(d);
                    for (int k = 0; k < 3; ++k) {
                        res[m][k] = p[k] + t * (q[k] - p[k]);
                        if (k != a) {
                            const double e = slack[k] + t_err * std::fabs(q[k] - p[k]) +
                                             kRound * (std::fabs(p[k]) + std::fabs(q[k]));
                            new_slack[k] = std::max(new_slack[k], e);
                        }
                    }
                    res[m][a] = plane;
                    ++m;
                }
            }
            for (int k = 0; k < 3; ++k) poly.slack[k] = new_slack[k];
            poly.n = m;
            poly.cur ^= 1;
        }
    }
}

// The float bounds of the clipped polygon, widened by its error where it matters, clamped to box.
inline bool clipped_bounds(const ClipPolygon& poly, const AxisBox& box, const BoundRounding& rounding, AxisBox& out) {
    if (poly.n == 0) return false;
    const double (*p)[3] = poly.points();
    for (int a = 0; a < 3; ++a) {
        double l = p[0][a], h = p[0][a];
        for (int i = 1; i < poly.n; ++i) {
            l = std::min(l, p[i][a]);
            h = std::max(h, p[i][a]);
        }
        out.lo[a] = std::max(bound_down(l, poly.slack[a], rounding.outward[a]), box.lo[a]);
        out.hi[a] = std::min(bound_up(h, poly.slack[a], rounding.outward[a]), box.hi[a]);
        if (out.lo[a] > out.hi[a]) return false;
    }
    return true;
}

// The bounds of a triangle lying inside box (no cut needed).
inline void inside_bounds(const double (&lo)[3], const double (&hi)[3], const AxisBox& box,
                          const BoundRounding& rounding, AxisBox& out) {
    for (int a = 0; a < 3; ++a) {
        out.lo[a] = std::max(bound_down(lo[a], 0.0, rounding.outward[a]), box.lo[a]);
        out.hi[a] = std::min(bound_up(hi[a], 0.0, rounding.outward[a]), box.hi[a]);
    }
}

inline ClipPolygon triangle_polygon(const double (&v)[3][3]) {
    ClipPolygon poly;
    for (int i = 0; i < 3; ++i)
        for (int a = 0; a < 3; ++a) poly.buf[0][i][a] = v[i][a];
    return poly;
}

}  // namespace clip_detail

// Conservative bounds of (triangle ∩ box), clamped to the box; false when they do not meet.
// Points on a box face count as inside, so a triangle touching a cell "meets" it.
//
// Clipping a nearly flat triangle against a plane almost parallel to it is ill-conditioned:
// in float the cut points can move by a large part of an edge and the bounds come out too
// small (then the tree misses the triangle in a cell it crosses). So the polygon is clipped in
// double from the exact vertices, a bound on the rounding error of every cut point is carried
// along (large only for ill-conditioned cuts), and where it matters the result is widened by
// it and rounded outward (see BoundRounding).
inline bool clip_triangle_to_box(const double (&v)[3][3], const AxisBox& box, AxisBox& out) {
    double lo[3], hi[3];
    bool inside = true;
    for (int a = 0; a < 3; ++a) {
        lo[a] = std::min(v[0][a], std::min(v[1][a], v[2][a]));
        hi[a] = std::max(v[0][a], std::max(v[1][a], v[2][a]));
        if (lo[a] > box.hi[a] || hi[a] < box.lo[a]) return false;
        inside = inside && lo[a] >= box.lo[a] && hi[a] <= box.hi[a];
    }
    const BoundRounding rounding = bound_rounding(lo, hi);
    if (inside) {
        clip_detail::inside_bounds(lo, hi, box, rounding, out);
        return true;
    }
    clip_detail::ClipPolygon poly = clip_detail::triangle_polygon(v);
    clip_detail::clip_axes(poly, box, lo, hi, 0, 3);
    return clip_detail::clipped_bounds(poly, box, rounding, out);
}

// clip_triangle_to_box for both children of `cell` split at `pos` on `axis`, with the same
// results; the cuts by the planes of the axes before the split axis, which the two cells share,
// are made once.
inline void clip_triangle_to_children(const double (&v)[3][3], const AxisBox& cell, int axis, float pos,
                                      bool& meets_below, AxisBox& below, bool& meets_above, AxisBox& above) {
    AxisBox below_cell = cell, above_cell = cell;
    below_cell.hi[axis] = pos;
    above_cell.lo[axis] = pos;
    double lo[3], hi[3];
    bool outside = false, inside = true;
    for (int a = 0; a < 3; ++a) {
        lo[a] = std::min(v[0][a], std::min(v[1][a], v[2][a]));
        hi[a] = std::max(v[0][a], std::max(v[1][a], v[2][a]));
        if (a == axis) continue;
        outside = outside || lo[a] > cell.hi[a] || hi[a] < cell.lo[a];
        inside = inside && lo[a] >= cell.lo[a] && hi[a] <= cell.hi[a];
    }
    const double l = lo[axis], h = hi[axis];
    meets_below = !outside && !(l > below_cell.hi[axis] || h < below_cell.lo[axis]);
    meets_above = !outside && !(l > above_cell.hi[axis] || h < above_cell.lo[axis]);
    if (!meets_below && !meets_above) return;
    const bool inside_below = inside && l >= below_cell.lo[axis] && h <= below_cell.hi[axis];
    const bool inside_above = inside && l >= above_cell.lo[axis] && h <= above_cell.hi[axis];
    const BoundRounding rounding = bound_rounding(lo, hi);
    if (meets_below && inside_below) clip_detail::inside_bounds(lo, hi, below_cell, rounding, below);
    if (meets_above && inside_above) clip_detail::inside_bounds(lo, hi, above_cell, rounding, above);
    const bool cut_below = meets_below && !inside_below, cut_above = meets_above && !inside_above;
    if (!cut_below && !cut_above) return;
    clip_detail::ClipPolygon shared = clip_detail::triangle_polygon(v);
    clip_detail::clip_axes(shared, cell, lo, hi, 0, axis);
    // The rest of the cuts, from the split axis on, for one child.
    auto finish = [&](clip_detail::ClipPolygon& poly, const AxisBox& child, AxisBox& out) {
        clip_detail::clip_axes(poly, child, lo, hi, axis, 3);
        return clip_detail::clipped_bounds(poly, child, rounding, out);
    };
    if (cut_below && cut_above) {
        clip_detail::ClipPolygon own = shared.copy();
        meets_below = finish(own, below_cell, below);
    } else if (cut_below) {
        meets_below = finish(shared, below_cell, below);
    }
    if (cut_above) meets_above = finish(shared, above_cell, above);
}

}  // namespace kdpm
