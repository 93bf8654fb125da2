#pragma once
// Turns a CUDA runtime error into a one-line std::runtime_error. Included only by CUDA sources.
#include <stdexcept>
#include <string>

#include <cuda_runtime.h>

namespace kdpm {

inline void cuda_check(cudaError_t status, const char* what) {
    if (status != cudaSuccess) {
        // The runtime also records a failed call as the "last error"; clear it, or the next
        // launch's cudaGetLastError() would report this failure (e.g. an out-of-memory frame
        // that the caller recovered from) as its own.
        (void)cudaGetLastError();
        throw std::runtime_error(std::string("CUDA: ") + what + ": " + cudaGetErrorString(status));
    }
}

}  // namespace kdpm
