#pragma once
// The CPU backend's Device (frame loop, photon shooting, density view): host arrays and oneTBB
// launches in small grains (each work item writes only its own slots).
#include <algorithm>
#include <cstdint>
#include <cstring>
#include <memory>
#include <type_traits>
#include <vector>

#include "runtime/backend/cpu_parallel_for.h"
#include "runtime/backend/device_concept.h"
#include "runtime/backend/host_block_cache.h"

namespace kdpm {

struct CpuDevice {
    // Arrays are host memory: a caller may read them in place instead of copying with to_host.
    static constexpr bool arrays_on_host = true;
    // The photon gather runs a tile of pixels per work item (PhotonTileGatherPass).
    static constexpr bool gathers_by_tile = true;
    // Camera rays are traced in packets, each block's trace pass going on from them (PacketTracePass).
    static constexpr bool traces_packets = true;
    // Where arrays of plain data come from and go back to when set (a frame backend's cache,
    // kept from frame to frame); else they are allocated and freed as any.
    HostBlockCache* cache = nullptr;

    // Frees an array's items: back to the cache they came from, or delete[].
    template <class T>
    struct Release {
        HostBlockCache* cache = nullptr;
        std::size_t capacity = 0;
        void operator()(T* items) const {
            if (cache)
                cache->give(items, capacity);
            else
                delete[] items;
        }
    };
    template <class T>
    struct Array {
        std::unique_ptr<T[], Release<T>> items;
        std::uint64_t count = 0;
        T* data() const { return items.get(); }
    };
    void begin() {}  // arrays own their memory until they are destroyed
    // Zero-filled.
    template <class T>
    Array<T> array(std::uint64_t n) {
        Array<T> a = scratch<T>(n);
        if (a.items.get_deleter().cache)
            std::memset(static_cast<void*>(a.data()), 0, n * sizeof(T));  // plain data: zero bits
        else
            std::fill(a.data(), a.data() + n, T{});
        return a;
    }
    // Left uninitialised: for arrays every item of which a pass writes before any is read.
    template <class T>
    Array<T> scratch(std::uint64_t n) {
        if constexpr (std::is_trivial_v<T>) {
            if (cache && n > 0) {
                std::size_t capacity = 0;
                T* items = static_cast<T*>(cache->take(n * sizeof(T), capacity));
                return Array<T>{std::unique_ptr<T[], Release<T>>(items, Release<T>{cache, capacity}), n};
            }
        }
        return Array<T>{std::unique_ptr<T[], Release<T>>(new T[n], Release<T>{}), n};
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

static_assert(BackendDevice<CpuDevice>);

}  // namespace kdpm
