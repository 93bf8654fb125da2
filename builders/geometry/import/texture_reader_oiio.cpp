// Texture files (PNG, JPEG, TGA, EXR, PPM, ...) through the OpenImageIO module (formats/oiio),
// loaded on the first texture only: a scene without textures never loads it.
#include <cmath>
#include <exception>

#include "builders/geometry/import/texture_import.h"
#include "formats/oiio/oiio_plugin_loader.h"

namespace kdpm {

std::optional<TextureImage> decode_texture_file(const std::filesystem::path& path, std::string& why) {
    OiioDecodedImage decoded;
    try {
        why = oiio_plugin().decode(path.string(), kMaxTextureSide, decoded);
    } catch (const std::exception& e) {
        why = e.what();
    }
    if (!why.empty()) return std::nullopt;
    const auto width = static_cast<std::uint32_t>(decoded.width), height = static_cast<std::uint32_t>(decoded.height);
    const int channels = decoded.channels;
    // Integer images hold sRGB-encoded colours; float images are linear already.
    TextureImage image;
    image.width = width;
    image.height = height;
    image.texels.resize(std::size_t{width} * height);
    for (std::uint32_t y = 0; y < height; ++y)
        for (std::uint32_t x = 0; x < width; ++x) {
            const float* p = &decoded.pixels[(std::size_t{y} * width + x) * channels];
            Texel& t = image.texels[std::size_t{height - 1 - y} * width + x];  // files store the top row first
            for (int c = 0; c < 3; ++c) {
                float v = p[channels >= 3 ? c : 0];  // grey (and grey + alpha) images
                if (decoded.integer_format) v = srgb_to_linear(v);
                t.rgb[c] = std::isfinite(v) && v > 0.0f ? v : 0.0f;
            }
        }
    return image;
}

}  // namespace kdpm
