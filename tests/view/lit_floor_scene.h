#pragma once
// The viewer tests' scene: a white floor under a small area light, seen from above.
#include <cstdint>

#include "tests/runtime/hand_built_scene.h"

namespace kdpm::test {

// eye_height 3 shows only the floor; lower, its edges come into view (where the camera's
// jitter changes the image).
inline HandBuiltScene lit_floor(float eye_height, std::uint32_t size) {
    HandBuiltScene s;
    const auto white = s.add_material(glm::vec3(0.8f));
    s.add_quad(glm::vec3(-1, 0, -1), glm::vec3(0, 0, 2), glm::vec3(2, 0, 0), white);
    s.add_parallelogram_light(glm::vec3(-0.2f, 2, -0.2f), glm::vec3(0.4f, 0, 0), glm::vec3(0, 0, 0.4f),
                              glm::vec3(5.0f));
    s.set_camera(glm::vec3(0, eye_height, 0.01f), glm::vec3(0, 0, 0), glm::vec3(0, 1, 0), 60.0f, size, size);
    return s;
}

}  // namespace kdpm::test
