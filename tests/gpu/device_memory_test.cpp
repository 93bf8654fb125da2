// The CUDA backend's memory handling: uploads come back unchanged, the frame arrays are reused
// across frames, and the two failures a user can cause -- a device index that does not exist and
// a frame larger than the free device memory -- are one-line errors the program recovers from.
#include <catch2/catch.hpp>

#include <random>
#include <stdexcept>
#include <string>

#include "runtime/backend/cuda_device.h"
#include "runtime/render/renderer.h"
#include "tests/gpu/gpu_probes.h"
#include "tests/gpu/gpu_scenes.h"

using namespace kdpm;

TEST_CASE("uploads to the device come back unchanged", "[gpu][memory]") {
    std::mt19937 rng(5);
    for (std::size_t size : {std::size_t{1}, std::size_t{3}, std::size_t{64}, std::size_t{4099}, std::size_t{1} << 22}) {
        std::vector<std::uint8_t> bytes(size);
        for (auto& b : bytes) b = static_cast<std::uint8_t>(rng());
        INFO(size << " bytes");
        CHECK(test::cuda_round_trip(bytes) == bytes);
    }
}

TEST_CASE("the CUDA device reuses its arrays across frames and zero-fills reused ones", "[gpu][memory]") {
    const test::PoolProbe p = test::cuda_pool_probe();
    CHECK(p.allocations_after_first == 2);
    CHECK(p.allocations_after_second == 2);  // same sizes: no new allocation
    CHECK(p.allocations_after_larger == 4);  // both arrays grew
    CHECK(p.zeroed_on_reuse);
}

TEST_CASE("a device index that does not exist is a one-line error", "[gpu][errors]") {
    const int count = cuda_device_status().device_count;
    for (int bad : {count, -1}) {
        try {
            use_cuda_device(bad);
            FAIL("no error for device " << bad);
        } catch (const std::runtime_error& e) {
            const std::string message = e.what();
            INFO(message);
            CHECK(message.find('\n') == std::string::npos);
            CHECK(message.find(std::to_string(bad)) != std::string::npos);
        }
    }
    use_cuda_device(0);  // and a good one still works afterwards
}

TEST_CASE("a frame larger than the free device memory is a one-line error, and the next frame works",
          "[gpu][errors]") {
    auto scene = test::build_gpu_test_scene("cornell-box", 0);
    Renderer cuda(scene.views, BackendKind::cuda);
    RenderSettings s;
    s.mode = RenderMode::direct;
    s.width = 1024;
    s.height = 1024;  // about 300 MiB of frame arrays
    s.light_samples = 1;
    {
        // Leave 64 MiB free, less than the frame needs.
        const std::size_t free = test::cuda_free_bytes();
        REQUIRE(free > (std::size_t{128} << 20));
        test::DeviceReservation hog(free - (std::size_t{64} << 20));
        try {
            cuda.render(s);
            FAIL("the frame did not run out of memory");
        } catch (const std::runtime_error& e) {
            const std::string message = e.what();
            INFO(message);
            CHECK(message.find('\n') == std::string::npos);
            CHECK(message.find("memory") != std::string::npos);
        }
    }
    const RenderResult after = cuda.render(s);
    CHECK(after.linear.width == 1024);
    double total = 0;
    for (float v : after.linear.rgb) total += v;
    CHECK(total > 0.0);
}
