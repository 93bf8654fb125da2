// kdpm's own image encoders: 8-bit PNG (grey or RGB, zlib-compressed, no filter)
// and float PFM (grey "Pf" or RGB "PF", little-endian, rows bottom to top as the format says).
#include "runtime/render/image/image_encoder.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>

#include <zlib.h>

namespace kdpm {

namespace {

void put_u32_be(std::vector<std::uint8_t>& out, std::uint32_t v) {
    for (int s = 24; s >= 0; s -= 8) out.push_back(static_cast<std::uint8_t>(v >> s));
}

void png_chunk(std::vector<std::uint8_t>& out, const char type[4], const std::vector<std::uint8_t>& data) {
    put_u32_be(out, static_cast<std::uint32_t>(data.size()));
    const std::size_t start = out.size();
    out.insert(out.end(), type, type + 4);
    out.insert(out.end(), data.begin(), data.end());
    const uLong crc = crc32(0L, out.data() + start, static_cast<uInt>(out.size() - start));
    put_u32_be(out, static_cast<std::uint32_t>(crc));
}

std::string encode_png(std::vector<std::uint8_t>& out, int width, int height, int nch, const std::vector<float>& pixels) {
    if (nch != 1 && nch != 3) return "PNG output holds 1 or 3 channels, not " + std::to_string(nch);
    const std::size_t row = static_cast<std::size_t>(width) * nch;
    std::vector<std::uint8_t> raw;
    raw.reserve((row + 1) * height);
    for (int y = 0; y < height; ++y) {
        raw.push_back(0);  // filter: none
        for (std::size_t i = 0; i < row; ++i) {
            const float v = pixels[static_cast<std::size_t>(y) * row + i];
            const float c = v > 0.0f ? (v < 1.0f ? v : 1.0f) : 0.0f;  // NaN -> 0
            raw.push_back(static_cast<std::uint8_t>(std::lround(c * 255.0f)));
        }
    }
    uLongf packed_size = compressBound(static_cast<uLong>(raw.size()));
    std::vector<std::uint8_t> packed(packed_size);
    if (compress2(packed.data(), &packed_size, raw.data(), static_cast<uLong>(raw.size()), 6) != Z_OK)
        return "zlib could not compress the image";
    packed.resize(packed_size);

    const std::uint8_t signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    out.assign(signature, signature + 8);
    std::vector<std::uint8_t> header;
    put_u32_be(header, static_cast<std::uint32_t>(width));
    put_u32_be(header, static_cast<std::uint32_t>(height));
    header.push_back(8);                 // bits per channel
    header.push_back(nch == 3 ? 2 : 0);  // colour type: RGB or grey
    header.push_back(0);                 // deflate
    header.push_back(0);                 // adaptive filtering (each row says "none")
    header.push_back(0);                 // not interlaced
    png_chunk(out, "IHDR", header);
    png_chunk(out, "IDAT", packed);
    png_chunk(out, "IEND", {});
    return {};
}

std::string encode_pfm(std::vector<std::uint8_t>& out, int width, int height, int nch, const std::vector<float>& pixels) {
    if (nch != 1 && nch != 3) return "PFM output holds 1 or 3 channels, not " + std::to_string(nch);
    const std::string header = std::string(nch == 3 ? "PF" : "Pf") + "\n" + std::to_string(width) + " " +
                               std::to_string(height) + "\n-1.0\n";
    out.assign(header.begin(), header.end());
    const std::size_t row = static_cast<std::size_t>(width) * nch;
    for (int y = height - 1; y >= 0; --y)
        for (std::size_t i = 0; i < row; ++i) {
            std::uint32_t bits;
            std::memcpy(&bits, &pixels[static_cast<std::size_t>(y) * row + i], 4);
            for (int s = 0; s < 32; s += 8) out.push_back(static_cast<std::uint8_t>(bits >> s));
        }
    return {};
}

}  // namespace

bool builtin_image_format(const std::filesystem::path& path, bool eight_bit) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
    return eight_bit ? ext == ".png" : ext == ".pfm";
}

std::string encode_builtin_image(std::vector<std::uint8_t>& out, const std::filesystem::path& path, int width,
                                 int height, const std::vector<std::string>& names, const std::vector<float>& pixels,
                                 bool eight_bit) {
    if (!builtin_image_format(path, eight_bit))
        return "unsupported image format '" + path.extension().string() + "' (this build writes .png and .pfm only)";
    const int nch = static_cast<int>(names.size());
    return eight_bit ? encode_png(out, width, height, nch, pixels) : encode_pfm(out, width, height, nch, pixels);
}

}  // namespace kdpm
