#pragma once
// Sampling a rectangular light uniformly in the solid angle it subtends from a point (Urena,
// Fajardo & King 2013, "An Area-Preserving Parametrization for Spherical Rectangles"). Uniform
// points on the light's area give shadow rays a weight cos_y / d^2: unbounded for a point close
// to the light and nearly in its plane (the Sponza's walls under its sky opening), fireflies no
// number of samples averages away. In solid angle the weight is the solid angle itself, bounded
// by 2 pi.
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "formats/host_device.h"
#include "runtime/shading/constants.h"

namespace kdpm {

struct SphericalRectangle {
    glm::vec3 origin, x, y, z;  // the rectangle's frame; z points from it toward the origin's side
    float x0, x1, y0, y1, z0;   // the rectangle in that frame, z0 < 0
    float b0, b1, k;
    float solid_angle = 0.0f;

    // The point of the rectangle for the unit square sample (u, v), uniform in solid angle.
    KDPM_HD glm::vec3 point(float u, float v) const {
        const float au = u * solid_angle + k;
        const float fu = (cosf(au) * b0 - b1) / sinf(au);
        float cu = (fu > 0.0f ? 1.0f : -1.0f) / sqrtf(fu * fu + b0 * b0);
        cu = cu < -1.0f ? -1.0f : (cu > 1.0f ? 1.0f : cu);
        const float s2 = 1.0f - cu * cu;
        float xu = -(cu * z0) / sqrtf(s2 > 1e-12f ? s2 : 1e-12f);
        xu = xu < x0 ? x0 : (xu > x1 ? x1 : xu);
        const float d = sqrtf(xu * xu + z0 * z0);
        const float h0 = y0 / sqrtf(d * d + y0 * y0), h1 = y1 / sqrtf(d * d + y1 * y1);
        const float hv = h0 + v * (h1 - h0), hv2 = hv * hv;
        const float yv = hv2 < 1.0f - 1e-6f ? (hv * d) / sqrtf(1.0f - hv2) : y1;
        return origin + xu * x + yv * y + z0 * z;
    }
};

// The rectangle corner + [0,1] ex + [0,1] ey (ex and ey perpendicular) as seen from `origin`;
// false where it subtends no solid angle there (the origin in its plane, degenerate edges).
KDPM_HD inline bool spherical_rectangle(const glm::vec3& origin, const glm::vec3& corner, const glm::vec3& ex,
                                        const glm::vec3& ey, SphericalRectangle& q) {
    const float ex_len = glm::length(ex), ey_len = glm::length(ey);
    if (!(ex_len > 0.0f) || !(ey_len > 0.0f)) return false;
    q.origin = origin;
    q.x = ex / ex_len;
    q.y = ey / ey_len;
    q.z = glm::cross(q.x, q.y);
    const glm::vec3 d = corner - origin;
    q.z0 = glm::dot(d, q.z);
    if (q.z0 > 0.0f) {
        q.z = -q.z;
        q.z0 = -q.z0;
    }
    if (!(q.z0 < 0.0f)) return false;
    q.x0 = glm::dot(d, q.x);
    q.y0 = glm::dot(d, q.y);
    q.x1 = q.x0 + ex_len;
    q.y1 = q.y0 + ey_len;
    // The normals of the planes through the origin and each edge, and the spherical
    // rectangle's inner angles between them.
    const glm::vec3 n0 = glm::normalize(glm::vec3(0.0f, q.z0, -q.y0));
    const glm::vec3 n1 = glm::normalize(glm::vec3(-q.z0, 0.0f, q.x1));
    const glm::vec3 n2 = glm::normalize(glm::vec3(0.0f, -q.z0, q.y1));
    const glm::vec3 n3 = glm::normalize(glm::vec3(q.z0, 0.0f, -q.x0));
    auto angle = [](const glm::vec3& a, const glm::vec3& b) {
        const float c = -glm::dot(a, b);
        return acosf(c < -1.0f ? -1.0f : (c > 1.0f ? 1.0f : c));
    };
    const float g0 = angle(n0, n1), g1 = angle(n1, n2), g2 = angle(n2, n3), g3 = angle(n3, n0);
    q.b0 = n0.z;
    q.b1 = n2.z;
    q.k = 2.0f * kPi - g2 - g3;
    q.solid_angle = g0 + g1 + g2 + g3 - 2.0f * kPi;
    return q.solid_angle > 0.0f && q.solid_angle < 7.0f;  // also false for NaN
}

}  // namespace kdpm
