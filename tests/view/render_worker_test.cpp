#include <catch2/catch.hpp>

#include <chrono>
#include <thread>

#include "runtime/render/renderer.h"
#include "runtime/view/render_worker.h"
#include "tests/view/lit_floor_scene.h"

using namespace kdpm;

namespace {

test::HandBuiltScene floor_scene() { return test::lit_floor(3.0f, 32); }

FrameJob job(std::uint64_t generation, std::uint32_t size, std::uint32_t spp) {
    FrameJob j;
    j.generation = generation;
    j.settings.width = j.settings.height = size;
    j.settings.spp = spp;
    j.settings.mode = RenderMode::direct;
    return j;
}

}  // namespace

TEST_CASE("render worker delivers the frame it was given", "[view][worker]") {
    auto scene = floor_scene();
    Renderer renderer(scene.views(), BackendKind::cpu);
    RenderWorker worker(renderer);
    worker.submit(job(1, 32, 2));
    FinishedFrame f = worker.wait();
    CHECK(f.error.empty());
    CHECK(f.job.generation == 1);
    CHECK(f.result.linear.width == 32);
    // Same as rendering directly: the worker adds nothing of its own.
    RenderSettings s = job(1, 32, 2).settings;
    RenderResult direct = renderer.render(s);
    CHECK(f.result.linear.rgb == direct.linear.rgb);
    CHECK_FALSE(worker.take());
}

TEST_CASE("render worker cancels a stale frame when a newer one is submitted", "[view][worker]") {
    auto scene = floor_scene();
    Renderer renderer(scene.views(), BackendKind::cpu);
    RenderWorker worker(renderer);
    // Thousands of samples: finishing this frame would take minutes, so the newer frame can only
    // arrive first if the stale one is abandoned at a sample boundary.
    worker.submit(job(1, 256, 4096));
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    worker.submit(job(2, 16, 1));
    FinishedFrame f = worker.wait();
    CHECK(f.job.generation == 2);
    CHECK(f.result.linear.width == 16);
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    CHECK_FALSE(worker.take());
    // Either abandoned mid-frame or replaced before it started: never completed.
    CHECK(worker.frames_completed() == 1);
    CHECK(worker.frames_cancelled() + (2 - worker.frames_started()) == 1);
}

TEST_CASE("render worker lets a preview in flight finish", "[view][worker]") {
    auto scene = floor_scene();
    Renderer renderer(scene.views(), BackendKind::cpu);
    RenderWorker worker(renderer);
    FrameJob preview = job(1, 128, 32);
    preview.preview = true;
    worker.submit(preview);
    // Submit the newer frame only once the preview is in flight.
    while (worker.frames_started() == 0) std::this_thread::sleep_for(std::chrono::milliseconds(1));
    worker.submit(job(2, 16, 1));
    // The newer frame always comes last; the preview may already have been replaced in the
    // single result slot (the viewer shows only the newest), so count instead of waiting for it.
    FinishedFrame last = worker.wait();
    while (last.job.generation != 2) last = worker.wait();
    CHECK(last.result.linear.width == 16);
    CHECK(worker.frames_cancelled() == 0);
    CHECK(worker.frames_completed() == 2);
}

TEST_CASE("render worker reports a render error as text", "[view][worker]") {
    auto scene = floor_scene();
    Renderer renderer(scene.views(), BackendKind::cpu);
    RenderWorker worker(renderer);
    FrameJob j = job(1, 16, 1);
    j.settings.mode = RenderMode::photons;  // no photon map
    worker.submit(j);
    FinishedFrame f = worker.wait();
    CHECK(f.error.find("photon map") != std::string::npos);
}
