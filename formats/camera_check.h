#pragma once
// The one check of a camera before it reaches a kernel: from a scene card, a .kdg file, a
// command-line override or the viewer. A camera that passes gives finite, non-degenerate rays.
#include <cstdint>
#include <string>

#include "formats/geometry_layout.h"

namespace kdpm {

// Largest image side the renderer and the viewer accept.
inline constexpr std::uint32_t kMaxImageSide = 16384;

// Throws std::runtime_error "<where>: camera ...: <reason>" (one line) when the camera has a
// non-finite value, eye == lookat, a zero up vector or one parallel to the view direction, a
// field of view outside (0, 180) degrees, or an image side outside 1..kMaxImageSide.
void check_camera(const CameraRecord& camera, const std::string& where);

}  // namespace kdpm
