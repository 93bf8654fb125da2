#pragma once
// A new view without a rebuilt .kdg: the parts of the file's camera a user replaced on the command
// line (kdpm-render and kdpm-view --eye/--lookat/--up/--vfov).
#include <array>
#include <optional>

#include "formats/geometry_layout.h"

namespace kdpm {

struct CameraOverride {
    std::optional<std::array<double, 3>> eye, lookat, up;
    std::optional<double> vfov_degrees;

    bool empty() const { return !eye && !lookat && !up && !vfov_degrees; }

    // The file's camera with the given parts replaced (resolution kept); throws std::runtime_error
    // with a one-line reason when the result is not a usable camera.
    CameraRecord applied_to(const CameraRecord& file_camera) const;
};

}  // namespace kdpm
