#pragma once
// Device detection. Compiled against the CUDA runtime only when the build has the CUDA backend
// (KDPM_HAVE_CUDA); otherwise a stub reports that there is none. Safe to call without a driver.
#include <string>

namespace kdpm {

struct CudaDeviceStatus {
    int device_count = 0;
    std::string reason;       // why there is no usable device (empty when device_count > 0)
};

CudaDeviceStatus cuda_device_status();

}  // namespace kdpm
