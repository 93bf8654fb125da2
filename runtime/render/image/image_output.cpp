#include "runtime/render/image/image_output.h"

#include <algorithm>
#include <cctype>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <system_error>

#include "formats/output_file.h"
#include "runtime/render/image/image_encoder.h"

namespace kdpm {

namespace {

struct Channel {
    std::string name;
    std::vector<float> values;  // one per pixel
};

std::string lower_extension(const std::filesystem::path& p) {
    std::string ext = p.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
    return ext;
}

// Encodes interleaved float channels into a finished private temporary beside `destination`
// (formats/output_file.h, through runtime/render/image/image_encoder.h); the caller publishes it.
std::unique_ptr<OutputTemp> encode_to_temporary(const std::filesystem::path& destination, int width, int height,
                                                const std::vector<Channel>& channels, bool eight_bit) {
    const std::size_t pixels = static_cast<std::size_t>(width) * height;
    const int nch = static_cast<int>(channels.size());
    std::vector<float> interleaved(pixels * nch);
    for (std::size_t i = 0; i < pixels; ++i)
        for (int c = 0; c < nch; ++c) interleaved[i * nch + c] = channels[static_cast<std::size_t>(c)].values[i];

    auto fail = [&](const std::string& why) -> void {
        throw std::runtime_error("cannot write " + destination.string() + ": " + why);
    };
    const std::filesystem::path folder = destination.has_parent_path() ? destination.parent_path() : ".";
    std::error_code exists_ec;
    if (!std::filesystem::is_directory(folder, exists_ec)) fail("folder " + folder.string() + " does not exist");
    auto temp = std::make_unique<OutputTemp>(destination);
    std::vector<std::string> names;
    for (const Channel& c : channels) names.push_back(c.name);
    try {
        encode_image(*temp, destination, width, height, names, interleaved, eight_bit);
    } catch (const std::runtime_error& e) {
        fail(e.what());
    }
    temp->finish();
    return temp;
}

std::vector<Channel> rgb_channels(const Image& img) {
    std::vector<Channel> ch{{"R", {}}, {"G", {}}, {"B", {}}};
    for (int c = 0; c < 3; ++c) {
        ch[static_cast<std::size_t>(c)].values.resize(img.pixel_count());
        for (std::size_t i = 0; i < img.pixel_count(); ++i)
            ch[static_cast<std::size_t>(c)].values[i] = img.rgb[i * 3 + c];
    }
    return ch;
}

void append_vec3(std::vector<Channel>& out, const std::string& prefix, const std::vector<float>& v, std::size_t n) {
    const char* axes[3] = {".X", ".Y", ".Z"};
    for (int c = 0; c < 3; ++c) {
        Channel ch{prefix + axes[c], std::vector<float>(n)};
        for (std::size_t i = 0; i < n; ++i) ch.values[i] = v[i * 3 + c];
        out.push_back(std::move(ch));
    }
}

// AOV channels, grouped per AOV. Triangle indices are stored as floats (exact below 2^24).
std::vector<std::vector<Channel>> aov_groups(const AovImages& a, const AovSet& set, std::size_t n,
                                             std::vector<std::string>* names) {
    std::vector<std::vector<Channel>> groups;
    if (set.depth) {
        groups.push_back({Channel{"Z", a.depth}});
        names->push_back("depth");
    }
    if (set.normal) {
        groups.emplace_back();
        append_vec3(groups.back(), "N", a.normal, n);
        names->push_back("normal");
    }
    if (set.position) {
        groups.emplace_back();
        append_vec3(groups.back(), "P", a.position, n);
        names->push_back("position");
    }
    if (set.triangle) {
        Channel ch{"triangle", std::vector<float>(n)};
        for (std::size_t i = 0; i < n; ++i) ch.values[i] = static_cast<float>(a.triangle[i]);
        groups.push_back({std::move(ch)});
        names->push_back("triangle");
    }
    return groups;
}

}  // namespace

bool is_float_format(const std::filesystem::path& path) {
    const std::string ext = lower_extension(path);
    return ext == ".exr" || ext == ".hdr" || ext == ".pfm";
}

std::vector<std::filesystem::path> write_frame(const std::filesystem::path& destination, const FrameOutput& f) {
    const bool floats = is_float_format(destination);
    const Image& main = floats ? *f.linear : *f.display;
    const std::size_t n = main.pixel_count();
    std::vector<std::string> names;
    std::vector<std::vector<Channel>> groups;
    if (f.aovs && f.aov_set.any()) groups = aov_groups(*f.aovs, f.aov_set, n, &names);

    // Every file is encoded to its temporary first, then all are published: a failed AOV never
    // leaves a new main image beside old AOVs.
    std::vector<std::filesystem::path> written;
    std::vector<std::unique_ptr<OutputTemp>> temps;
    std::vector<Channel> channels = rgb_channels(main);
    if (floats)
        for (auto& g : groups)
            for (auto& c : g) channels.push_back(std::move(c));
    temps.push_back(encode_to_temporary(destination, main.width, main.height, channels, !floats));
    written.push_back(destination);
    if (!floats) {
        for (std::size_t g = 0; g < groups.size(); ++g) {
            std::filesystem::path p = destination;
            p.replace_extension("." + names[g] + ".exr");
            temps.push_back(encode_to_temporary(p, main.width, main.height, groups[g], false));
            written.push_back(p);
        }
    }
    for (auto& t : temps) t->publish();
    return written;
}

}  // namespace kdpm
