// trace-and-gather scene.kdg scene.kdp [k]: maps both files, traces the ray through the centre of
// the file camera's image, and prints the hit and the k photons nearest to it.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>

#include <glm/geometric.hpp>

#include "formats/photon_layout.h"
#include "runtime/geometry/geometry_file.h"
#include "runtime/geometry/scene_traversal.h"
#include "runtime/photons/knn_search.h"
#include "runtime/photons/photon_map_file.h"

int main(int argc, char** argv) {
    if (argc < 3) {
        std::fprintf(stderr, "usage: trace-and-gather scene.kdg scene.kdp [k]\n");
        return 2;
    }
    try {
        const kdpm::GeometryFile geometry = kdpm::GeometryFile::open(argv[1]);
        const kdpm::PhotonMapFile photons = kdpm::PhotonMapFile::open(argv[2]);
        const std::uint32_t k = argc > 3 ? static_cast<std::uint32_t>(std::atoi(argv[3])) : 8;

        const kdpm::CameraRecord& cam = geometry.camera();
        const glm::vec3 eye(cam.eye[0], cam.eye[1], cam.eye[2]);
        const glm::vec3 lookat(cam.lookat[0], cam.lookat[1], cam.lookat[2]);
        const kdpm::Ray ray{eye, 0.0f, glm::normalize(lookat - eye), 3.4e38f};
        const kdpm::Hit hit = kdpm::closest_hit(geometry.view(), ray);
        if (!hit.found()) {
            std::printf("the centre ray misses the scene\n");
            return 0;
        }
        const glm::vec3 p = ray.origin + hit.t * ray.direction;
        std::printf("hit triangle %u at t=%.4f, point (%.4f, %.4f, %.4f)\n", hit.triangle, hit.t, p.x, p.y, p.z);

        static kdpm::KnnHeap heap;  // 2 KiB: kept off the stack
        const kdpm::PhotonMapView map = photons.view(kdpm::PhotonMapKind::global);
        const std::uint32_t found = kdpm::knn_search(map, p, k, 0.0f, heap);
        std::printf("%u nearest of %u photons:\n", found, map.photon_count);
        for (std::uint32_t i = 0; i < found; ++i) {
            const std::uint32_t id = heap.index[i];
            float rgb[3];
            kdpm::decode_rgbe(map.power[id], rgb);
            std::printf("  photon %u at (%.4f, %.4f, %.4f), distance %.5f, power (%.4g, %.4g, %.4g)\n", id, map.x[id],
                        map.y[id], map.z[id], std::sqrt(heap.d2[i]), rgb[0], rgb[1], rgb[2]);
        }
        return 0;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "trace-and-gather: error: %s\n", e.what());
        return 1;
    }
}
