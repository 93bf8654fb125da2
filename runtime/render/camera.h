#pragma once
// Pinhole camera rays from a CameraRecord (vertical field of view, look-at), at any resolution.
// One sample goes through the pixel centre; with several samples per pixel each is jittered by
// counter-based random numbers.
#include <cmath>
#include <cstdint>

#include <glm/glm.hpp>

#include "formats/geometry_layout.h"
#include "formats/host_device.h"
#include "runtime/shading/counter_random.h"

namespace kdpm {

struct CameraRay {
    glm::vec3 origin;
    glm::vec3 direction;  // unit length
};

struct PinholeCamera {
    glm::vec3 eye{0.0f};
    glm::vec3 forward{0.0f, 0.0f, -1.0f};
    glm::vec3 right{1.0f, 0.0f, 0.0f};  // scaled by tan(vfov/2) * aspect
    glm::vec3 up{0.0f, 1.0f, 0.0f};     // scaled by tan(vfov/2)
    std::uint32_t width = 1;
    std::uint32_t height = 1;
    std::uint32_t samples = 1;

    // Host only: builds the basis once per frame.
    static PinholeCamera from_record(const CameraRecord& c, std::uint32_t width, std::uint32_t height,
                                     std::uint32_t samples) {
        PinholeCamera cam;
        cam.eye = glm::vec3(c.eye[0], c.eye[1], c.eye[2]);
        cam.forward = glm::normalize(glm::vec3(c.lookat[0], c.lookat[1], c.lookat[2]) - cam.eye);
        glm::vec3 up_hint(c.up[0], c.up[1], c.up[2]);
        glm::vec3 right = glm::normalize(glm::cross(cam.forward, up_hint));
        glm::vec3 true_up = glm::cross(right, cam.forward);
        const float tan_half = std::tan(glm::radians(c.vfov_degrees) * 0.5f);
        const float aspect = static_cast<float>(width) / static_cast<float>(height);
        cam.right = right * (tan_half * aspect);
        cam.up = true_up * tan_half;
        cam.width = width;
        cam.height = height;
        cam.samples = samples < 1 ? 1 : samples;
        return cam;
    }

    // The angle one pixel subtends (radians, small-angle): a camera ray's footprint is t times it.
    KDPM_HD float pixel_spread() const { return 2.0f * glm::length(up) / static_cast<float>(height); }

    // The ray of the row-major pixel index `pixel` of an image `image_width` pixels wide.
    KDPM_HD CameraRay ray_at(std::uint64_t pixel, std::uint32_t image_width, std::uint32_t s) const {
        return ray(static_cast<std::uint32_t>(pixel % image_width), static_cast<std::uint32_t>(pixel / image_width), s);
    }
    // Ray through pixel (x, y) (row 0 at the top) for sample s of `samples`.
    KDPM_HD CameraRay ray(std::uint32_t x, std::uint32_t y, std::uint32_t s) const {
        float jx = 0.5f, jy = 0.5f;
        if (samples > 1) {
            const std::uint32_t pixel = y * width + x;
            jx = random01(pixel, s, 0x51u);
            jy = random01(pixel, s, 0x52u);
        }
        const float ndc_x = 2.0f * (static_cast<float>(x) + jx) / static_cast<float>(width) - 1.0f;
        const float ndc_y = 1.0f - 2.0f * (static_cast<float>(y) + jy) / static_cast<float>(height);
        CameraRay r;
        r.origin = eye;
        r.direction = glm::normalize(forward + ndc_x * right + ndc_y * up);
        return r;
    }
};

}  // namespace kdpm
