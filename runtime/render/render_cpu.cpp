// The CPU backend: the passes run over the mapped sections in place, in oneTBB grains.
#include "runtime/backend/cpu_device.h"
#include "runtime/photons/node_vector_bounds.h"
#include "runtime/photons/unpacked_directions.h"
#include "runtime/render/frame_backend.h"
#include "runtime/render/frame_memory.h"
#include "runtime/render/passes/photon_density_pass.h"
#include "runtime/shading/light_power_table.h"

namespace kdpm {

namespace {

class CpuFrameBackend final : public FrameBackend {
public:
    explicit CpuFrameBackend(const SceneViews& scene) : scene_(scene), lights_(light_power_table(scene.geometry)) {}

    void run(const FramePlan& plan, Image& linear, AovImages& aovs, StageTimes& times) override {
        CpuDevice device;
        device.cache = &kept_;
        if (plan.gather_photons()) unpack_once();
        const PhotonGatherPass gather = make_gather_pass(scene_.photons, plan.direct_light(), plan.settings);
        run_frame(device, scene_.geometry, lights_.selection(), gather, plan, linear, aovs, times);
        kept_.trim();  // only what this frame used again is kept for the next
    }

    std::uint64_t kept_bytes() const override { return kept_.kept_bytes(); }

    std::vector<float> photon_density(const std::vector<float>& positions, const std::vector<float>& normals,
                                      std::uint32_t k) override {
        CpuDevice device;
        return run_photon_density(device, scene_.photons.global, positions, normals, k);
    }

private:
    // The photon maps' vectors and powers decoded, and each tree node's boxes of those vectors,
    // for every gather of this renderer (the first frame that gathers pays for it, once). Where
    // 36 bytes a photon and 64 a node would take more than a quarter of the memory left, the
    // gather decodes per use instead: the same decisions and sums, slower.
    void unpack_once() {
        if (unpacked_) return;
        unpacked_ = true;
        const PhotonMapView& chosen_photons = scene_.photons.irradiance.photons;
        const std::uint64_t photons = std::uint64_t{scene_.photons.global.photon_count} +
                                      scene_.photons.caustic.photon_count + chosen_photons.photon_count;
        const std::uint64_t nodes = std::uint64_t{scene_.photons.global.node_count} +
                                    scene_.photons.caustic.node_count + chosen_photons.node_count;
        if ((photons * 9 + nodes * kVectorBoundFloats) * sizeof(float) > available_memory_bytes() / 4) return;
        global_vectors_ = attach_search_vectors(scene_.photons.global);
        caustic_vectors_ = attach_search_vectors(scene_.photons.caustic);
        // The irradiance map's chosen photons too: final gathering's lookups filter them alike.
        chosen_vectors_ = attach_search_vectors(scene_.photons.irradiance.photons);
        global_powers_ = unpack_powers(scene_.photons.global);
        caustic_powers_ = unpack_powers(scene_.photons.caustic);
        auto data_or_null = [](const std::vector<float>& v) { return v.empty() ? nullptr : v.data(); };
        scene_.photons.global.unpacked_power = data_or_null(global_powers_);
        scene_.photons.caustic.unpacked_power = data_or_null(caustic_powers_);
    }

    SceneViews scene_;
    LightPowerTable lights_;
    HostBlockCache kept_;  // the frame's arrays, from one frame to the next
    bool unpacked_ = false;
    SearchVectors global_vectors_, caustic_vectors_, chosen_vectors_;
    std::vector<float> global_powers_, caustic_powers_;
};

}  // namespace

std::unique_ptr<FrameBackend> make_cpu_frame_backend(const SceneViews& scene) {
    return std::make_unique<CpuFrameBackend>(scene);
}

}  // namespace kdpm
