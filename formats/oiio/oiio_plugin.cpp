// The shared module kdpm-oiio.so: image encoding and decoding through OpenImageIO (see
// oiio_plugin_api.h for why it is a module). Formats OpenImageIO can encode to memory are
// returned as bytes; the others are written to the caller's temporary and read back whole, since
// some of its writers do not report a full disk.
#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <filesystem>

#include "formats/oiio/oiio_plugin_api.h"

namespace {

std::string one_line(std::string s) {
    std::replace(s.begin(), s.end(), '\n', ' ');
    while (!s.empty() && s.back() == ' ') s.pop_back();
    return s;
}

std::string encode(const kdpm::OiioImageRequest& r, std::vector<std::uint8_t>& memory) {
    memory.clear();
    auto out = OIIO::ImageOutput::create(r.destination);
    if (!out) return "unsupported image format '" + std::filesystem::path(r.destination).extension().string() + "'";
    const int nch = static_cast<int>(r.channel_names.size());
    OIIO::ImageSpec spec(r.width, r.height, nch, r.eight_bit ? OIIO::TypeDesc::UINT8 : OIIO::TypeDesc::FLOAT);
    spec.channelnames = r.channel_names;
    spec.alpha_channel = -1;
    for (int c = 0; c < nch; ++c)
        if (r.channel_names[static_cast<std::size_t>(c)] == "Z") spec.z_channel = c;

    const bool in_memory = out->supports("ioproxy") != 0;
    OIIO::Filesystem::IOVecOutput proxy;
    if (in_memory && !out->set_ioproxy(&proxy)) return one_line(out->geterror());
    if (!out->open(r.temp_path, spec)) return one_line(out->geterror());
    if (!out->write_image(OIIO::TypeDesc::FLOAT, r.pixels)) {
        std::string why = out->geterror();
        out->close();
        return one_line(why);
    }
    if (!out->close()) return one_line(out->geterror());
    out.reset();
    if (in_memory) {
        if (proxy.buffer().empty()) return "the encoder produced no bytes";
        memory.assign(proxy.buffer().begin(), proxy.buffer().end());
        return {};
    }
    auto in = OIIO::ImageInput::open(r.temp_path);
    std::vector<float> check(static_cast<std::size_t>(r.width) * r.height * nch);
    if (!in || in->spec().width != r.width || in->spec().height != r.height ||
        !in->read_image(0, 0, 0, nch, OIIO::TypeDesc::FLOAT, check.data()))
        return "the written image does not read back (is the disk full?)";
    return {};
}

std::string decode(const std::string& path, std::uint64_t max_side, kdpm::OiioDecodedImage& image) {
    auto in = OIIO::ImageInput::open(path);
    if (!in) return one_line("cannot read image: " + OIIO::geterror());
    const OIIO::ImageSpec& spec = in->spec();
    image.width = spec.width;
    image.height = spec.height;
    image.channels = spec.nchannels;
    image.integer_format = spec.format.basetype == OIIO::TypeDesc::UINT8 || spec.format.basetype == OIIO::TypeDesc::UINT16;
    if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0 || spec.depth > 1 ||
        static_cast<std::uint64_t>(spec.width) > max_side || static_cast<std::uint64_t>(spec.height) > max_side)
        return "image size " + std::to_string(spec.width) + "x" + std::to_string(spec.height) + " is not 1.." +
               std::to_string(max_side) + " per side";
    image.pixels.assign(static_cast<std::size_t>(spec.width) * spec.height * spec.nchannels, 0.0f);
    if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, image.pixels.data()))
        return one_line("cannot read image: " + in->geterror());
    return {};
}

const kdpm::OiioPluginApi kApi{kdpm::kOiioPluginAbi, &encode, &decode};

}  // namespace

extern "C" __attribute__((visibility("default"))) const kdpm::OiioPluginApi* kdpm_oiio_plugin_api() { return &kApi; }
