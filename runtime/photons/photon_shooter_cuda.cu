// Photon shooting on the GPU: the scene goes up once, then the same shoot_paths loop as the CPU
// runs the same ShootPathsPass through CudaDevice (see photon_shooter.h on floating point).
#include "runtime/photons/photon_shooter_cuda.h"

#include "runtime/backend/cuda_device.cuh"
#include "runtime/backend/cuda_device.h"
#include "runtime/backend/device_scene_upload.cuh"
#include "runtime/photons/shoot_loop.h"

namespace kdpm {

std::uint64_t shoot_paths_on_cuda(const GeometryView& host, const LightPowerTable& lights,
                                  const ShootSettings& settings, std::uint64_t first_path, std::uint64_t end_path,
                                  std::vector<PhotonHit>& hits, const std::function<void(double)>& progress) {
    (void)start_cuda_device();  // a no-op where the tool started it already
    std::vector<DeviceBuffer> owned;
    const GeometryView geometry = upload_geometry(owned, host);
    const LightSelection table{upload_array(owned, lights.cdf.data(), lights.cdf.size()),
                               static_cast<std::uint32_t>(lights.cdf.size()), lights.total_power};
    CudaDevice device;
    return shoot_paths(device, geometry, table, settings, first_path, end_path,
                       shoot_batch_size(settings.max_bounces, 1u << 20, 512u << 20), hits, progress);
}

}  // namespace kdpm
