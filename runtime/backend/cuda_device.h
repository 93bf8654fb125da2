#pragma once
// Device detection and selection. Compiled against the CUDA runtime only when the build has the
// CUDA backend (KDPM_HAVE_CUDA); otherwise a stub reports that there is none. Safe to call
// without a driver.
#include <string>

namespace kdpm {

struct CudaDeviceStatus {
    int device_count = 0;
    std::string reason;       // why there is no usable device (empty when device_count > 0)
};

CudaDeviceStatus cuda_device_status();

// Makes `index` the device that later CUDA work of this thread runs on (default: device 0).
// Throws std::runtime_error (one line) for an index no device has, or without a device.
void use_cuda_device(int index);

}  // namespace kdpm
