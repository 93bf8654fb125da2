#pragma once
// Image statistics the mode comparisons share: the mean of an image and the relative MSE
// against a reference (mean over pixels and channels of (a - b)^2 / (b^2 + 0.01), linear radiance).
#include <cstddef>
#include <vector>

#include "runtime/render/image.h"

namespace kdpm::test {

inline double mean_of(const std::vector<float>& v) {
    double sum = 0;
    for (float x : v) sum += x;
    return sum / static_cast<double>(v.size());
}

inline double mean_of(const Image& image) { return mean_of(image.rgb); }

inline double relative_mse(const Image& image, const Image& reference) {
    double sum = 0;
    for (std::size_t i = 0; i < reference.rgb.size(); ++i) {
        const double a = image.rgb[i], b = reference.rgb[i];
        sum += (a - b) * (a - b) / (b * b + 0.01);
    }
    return sum / static_cast<double>(reference.rgb.size());
}

}  // namespace kdpm::test
