#pragma once
// Writes a rendered frame with OpenImageIO, the format chosen by the extension (.png, .exr, ...).
// Every file goes through the output discipline of formats/output_file.h, and the files of one
// frame are published together, so an error never leaves a half-written or mismatched image. 8-bit formats receive the display image; EXR (and
// other float formats) the exposed linear radiance, with the AOVs as extra channels
// (Z; N.x N.y N.z; P.x P.y P.z; triangle). For 8-bit outputs the AOVs go to separate EXR files
// beside it: out.depth.exr, out.normal.exr, out.position.exr, out.triangle.exr.
#include <filesystem>
#include <vector>

#include "runtime/render/image/image.h"

namespace kdpm {

struct FrameOutput {
    const Image* linear = nullptr;   // exposed linear radiance
    const Image* display = nullptr;  // tone-mapped sRGB in [0, 1]
    const AovImages* aovs = nullptr;
    AovSet aov_set;
};

// Returns every file written. Throws std::runtime_error (one line) on failure.
std::vector<std::filesystem::path> write_frame(const std::filesystem::path& destination, const FrameOutput& frame);

// True for extensions whose pixels are stored as floats (.exr, .hdr, .pfm).
bool is_float_format(const std::filesystem::path& path);

}  // namespace kdpm
