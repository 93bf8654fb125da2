#pragma once
// Renders frames on a background thread so the window never waits for a slow frame. A newer
// submission replaces a pending one; a refinement frame in flight is cancelled at once on the
// CPU backend (its oneTBB loops stop) and otherwise at its next sample boundary (the Renderer's
// progress callback). Previews in flight finish: while the camera keeps moving they are the
// newest picture there is.
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include <tbb/task_group.h>

#include "runtime/render/renderer.h"

namespace kdpm {

struct FrameJob {
    std::uint64_t generation = 0;  // bumped by the viewer on every change that makes frames stale
    RenderSettings settings;       // complete: camera, size, spp, mode, k, AOVs
    bool preview = false;
    std::uint32_t density_k = 0;   // > 0: also estimate the photon density (needs position AOVs)
};

struct FinishedFrame {
    FrameJob job;
    RenderResult result;
    std::vector<float> density;  // per pixel, when the job asked for it
    double density_ms = 0.0;
    std::string error;  // non-empty when the render threw (e.g. an impossible setting)
};

class RenderWorker {
public:
    // Density jobs run on the renderer's backend over its scene's global photon map.
    explicit RenderWorker(Renderer& renderer);
    ~RenderWorker();  // cancels the frame in flight and joins
    RenderWorker(const RenderWorker&) = delete;
    RenderWorker& operator=(const RenderWorker&) = delete;

    void submit(FrameJob job);
    // A frame finished since the last call, if any (never blocks).
    std::optional<FinishedFrame> take();
    // Blocks until a frame finishes (for scripted runs).
    FinishedFrame wait();
    bool idle() const;
    // Counts since construction: frames taken up, completed (delivered or replaced by a newer
    // one before anyone took them) and abandoned as stale.
    std::uint64_t frames_started() const;
    std::uint64_t frames_completed() const;
    std::uint64_t frames_cancelled() const;

private:
    void loop();
    void cancel_running_locked();

    Renderer& renderer_;
    mutable std::mutex mutex_;
    std::condition_variable wake_, done_;
    std::optional<FrameJob> pending_;
    std::optional<FinishedFrame> finished_;
    bool busy_ = false;
    tbb::task_group* running_group_ = nullptr;
    bool running_cancelled_ = false;
    bool running_preview_ = false;
    bool stop_ = false;
    std::uint64_t started_ = 0, completed_ = 0, cancelled_ = 0;
    std::thread thread_;
};

}  // namespace kdpm
