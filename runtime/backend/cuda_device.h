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

// Creates the CUDA context on the current device now (it is otherwise made by the first CUDA
// call, which it slows) and returns the milliseconds it took, so that tools can time their
// work without it. Throws std::runtime_error (one line) where it fails, or without a device.
double start_cuda_device();

}  // namespace kdpm
