#pragma once
// Diffuse textures for the .kdg: each distinct texture file a material names is read once
// (OpenImageIO; the runtime reads no images), turned into linear RGB (8- and 16-bit images are
// sRGB-decoded, float images taken as linear), flipped so that row 0 is v = 0, and stored with
// its box-filtered mip chain. A file that is missing or unreadable is one warning, and the
// materials that name it keep their diffuse colour.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "builders/geometry/scene.h"

namespace kdpm {

// Level 0 of a texture in linear RGB, rows bottom to top.
struct TextureImage {
    std::uint32_t width = 0, height = 0;
    std::vector<Texel> texels;
};

// The image, or nullopt with `why` set (one line) when it cannot be used. Only regular files are
// opened: a FIFO or a device would block or never end.
std::optional<TextureImage> read_texture_image(const std::filesystem::path& path, std::string& why);

// The image decoder of this build (OpenImageIO, or kdpm's PPM reader without it), for a path
// read_texture_image has found to be a regular file.
std::optional<TextureImage> decode_texture_file(const std::filesystem::path& path, std::string& why);

// sRGB transfer function decoded to linear.
float srgb_to_linear(float encoded);

// Reads scene.texture_paths into scene.textures / scene.texels and points each material at its
// texture (MaterialRecord::diffuse_texture); appends a warning per texture it cannot use.
void load_textures(Scene& scene);

}  // namespace kdpm
