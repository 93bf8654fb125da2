// encode_image with OpenImageIO: .pfm by kdpm's own encoder (OpenImageIO may lack it), every other
// format by OpenImageIO. Formats it can encode to memory go through the checked writer; the others
// are written by OpenImageIO to the temporary's path and read back whole, since some of its
// writers do not report a full disk.
#include <stdexcept>

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include "runtime/render/image_encoder.h"

namespace kdpm {

void encode_image(OutputTemp& temp, const std::filesystem::path& destination, int width, int height,
                  const std::vector<std::string>& names, const std::vector<float>& pixels, bool eight_bit) {
    auto fail = [](const std::string& why) { throw std::runtime_error(why); };
    if (!eight_bit && builtin_image_format(destination, false)) {
        std::vector<std::uint8_t> bytes;
        const std::string why = encode_builtin_image(bytes, destination, width, height, names, pixels, eight_bit);
        if (!why.empty()) fail(why);
        temp.write(bytes.data(), bytes.size());
        return;
    }
    // The format is chosen by the destination's extension; the temporary's name has none.
    auto out = OIIO::ImageOutput::create(destination.string());
    if (!out) fail("unsupported image format '" + destination.extension().string() + "'");
    const int nch = static_cast<int>(names.size());
    OIIO::ImageSpec spec(width, height, nch, eight_bit ? OIIO::TypeDesc::UINT8 : OIIO::TypeDesc::FLOAT);
    spec.channelnames = names;
    spec.alpha_channel = -1;
    for (int c = 0; c < nch; ++c)
        if (names[static_cast<std::size_t>(c)] == "Z") spec.z_channel = c;

    const bool in_memory = out->supports("ioproxy") != 0;
    OIIO::Filesystem::IOVecOutput memory;
    if (in_memory && !out->set_ioproxy(&memory)) fail(out->geterror());
    if (!out->open(temp.temp_path().string(), spec)) fail(out->geterror());
    if (!out->write_image(OIIO::TypeDesc::FLOAT, pixels.data())) {
        std::string why = out->geterror();
        out->close();
        fail(why);
    }
    if (!out->close()) fail(out->geterror());
    out.reset();
    if (in_memory) {
        if (memory.buffer().empty()) fail("the encoder produced no bytes");
        temp.write(memory.buffer().data(), memory.buffer().size());
    } else {
        auto in = OIIO::ImageInput::open(temp.temp_path().string());
        std::vector<float> check(static_cast<std::size_t>(width) * height * nch);
        if (!in || in->spec().width != width || in->spec().height != height ||
            !in->read_image(0, 0, 0, nch, OIIO::TypeDesc::FLOAT, check.data()))
            fail("the written image does not read back (is the disk full?)");
    }
}

}  // namespace kdpm
