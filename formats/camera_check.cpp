#include "formats/camera_check.h"

#include <cmath>
#include <stdexcept>

namespace kdpm {
namespace {

struct Vec {
    double x, y, z;
};

double length(const Vec& v) { return std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z); }

Vec cross(const Vec& a, const Vec& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

bool finite(const float (&v)[3]) { return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]); }

}  // namespace

void check_camera(const CameraRecord& c, const std::string& where) {
    auto fail = [&](const std::string& why) { throw std::runtime_error("camera (" + where + "): " + why); };
    if (!finite(c.eye)) fail("eye is not a finite point");
    if (!finite(c.lookat)) fail("lookat is not a finite point");
    if (!finite(c.up)) fail("up is not a finite vector");
    if (!(c.vfov_degrees > 0.0f && c.vfov_degrees < 180.0f))
        fail("vertical field of view " + std::to_string(c.vfov_degrees) + " is outside (0, 180) degrees");
    // In double: float differences of huge coordinates would overflow before the test.
    const Vec view{double(c.lookat[0]) - c.eye[0], double(c.lookat[1]) - c.eye[1], double(c.lookat[2]) - c.eye[2]};
    const Vec up{c.up[0], c.up[1], c.up[2]};
    const double view_length = length(view), up_length = length(up);
    if (!(view_length > 0.0) || !std::isfinite(view_length)) fail("eye and lookat are the same point");
    if (!(up_length > 0.0) || !std::isfinite(up_length)) fail("up is the zero vector");
    // The image plane needs a right vector: sin(angle between view and up) well above rounding.
    if (!(length(cross(view, up)) > 1e-6 * view_length * up_length)) fail("up is parallel to the view direction");
    // The frame is built in float: a view that is finite in double but not in float is unusable.
    if (!std::isfinite(static_cast<float>(view_length))) fail("eye and lookat are too far apart");
}

}  // namespace kdpm
