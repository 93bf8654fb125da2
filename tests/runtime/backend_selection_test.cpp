// --backend: cpu is always available; auto falls back to the CPU with a notice when there is no
// CUDA device; cuda without a device is an error. CUDA_VISIBLE_DEVICES hides devices on a GPU
// machine, so these hold everywhere (ctest runs each test case in its own process).
#include <catch2/catch.hpp>

#include <cstdlib>

#include "runtime/backend/backend_kind.h"
#include "runtime/backend/cuda_device.h"

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
