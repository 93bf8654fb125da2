#pragma once
// Triangle against axis-aligned box: the bounds of their intersection (Sutherland–Hodgman on the
// six box planes). The SAH builder uses it for perfect splits, the validator for leaf coverage;
// sharing it keeps "the triangle overlaps this cell" the same question for both.
#include <cmath>
#include <cstdint>

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

// The three vertices of a stored triangle.
inline void triangle_vertices(const TriangleRecord& t, float (&v)[3][3]) {
    for (int i = 0; i < 3; ++i) {
        v[0][i] = t.v0[i];
        v[1][i] = t.v0[i] + t.e1[i];
        v[2][i] = t.v0[i] + t.e2[i];
    }
}

// Bounds of (triangle ∩ box), clamped to the box; false when they do not meet. Points on a box
// face count as inside, so a triangle touching a cell "meets" it.
inline bool clip_triangle_to_box(const float (&v)[3][3], const AxisBox& box, AxisBox& out) {
    float lo[3], hi[3];
    for (int a = 0; a < 3; ++a) {
        lo[a] = std::fmin(v[0][a], std::fmin(v[1][a], v[2][a]));
        hi[a] = std::fmax(v[0][a], std::fmax(v[1][a], v[2][a]));
        if (lo[a] > box.hi[a] || hi[a] < box.lo[a]) return false;
    }
    bool inside = true;
    for (int a = 0; a < 3; ++a) inside = inside && lo[a] >= box.lo[a] && hi[a] <= box.hi[a];
    if (inside) {
        for (int a = 0; a < 3; ++a) out.lo[a] = lo[a], out.hi[a] = hi[a];
        return true;
    }
    // Each plane adds at most one vertex: 3 + 6.
    float buf[2][9][3];
    int n = 3;
    for (int i = 0; i < 3; ++i)
        for (int a = 0; a < 3; ++a) buf[0][i][a] = v[i][a];
    int cur = 0;
    for (int a = 0; a < 3 && n > 0; ++a) {
        for (int side = 0; side < 2 && n > 0; ++side) {
            const float plane = side == 0 ? box.lo[a] : box.hi[a];
            const float (*in)[3] = buf[cur];
            float (*res)[3] = buf[cur ^ 1];
            int m = 0;
            for (int i = 0; i < n; ++i) {
                const float* p = in[i];
                const float* q = in[(i + 1) % n];
                const bool p_in = side == 0 ? p[a] >= plane : p[a] <= plane;
                const bool q_in = side == 0 ? q[a] >= plane : q[a] <= plane;
                if (p_in && m < 9) {
                    for (int k = 0; k < 3; ++k) res[m][k] = p[k];
                    ++m;
                }
                if (p_in != q_in && m < 9) {
                    const float t = (plane - p[a]) / (q[a] - p[a]);
                    for (int k = 0; k < 3; ++k) res[m][k] = p[k] + t * (q[k] - p[k]);
                    res[m][a] = plane;
                    ++m;
                }
            }
            n = m;
            cur ^= 1;
        }
    }
    if (n == 0) return false;
    for (int a = 0; a < 3; ++a) {
        float l = buf[cur][0][a], h = buf[cur][0][a];
        for (int i = 1; i < n; ++i) {
            l = std::fmin(l, buf[cur][i][a]);
            h = std::fmax(h, buf[cur][i][a]);
        }
        out.lo[a] = std::fmax(l, box.lo[a]);
        out.hi[a] = std::fmin(h, box.hi[a]);
        if (out.lo[a] > out.hi[a]) return false;
    }
    return true;
}

}  // namespace kdpm
