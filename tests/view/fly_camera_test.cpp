#include <catch2/catch.hpp>

#include <cstring>

#include <glm/glm.hpp>

#include "runtime/view/fly_camera.h"

using namespace kdpm;

namespace {

CameraRecord cornell_camera() {
    CameraRecord c{};
    c.eye[1] = 1.0f;
    c.eye[2] = 3.9f;
    c.lookat[1] = 1.0f;
    c.up[1] = 1.0f;
    c.vfov_degrees = 40.0f;
    c.width = c.height = 512;
    return c;
}

GeometryInfo unit_box() {
    GeometryInfo info{};
    info.bounds_min[0] = -1.0f;
    info.bounds_max[0] = 1.0f;
    info.bounds_max[1] = 2.0f;
    info.bounds_min[2] = -1.0f;
    info.bounds_max[2] = 1.0f;
    return info;
}

bool same_record(const CameraRecord& a, const CameraRecord& b) { return std::memcmp(&a, &b, sizeof a) == 0; }

glm::vec3 v3(const float (&v)[3]) { return glm::vec3(v[0], v[1], v[2]); }

}  // namespace

TEST_CASE("fly camera starts at and resets to the file camera exactly", "[view][camera]") {
    const CameraRecord file = cornell_camera();
    FlyCamera cam(file, unit_box());
    CHECK(same_record(cam.record(), file));
    CHECK(cam.at_file_camera());
    FlyInput in;
    in.forward = 1.0f;
    in.right = -1.0f;
    cam.move(in, 0.3f);
    cam.look(40.0f, -25.0f);
    CHECK_FALSE(same_record(cam.record(), file));
    cam.reset();
    CHECK(same_record(cam.record(), file));
}

TEST_CASE("fly camera forward move goes along the view direction by speed times dt", "[view][camera]") {
    FlyCamera cam(cornell_camera(), unit_box());
    // Speed scales with the scene: a fifth of the bounds' diagonal per second.
    CHECK(cam.speed() == Approx(0.2f * std::sqrt(12.0f)));
    const glm::vec3 start = cam.eye();
    const glm::vec3 dir = cam.forward();
    CHECK(dir.z == Approx(-1.0f));
    FlyInput in;
    in.forward = 1.0f;
    REQUIRE(cam.move(in, 0.5f));
    const glm::vec3 moved = cam.eye() - start;
    CHECK(glm::length(moved) == Approx(cam.speed() * 0.5f));
    CHECK(glm::dot(glm::normalize(moved), dir) == Approx(1.0f));

    // Shift multiplies the step; Q/E move along the up vector; no input does nothing.
    const glm::vec3 before_fast = cam.eye();
    in.fast = true;
    cam.move(in, 0.25f);
    CHECK(glm::length(cam.eye() - before_fast) == Approx(cam.speed() * 0.25f * FlyCamera::kFastFactor));
    FlyInput up;
    up.up = 1.0f;
    const glm::vec3 before_up = cam.eye();
    cam.move(up, 1.0f);
    CHECK(cam.eye().y - before_up.y == Approx(cam.speed()));
    CHECK_FALSE(cam.move(FlyInput{}, 1.0f));
}

TEST_CASE("fly camera forward follows pitch and right matches the image's right", "[view][camera]") {
    CameraRecord file = cornell_camera();
    file.lookat[0] = 2.0f;  // looking right and down
    file.lookat[1] = -1.0f;
    FlyCamera cam(file, unit_box());
    const glm::vec3 expected = glm::normalize(v3(file.lookat) - v3(file.eye));
    CHECK(glm::dot(cam.forward(), expected) == Approx(1.0f));
    // The renderer's image right is normalize(cross(forward, up)).
    const glm::vec3 image_right = glm::normalize(glm::cross(expected, glm::vec3(0, 1, 0)));
    CHECK(glm::dot(cam.right(), image_right) == Approx(1.0f));
    // The record of a moved camera looks the same way.
    FlyInput in;
    in.right = 1.0f;
    cam.move(in, 0.1f);
    const CameraRecord r = cam.record();
    CHECK(glm::dot(glm::normalize(v3(r.lookat) - v3(r.eye)), expected) == Approx(1.0f));
    CHECK(glm::dot(v3(r.eye) - v3(file.eye), image_right) == Approx(cam.speed() * 0.1f));
}

TEST_CASE("fly camera look turns right on a rightward drag and clamps pitch", "[view][camera]") {
    FlyCamera cam(cornell_camera(), unit_box());
    const glm::vec3 right = cam.right();
    cam.look(50.0f, 0.0f);
    CHECK(glm::dot(cam.forward(), right) > 0.1f);
    CHECK(cam.forward().y == Approx(0.0f).margin(1e-6));
    cam.look(0.0f, 30.0f);  // drag down: look down
    CHECK(cam.forward().y < -0.05f);
    cam.look(0.0f, -1e6f);  // far past straight up
    const float pitch = std::asin(cam.forward().y);
    CHECK(pitch <= glm::radians(89.0f) + 1e-4f);
    CHECK(pitch > glm::radians(88.0f));
    const CameraRecord r = cam.record();
    const glm::vec3 f = v3(r.lookat) - v3(r.eye);
    CHECK(glm::length(glm::cross(f, v3(r.up))) > 1e-3f);  // a usable look-at basis
}

TEST_CASE("fly camera accepts a camera looking straight down", "[view][camera]") {
    CameraRecord file = cornell_camera();
    file.lookat[0] = 0.0f;
    file.lookat[1] = -5.0f;
    file.lookat[2] = 3.9f;
    FlyCamera cam(file, unit_box());
    CHECK(std::isfinite(cam.forward().x));
    CHECK(cam.forward().y < -0.99f);
    cam.look(10.0f, 0.0f);
    CHECK(std::isfinite(cam.record().lookat[0]));
}
