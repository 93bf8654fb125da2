#pragma once
// The device arrays a frame's AOVs are written into, shared by the frame loop and the SPPM loop:
// allocated for the AOVs asked for, named in the passes' FrameBuffersView, copied back to host
// images (3 floats per pixel for the vector ones) at the end of the frame.
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "runtime/render/frame_buffers.h"
#include "runtime/render/image/image.h"

namespace kdpm {

template <class Device>
struct AovArrays {
    AovSet want;
    typename Device::template Array<float> depth;
    typename Device::template Array<glm::vec3> normal, position;
    typename Device::template Array<std::int32_t> triangle;

    AovArrays(Device& dev, const AovSet& wanted, std::uint64_t pixels)
        : want(wanted),
          depth(dev.template scratch<float>(wanted.depth ? pixels : 0)),
          normal(dev.template scratch<glm::vec3>(wanted.normal ? pixels : 0)),
          position(dev.template scratch<glm::vec3>(wanted.position ? pixels : 0)),
          triangle(dev.template scratch<std::int32_t>(wanted.triangle ? pixels : 0)) {}

    void name_in(FrameBuffersView& fb) const {
        fb.depth = want.depth ? depth.data() : nullptr;
        fb.normal = want.normal ? normal.data() : nullptr;
        fb.position = want.position ? position.data() : nullptr;
        fb.triangle = want.triangle ? triangle.data() : nullptr;
    }

    void to_host(Device& dev, AovImages& aovs) const {
        aovs = AovImages{};
        if (want.depth) dev.to_host(depth, aovs.depth);
        if (want.triangle) dev.to_host(triangle, aovs.triangle);
        auto flatten = [&](const auto& array, std::vector<float>& out) {
            std::vector<glm::vec3> v;
            dev.to_host(array, v);
            out.resize(v.size() * 3);
            for (std::size_t i = 0; i < v.size(); ++i)
                for (int c = 0; c < 3; ++c) out[i * 3 + c] = v[i][c];
        };
        if (want.normal) flatten(normal, aovs.normal);
        if (want.position) flatten(position, aovs.position);
    }
};

}  // namespace kdpm
