#pragma once
// Reads the PFM float images kdpm writes (.pfm, 1 or 3 channels, either byte order), for the
// tools that compare renders (kdpm-image-diff, kdpm-bench-quality's cached reference).
#include <string>
#include <vector>

namespace kdpm {

struct FloatImage {
    int width = 0, height = 0, channels = 0;
    std::vector<float> values;  // rows as stored: bottom row first
};

// Throws std::runtime_error (one line) for a missing, malformed or truncated file.
FloatImage read_pfm(const std::string& path);

}  // namespace kdpm
