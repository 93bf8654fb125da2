#include "builders/geometry/import/texture_ppm.h"

#include <cctype>
#include <fstream>
#include <iterator>

namespace kdpm {

namespace {

// Header and P3 numbers: decimal integers separated by whitespace, '#' comments to line end.
bool next_number(const std::string& s, std::size_t& at, std::uint32_t& value) {
    for (;;) {
        while (at < s.size() && std::isspace(static_cast<unsigned char>(s[at]))) ++at;
        if (at < s.size() && s[at] == '#') {
            while (at < s.size() && s[at] != '\n') ++at;
            continue;
        }
        break;
    }
    if (at >= s.size() || !std::isdigit(static_cast<unsigned char>(s[at]))) return false;
    std::uint64_t v = 0;
    while (at < s.size() && std::isdigit(static_cast<unsigned char>(s[at]))) {
        v = v * 10 + static_cast<std::uint64_t>(s[at++] - '0');
        if (v > 0xffffffffu) return false;
    }
    value = static_cast<std::uint32_t>(v);
    return true;
}

}  // namespace

std::optional<TextureImage> read_ppm_texture(const std::filesystem::path& path, std::string& why) {
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        why = "cannot open the file";
        return std::nullopt;
    }
    const std::string s((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (s.size() < 2 || s[0] != 'P' || (s[1] != '3' && s[1] != '6')) {
        why = "not a P3 or P6 PPM image";
        return std::nullopt;
    }
    std::size_t at = 2;
    std::uint32_t width = 0, height = 0, maxval = 0;
    if (!next_number(s, at, width) || !next_number(s, at, height) || !next_number(s, at, maxval) || maxval == 0 ||
        maxval > 65535) {
        why = "a malformed PPM header";
        return std::nullopt;
    }
    if (width == 0 || height == 0 || width > kMaxTextureSide || height > kMaxTextureSide) {
        why = "image size " + std::to_string(width) + "x" + std::to_string(height) + " is not 1.." +
              std::to_string(kMaxTextureSide) + " per side";
        return std::nullopt;
    }
    const std::size_t samples = std::size_t{width} * height * 3;
    const bool binary = s[1] == '6';
    const std::size_t bytes_per_sample = maxval > 255 ? 2 : 1;
    if (binary) ++at;  // the single whitespace between maxval and the samples
    if (binary && s.size() < at + samples * bytes_per_sample) {
        why = "the PPM file is cut short";
        return std::nullopt;
    }
    TextureImage image;
    image.width = width;
    image.height = height;
    image.texels.resize(std::size_t{width} * height);
    for (std::size_t i = 0; i < samples; ++i) {
        std::uint32_t v = 0;
        if (binary) {
            v = static_cast<unsigned char>(s[at++]);
            if (bytes_per_sample == 2) v = v << 8 | static_cast<unsigned char>(s[at++]);
        } else if (!next_number(s, at, v)) {
            why = "the PPM file is cut short or holds a non-number";
            return std::nullopt;
        }
        if (v > maxval) {
            why = "a PPM sample exceeds its maximum value";
            return std::nullopt;
        }
        const std::size_t pixel = i / 3, x = pixel % width, y = pixel / width;
        image.texels[(height - 1 - y) * width + x].rgb[i % 3] = srgb_to_linear(static_cast<float>(v) / static_cast<float>(maxval));
    }
    return image;
}

}  // namespace kdpm
