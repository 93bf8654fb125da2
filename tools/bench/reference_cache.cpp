#include "tools/bench/reference_cache.h"

#include <algorithm>
#include <cinttypes>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <vector>

#include "formats/checksum.h"
#include "formats/metadata.h"
#include "runtime/render/image/image_output.h"
#include "tools/render/pfm_reader.h"

namespace kdpm::bench {
namespace {

std::uint64_t file_hash(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error("cannot read " + path.string());
    const std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    return checksum64(bytes.data(), bytes.size());
}

}  // namespace

std::string reference_file_name(const ReferenceKey& k) {
    const std::string fields = std::string("kdpm-bench-quality reference 1; kdpm ") + kdpm_version() +
                               "; geometry " + std::to_string(file_hash(k.geometry)) + "; " + std::to_string(k.width) +
                               "x" + std::to_string(k.height) + "; spp " + std::to_string(k.spp) + "; max_bounces " +
                               std::to_string(k.max_bounces) + "; max_depth " + std::to_string(k.max_depth);
    char hash[17];
    std::snprintf(hash, sizeof hash, "%016" PRIx64, checksum64(fields.data(), fields.size()));
    return k.scene + "-" + std::to_string(k.width) + "x" + std::to_string(k.height) + "-" + std::to_string(k.spp) +
           "spp-b" + std::to_string(k.max_bounces) + "-" + hash + ".pfm";
}

std::optional<Image> load_reference(const std::filesystem::path& file, const ReferenceKey& key) {
    std::error_code ec;
    if (!std::filesystem::exists(file, ec)) return std::nullopt;
    FloatImage pfm;
    try {
        pfm = read_pfm(file.string());
    } catch (const std::runtime_error& e) {
        throw std::runtime_error(std::string(e.what()) + "; remove it to render the reference anew");
    }
    if (pfm.channels != 3 || pfm.width != static_cast<int>(key.width) || pfm.height != static_cast<int>(key.height))
        throw std::runtime_error(file.string() + " is not a " + std::to_string(key.width) + "x" +
                                 std::to_string(key.height) + " RGB reference; remove it to render it anew");
    // PFM rows run bottom to top; an Image's top to bottom.
    Image image(pfm.width, pfm.height);
    const std::size_t row = static_cast<std::size_t>(pfm.width) * 3;
    for (int y = 0; y < pfm.height; ++y)
        std::copy_n(pfm.values.begin() + static_cast<std::ptrdiff_t>((pfm.height - 1 - y) * row), row,
                    image.rgb.begin() + static_cast<std::ptrdiff_t>(y * row));
    return image;
}

void store_reference(const std::filesystem::path& file, const Image& linear) {
    FrameOutput out;
    out.linear = &linear;
    write_frame(file, out);
}

}  // namespace kdpm::bench
