#include "runtime/view/fly_camera.h"

#include <algorithm>
#include <cmath>

#include "formats/scene_limits.h"

namespace kdpm {

namespace {

glm::vec3 vec(const float (&v)[3]) { return glm::vec3(v[0], v[1], v[2]); }

void store(float (&out)[3], glm::vec3 v) {
    out[0] = v.x;
    out[1] = v.y;
    out[2] = v.z;
}

constexpr float kMaxPitch = 1.5533430f;  // 89 degrees: the look-at basis degenerates at 90

}  // namespace

FlyCamera::FlyCamera(const CameraRecord& file_camera, const GeometryInfo& bounds) : file_(file_camera) {
    // Crossing a typical scene takes about five seconds; shift for more.
    const auto diagonal = static_cast<float>(bounds_diagonal(bounds.bounds_min, bounds.bounds_max));
    speed_ = std::isfinite(diagonal) && diagonal > 0.0f ? diagonal * 0.2f : 1.0f;
    reset();
}

void FlyCamera::reset() {
    eye_ = vec(file_.eye);
    glm::vec3 up = vec(file_.up);
    up_ = glm::length(up) > 0.0f ? glm::normalize(up) : glm::vec3(0.0f, 1.0f, 0.0f);
    glm::vec3 view = vec(file_.lookat) - eye_;
    focus_distance_ = glm::length(view) > 0.0f ? glm::length(view) : 1.0f;
    glm::vec3 f = glm::length(view) > 0.0f ? view / glm::length(view) : glm::vec3(0.0f, 0.0f, -1.0f);
    pitch_ = std::asin(std::clamp(glm::dot(f, up_), -1.0f, 1.0f));
    pitch_ = std::clamp(pitch_, -kMaxPitch, kMaxPitch);
    glm::vec3 horizontal = f - glm::dot(f, up_) * up_;
    if (glm::length(horizontal) < 1e-6f) {
        // Looking straight along the up vector: any horizontal direction serves as yaw zero.
        horizontal = glm::cross(up_, std::fabs(up_.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 0, 1));
    }
    yaw_zero_ = glm::normalize(horizontal);
    yaw_right_ = glm::normalize(glm::cross(yaw_zero_, up_));
    yaw_ = 0.0f;
    pristine_ = true;
}

glm::vec3 FlyCamera::forward() const {
    glm::vec3 horizontal = std::cos(yaw_) * yaw_zero_ + std::sin(yaw_) * yaw_right_;
    return glm::normalize(std::cos(pitch_) * horizontal + std::sin(pitch_) * up_);
}

glm::vec3 FlyCamera::right() const { return std::cos(yaw_) * yaw_right_ - std::sin(yaw_) * yaw_zero_; }

bool FlyCamera::move(const FlyInput& input, float dt_seconds) {
    if (!input.any() || !(dt_seconds > 0.0f)) return false;
    const float step = speed_ * dt_seconds * (input.fast ? kFastFactor : 1.0f);
    glm::vec3 d = input.forward * forward() + input.right * right() + input.up * up_;
    eye_ += d * step;
    pristine_ = false;
    return true;
}

bool FlyCamera::look(float dx_pixels, float dy_pixels) {
    if (dx_pixels == 0.0f && dy_pixels == 0.0f) return false;
    yaw_ += dx_pixels * kRadiansPerPixel;
    yaw_ = std::remainder(yaw_, 6.2831853f);
    pitch_ = std::clamp(pitch_ - dy_pixels * kRadiansPerPixel, -kMaxPitch, kMaxPitch);
    pristine_ = false;
    return true;
}

CameraRecord FlyCamera::record() const {
    if (pristine_) return file_;
    CameraRecord r = file_;
    store(r.eye, eye_);
    store(r.lookat, eye_ + forward() * focus_distance_);
    store(r.up, up_);
    return r;
}

}  // namespace kdpm
