#pragma once
// Reading a device array's items on the host without a copy where the device's arrays are host
// memory (CpuDevice), and through one where they are not (CUDA).
#include <vector>

#include "runtime/backend/device_concept.h"

namespace kdpm {

// The items of `a` readable on the host: `a` itself on a device whose arrays are host memory,
// else a copy in `buffer`.
template <class Device, class Array, class T>
const T* items_on_host(Device& dev, const Array& a, std::vector<T>& buffer) {
    if constexpr (arrays_on_host_v<Device>) {
        return a.data();
    } else {
        dev.to_host(a, buffer);
        return buffer.data();
    }
}

}  // namespace kdpm
