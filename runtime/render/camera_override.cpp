#include "runtime/render/camera_override.h"

#include "formats/camera_check.h"

namespace kdpm {
namespace {

void replace(float (&target)[3], const std::optional<std::array<double, 3>>& value) {
    if (!value) return;
    for (int i = 0; i < 3; ++i) target[i] = static_cast<float>((*value)[i]);
}

}  // namespace

CameraRecord CameraOverride::applied_to(const CameraRecord& file_camera) const {
    CameraRecord c = file_camera;
    replace(c.eye, eye);
    replace(c.lookat, lookat);
    replace(c.up, up);
    if (vfov_degrees) c.vfov_degrees = static_cast<float>(*vfov_degrees);
    check_camera(c, empty() ? "file" : "file with command-line overrides");
    return c;
}

}  // namespace kdpm
