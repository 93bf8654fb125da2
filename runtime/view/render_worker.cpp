#include "runtime/view/render_worker.h"

#include "runtime/view/photon_density.h"

#include <exception>
#include <utility>

namespace kdpm {

namespace {
// Thrown from the progress callback to abandon a stale frame; never leaves the worker.
struct FrameCancelled {};
}  // namespace

RenderWorker::RenderWorker(Renderer& renderer, const PhotonMapView& density_map)
    : renderer_(renderer), density_map_(density_map), thread_([this] { loop(); }) {}

RenderWorker::~RenderWorker() {
    {
        std::lock_guard lock(mutex_);
        stop_ = true;
        pending_.reset();
    }
    wake_.notify_all();
    thread_.join();
}

void RenderWorker::submit(FrameJob job) {
    {
        std::lock_guard lock(mutex_);
        newest_generation_ = std::max(newest_generation_, job.generation);
        pending_ = std::move(job);
    }
    wake_.notify_all();
}

std::optional<FinishedFrame> RenderWorker::take() {
    std::lock_guard lock(mutex_);
    std::optional<FinishedFrame> out = std::move(finished_);
    finished_.reset();
    return out;
}

FinishedFrame RenderWorker::wait() {
    std::unique_lock lock(mutex_);
    done_.wait(lock, [&] { return finished_.has_value(); });
    FinishedFrame out = std::move(*finished_);
    finished_.reset();
    return out;
}

bool RenderWorker::idle() const {
    std::lock_guard lock(mutex_);
    return !busy_ && !pending_;
}

void RenderWorker::loop() {
    for (;;) {
        FrameJob job;
        {
            std::unique_lock lock(mutex_);
            wake_.wait(lock, [&] { return stop_ || pending_.has_value(); });
            if (stop_) return;
            job = std::move(*pending_);
            pending_.reset();
            busy_ = true;
        }
        const std::uint64_t generation = job.generation;
        RenderSettings settings = job.settings;
        settings.progress = [this, generation](double) {
            std::lock_guard lock(mutex_);
            if (stop_ || newest_generation_ != generation) throw FrameCancelled{};
        };
        FinishedFrame frame;
        bool cancelled = false;
        try {
            frame.result = renderer_.render(settings);
            StopWatch watch;
            if (job.density_k > 0)
                frame.density = photon_density(density_map_, frame.result.aovs.position, frame.result.aovs.normal,
                                               job.density_k);
            frame.density_ms = watch.lap_ms();
        } catch (const FrameCancelled&) {
            cancelled = true;
        } catch (const std::exception& e) {
            frame.error = e.what();
        }
        {
            std::lock_guard lock(mutex_);
            busy_ = false;
            if (!cancelled) {
                frame.job = std::move(job);
                finished_ = std::move(frame);
            }
        }
        if (!cancelled) done_.notify_all();
    }
}

}  // namespace kdpm
