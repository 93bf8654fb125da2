#pragma once
// The frame renderer as a library: built once over a loaded scene (uploading it when the
// backend is CUDA), then render(settings) per frame, e.g. by a viewer or a benchmark with a
// changing camera. Also post-processes (exposure, bloom, tone mapping).
#include <memory>

#include "runtime/backend/backend_kind.h"
#include "runtime/render/render_settings.h"
#include "runtime/render/scene_views.h"

namespace kdpm {

class FrameBackend;

class Renderer {
public:
    Renderer(const SceneViews& scene, BackendKind backend);
    ~Renderer();
    Renderer(Renderer&&) noexcept;
    Renderer& operator=(Renderer&&) noexcept;

    // Throws std::runtime_error (one line) on an impossible request (e.g. a photon mode without
    // photon maps, or a zero-sized image).
    RenderResult render(const RenderSettings& settings);

    BackendKind backend() const { return backend_; }
    double upload_ms() const;  // CUDA: time to copy the scene to the device

private:
    SceneViews scene_;
    BackendKind backend_;
    std::unique_ptr<FrameBackend> impl_;
};

}  // namespace kdpm
