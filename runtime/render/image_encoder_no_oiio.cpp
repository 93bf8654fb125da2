// encode_image_file in builds without OpenImageIO: kdpm's own .png and .pfm only.
#include "runtime/render/image_encoder.h"

namespace kdpm {

std::string encode_image_file(const std::filesystem::path& path, int width, int height,
                              const std::vector<std::string>& names, const std::vector<float>& pixels, bool eight_bit) {
    return encode_builtin_image(path, width, height, names, pixels, eight_bit);
}

}  // namespace kdpm
