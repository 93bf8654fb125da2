// The CUDA-free build's answer to device detection: there is never a device.
#include "runtime/backend/cuda_device.h"

namespace kdpm {

CudaDeviceStatus cuda_device_status() {
    CudaDeviceStatus s;
    s.reason = "this build of kdpm has no CUDA backend";
    return s;
}

}  // namespace kdpm
