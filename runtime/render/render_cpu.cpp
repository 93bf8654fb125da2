// The CPU backend: the passes run over the mapped sections in place, in oneTBB grains.
#include "runtime/render/cpu_device.h"
#include "runtime/render/frame_backend.h"
#include "runtime/render/light_distribution.h"

namespace kdpm {

namespace {

class CpuFrameBackend final : public FrameBackend {
public:
    explicit CpuFrameBackend(const SceneViews& scene) : scene_(scene), light_cdf_(light_power_cdf(scene.geometry)) {}

    void run(const FramePlan& plan, Image& linear, AovImages& aovs, StageTimes& times) override {
        CpuDevice device;
        const PhotonGatherPass gather = make_gather_pass(scene_.photons, plan.direct_light, plan.settings.k,
                                                          plan.settings.max_radius);
        const LightDistributionView lights{light_cdf_.data(), static_cast<std::uint32_t>(light_cdf_.size())};
        run_frame(device, scene_.geometry, lights, gather, plan, linear, aovs, times);
    }

private:
    SceneViews scene_;
    std::vector<float> light_cdf_;
};

}  // namespace

std::unique_ptr<FrameBackend> make_cpu_frame_backend(const SceneViews& scene) {
    return std::make_unique<CpuFrameBackend>(scene);
}

}  // namespace kdpm
