#pragma once
// The last step of a depth-first shooting batch (CUDA, and the bench's Embree peer): its paths'
// stored hits, each path's in its own fixed slots, appended to the shot's hits in path order.
// Host code, on oneTBB's workers, because pushed back one at a time on one thread this step holds
// up the shot. The resize's first touches of the shot's fresh pages stay serial (std::vector
// zero-fills).
#include <cstdint>
#include <vector>

#include "formats/photon_layout.h"
#include "runtime/photons/photon_path.h"

namespace kdpm {

// Appends slots[i * per_path + k] for k < results[i].stored, path i = 0 .. n - 1 in order;
// `batch_stored` is the sum of those counts. hits' capacity is the caller's choice (reserve).
void append_path_hits(const PhotonHit* slots, std::uint64_t per_path, const PhotonPathResult* results,
                      std::uint64_t n, std::uint64_t batch_stored, std::vector<PhotonHit>& hits);

}  // namespace kdpm
