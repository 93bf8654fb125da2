#pragma once
// The CUDA backend's launcher: the same functor the CPU backend runs through cpu_parallel_for,
// called once per work item by a grid-stride loop. The functor's operator() must be KDPM_HD
// and hold only device pointers. Include from .cu files only.
#include <algorithm>
#include <cstdint>

#include "runtime/backend/cuda_check.h"

namespace kdpm {

template <class Body>
__global__ void grid_stride_kernel(std::uint64_t n, Body body) {
    const std::uint64_t stride = static_cast<std::uint64_t>(blockDim.x) * gridDim.x;
    for (std::uint64_t i = static_cast<std::uint64_t>(blockIdx.x) * blockDim.x + threadIdx.x; i < n; i += stride)
        body(i);
}

// Synchronous: returns when every item is done, so stage timings on the host are meaningful.
template <class Body>
void cuda_parallel_for(std::uint64_t n, const Body& body, unsigned block_size = 128) {
    if (n == 0) return;
    const std::uint64_t blocks = std::min<std::uint64_t>((n + block_size - 1) / block_size, 65535u * 8u);
    grid_stride_kernel<<<static_cast<unsigned>(blocks), block_size>>>(n, body);
    cuda_check(cudaGetLastError(), "kernel launch");
    cuda_check(cudaDeviceSynchronize(), "kernel execution");
}

}  // namespace kdpm
