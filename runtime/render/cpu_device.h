#pragma once
// The CPU backend's side of run_frame: host vectors and oneTBB launches in row-sized grains
// (each work item is one pixel or one vertex slot and writes only its own slots).
#include <cstdint>
#include <vector>

#include "runtime/backend/cpu_parallel_for.h"

namespace kdpm {

struct CpuDevice {
    template <class T>
    std::vector<T> array(std::uint64_t n) {
        return std::vector<T>(n, T{});
    }
    template <class T>
    void to_host(const std::vector<T>& a, std::vector<T>& out) {
        out = a;
    }
    template <class Pass>
    void launch(std::uint64_t n, const Pass& pass) {
        cpu_parallel_for(n, pass, 16);
    }
};

}  // namespace kdpm
