#pragma once
// Encodes interleaved float pixels into one image file, the format chosen by the extension.
// kdpm writes 8-bit .png and float .pfm itself (encode_builtin_image); every other format goes
// through OpenImageIO, in builds that have it (KDPM_WITH_OPENIMAGEIO, the default). The GPU
// bundle is built without it, as OpenImageIO loads ~250 shared libraries.
#include <filesystem>
#include <string>
#include <vector>

namespace kdpm {

// `pixels`: width * height * names.size() floats, rows top to bottom. eight_bit: values in
// [0, 1] stored as 8 bits per channel. Returns an empty string on success, else why not (one
// line); a failed write may leave a partial file at `path` (callers write to a temporary).
std::string encode_image_file(const std::filesystem::path& path, int width, int height,
                              const std::vector<std::string>& names, const std::vector<float>& pixels, bool eight_bit);

// The built-in encoders: .png (eight_bit, 1 or 3 channels) and .pfm (floats, 1 or 3 channels).
bool builtin_image_format(const std::filesystem::path& path, bool eight_bit);
std::string encode_builtin_image(const std::filesystem::path& path, int width, int height,
                                 const std::vector<std::string>& names, const std::vector<float>& pixels, bool eight_bit);

}  // namespace kdpm
