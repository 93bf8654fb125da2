// Pinhole camera rays: the centre ray looks at the look-at point, the frame spans the vertical
// field of view, and jittered samples stay inside their pixel.
#include <catch2/catch.hpp>

#include <cmath>

#include "runtime/render/camera.h"

using namespace kdpm;

namespace {
CameraRecord record() {
    CameraRecord c{};
    c.eye[0] = 1; c.eye[1] = 2; c.eye[2] = 3;
    c.lookat[0] = 1; c.lookat[1] = 2; c.lookat[2] = -7;
    c.up[1] = 1;
    c.vfov_degrees = 60;
    c.width = 4;
    c.height = 2;
    return c;
}
}  // namespace

TEST_CASE("camera rays span the vertical field of view around the look-at direction", "[camera]") {
    // An odd resolution has a pixel centred on the optical axis.
    PinholeCamera cam = PinholeCamera::from_record(record(), 5, 3, 1);
    CameraRay centre = cam.ray(2, 1, 0);
    CHECK(centre.direction.z == Approx(-1.0f));
    CHECK(centre.origin.y == 2.0f);
    // The top edge of the top row is vfov/2 above the axis: its centre is 2/3 of the way.
    CameraRay top = cam.ray(2, 0, 0);
    const double angle = std::atan2(top.direction.y, -top.direction.z);
    CHECK(angle == Approx(std::atan(std::tan(30.0 * 3.14159265358979 / 180) * 2.0 / 3.0)));
    // Square pixels: the horizontal step equals the vertical one.
    CameraRay right = cam.ray(3, 1, 0);
    CHECK(right.direction.x / -right.direction.z == Approx(top.direction.y / -top.direction.z));
}

TEST_CASE("jittered samples stay inside their pixel and differ between samples", "[camera]") {
    PinholeCamera one = PinholeCamera::from_record(record(), 4, 2, 1);
    PinholeCamera many = PinholeCamera::from_record(record(), 4, 2, 8);
    const float half_x = std::fabs(one.ray(1, 0, 0).direction.x / one.ray(1, 0, 0).direction.z -
                                   one.ray(2, 0, 0).direction.x / one.ray(2, 0, 0).direction.z) / 2;
    CameraRay c = one.ray(1, 0, 0);
    float cx = c.direction.x / -c.direction.z;
    bool differ = false;
    for (std::uint32_t s = 0; s < 8; ++s) {
        CameraRay r = many.ray(1, 0, s);
        float x = r.direction.x / -r.direction.z;
        CHECK(std::fabs(x - cx) <= half_x * 1.0001f);
        differ |= s > 0 && r.direction != many.ray(1, 0, 0).direction;
    }
    CHECK(differ);
}
