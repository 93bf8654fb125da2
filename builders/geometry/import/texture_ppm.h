#pragma once
// kdpm's own reader of Netpbm colour images (P3 plain text, P6 binary): what builds without
// OpenImageIO (the GPU bundle) read, so that the shipped textured scene works everywhere.
#include <filesystem>
#include <optional>
#include <string>

#include "builders/geometry/import/texture_import.h"

namespace kdpm {

// Level 0 in linear RGB (sRGB-decoded), rows bottom to top; nullopt with `why` when the file is
// not a readable P3/P6 image.
std::optional<TextureImage> read_ppm_texture(const std::filesystem::path& path, std::string& why);

}  // namespace kdpm
