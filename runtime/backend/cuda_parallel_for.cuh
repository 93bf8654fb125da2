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

// Block size of one kernel (one functor type), from the occupancy API: computed on the first
// launch and kept for the life of the process, so every later frame launches without asking.
struct CudaLaunchShape {
    int block_size = 128;
    int max_blocks = 65535;  // enough blocks to fill the device; the grid-stride loop does the rest
};

template <class Body>
const CudaLaunchShape& cuda_launch_shape() {
    static const CudaLaunchShape shape = [] {
        CudaLaunchShape s;
        int min_grid = 0, block = 0;
        cuda_check(cudaOccupancyMaxPotentialBlockSize(&min_grid, &block, grid_stride_kernel<Body>, 0, 0),
                   "cudaOccupancyMaxPotentialBlockSize");
        if (block > 0) s.block_size = block;
        // Ray and photon work items differ a lot in cost; several waves of blocks balance them.
        if (min_grid > 0) s.max_blocks = std::max(min_grid * 8, 1);
        return s;
    }();
    return shape;
}

// Launches and waits once: the only synchronisation of a pass, so stage timings on the host
// are meaningful and a failing kernel is reported by the pass that ran it.
template <class Body>
void cuda_parallel_for(std::uint64_t n, const Body& body) {
    if (n == 0) return;
    const CudaLaunchShape& shape = cuda_launch_shape<Body>();
    const std::uint64_t block = static_cast<std::uint64_t>(shape.block_size);
    const std::uint64_t blocks = std::min<std::uint64_t>((n + block - 1) / block, static_cast<std::uint64_t>(shape.max_blocks));
    grid_stride_kernel<<<static_cast<unsigned>(blocks), static_cast<unsigned>(block)>>>(n, body);
    cuda_check(cudaGetLastError(), "kernel launch");
    cuda_check(cudaDeviceSynchronize(), "kernel execution");
}

}  // namespace kdpm
