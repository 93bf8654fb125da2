#include "tests/gpu/gpu_probes.h"

#include "runtime/backend/cuda_check.h"
#include "runtime/backend/cuda_device.cuh"
#include "runtime/backend/device_buffer.h"
#include "runtime/backend/device_scene_upload.cuh"

namespace kdpm::test {

std::vector<Hit> cuda_closest_hits(const GeometryView& host, const std::vector<Ray>& rays) {
    std::vector<DeviceBuffer> owned;
    const GeometryView geometry = upload_geometry(owned, host);
    CudaDevice device;
    return run_closest_hits(device, geometry, rays);
}

KnnResults cuda_knn(const PhotonMapView& host, const std::vector<glm::vec3>& points, std::uint32_t k) {
    std::vector<DeviceBuffer> owned;
    const PhotonMapView map = upload_photon_map(owned, host);
    CudaDevice device;
    return run_knn(device, map, points, k);
}

std::vector<std::uint8_t> cuda_round_trip(const std::vector<std::uint8_t>& bytes) {
    const DeviceBuffer buffer = DeviceBuffer::upload(bytes.data(), bytes.size());
    std::vector<std::uint8_t> back(bytes.size(), 0);
    buffer.download(back.data(), back.size());
    return back;
}

PoolProbe cuda_pool_probe() {
    PoolProbe probe;
    CudaDevice device;
    auto frame = [&](std::uint64_t n, bool fill_ones) {
        device.begin();
        auto a = device.array<std::uint32_t>(n);
        auto b = device.scratch<float>(2 * n);
        std::vector<std::uint32_t> host;
        device.to_host(a, host);
        bool zero = true;
        for (std::uint32_t v : host) zero = zero && v == 0;
        if (fill_ones) cuda_check(cudaMemset(a.data(), 0xff, n * sizeof(std::uint32_t)), "cudaMemset");
        (void)b;
        return zero;
    };
    frame(1000, true);
    probe.allocations_after_first = device.allocations();
    probe.zeroed_on_reuse = frame(1000, false);
    probe.allocations_after_second = device.allocations();
    frame(5000, false);
    probe.allocations_after_larger = device.allocations();
    return probe;
}

std::size_t cuda_free_bytes() {
    std::size_t free = 0, total = 0;
    cuda_check(cudaMemGetInfo(&free, &total), "cudaMemGetInfo");
    return free;
}

struct DeviceReservation::Held {
    DeviceBuffer buffer;
};

DeviceReservation::DeviceReservation(std::size_t bytes) : held_(std::make_unique<Held>(Held{DeviceBuffer(bytes)})) {}
DeviceReservation::~DeviceReservation() = default;

}  // namespace kdpm::test
