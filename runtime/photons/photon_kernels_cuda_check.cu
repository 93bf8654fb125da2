// Compiles the photon kernels (shooting, kNN, fixed-radius search, radiance estimate) for the
// GPU, so that a change that breaks nvcc fails the build even on machines without a GPU. The
// CUDA backend's own launch code lives with the backend; these wrappers are not called.
#include "runtime/photons/knn_search.h"
#include "runtime/photons/photon_path.h"
#include "runtime/photons/radiance_estimate.h"
#include "runtime/photons/radius_search.h"

namespace kdpm::cuda_check {

struct CountVisits {
    unsigned* count;
    __device__ void operator()(std::uint32_t, float) const { atomicAdd(count, 1u); }
};

__global__ void gather(PhotonMapView map, const glm::vec3* points, glm::vec3* radiance, unsigned n,
                       RadianceEstimateParams params, unsigned* count) {
    const unsigned i = blockIdx.x * blockDim.x + threadIdx.x;
    if (i >= n) return;
    KnnHeap heap;
    radiance[i] = estimate_radiance(map, points[i], glm::vec3(0, 1, 0), glm::vec3(0.5f), params, heap).radiance;
    knn_search(map, points[i], params.k, params.max_radius, heap);
    radius_search(map, points[i], params.max_radius, CountVisits{count});
}

__global__ void shoot(GeometryView g, LightSelection lights, ShootSettings s, PhotonHit* slots, PhotonPathResult* results,
                      unsigned n) {
    const unsigned i = blockIdx.x * blockDim.x + threadIdx.x;
    if (i >= n) return;
    results[i] = trace_photon_path(g, lights, s, i, slots + static_cast<std::size_t>(i) * (s.max_bounces + 1));
}

}  // namespace kdpm::cuda_check
