#pragma once
// An affine map of 3-space as a 3x4 row-major matrix: what places an instance's object in the
// world (geometry.instances), and its inverse, which takes world rays into the object's frame.
// The host half: files and cards are checked with it; runtime/geometry/affine.h applies maps.
#include <cmath>

namespace kdpm {

struct Affine {
    float m[3][4];  // row i: (linear row i, translation i)
};

inline Affine identity_affine() {
    return Affine{{{1.0f, 0.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f, 0.0f}, {0.0f, 0.0f, 1.0f, 0.0f}}};
}

inline bool is_identity_affine(const Affine& a) {
    const Affine id = identity_affine();
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 4; ++j)
            if (a.m[i][j] != id.m[i][j]) return false;
    return true;
}

// Determinant of the linear part, in double (the invertibility test of files and cards).
inline double affine_determinant(const Affine& a) {
    const auto& m = a.m;
    return double(m[0][0]) * (double(m[1][1]) * m[2][2] - double(m[1][2]) * m[2][1]) -
           double(m[0][1]) * (double(m[1][0]) * m[2][2] - double(m[1][2]) * m[2][0]) +
           double(m[0][2]) * (double(m[1][0]) * m[2][1] - double(m[1][1]) * m[2][0]);
}

// The inverse map, computed in double; the caller has checked the determinant.
inline Affine inverse_affine(const Affine& a) {
    const auto& m = a.m;
    const double inv_det = 1.0 / affine_determinant(a);
    double r[3][3];
    r[0][0] = (double(m[1][1]) * m[2][2] - double(m[1][2]) * m[2][1]) * inv_det;
    r[0][1] = (double(m[0][2]) * m[2][1] - double(m[0][1]) * m[2][2]) * inv_det;
    r[0][2] = (double(m[0][1]) * m[1][2] - double(m[0][2]) * m[1][1]) * inv_det;
    r[1][0] = (double(m[1][2]) * m[2][0] - double(m[1][0]) * m[2][2]) * inv_det;
    r[1][1] = (double(m[0][0]) * m[2][2] - double(m[0][2]) * m[2][0]) * inv_det;
    r[1][2] = (double(m[0][2]) * m[1][0] - double(m[0][0]) * m[1][2]) * inv_det;
    r[2][0] = (double(m[1][0]) * m[2][1] - double(m[1][1]) * m[2][0]) * inv_det;
    r[2][1] = (double(m[0][1]) * m[2][0] - double(m[0][0]) * m[2][1]) * inv_det;
    r[2][2] = (double(m[0][0]) * m[1][1] - double(m[0][1]) * m[1][0]) * inv_det;
    Affine out{};
    for (int i = 0; i < 3; ++i) {
        double t = 0.0;
        for (int j = 0; j < 3; ++j) {
            out.m[i][j] = static_cast<float>(r[i][j]);
            t -= r[i][j] * m[j][3];
        }
        out.m[i][3] = static_cast<float>(t);
    }
    return out;
}

// A map a file or card may hold: finite, with a linear part far from singular relative to its
// own scale (|det| >= 1e-9 * the largest entry's cube), so its inverse is finite and usable.
inline bool usable_affine(const Affine& a) {
    double largest = 0.0;
    for (const auto& row : a.m)
        for (float v : row) {
            if (!std::isfinite(v)) return false;
            largest = std::fmax(largest, std::fabs(double(v)));
        }
    double linear = 0.0;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) linear = std::fmax(linear, std::fabs(double(a.m[i][j])));
    return linear > 0.0 && std::fabs(affine_determinant(a)) >= 1e-9 * linear * linear * linear && largest < 1e18;
}

}  // namespace kdpm
