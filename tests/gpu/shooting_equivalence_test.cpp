// Photon shooting on both backends, same seed: the same paths store the same hits. Tolerance,
// stated: cosf/sinf of the bounce directions may differ in the last place between glibc and
// CUDA (runtime/photons/photon_shooter.h), so at least 99% of the paths must store the same
// number of hits with the same flags, each within 1e-4 of the scene's size of the CPU's
// position; the total stored and the rays traced within 1%.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <map>

#include "runtime/photons/photon_shooter.h"
#include "tests/gpu/gpu_scenes.h"

using namespace kdpm;

TEST_CASE("CUDA shoots the same photons as the CPU for the same seed", "[gpu][shoot]") {
    auto scene = test::build_gpu_test_scene("cornell-box", 0);
    const GeometryView& g = scene.views.geometry;
    ShootOptions options;
    options.photons = 200000;  // spans batches on the CPU (65,536 paths each)
    options.max_bounces = 4;
    options.seed = 3;
    const ShotPhotons expected = shoot_photons(g, options);
    options.backend = BackendKind::cuda;
    const ShotPhotons got = shoot_photons(g, options);

    REQUIRE(expected.hits.size() > 100000);
    CHECK(std::fabs(static_cast<double>(got.hits.size()) - expected.hits.size()) <= 0.01 * expected.hits.size());
    CHECK(std::fabs(static_cast<double>(got.rays) - expected.rays) <= 0.01 * expected.rays);
    CHECK(got.info.emitted_count == expected.info.emitted_count);

    // Hits are in path order on both sides: group them by path.
    auto by_path = [](const std::vector<PhotonHit>& hits) {
        std::map<std::uint32_t, std::vector<const PhotonHit*>> paths;
        for (const PhotonHit& h : hits) paths[h.path].push_back(&h);
        return paths;
    };
    const auto cpu_paths = by_path(expected.hits), cuda_paths = by_path(got.hits);
    float extent = 0;
    for (int a = 0; a < 3; ++a) extent = std::max(extent, g.info.bounds_max[a] - g.info.bounds_min[a]);
    std::size_t same = 0, identical_bytes = 0;
    for (const auto& [path, hits] : cpu_paths) {
        auto it = cuda_paths.find(path);
        if (it == cuda_paths.end() || it->second.size() != hits.size()) continue;
        bool close = true, bytes = true;
        for (std::size_t i = 0; i < hits.size(); ++i) {
            const PhotonHit &a = *hits[i], &b = *it->second[i];
            close = close && a.flags == b.flags;
            for (int c = 0; c < 3; ++c) close = close && std::fabs(a.position[c] - b.position[c]) <= 1e-4f * extent;
            bytes = bytes && std::memcmp(&a, &b, sizeof a) == 0;
        }
        same += close;
        identical_bytes += bytes;
    }
    INFO(cpu_paths.size() << " paths stored hits on the CPU; " << same << " agree within tolerance, "
                          << identical_bytes << " byte for byte");
    CHECK(same >= 0.99 * static_cast<double>(cpu_paths.size()));
}
