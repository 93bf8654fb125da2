#pragma once
// The gpu tests' CUDA side (gpu_probes.cu): the query batches of query_passes.h on the device,
// and direct probes of the backend's memory handling. Host code calls these; only the .cu file
// sees CUDA.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "tests/gpu/query_passes.h"

namespace kdpm::test {

// Upload the scene / map, run the batch on the current device, download.
std::vector<Hit> cuda_closest_hits(const GeometryView& host, const std::vector<Ray>& rays);
KnnResults cuda_knn(const PhotonMapView& host, const std::vector<glm::vec3>& points, std::uint32_t k);

// Bytes up to a DeviceBuffer and back.
std::vector<std::uint8_t> cuda_round_trip(const std::vector<std::uint8_t>& bytes);

// CudaDevice's pool over three "frames": the same arrays twice, then larger ones. Also whether
// array() came back zero-filled from a buffer the previous frame had filled with ones.
struct PoolProbe {
    std::size_t allocations_after_first = 0, allocations_after_second = 0, allocations_after_larger = 0;
    bool zeroed_on_reuse = false;
};
PoolProbe cuda_pool_probe();

std::size_t cuda_free_bytes();

// Holds `bytes` of device memory until destroyed (to make a frame run out of memory).
class DeviceReservation {
public:
    explicit DeviceReservation(std::size_t bytes);
    ~DeviceReservation();
    DeviceReservation(const DeviceReservation&) = delete;
    DeviceReservation& operator=(const DeviceReservation&) = delete;

private:
    struct Held;
    std::unique_ptr<Held> held_;
};

}  // namespace kdpm::test
