#include "tests/photons/synthetic_photons.h"

#include <cmath>
#include <random>

namespace kdpm::test {

PhotonHitSet synthetic_photons(std::uint32_t count, std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    PhotonHitSet set;
    set.info.emitted_count = count;
    set.info.max_bounces = 4;
    set.info.emitted_power[0] = set.info.emitted_power[1] = set.info.emitted_power[2] = 100.0f;
    for (std::uint32_t i = 0; i < count; ++i) {
        PhotonHit h{};
        int kind = static_cast<int>(u(rng) * 5.0f);
        float a = u(rng), b = u(rng);
        float n[3] = {0, 0, 0};
        if (kind == 0) {  // floor y = 0
            h.position[0] = a, h.position[1] = 0.0f, h.position[2] = b, n[1] = 1.0f;
        } else if (kind == 1) {  // wall x = 0
            h.position[0] = 0.0f, h.position[1] = a, h.position[2] = b, n[0] = 1.0f;
        } else if (kind == 2) {  // a small dense caustic spot
            h.position[0] = 0.5f + 0.02f * a, h.position[1] = 0.0f, h.position[2] = 0.5f + 0.02f * b, n[1] = 1.0f;
            h.flags |= kPhotonCaustic;
        } else if (kind == 3 && i > 0 && u(rng) < 0.3f) {  // an exact duplicate of an earlier photon
            h = set.hits[static_cast<std::size_t>(u(rng) * static_cast<float>(set.hits.size() - 1))];
            set.hits.push_back(h);
            continue;
        } else {  // a uniform cloud
            h.position[0] = a, h.position[1] = b, h.position[2] = u(rng), n[2] = 1.0f;
        }
        for (int c = 0; c < 3; ++c) h.normal[c] = n[c], h.direction[c] = -n[c];
        h.power[0] = 0.01f * u(rng), h.power[1] = 0.01f * u(rng), h.power[2] = 0.01f * u(rng);
        h.flags |= make_photon_flags(static_cast<std::uint32_t>(u(rng) * 5.0f) % 5, false);
        h.path = i;
        set.hits.push_back(h);
    }
    update_hits_info(set);
    return set;
}

void write_photon_hits_file(const PhotonHitSet& set, const std::filesystem::path& path) {
    Metadata m;
    m.tool = "kdpm-photon-tests";
    m.tool_version = kdpm_version();
    photon_hits_writer(set, m).write(path);
}

}  // namespace kdpm::test
