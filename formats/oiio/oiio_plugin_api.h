#pragma once
// What kdpm asks of OpenImageIO, behind one shared module (kdpm-oiio.so) that the tools load only
// when they meet an image format kdpm does not encode or decode itself: OpenImageIO pulls in
// about 250 shared libraries (OpenCV, FFmpeg, OpenVDB, ...), whose loading delays the start of
// every process that links it. Plain data across the boundary; the caller keeps
// its own output discipline (the module never publishes a file).
#include <cstdint>
#include <string>
#include <vector>

namespace kdpm {

struct OiioImageRequest {
    std::string destination;  // chooses the format by its extension
    std::string temp_path;    // where a format that cannot encode to memory is written
    int width = 0, height = 0;
    std::vector<std::string> channel_names;
    const float* pixels = nullptr;  // width * height * channel_names.size(), rows top to bottom
    bool eight_bit = false;
};

struct OiioDecodedImage {
    int width = 0, height = 0, channels = 0;
    bool integer_format = false;  // 8- or 16-bit integers (sRGB-encoded colours)
    std::vector<float> pixels;    // width * height * channels, rows top to bottom
};

struct OiioPluginApi {
    std::uint32_t abi_version;
    // Encodes to `memory`, or (when memory stays empty) has written and read back temp_path.
    // Returns "" on success, else why not (one line).
    std::string (*encode)(const OiioImageRequest& request, std::vector<std::uint8_t>& memory);
    // Reads the header first: an image over `max_side` per side is refused before its pixels.
    // Returns "" on success, else why not (one line).
    std::string (*decode)(const std::string& path, std::uint64_t max_side, OiioDecodedImage& image);
};

// Bumped whenever OiioPluginApi or the structures above change: a stale module is refused.
inline constexpr std::uint32_t kOiioPluginAbi = 2;

}  // namespace kdpm

// The module's one exported symbol.
extern "C" const kdpm::OiioPluginApi* kdpm_oiio_plugin_api();
