#pragma once
// The CUDA side of shoot_photons (photon_shooter_cuda.cu; without the CUDA backend, a stub in
// photon_shooter.cpp's build that throws). Not for other callers: use shoot_photons.
#include <cstdint>
#include <functional>
#include <vector>

#include "formats/photon_layout.h"
#include "runtime/geometry/geometry_view.h"
#include "runtime/photons/photon_path.h"
#include "runtime/photons/photon_shooter.h"
#include "runtime/shading/light_power_table.h"

namespace kdpm {

// `host` and `lights` hold host arrays; they are uploaded, paths first_path .. end_path - 1 run on
// the current device through shoot_paths, and the stored hits are appended to `hits`. Returns the
// rays traced.
std::uint64_t shoot_paths_on_cuda(const GeometryView& host, const LightPowerTable& lights,
                                  const ShootSettings& settings, std::uint64_t first_path, std::uint64_t end_path,
                                  std::vector<PhotonHit>& hits, const std::function<void(double)>& progress);

}  // namespace kdpm
