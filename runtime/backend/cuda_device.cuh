#pragma once
// The CUDA backend's Device, the counterpart of CpuDevice for the templates written once for
// both (run_frame, the photon shooting loop, the density view): device arrays, launches and
// copies to the host. Include from .cu files only.
//
// Arrays come from a pool kept for the life of the object: the n-th array asked for since
// begin() reuses the n-th buffer when it is large enough, so a frame loop that asks for the
// same arrays every frame allocates only when the image grows. An array is a view into its
// pool buffer and is valid until the next begin().
#include <cstdint>
#include <string>
#include <vector>

#include "runtime/backend/cuda_check.h"
#include "runtime/backend/cuda_parallel_for.cuh"
#include "runtime/backend/device_buffer.h"
#include "runtime/backend/device_concept.h"

namespace kdpm {

class CudaDevice {
public:
    template <class T>
    struct Array {
        T* pointer = nullptr;
        std::uint64_t count = 0;
        T* data() const { return pointer; }
    };

    // Starts a new frame (or batch): arrays are handed out from the first pool buffer again.
    void begin() { next_ = 0; }

    // Zero-filled (asynchronously: ordered before the next launch on the same stream).
    template <class T>
    Array<T> array(std::uint64_t n) {
        Array<T> a = scratch<T>(n);
        if (n) cuda_check(cudaMemsetAsync(a.pointer, 0, n * sizeof(T)), "cudaMemsetAsync");
        return a;
    }
    // Left uninitialised: for arrays every item of which a pass writes before any is read.
    template <class T>
    Array<T> scratch(std::uint64_t n) {
        return Array<T>{static_cast<T*>(take(n * sizeof(T))), n};
    }
    template <class T>
    void to_host(const Array<T>& a, std::vector<T>& out) {
        out.resize(a.count);
        if (a.count)
            cuda_check(cudaMemcpy(out.data(), a.pointer, a.count * sizeof(T), cudaMemcpyDeviceToHost), "download");
    }
    template <class T>
    Array<T> from_host(const std::vector<T>& items) {
        Array<T> a = scratch<T>(items.size());
        if (!items.empty())
            cuda_check(cudaMemcpy(a.pointer, items.data(), items.size() * sizeof(T), cudaMemcpyHostToDevice), "upload");
        return a;
    }
    template <class Pass>
    void launch(std::uint64_t n, const Pass& pass) {
        cuda_parallel_for(n, pass);
    }

    std::size_t allocations() const { return allocations_; }  // cudaMalloc calls so far

private:
    // An empty array still takes its place in the order, so that each array keeps its buffer
    // when a frame leaves out an optional one (an AOV, the gather's) that the next asks for.
    void* take(std::size_t bytes) {
        if (next_ == pool_.size()) pool_.emplace_back();
        DeviceBuffer& slot = pool_[next_++];
        if (bytes == 0) return nullptr;
        if (slot.size() < bytes) {
            slot = DeviceBuffer();  // free first, so the old and new buffer never both count
            slot = DeviceBuffer(bytes);
            ++allocations_;
        }
        return slot.as<void>();
    }

    std::vector<DeviceBuffer> pool_;
    std::size_t next_ = 0;
    std::size_t allocations_ = 0;
};

static_assert(BackendDevice<CudaDevice>);

}  // namespace kdpm
