#pragma once
// The photon density view's kernel and its driver, written once for both backends: at each
// pixel's first hit, the k nearest photons of the global map give an areal density estimate
// k / (pi r_k^2) (photons per square scene unit) -- the same search the gather does.
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "formats/host_device.h"
#include "runtime/photons/knn_search.h"
#include "runtime/photons/photon_map_view.h"

namespace kdpm {

struct PhotonDensityPass {
    PhotonMapView map;
    const float* positions = nullptr;  // 3 per pixel
    const float* normals = nullptr;    // 3 per pixel; zero where the pixel missed the scene
    std::uint32_t k = 0;
    float* density = nullptr;          // per pixel

    KDPM_HD void operator()(std::uint64_t i) const {
        density[i] = 0.0f;
        if (normals[i * 3] == 0.0f && normals[i * 3 + 1] == 0.0f && normals[i * 3 + 2] == 0.0f) return;
        const glm::vec3 p(positions[i * 3], positions[i * 3 + 1], positions[i * 3 + 2]);
        KnnHeap heap;
        const std::uint32_t found = knn_search(map, p, k, 0.0f, heap);
        if (found == 0 || !(heap.d2[0] > 0.0f)) return;
        density[i] = static_cast<float>(found) / (3.14159265f * heap.d2[0]);
    }
};

// `map` holds arrays where `dev` runs (host for CpuDevice, device memory for CudaDevice).
// positions/normals: the position and normal AOVs. Each pixel writes only its own slot, so the
// result does not depend on the thread count.
template <class Device>
std::vector<float> run_photon_density(Device& dev, const PhotonMapView& map, const std::vector<float>& positions,
                                      const std::vector<float>& normals, std::uint32_t k) {
    const std::size_t pixels = positions.size() / 3;
    if (map.node_count == 0 || normals.size() != positions.size() || pixels == 0 || k == 0)
        return std::vector<float>(pixels, 0.0f);
    auto device_positions = dev.from_host(positions);
    auto device_normals = dev.from_host(normals);
    auto density = dev.template scratch<float>(pixels);
    dev.launch(pixels, PhotonDensityPass{map, device_positions.data(), device_normals.data(), k, density.data()});
    std::vector<float> out;
    dev.to_host(density, out);
    return out;
}

}  // namespace kdpm
