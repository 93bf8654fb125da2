#include "runtime/photons/unpacked_directions.h"

#include "formats/photon_layout.h"
#include "runtime/backend/cpu_parallel_for.h"
#include "runtime/photons/radiance_estimate.h"

namespace kdpm {

std::vector<float> unpack_directions(const PhotonMapView& map) {
    const std::size_t n = map.photon_count;
    std::vector<float> out(6 * n);
    cpu_parallel_for(n, [&](std::uint64_t p) {
        float d[3], s[3];
        decode_octahedral(map.directions[p].direction, d);
        decode_octahedral(map.directions[p].normal, s);
        for (std::size_t c = 0; c < 3; ++c) {
            out[c * n + p] = d[c];
            out[(3 + c) * n + p] = s[c];
        }
    }, 4096);
    return out;
}

std::vector<float> unpack_powers(const PhotonMapView& map) {
    std::vector<float> out(3 * static_cast<std::size_t>(map.photon_count));
    cpu_parallel_for(map.photon_count, [&](std::uint64_t p) {
        const glm::vec3 power = photon_power(map.power[p]);
        out[3 * p] = power.x;
        out[3 * p + 1] = power.y;
        out[3 * p + 2] = power.z;
    }, 4096);
    return out;
}

}  // namespace kdpm
