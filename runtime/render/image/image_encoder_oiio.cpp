// encode_image in builds with OpenImageIO: .png and .pfm by kdpm's own encoders, every other
// format through the OpenImageIO module (formats/oiio), loaded on the first such image only.
#include <stdexcept>

#include "formats/oiio/oiio_plugin_loader.h"
#include "runtime/render/image/image_encoder.h"

namespace kdpm {

void encode_image(OutputTemp& temp, const std::filesystem::path& destination, int width, int height,
                  const std::vector<std::string>& names, const std::vector<float>& pixels, bool eight_bit) {
    auto fail = [](const std::string& why) { throw std::runtime_error(why); };
    std::vector<std::uint8_t> bytes;
    if (builtin_image_format(destination, eight_bit)) {
        const std::string why = encode_builtin_image(bytes, destination, width, height, names, pixels, eight_bit);
        if (!why.empty()) fail(why);
        temp.write(bytes.data(), bytes.size());
        return;
    }
    OiioImageRequest request;
    request.destination = destination.string();
    request.temp_path = temp.temp_path().string();
    request.width = width;
    request.height = height;
    request.channel_names = names;
    request.pixels = pixels.data();
    request.eight_bit = eight_bit;
    const std::string why = oiio_plugin().encode(request, bytes);
    if (!why.empty()) fail(why);
    // Empty: the module wrote the temporary itself and read it back.
    if (!bytes.empty()) temp.write(bytes.data(), bytes.size());
}

}  // namespace kdpm
