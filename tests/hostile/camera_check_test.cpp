// check_camera: every camera that would give NaN rays (an all-black image) is refused.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <stdexcept>

#include "formats/camera_check.h"

using namespace kdpm;

namespace {

CameraRecord good() {
    CameraRecord c{};
    c.eye[2] = 4.0f;
    c.up[1] = 1.0f;
    c.vfov_degrees = 40.0f;
    c.width = c.height = 64;
    return c;
}

std::string reason(const CameraRecord& c) {
    try {
        check_camera(c, "scene.json");
    } catch (const std::runtime_error& e) {
        return e.what();
    }
    return "";
}

}  // namespace

TEST_CASE("check_camera accepts an ordinary camera", "[hostile][camera]") {
    CHECK(reason(good()).empty());
    CameraRecord tilted = good();
    tilted.up[0] = 0.3f;  // not orthogonal to the view, but not parallel either
    CHECK(reason(tilted).empty());
}

TEST_CASE("check_camera refuses degenerate cameras with a one-line reason", "[hostile][camera]") {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    CameraRecord c = good();
    c.up[1] = 0.0f;
    c.up[2] = 1.0f;  // along the view direction (0, 0, -1)
    CHECK(reason(c).find("parallel") != std::string::npos);
    c = good();
    c.lookat[2] = c.eye[2];
    CHECK(reason(c).find("same point") != std::string::npos);
    c = good();
    c.eye[0] = nan;
    CHECK(reason(c).find("eye is not finite") != std::string::npos);
    c = good();
    c.lookat[1] = inf;
    CHECK(reason(c).find("lookat is not finite") != std::string::npos);
    c = good();
    c.up[1] = 0.0f;
    CHECK(reason(c).find("zero vector") != std::string::npos);
    c = good();
    c.up[1] = 1e-30f;  // its squared length underflows in float
    CHECK(!reason(c).empty());
    c = good();
    c.eye[2] = -3e38f;
    c.lookat[2] = 3e38f;  // the difference overflows
    CHECK(!reason(c).empty());
    for (float vfov : {0.0f, 180.0f, -5.0f, nan}) {
        c = good();
        c.vfov_degrees = vfov;
        CHECK(reason(c).find("vfov") != std::string::npos);
    }
    c = good();
    c.width = 65536;
    CHECK(reason(c).find("size") != std::string::npos);
    c = good();
    c.height = 0;
    CHECK(reason(c).find("size") != std::string::npos);
    const std::string r = reason(c);
    CHECK(r.rfind("scene.json: camera", 0) == 0);
    CHECK(r.find('\n') == std::string::npos);
}
