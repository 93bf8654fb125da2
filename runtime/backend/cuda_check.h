#pragma once
// Turns a CUDA runtime error into a one-line std::runtime_error. Included only by CUDA sources.
#include <stdexcept>
#include <string>

#include <cuda_runtime.h>

namespace kdpm {

inline void cuda_check(cudaError_t status, const char* what) {
    if (status != cudaSuccess)
        throw std::runtime_error(std::string("CUDA: ") + what + ": " + cudaGetErrorString(status));
}

}  // namespace kdpm
