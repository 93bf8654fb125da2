#pragma once
// The frame renderer as a library: built once over a loaded scene (uploading it when the
// backend is CUDA), then render(settings) per frame, e.g. by a viewer or a benchmark with a
// changing camera. Also post-processes (exposure, bloom, tone mapping).
#include <cstdint>
#include <memory>
#include <vector>

#include "runtime/backend/backend_kind.h"
#include "runtime/render/render_settings.h"
#include "runtime/render/scene_views.h"

namespace kdpm {

class FrameBackend;
class ImagePool;
struct KeptIrradianceCache;

class Renderer {
public:
    Renderer(const SceneViews& scene, BackendKind backend);
    ~Renderer();
    Renderer(Renderer&&) noexcept;
    Renderer& operator=(Renderer&&) noexcept;

    // Throws std::runtime_error (one line) on an impossible request (e.g. a photon mode without
    // photon maps, or a zero-sized image).
    RenderResult render(const RenderSettings& settings);
    // Gives a finished frame's images back for the next frames to reuse (optional: a caller
    // rendering frame after frame saves the page faults of fresh 3 MiB images).
    void recycle(RenderResult&& frame);

    // The photon density view of a rendered frame's position and normal AOVs (3 floats per
    // pixel), on this renderer's backend over the scene's global map; zeros without one.
    std::vector<float> photon_density(const std::vector<float>& positions, const std::vector<float>& normals,
                                      std::uint32_t k);

    BackendKind backend() const { return backend_; }
    double device_start_ms() const;  // CUDA: time to create the device's context (once a process)
    double upload_ms() const;        // CUDA: time to copy the scene to the device

private:
    SceneViews scene_;
    BackendKind backend_;
    std::unique_ptr<FrameBackend> impl_;
    std::unique_ptr<KeptIrradianceCache> kept_cache_;  // RenderSettings::keep_irradiance_cache
    std::unique_ptr<ImagePool> images_;                // storage of recycled frames' images
};

}  // namespace kdpm
