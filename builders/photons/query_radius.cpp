#include "builders/photons/query_radius.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace kdpm::photon_build {

float estimate_query_radius(const PhotonRecord* photons, std::uint32_t count, std::uint32_t k) {
    if (count < 2 || k == 0) return 0.0f;
    const std::uint32_t samples = std::min<std::uint32_t>(count, 4096);
    const std::uint32_t kk = std::min(k, samples - 1);
    const std::uint32_t queries = std::min<std::uint32_t>(samples, 64);
    std::vector<std::uint32_t> sample(samples);
    for (std::uint32_t i = 0; i < samples; ++i)
        sample[i] = static_cast<std::uint32_t>(static_cast<std::uint64_t>(i) * count / samples);

    std::vector<float> radii, d2(samples);
    for (std::uint32_t q = 0; q < queries; ++q) {
        std::uint32_t qi = sample[static_cast<std::uint64_t>(q) * samples / queries];
        std::uint32_t m = 0;
        for (std::uint32_t s : sample) {
            if (s == qi) continue;
            const float* ps = photons[s].position;
            const float* pq = photons[qi].position;
            float dx = ps[0] - pq[0], dy = ps[1] - pq[1], dz = ps[2] - pq[2];
            d2[m++] = dx * dx + dy * dy + dz * dz;
        }
        std::nth_element(d2.begin(), d2.begin() + (kk - 1), d2.begin() + m);
        radii.push_back(std::sqrt(d2[kk - 1]));
    }
    std::nth_element(radii.begin(), radii.begin() + radii.size() / 2, radii.end());
    double r = radii[radii.size() / 2] * std::sqrt(static_cast<double>(samples) / count);
    return static_cast<float>(r);
}

}  // namespace kdpm::photon_build
