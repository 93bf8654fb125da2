#pragma once
// The contract of a backend device, as the frame loop, SPPM and the photon shooter use it:
// begin() a frame's arrays; array<T>(n) zero-filled and scratch<T>(n) uninitialised, each with
// data() the pointer the kernels read; from_host and to_host copies; launch(n, pass) calls pass(i)
// for i in [0, n). Optional capabilities are constants a device may declare (each false when
// absent): arrays_on_host (data() is host memory), traces_packets and gathers_by_tile (the CPU's
// SIMD packet trace and tiled gather). A new backend is a device header that models this, the
// source that runs the frame loop on it, and its CMake.
#include <concepts>
#include <cstdint>
#include <vector>

namespace kdpm {

namespace device_contract {
struct Item {
    float value;
};
struct Pass {
    void operator()(std::uint64_t) const {}
};
}  // namespace device_contract

template <class D>
concept BackendDevice = requires(D& d, std::uint64_t n, const std::vector<device_contract::Item>& host,
                                 std::vector<device_contract::Item>& out) {
    d.begin();
    { d.template array<device_contract::Item>(n).data() } -> std::same_as<device_contract::Item*>;
    { d.template scratch<device_contract::Item>(n).data() } -> std::same_as<device_contract::Item*>;
    { d.from_host(host).data() } -> std::same_as<device_contract::Item*>;
    d.to_host(d.template array<device_contract::Item>(n), out);
    d.launch(n, device_contract::Pass{});
};

template <class D>
inline constexpr bool arrays_on_host_v = requires { requires D::arrays_on_host; };
template <class D>
inline constexpr bool traces_packets_v = requires { requires D::traces_packets; };
template <class D>
inline constexpr bool gathers_by_tile_v = requires { requires D::gathers_by_tile; };

}  // namespace kdpm
