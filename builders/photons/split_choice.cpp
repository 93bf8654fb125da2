#include "builders/photons/split_choice.h"

#include <algorithm>

namespace kdpm::photon_build {

Cell photon_bounds(const PhotonRecord* r, std::uint32_t n) {
    Cell c{};
    for (int a = 0; a < 3; ++a) {
        if (n == 0) continue;
        float lo = r[0].position[a], hi = lo;
        for (std::uint32_t i = 1; i < n; ++i) {
            float v = r[i].position[a];
            lo = std::min(lo, v);
            hi = std::max(hi, v);
        }
        c.lo[a] = lo;
        c.hi[a] = hi;
    }
    return c;
}

}  // namespace kdpm::photon_build
