#include "runtime/view/photon_density.h"

#include <glm/glm.hpp>

#include "runtime/backend/cpu_parallel_for.h"
#include "runtime/photons/knn_search.h"
#include "runtime/shading/constants.h"

namespace kdpm {

std::vector<float> photon_density(const PhotonMapView& map, const std::vector<float>& positions,
                                  const std::vector<float>& normals, std::uint32_t k) {
    const std::size_t pixels = positions.size() / 3;
    std::vector<float> density(pixels, 0.0f);
    if (map.node_count == 0 || normals.size() != positions.size()) return density;
    cpu_parallel_for(
        pixels,
        [&](std::uint64_t i) {
            if (normals[i * 3] == 0.0f && normals[i * 3 + 1] == 0.0f && normals[i * 3 + 2] == 0.0f) return;
            const glm::vec3 p(positions[i * 3], positions[i * 3 + 1], positions[i * 3 + 2]);
            KnnHeap heap;
            const std::uint32_t found = knn_search(map, p, k, 0.0f, heap);
            if (found == 0 || !(heap.d2[0] > 0.0f)) return;
            density[i] = static_cast<float>(found) / (kPi * heap.d2[0]);
        },
        16);
    return density;
}

}  // namespace kdpm
