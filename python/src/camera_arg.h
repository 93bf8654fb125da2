#pragma once
// The `camera=` argument of render and camera_rays: a dict overriding the file camera's eye,
// lookat, up and vfov, checked as every camera is (formats/camera_check.h).
#include <pybind11/pybind11.h>

#include "formats/geometry_layout.h"

namespace kdpm::python {

// ValueError (one line) for an unknown key, a wrong length or a degenerate camera.
CameraRecord camera_arg(const CameraRecord& file_camera, const pybind11::object& camera);

}  // namespace kdpm::python
