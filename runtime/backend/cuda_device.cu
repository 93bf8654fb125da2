// Device detection through the CUDA runtime. A missing driver is reported, not fatal.
#include "runtime/backend/cuda_device.h"

#include <cuda_runtime.h>

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

}  // namespace kdpm
