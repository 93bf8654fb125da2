// Texture files through OpenImageIO (PNG, JPEG, TGA, EXR, ...).
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>

#include "builders/geometry/texture_import.h"

namespace kdpm {

std::optional<TextureImage> decode_texture_file(const std::filesystem::path& path, std::string& why) {
    auto in = OIIO::ImageInput::open(path.string());
    if (!in) {
        why = "cannot read image: " + OIIO::geterror();
        std::replace(why.begin(), why.end(), '\n', ' ');
        return std::nullopt;
    }
    const OIIO::ImageSpec& spec = in->spec();
    if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0 || spec.depth > 1 ||
        static_cast<std::uint64_t>(spec.width) > kMaxTextureSide || static_cast<std::uint64_t>(spec.height) > kMaxTextureSide) {
        why = "image size " + std::to_string(spec.width) + "x" + std::to_string(spec.height) + " is not 1.." +
              std::to_string(kMaxTextureSide) + " per side";
        return std::nullopt;
    }
    const auto width = static_cast<std::uint32_t>(spec.width), height = static_cast<std::uint32_t>(spec.height);
    const int channels = spec.nchannels;
    std::vector<float> pixels(std::size_t{width} * height * channels);
    if (!in->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, pixels.data())) {
        why = "cannot read image: " + in->geterror();
        std::replace(why.begin(), why.end(), '\n', ' ');
        return std::nullopt;
    }
    // Integer images hold sRGB-encoded colours; float images are linear already.
    const bool encoded = spec.format.basetype == OIIO::TypeDesc::UINT8 || spec.format.basetype == OIIO::TypeDesc::UINT16;
    TextureImage image;
    image.width = width;
    image.height = height;
    image.texels.resize(std::size_t{width} * height);
    for (std::uint32_t y = 0; y < height; ++y)
        for (std::uint32_t x = 0; x < width; ++x) {
            const float* p = &pixels[(std::size_t{y} * width + x) * channels];
            Texel& t = image.texels[std::size_t{height - 1 - y} * width + x];  // files store the top row first
            for (int c = 0; c < 3; ++c) {
                float v = p[channels >= 3 ? c : 0];  // grey (and grey + alpha) images
                if (encoded) v = srgb_to_linear(v);
                t.rgb[c] = std::isfinite(v) && v > 0.0f ? v : 0.0f;
            }
        }
    return image;
}

}  // namespace kdpm
