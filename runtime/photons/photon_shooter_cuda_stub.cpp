// The CUDA-free build's side of shoot_photons(backend = cuda): there is no device to run on.
#include <stdexcept>

#include "runtime/photons/photon_shooter_cuda.h"

namespace kdpm {

std::uint64_t shoot_paths_on_cuda(const GeometryView&, const LightPowerTable&, const ShootSettings&, std::uint64_t,
                                  std::uint64_t, std::vector<PhotonHit>&, const std::function<void(double)>&) {
    throw std::runtime_error("this build of kdpm has no CUDA backend");
}

}  // namespace kdpm
