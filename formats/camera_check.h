#pragma once
// The one test of a usable pinhole camera, applied wherever a camera enters kdpm (scene cards,
// command-line overrides, .kdg files): a camera that fails it would render a silent black image.
#include <string>

#include "formats/geometry_layout.h"

namespace kdpm {

// Throws std::runtime_error "camera (WHERE): REASON" when a coordinate is not finite, eye equals
// lookat, up is zero or parallel to the view direction, or the vertical field of view is not in
// (0, 180) degrees.
void check_camera(const CameraRecord& camera, const std::string& where);

}  // namespace kdpm
