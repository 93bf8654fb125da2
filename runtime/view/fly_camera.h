#pragma once
// The viewer's fly camera: a position plus yaw/pitch about the file camera's up vector. Moves
// with a speed scaled to the scene bounds, turns with mouse drags, and resets to the file's
// camera exactly (an unmoved camera returns the file's record bit for bit, so a viewer frame
// matches kdpm-render's).
#include <glm/glm.hpp>

#include "formats/geometry_layout.h"

namespace kdpm {

// Held movement keys as axes in {-1, 0, 1}.
struct FlyInput {
    float forward = 0.0f;  // W +, S -
    float right = 0.0f;    // D +, A -
    float up = 0.0f;       // E +, Q -
    bool fast = false;     // shift
    bool any() const { return forward != 0.0f || right != 0.0f || up != 0.0f; }
};

class FlyCamera {
public:
    static constexpr float kFastFactor = 4.0f;
    static constexpr float kRadiansPerPixel = 0.004f;

    FlyCamera(const CameraRecord& file_camera, const GeometryInfo& bounds);

    void reset();
    // Moves along the view direction (forward), the horizontal right vector and the up vector
    // by speed() * dt (times kFastFactor when fast). Returns true when the camera moved.
    bool move(const FlyInput& input, float dt_seconds);
    // Mouse drag in pixels: right turns right, down looks down. Pitch stays within +-89 degrees.
    bool look(float dx_pixels, float dy_pixels);

    CameraRecord record() const;  // the file's record while unmoved
    glm::vec3 eye() const { return eye_; }
    glm::vec3 forward() const;
    glm::vec3 right() const;  // horizontal, unit length
    glm::vec3 world_up() const { return up_; }
    float speed() const { return speed_; }  // scene units per second (without fast)
    bool at_file_camera() const { return pristine_; }

private:
    CameraRecord file_;
    glm::vec3 up_{0.0f, 1.0f, 0.0f};
    glm::vec3 yaw_zero_{0.0f, 0.0f, -1.0f};  // horizontal forward at yaw 0
    glm::vec3 yaw_right_{1.0f, 0.0f, 0.0f};  // horizontal right at yaw 0
    glm::vec3 eye_{0.0f};
    float yaw_ = 0.0f, pitch_ = 0.0f, focus_distance_ = 1.0f, speed_ = 1.0f;
    bool pristine_ = true;
};

}  // namespace kdpm
