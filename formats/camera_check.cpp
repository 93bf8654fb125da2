#include "formats/camera_check.h"

#include <cmath>
#include <stdexcept>

namespace kdpm {

namespace {

bool finite3(const float (&v)[3]) { return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]); }

float dot(const float (&a)[3], const float (&b)[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

}  // namespace

void check_camera(const CameraRecord& c, const std::string& where) {
    auto fail = [&](const std::string& why) { throw std::runtime_error(where + ": camera " + why); };
    if (!finite3(c.eye)) fail("eye is not finite");
    if (!finite3(c.lookat)) fail("lookat is not finite");
    if (!finite3(c.up)) fail("up is not finite");
    if (!(c.vfov_degrees > 0.0f && c.vfov_degrees < 180.0f))
        fail("vfov must be in (0, 180) degrees, not " + std::to_string(c.vfov_degrees));
    if (c.width < 1 || c.width > kMaxImageSide || c.height < 1 || c.height > kMaxImageSide)
        fail("size " + std::to_string(c.width) + "x" + std::to_string(c.height) + " is out of range (1.." +
             std::to_string(kMaxImageSide) + ")");

    // The renderer normalises in float (x / sqrt(dot(x, x))): the squared lengths must be
    // normal floats, or the basis turns into NaN and the image into black.
    const float view[3] = {c.lookat[0] - c.eye[0], c.lookat[1] - c.eye[1], c.lookat[2] - c.eye[2]};
    if (!finite3(view)) fail("lookat - eye overflows");
    const float view_sq = dot(view, view), up_sq = dot(c.up, c.up);
    if (view_sq == 0.0f) fail("eye and lookat are the same point");
    if (!std::isnormal(view_sq)) fail("eye and lookat are too close or too far apart");
    if (up_sq == 0.0f) fail("up is the zero vector");
    if (!std::isnormal(up_sq)) fail("up is too short or too long");
    // Sine of the angle between view and up: near zero the image basis is undefined.
    const double v[3] = {view[0], view[1], view[2]}, u[3] = {c.up[0], c.up[1], c.up[2]};
    const double cross[3] = {v[1] * u[2] - v[2] * u[1], v[2] * u[0] - v[0] * u[2], v[0] * u[1] - v[1] * u[0]};
    const double sine = std::sqrt(cross[0] * cross[0] + cross[1] * cross[1] + cross[2] * cross[2]) /
                        std::sqrt(double(view_sq) * double(up_sq));
    if (!(sine > 1e-5)) fail("up is parallel to the view direction");
}

}  // namespace kdpm
