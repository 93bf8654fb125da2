// The CUDA backend: the scene's sections are uploaded once (one copy each, straight from the
// mapped file), then every frame runs the same passes as the CPU through the grid-stride
// launcher. The frame arrays live in a pool kept across frames (allocated again only when the
// image grows), each kernel's block size comes from the occupancy API once, and each pass ends
// with its one synchronisation. Only transfers and launches are CUDA-specific.
#include <cstdint>
#include <vector>

#include "runtime/backend/cuda_check.h"
#include "runtime/backend/cuda_device.cuh"
#include "runtime/backend/cuda_device.h"
#include "runtime/backend/device_scene_upload.cuh"
#include "runtime/render/frame_backend.h"
#include "runtime/render/passes/photon_density_pass.h"
#include "runtime/shading/light_power_table.h"

namespace kdpm {

namespace {

class CudaFrameBackend final : public FrameBackend {
public:
    explicit CudaFrameBackend(const SceneViews& scene) {
        // The current device (0 unless use_cuda_device chose another); a broken driver or a
        // device in use by another exclusive process fails here, with one line. Timed apart,
        // as the context's cost does not depend on the scene.
        device_start_ms_ = start_cuda_device();
        StopWatch watch;
        device_geometry_ = upload_geometry(owned_, scene.geometry);
        device_photons_ = scene.photons;
        device_photons_.global = upload_photon_map(owned_, scene.photons.global);
        device_photons_.caustic = upload_photon_map(owned_, scene.photons.caustic);
        device_photons_.irradiance.photons = upload_photon_map(owned_, scene.photons.irradiance.photons);
        device_photons_.irradiance.irradiance = upload_array(owned_, scene.photons.irradiance.irradiance,
                                                             scene.photons.irradiance.photons.photon_count);
        const LightPowerTable lights = light_power_table(scene.geometry);
        device_lights_ = lights.selection();
        device_lights_.cdf = upload_array(owned_, lights.cdf.data(), lights.cdf.size());
        upload_ms_ = watch.lap_ms();
    }

    void run(const FramePlan& plan, Image& linear, AovImages& aovs, StageTimes& times) override {
        device_.begin();
        const PhotonGatherPass gather = make_gather_pass(device_photons_, plan.direct_light(), plan.settings);
        run_frame(device_, device_geometry_, device_lights_, gather, plan, linear, aovs, times);
    }

    std::vector<float> photon_density(const std::vector<float>& positions, const std::vector<float>& normals,
                                      std::uint32_t k) override {
        device_.begin();
        return run_photon_density(device_, device_photons_.global, positions, normals, k);
    }

    double device_start_ms() const override { return device_start_ms_; }
    double upload_ms() const override { return upload_ms_; }

private:
    std::vector<DeviceBuffer> owned_;
    GeometryView device_geometry_;
    PhotonMaps device_photons_;
    LightSelection device_lights_;
    CudaDevice device_;  // the frame arrays, reused by every frame
    double device_start_ms_ = 0.0;
    double upload_ms_ = 0.0;
};

}  // namespace

std::unique_ptr<FrameBackend> make_cuda_frame_backend(const SceneViews& scene) {
    return std::make_unique<CudaFrameBackend>(scene);
}

}  // namespace kdpm
