// The gpu tests' main: without a usable CUDA device, one line and exit code 77 (ctest's
// SKIP_RETURN_CODE) instead of failures; listing the tests (ctest's discovery) always works.
#define CATCH_CONFIG_RUNNER
#include <catch2/catch.hpp>

#include <cstdio>
#include <cstring>

#include "runtime/backend/cuda_device.h"

int main(int argc, char** argv) {
    bool listing = false;
    for (int i = 1; i < argc; ++i) listing = listing || std::strncmp(argv[i], "--list", 6) == 0;
    if (!listing) {
        const kdpm::CudaDeviceStatus status = kdpm::cuda_device_status();
        if (status.device_count == 0) {
            std::printf("kdpm_gpu_tests: skipped, no CUDA device (%s)\n", status.reason.c_str());
            return 77;
        }
    }
    return Catch::Session().run(argc, argv);
}
