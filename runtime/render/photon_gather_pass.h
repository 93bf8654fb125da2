#pragma once
// Pass 2 of a frame sample: the photon-map radiance at each diffuse vertex.
// Placeholder until the photon library lands: gathers nothing.
#include <cstdint>

#include <glm/vec3.hpp>

#include "formats/host_device.h"
#include "runtime/render/frame_buffers.h"

namespace kdpm {

struct PhotonMaps {
    bool present = false;
    bool empty() const { return !present; }
};

struct PhotonGatherPass {
    FrameBuffersView frame;

    KDPM_HD void operator()(std::uint64_t slot) const {
        frame.gathered[slot] = glm::vec3(0.0f);
    }
};

struct FramePlan;
inline PhotonGatherPass make_gather_pass(const PhotonMaps&, const FramePlan&) { return PhotonGatherPass{}; }

}  // namespace kdpm
