#pragma once
// The viewer's current view as kdpm-render options, so a view found by flying can be rendered
// offline ("copy as command line" in the panel).
#include <string>

#include "formats/geometry_layout.h"

namespace kdpm {

// "--eye X Y Z --lookat X Y Z --up X Y Z --vfov DEG", each float printed so it reads back exactly.
std::string camera_command_line(const CameraRecord& camera);

}  // namespace kdpm
