// kdpm-image-diff A.pfm B.pfm: the difference of two float images of the same size (e.g. the
// CPU and CUDA renders of one frame), as one line: mean and largest absolute difference, the
// mean value of A, and how many values differ at all. Reads the PFM files kdpm-render writes.
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "tools/cli/args.h"
#include "tools/cli/run_tool.h"
#include "tools/render/pfm_reader.h"

using namespace kdpm;

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
