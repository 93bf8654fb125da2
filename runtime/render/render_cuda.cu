// The CUDA backend: the scene's sections are uploaded once (one copy each, straight from the
// mapped file), then every frame runs the same passes as the CPU through the grid-stride
// launcher. Only transfers and launches are CUDA-specific.
#include <cstdint>
#include <vector>

#include "runtime/backend/cuda_check.h"
#include "runtime/backend/cuda_parallel_for.cuh"
#include "runtime/backend/device_buffer.h"
#include "runtime/render/frame_backend.h"
#include "runtime/shading/light_power_table.h"

namespace kdpm {

namespace {

struct CudaDevice {
    template <class T>
    struct Array {
        DeviceBuffer buffer;
        std::uint64_t count = 0;
        T* data() const { return buffer.as<T>(); }
    };
    template <class T>
    Array<T> array(std::uint64_t n) {
        Array<T> a{DeviceBuffer(n * sizeof(T)), n};
        if (n) cuda_check(cudaMemset(a.data(), 0, n * sizeof(T)), "cudaMemset");
        return a;
    }
    template <class T>
    Array<T> scratch(std::uint64_t n) {
        return Array<T>{DeviceBuffer(n * sizeof(T)), n};
    }
    template <class T>
    void to_host(const Array<T>& a, std::vector<T>& out) {
        out.resize(a.count);
        a.buffer.download(out.data(), a.count * sizeof(T));
    }
    template <class Pass>
    void launch(std::uint64_t n, const Pass& pass) {
        cuda_parallel_for(n, pass);
    }
};

template <class T>
const T* upload(std::vector<DeviceBuffer>& owned, const T* host, std::uint64_t count) {
    if (host == nullptr || count == 0) return nullptr;
    owned.push_back(DeviceBuffer::upload(host, count * sizeof(T)));
    return owned.back().as<const T>();
}

class CudaFrameBackend final : public FrameBackend {
public:
    explicit CudaFrameBackend(const SceneViews& scene) {
        StopWatch watch;
        cuda_check(cudaSetDevice(0), "cudaSetDevice");
        const GeometryView& h = scene.geometry;
        device_geometry_ = h;
        device_geometry_.nodes = upload(owned_, h.nodes, h.node_count);
        device_geometry_.leaf_indices = upload(owned_, h.leaf_indices, h.leaf_index_count);
        device_geometry_.triangles = upload(owned_, h.triangles, h.triangle_count);
        device_geometry_.normals = upload(owned_, h.normals, h.normals ? h.triangle_count : 0);
        device_geometry_.materials = upload(owned_, h.materials, h.material_count);
        device_geometry_.lights = upload(owned_, h.lights, h.light_count);
        device_photons_ = upload_photon_maps(owned_, scene.photons);
        const LightPowerTable lights = light_power_table(h);
        device_lights_ = lights.selection();
        device_lights_.cdf = upload(owned_, lights.cdf.data(), lights.cdf.size());
        upload_ms_ = watch.lap_ms();
    }

    void run(const FramePlan& plan, Image& linear, AovImages& aovs, StageTimes& times) override {
        CudaDevice device;
        const PhotonGatherPass gather = make_gather_pass(device_photons_, plan.direct_light, plan.settings);
        run_frame(device, device_geometry_, device_lights_, gather, plan, linear, aovs, times);
    }
    double upload_ms() const override { return upload_ms_; }

private:
    static PhotonMapView upload_map(std::vector<DeviceBuffer>& owned, const PhotonMapView& h) {
        PhotonMapView d = h;
        d.nodes = upload(owned, h.nodes, h.node_count);
        d.x = upload(owned, h.x, h.photon_count);
        d.y = upload(owned, h.y, h.photon_count);
        d.z = upload(owned, h.z, h.photon_count);
        d.power = upload(owned, h.power, h.photon_count);
        d.directions = upload(owned, h.directions, h.photon_count);
        d.flags = upload(owned, h.flags, h.photon_count);
        return d;
    }
    static PhotonMaps upload_photon_maps(std::vector<DeviceBuffer>& owned, const PhotonMaps& host) {
        PhotonMaps d = host;
        d.global = upload_map(owned, host.global);
        d.caustic = upload_map(owned, host.caustic);
        return d;
    }

    std::vector<DeviceBuffer> owned_;
    GeometryView device_geometry_;
    PhotonMaps device_photons_;
    LightSelection device_lights_;
    double upload_ms_ = 0.0;
};

}  // namespace

std::unique_ptr<FrameBackend> make_cuda_frame_backend(const SceneViews& scene) {
    return std::make_unique<CudaFrameBackend>(scene);
}

}  // namespace kdpm
