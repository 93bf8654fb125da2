#include "runtime/photons/unpacked_directions.h"

#include "formats/photon_layout.h"
#include "runtime/backend/cpu_parallel_for.h"

namespace kdpm {

std::vector<float> unpack_directions(const PhotonMapView& map) {
    std::vector<float> out(6 * static_cast<std::size_t>(map.photon_count));
    cpu_parallel_for(map.photon_count, [&](std::uint64_t p) {
        decode_octahedral(map.directions[p].direction, &out[6 * p]);
        decode_octahedral(map.directions[p].normal, &out[6 * p + 3]);
    }, 4096);
    return out;
}

}  // namespace kdpm
