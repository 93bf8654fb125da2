#pragma once
// Encodes interleaved float pixels into one image file, the format chosen by the destination's
// extension, through the output discipline (formats/output_file.h): the bytes go into a private
// temporary that the caller publishes. kdpm writes 8-bit .png and float .pfm itself
// (encode_builtin_image); every other format goes through the OpenImageIO module (formats/oiio),
// loaded on first use, in builds that have it (KDPM_WITH_OPENIMAGEIO, the default). The GPU
// bundle is built without it, as OpenImageIO loads ~250 shared libraries.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "formats/output_file.h"

namespace kdpm {

// `pixels`: width * height * names.size() floats, rows top to bottom. eight_bit: values in
// [0, 1] stored as 8 bits per channel. Fills `temp` completely and checked, or throws
// std::runtime_error with why not (one line).
void encode_image(OutputTemp& temp, const std::filesystem::path& destination, int width, int height,
                  const std::vector<std::string>& names, const std::vector<float>& pixels, bool eight_bit);

// The built-in encoders: .png (eight_bit, 1 or 3 channels) and .pfm (floats, 1 or 3 channels).
// encode_builtin_image returns the file's bytes in `out` and an empty string, else why not.
bool builtin_image_format(const std::filesystem::path& path, bool eight_bit);
std::string encode_builtin_image(std::vector<std::uint8_t>& out, const std::filesystem::path& path, int width,
                                 int height, const std::vector<std::string>& names, const std::vector<float>& pixels,
                                 bool eight_bit);

}  // namespace kdpm
