// encode_image_file with OpenImageIO: .pfm by kdpm's own encoder (OpenImageIO may lack it),
// every other format by OpenImageIO.
#include "runtime/render/image_encoder.h"

#include <OpenImageIO/imageio.h>

namespace kdpm {

std::string encode_image_file(const std::filesystem::path& path, int width, int height,
                              const std::vector<std::string>& names, const std::vector<float>& pixels, bool eight_bit) {
    if (!eight_bit && builtin_image_format(path, false))
        return encode_builtin_image(path, width, height, names, pixels, eight_bit);
    auto out = OIIO::ImageOutput::create(path.string());
    if (!out) return "unsupported image format '" + path.extension().string() + "'";
    const int nch = static_cast<int>(names.size());
    OIIO::ImageSpec spec(width, height, nch, eight_bit ? OIIO::TypeDesc::UINT8 : OIIO::TypeDesc::FLOAT);
    spec.channelnames = names;
    spec.alpha_channel = -1;
    for (int c = 0; c < nch; ++c)
        if (names[static_cast<std::size_t>(c)] == "Z") spec.z_channel = c;
    if (!out->open(path.string(), spec)) return out->geterror();
    if (!out->write_image(OIIO::TypeDesc::FLOAT, pixels.data())) {
        std::string why = out->geterror();
        out->close();
        return why;
    }
    if (!out->close()) return out->geterror();
    return {};
}

}  // namespace kdpm
