#pragma once
// The backend-specific half of the Renderer: where the scene arrays live and how passes run.
// The CPU backend uses the mapped sections in place; the CUDA backend uploads each once.
#include <cstdint>
#include <memory>
#include <vector>

#include "runtime/render/frame_loop.h"
#include "runtime/render/scene_views.h"

namespace kdpm {

class FrameBackend {
public:
    virtual ~FrameBackend() = default;
    virtual void run(const FramePlan& plan, Image& linear, AovImages& aovs, StageTimes& times) = 0;
    // The photon density view over the scene's global map (see photon_density_pass.h).
    virtual std::vector<float> photon_density(const std::vector<float>& positions, const std::vector<float>& normals,
                                              std::uint32_t k) = 0;
    virtual double device_start_ms() const { return 0.0; }  // CUDA: creating the context
    virtual double upload_ms() const { return 0.0; }        // CUDA: copying the scene to the device
    // Host memory the backend keeps between frames for its next frame's arrays.
    virtual std::uint64_t kept_bytes() const { return 0; }
};

std::unique_ptr<FrameBackend> make_cpu_frame_backend(const SceneViews& scene);
// Defined only when the build has the CUDA backend (KDPM_HAVE_CUDA).
std::unique_ptr<FrameBackend> make_cuda_frame_backend(const SceneViews& scene);

}  // namespace kdpm
