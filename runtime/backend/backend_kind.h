#pragma once
// Which backend runs the kernels, and how the user's --backend request is resolved against the
// devices present: `auto` falls back to the CPU with a notice, `cuda` without a device fails.
#include <string>
#include <string_view>

namespace kdpm {

enum class BackendKind { cpu, cuda };
enum class BackendRequest { automatic, cpu, cuda };

// "auto", "cpu" or "cuda"; throws std::invalid_argument otherwise.
BackendRequest parse_backend_request(std::string_view text);
const char* backend_name(BackendKind kind);

struct BackendSelection {
    BackendKind kind = BackendKind::cpu;
    std::string notice;  // one line for the user when `auto` fell back to the CPU; empty otherwise
};

// Throws std::runtime_error (one line) when the CUDA backend is requested but cannot run.
BackendSelection select_backend(BackendRequest request);

}  // namespace kdpm
