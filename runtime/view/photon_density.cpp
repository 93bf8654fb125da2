#include "runtime/view/photon_density.h"

#include "runtime/backend/cpu_device.h"
#include "runtime/render/passes/photon_density_pass.h"

namespace kdpm {

std::vector<float> photon_density(const PhotonMapView& map, const std::vector<float>& positions,
                                  const std::vector<float>& normals, std::uint32_t k) {
    CpuDevice device;
    return run_photon_density(device, map, positions, normals, k);
}

}  // namespace kdpm
