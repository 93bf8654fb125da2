// --backend: cpu is always available; auto falls back to the CPU with a notice when there is no
// CUDA device; cuda without a device is an error. CUDA_VISIBLE_DEVICES hides devices on a GPU
// machine, so these hold everywhere (ctest runs each test case in its own process).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <string>

#include "runtime/backend/backend_kind.h"
#include "runtime/backend/cuda_device.h"
#include "tests/support/run_command.h"
#include "tests/support/temp_dir.h"

using namespace kdpm;

TEST_CASE("backend requests parse and unknown names are refused", "[backend]") {
    CHECK(parse_backend_request("auto") == BackendRequest::automatic);
    CHECK(parse_backend_request("cpu") == BackendRequest::cpu);
    CHECK(parse_backend_request("cuda") == BackendRequest::cuda);
    CHECK_THROWS_AS(parse_backend_request("gpu"), std::invalid_argument);
    CHECK(select_backend(BackendRequest::cpu).kind == BackendKind::cpu);
    CHECK(select_backend(BackendRequest::cpu).notice.empty());
}

TEST_CASE("without a CUDA device auto falls back with a notice and cuda fails", "[backend]") {
    ::setenv("CUDA_VISIBLE_DEVICES", "", 1);
    REQUIRE(cuda_device_status().device_count == 0);
    BackendSelection s = select_backend(BackendRequest::automatic);
    CHECK(s.kind == BackendKind::cpu);
    CHECK(s.notice.find("using the CPU backend") != std::string::npos);
    CHECK_THROWS_WITH(select_backend(BackendRequest::cuda), Catch::Contains("no usable CUDA device"));
}

TEST_CASE("without a CUDA device, device selection and CUDA photon shooting fail with one line", "[backend]") {
    ::setenv("CUDA_VISIBLE_DEVICES", "", 1);
    REQUIRE(cuda_device_status().device_count == 0);
    try {
        use_cuda_device(0);
        FAIL("use_cuda_device(0) did not fail");
    } catch (const std::runtime_error& e) {
        CHECK(std::string(e.what()).find('\n') == std::string::npos);
    }

    test::TempDir dir;
    const auto kdg = dir / "cb.kdg", kdph = dir / "cb.kdph";
    auto b = test::run_tool("kdpm-build-geometry " + test::source_path("scenes/cornell-box/cornell-box.json") + " -o " +
                            kdg.string() + " --quiet");
    REQUIRE(b.exit_code == 0);
    auto cuda = test::run_tool("kdpm-shoot-photons " + kdg.string() + " -n 1000 --backend cuda -o " + kdph.string());
    INFO(cuda.output);
    CHECK(cuda.exit_code != 0);
    CHECK(cuda.output.find("no usable CUDA device") != std::string::npos);
    CHECK(std::count(cuda.output.begin(), cuda.output.end(), '\n') == 1);
    CHECK_FALSE(std::filesystem::exists(kdph));
    auto automatic = test::run_tool("kdpm-shoot-photons " + kdg.string() + " -n 1000 --backend auto -o " + kdph.string());
    INFO(automatic.output);
    CHECK(automatic.exit_code == 0);
    CHECK(automatic.output.find("using the CPU backend") != std::string::npos);
    CHECK(std::filesystem::exists(kdph));
    auto bogus = test::run_tool("kdpm-shoot-photons " + kdg.string() + " --backend gpu -o " + kdph.string());
    CHECK(bogus.exit_code != 0);
}
