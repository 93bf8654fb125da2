// The CUDA-free build's answer to device detection: there is never a device.
#include "runtime/backend/cuda_device.h"

#include <stdexcept>

namespace kdpm {

CudaDeviceStatus cuda_device_status() {
    CudaDeviceStatus s;
    s.reason = "this build of kdpm has no CUDA backend";
    return s;
}

void use_cuda_device(int) { throw std::runtime_error("this build of kdpm has no CUDA backend"); }

double start_cuda_device() { throw std::runtime_error("this build of kdpm has no CUDA backend"); }

}  // namespace kdpm
