// kdpm-image-diff A.pfm B.pfm: the difference of two float images of the same size (e.g. the
// CPU and CUDA renders of one frame), as one line: mean and largest absolute difference, the
// mean value of A, and how many values differ at all. Reads the PFM files kdpm-render writes.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "tools/cli/args.h"
#include "tools/cli/run_tool.h"

using namespace kdpm;

namespace {

struct FloatImage {
    int width = 0, height = 0, channels = 0;
    std::vector<float> values;
};

FloatImage read_pfm(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error("cannot open " + path);
    std::string magic;
    FloatImage img;
    double scale = 0;
    in >> magic >> img.width >> img.height >> scale;
    if (!in || (magic != "PF" && magic != "Pf") || img.width <= 0 || img.height <= 0 || img.width > 65536 ||
        img.height > 65536 || scale == 0.0)
        throw std::runtime_error(path + " is not a PFM image");
    in.get();  // the single whitespace after the scale
    img.channels = magic == "PF" ? 3 : 1;
    const std::size_t count = static_cast<std::size_t>(img.width) * img.height * img.channels;
    std::vector<unsigned char> bytes(count * 4);
    if (!in.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(bytes.size())))
        throw std::runtime_error(path + " is truncated");
    const bool little = scale < 0;
    img.values.resize(count);
    for (std::size_t i = 0; i < count; ++i) {
        std::uint32_t bits = 0;
        for (int b = 0; b < 4; ++b) {
            const std::uint32_t byte = bytes[i * 4 + (little ? b : 3 - b)];
            bits |= byte << (8 * b);
        }
        std::memcpy(&img.values[i], &bits, 4);
    }
    return img;
}

}  // namespace

int main(int argc, char** argv) {
    std::string a_path, b_path;
    cli::Args args("kdpm-image-diff", "Prints the mean and largest absolute difference of two PFM images.");
    args.positional("A.pfm", &a_path, "reference image").positional("B.pfm", &b_path, "image compared with it");
    args.parse(argc, argv);
    return cli::run_tool("kdpm-image-diff", [&] {
        const FloatImage a = read_pfm(a_path), b = read_pfm(b_path);
        if (a.width != b.width || a.height != b.height || a.channels != b.channels)
            throw std::runtime_error("the images differ in size: " + std::to_string(a.width) + "x" +
                                     std::to_string(a.height) + " vs " + std::to_string(b.width) + "x" +
                                     std::to_string(b.height));
        double sum = 0, largest = 0, mean_a = 0;
        std::size_t differing = 0;
        for (std::size_t i = 0; i < a.values.size(); ++i) {
            const double d = std::fabs(static_cast<double>(a.values[i]) - b.values[i]);
            sum += d;
            largest = std::max(largest, d);
            mean_a += std::fabs(a.values[i]);
            differing += !(a.values[i] == b.values[i]);
        }
        const double n = static_cast<double>(a.values.size());
        std::printf("mean |diff| %.6g, max |diff| %.6g, mean value %.6g, %zu of %zu values differ\n", sum / n, largest,
                    mean_a / n, differing, a.values.size());
        return 0;
    });
}
