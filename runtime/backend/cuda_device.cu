// Device detection through the CUDA runtime. A missing driver is reported, not fatal.
#include "runtime/backend/cuda_device.h"

#include <chrono>
#include <stdexcept>

#include <cuda_runtime.h>

#include "runtime/backend/cuda_check.h"

namespace kdpm {

CudaDeviceStatus cuda_device_status() {
    CudaDeviceStatus s;
    int count = 0;
    cudaError_t status = cudaGetDeviceCount(&count);
    if (status != cudaSuccess) {
        (void)cudaGetLastError();  // clear the sticky error so later calls are not poisoned
        s.reason = cudaGetErrorString(status);
        return s;
    }
    if (count == 0) {
        s.reason = "no device found";
        return s;
    }
    s.device_count = count;
    return s;
}

void use_cuda_device(int index) {
    const CudaDeviceStatus s = cuda_device_status();
    if (s.device_count == 0) throw std::runtime_error("CUDA: no usable device (" + s.reason + ")");
    if (index < 0 || index >= s.device_count)
        throw std::runtime_error("CUDA: there is no device " + std::to_string(index) + " (this machine has " +
                                 std::to_string(s.device_count) + ", numbered from 0)");
    cuda_check(cudaSetDevice(index), "cudaSetDevice");
}

double start_cuda_device() {
    const auto start = std::chrono::steady_clock::now();
    cuda_check(cudaFree(nullptr), "initialising the device");
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace kdpm
