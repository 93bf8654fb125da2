// encode_image in builds without OpenImageIO: kdpm's own .png and .pfm only.
#include <stdexcept>

#include "runtime/render/image/image_encoder.h"

namespace kdpm {

void encode_image(OutputTemp& temp, const std::filesystem::path& destination, int width, int height,
                  const std::vector<std::string>& names, const std::vector<float>& pixels, bool eight_bit) {
    std::vector<std::uint8_t> bytes;
    const std::string why = encode_builtin_image(bytes, destination, width, height, names, pixels, eight_bit);
    if (!why.empty()) throw std::runtime_error(why);
    temp.write(bytes.data(), bytes.size());
}

}  // namespace kdpm
