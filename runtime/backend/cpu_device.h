#pragma once
// The CPU backend's Device (frame loop, photon shooting, density view): host arrays and oneTBB
// launches in small grains (each work item writes only its own slots).
#include <algorithm>
#include <cstdint>
#include <memory>
#include <vector>

#include "runtime/backend/cpu_parallel_for.h"

namespace kdpm {

struct CpuDevice {
    // Arrays are host memory: a caller may read them in place instead of copying with to_host.
    static constexpr bool arrays_on_host = true;
    // The photon gather runs a tile of pixels per work item (PhotonTileGatherPass).
    static constexpr bool gathers_by_tile = true;
    // Camera rays are traced in packets first (CameraPacketPass).
    static constexpr bool traces_packets = true;
    template <class T>
    struct Array {
        std::unique_ptr<T[]> items;
        std::uint64_t count = 0;
        T* data() const { return items.get(); }
    };
    void begin() {}  // arrays own their memory; nothing is pooled
    // Zero-filled.
    template <class T>
    Array<T> array(std::uint64_t n) {
        return Array<T>{std::unique_ptr<T[]>(new T[n]()), n};
    }
    // Left uninitialised: for arrays every item of which a pass writes before any is read.
    template <class T>
    Array<T> scratch(std::uint64_t n) {
        return Array<T>{std::unique_ptr<T[]>(new T[n]), n};
    }
    template <class T>
    void to_host(const Array<T>& a, std::vector<T>& out) {
        out.assign(a.data(), a.data() + a.count);
    }
    template <class T>
    Array<T> from_host(const std::vector<T>& items) {
        Array<T> a = scratch<T>(items.size());
        std::copy(items.begin(), items.end(), a.data());
        return a;
    }
    template <class Pass>
    void launch(std::uint64_t n, const Pass& pass) {
        cpu_parallel_for(n, pass, 16);
    }
};

}  // namespace kdpm
