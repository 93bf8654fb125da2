#pragma once
// Image statistics the mode comparisons share (the tests and kdpm-bench-quality): the mean of an
// image and the relative MSE against a reference (mean over pixels and channels of
// (a - b)^2 / (b^2 + 0.01), linear radiance).
#include <cstddef>
#include <vector>

#include "runtime/render/image/image.h"

namespace kdpm {

// Mean of v[begin, end) (end 0: to the end).
inline double mean_of(const std::vector<float>& v, std::size_t begin = 0, std::size_t end = 0) {
    if (end == 0) end = v.size();
    double sum = 0;
    for (std::size_t i = begin; i < end; ++i) sum += v[i];
    return sum / static_cast<double>(end - begin);
}

inline double mean_of(const Image& image) { return mean_of(image.rgb); }

inline double relative_mse(const std::vector<float>& image, const std::vector<float>& reference) {
    double sum = 0;
    for (std::size_t i = 0; i < reference.size(); ++i) {
        const double a = image[i], b = reference[i];
        sum += (a - b) * (a - b) / (b * b + 0.01);
    }
    return sum / static_cast<double>(reference.size());
}

inline double relative_mse(const Image& image, const Image& reference) { return relative_mse(image.rgb, reference.rgb); }

}  // namespace kdpm
