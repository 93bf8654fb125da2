#include "runtime/backend/backend_kind.h"

#include <stdexcept>

#include "runtime/backend/cuda_device.h"

namespace kdpm {

BackendRequest parse_backend_request(std::string_view text) {
    if (text == "auto") return BackendRequest::automatic;
    if (text == "cpu") return BackendRequest::cpu;
    if (text == "cuda") return BackendRequest::cuda;
    throw std::invalid_argument("expected auto, cpu or cuda, got '" + std::string(text) + "'");
}

const char* backend_name(BackendKind kind) { return kind == BackendKind::cuda ? "cuda" : "cpu"; }

BackendSelection select_backend(BackendRequest request) {
    if (request == BackendRequest::cpu) return {BackendKind::cpu, ""};
    CudaDeviceStatus status = cuda_device_status();
    if (status.device_count > 0) return {BackendKind::cuda, ""};
    if (request == BackendRequest::cuda)
        throw std::runtime_error("--backend cuda: no usable CUDA device (" + status.reason + ")");
    return {BackendKind::cpu, "no CUDA device (" + status.reason + "); using the CPU backend"};
}

}  // namespace kdpm
