#include "runtime/view/render_worker.h"

#include <exception>
#include <utility>

#include <tbb/task_group.h>

namespace kdpm {

namespace {
// Thrown from the progress callback to abandon a stale frame; never leaves the worker.
struct FrameCancelled {};
}  // namespace

RenderWorker::RenderWorker(Renderer& renderer)
    : renderer_(renderer), thread_([this] { loop(); }) {}

RenderWorker::~RenderWorker() {
    {
        std::lock_guard lock(mutex_);
        stop_ = true;
        pending_.reset();
        cancel_running_locked();
    }
    wake_.notify_all();
    thread_.join();
}

void RenderWorker::cancel_running_locked() {
    if (running_group_ && !running_cancelled_) {
        running_cancelled_ = true;
        running_group_->cancel();
    }
}

void RenderWorker::submit(FrameJob job) {
    {
        std::lock_guard lock(mutex_);
        // Previews are short and are still the newest picture while the camera moves, so they
        // always finish; a refinement frame for an old view is abandoned at once.
        if (!running_preview_) cancel_running_locked();
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

std::uint64_t RenderWorker::frames_started() const {
    std::lock_guard lock(mutex_);
    return started_;
}

std::uint64_t RenderWorker::frames_completed() const {
    std::lock_guard lock(mutex_);
    return completed_;
}

std::uint64_t RenderWorker::frames_cancelled() const {
    std::lock_guard lock(mutex_);
    return cancelled_;
}

void RenderWorker::loop() {
    for (;;) {
        FrameJob job;
        // The frame runs inside its own task group: cancelling the group stops the CPU backend's
        // parallel loops (nested oneTBB algorithms share the group's cancellation) part-way
        // through a pass; the half-written frame is then thrown away.
        tbb::task_group group;
        {
            std::unique_lock lock(mutex_);
            wake_.wait(lock, [&] { return stop_ || pending_.has_value(); });
            if (stop_) return;
            job = std::move(*pending_);
            pending_.reset();
            busy_ = true;
            ++started_;
            running_group_ = &group;
            running_cancelled_ = false;
            running_preview_ = job.preview;
        }
        RenderSettings settings = job.settings;
        // Between sample passes (and on the CUDA backend, whose launches cannot be interrupted).
        settings.progress = [this](double) {
            std::lock_guard lock(mutex_);
            if (running_cancelled_) throw FrameCancelled{};
        };
        FinishedFrame frame;
        group.run_and_wait([&] {
            try {
                frame.result = renderer_.render(settings);
                StopWatch watch;
                if (job.density_k > 0)
                    frame.density = renderer_.photon_density(frame.result.aovs.position, frame.result.aovs.normal,
                                                             job.density_k);
                frame.density_ms = watch.lap_ms();
            } catch (const FrameCancelled&) {
            } catch (const std::exception& e) {
                frame.error = e.what();
            }
        });
        bool cancelled = false;
        {
            std::lock_guard lock(mutex_);
            busy_ = false;
            running_group_ = nullptr;
            cancelled = running_cancelled_;
            if (cancelled) {
                ++cancelled_;
            } else {
                ++completed_;
                frame.job = std::move(job);
                finished_ = std::move(frame);
            }
        }
        if (!cancelled) done_.notify_all();
    }
}

}  // namespace kdpm
