#include "tools/render/pfm_reader.h"

#include <cstdint>
#include <cstring>
#include <fstream>
#include <stdexcept>

namespace kdpm {

FloatImage read_pfm(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error("cannot open " + path);
    std::string magic;
    FloatImage img;
    double scale = 0;
    in >> magic >> img.width >> img.height >> scale;
    if (!in || (magic != "PF" && magic != "Pf") || img.width <= 0 || img.height <= 0 || img.width > 65536 ||
        img.height > 65536 || scale == 0.0)
        throw std::runtime_error(path + " is not a PFM image");
    in.get();  // the single whitespace after the scale
    img.channels = magic == "PF" ? 3 : 1;
    const std::size_t count = static_cast<std::size_t>(img.width) * img.height * img.channels;
    std::vector<unsigned char> bytes(count * 4);
    if (!in.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(bytes.size())))
        throw std::runtime_error(path + " is truncated");
    const bool little = scale < 0;
    img.values.resize(count);
    for (std::size_t i = 0; i < count; ++i) {
        std::uint32_t bits = 0;
        for (int b = 0; b < 4; ++b) {
            const std::uint32_t byte = bytes[i * 4 + (little ? b : 3 - b)];
            bits |= byte << (8 * b);
        }
        std::memcpy(&img.values[i], &bits, 4);
    }
    return img;
}

}  // namespace kdpm
