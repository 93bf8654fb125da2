// kdpm.render: one frame of a mapped scene as a float32 (H, W, 3) array of linear radiance,
// through the same Renderer as kdpm-render (every mode, CPU or CUDA backend).
#include <cstring>
#include <string>
#include <vector>

#include <pybind11/stl.h>

#include "formats/camera_check.h"
#include "formats/scene_limits.h"
#include "runtime/backend/backend_kind.h"
#include "runtime/backend/cuda_device.h"
#include "runtime/backend/thread_limit.h"
#include "runtime/render/default_mode.h"
#include "runtime/render/renderer.h"
#include "runtime/render/scene_loader.h"
#include "tools/cli/progress.h"
#include "python/src/camera_arg.h"
#include "python/src/file_objects.h"
#include "python/src/numpy_args.h"

namespace kdpm::python {

namespace {

AovSet aovs_arg(const std::vector<std::string>& names) {
    AovSet set;
    for (const std::string& n : names) {
        if (n == "depth") set.depth = true;
        else if (n == "normal") set.normal = true;
        else if (n == "position") set.position = true;
        else if (n == "triangle") set.triangle = true;
        else throw py::value_error("AOV '" + n + "' is not depth, normal, position or triangle");
    }
    return set;
}

template <class T>
py::array_t<T> image_array(const std::vector<T>& values, int height, int width, int channels) {
    std::vector<py::ssize_t> shape{height, width};
    if (channels > 1) shape.push_back(channels);
    py::array_t<T> out(shape);
    std::memcpy(out.mutable_data(), values.data(), values.size() * sizeof(T));
    return out;
}

py::object render(const PyGeometryFile& geometry, const py::object& photons, const py::object& mode, int spp,
                  int width, int height, int k, const py::object& max_radius, int light_samples, int max_depth,
                  int max_bounces, const py::object& passes, int gather_rays, const std::string& gather_lookup,
                  bool irradiance_cache,
                  const py::object& camera, const std::vector<std::string>& aovs, const std::string& backend,
                  int threads, bool quiet) {
    RenderSettings settings;
    const PyPhotonMapFile* maps = photons.is_none() ? nullptr : &photons.cast<const PyPhotonMapFile&>();
    // None: kdpm-render's default for these files (default_mode.h).
    settings.mode = mode.is_none() ? default_render_mode(scene_views_of(geometry.file, maps ? &maps->file : nullptr))
                                   : parse_render_mode(mode.cast<std::string>());
    if (mode_needs_photons(settings.mode) && !maps)
        throw py::value_error(std::string("mode ") + render_mode_name(settings.mode) +
                              " reads a photon map: pass photons=kdpm.PhotonMapFile(...)");
    check_range("spp", spp, 1, 4096);
    check_range("width", width, 0, kMaxImageSide);
    check_range("height", height, 0, kMaxImageSide);
    if (k != 0) check_range("k", k, kMinEstimateK, kMaxEstimateK);
    check_range("light_samples", light_samples, 1, 4096);
    check_range("max_depth", max_depth, 1, 64);
    check_range("max_bounces", max_bounces, 0, 1000000);
    check_range("gather_rays", gather_rays, 1, kMaxGatherRays);
    check_range("threads", threads, 0, 4096);
    if (!passes.is_none()) {
        if (settings.mode != RenderMode::sppm) throw py::value_error("passes is for mode sppm");
        const long long p = passes.cast<long long>();
        check_range("passes", p, 1, 1000000);
        settings.passes = static_cast<std::uint32_t>(p);
    }
    settings.max_radius = -1.0f;
    if (!max_radius.is_none()) {
        const double r = max_radius.cast<double>();
        const GeometryInfo& b = geometry.file.info();
        if (radius_too_small(r, b.bounds_min, b.bounds_max))
            throw py::value_error("max_radius " + radius_limit_text(r, b.bounds_min, b.bounds_max) +
                                  ": no photon would be found (0: no limit)");
        settings.max_radius = static_cast<float>(r);
    }
    settings.width = static_cast<std::uint32_t>(width);
    settings.height = static_cast<std::uint32_t>(height);
    settings.spp = static_cast<std::uint32_t>(spp);
    settings.k = static_cast<std::uint32_t>(k);
    settings.light_samples = static_cast<std::uint32_t>(light_samples);
    settings.max_depth = static_cast<std::uint32_t>(max_depth);
    settings.max_bounces = static_cast<std::uint32_t>(max_bounces);
    settings.gather_rays = static_cast<std::uint32_t>(gather_rays);
    try {
        settings.gather_lookup = parse_gather_lookup(gather_lookup);
    } catch (const std::invalid_argument& e) {
        throw py::value_error(std::string("gather_lookup: ") + e.what());
    }
    settings.irradiance_cache = irradiance_cache;
    settings.camera = camera_arg(geometry.file.camera(), camera);
    settings.aovs = aovs_arg(aovs);
    const BackendSelection selected = select_backend(parse_backend_request(backend));

    RenderResult result;
    {
        py::gil_scoped_release release;
        ThreadLimit limit(threads);
        if (selected.kind == BackendKind::cuda) start_cuda_device();
        Renderer renderer(scene_views_of(geometry.file, maps ? &maps->file : nullptr), selected.kind);
        cli::Progress progress("rendering", quiet);
        settings.progress = [&](double f) { progress.update(f); };
        result = renderer.render(settings);
        progress.finish();
    }
    const int h = result.linear.height, w = result.linear.width;
    py::array_t<float> color = image_array(result.linear.rgb, h, w, 3);
    if (!settings.aovs.any()) return color;
    py::dict out;
    out["color"] = color;
    if (settings.aovs.depth) out["depth"] = image_array(result.aovs.depth, h, w, 1);
    if (settings.aovs.normal) out["normal"] = image_array(result.aovs.normal, h, w, 3);
    if (settings.aovs.position) out["position"] = image_array(result.aovs.position, h, w, 3);
    if (settings.aovs.triangle) out["triangle"] = image_array(result.aovs.triangle, h, w, 1);
    return out;
}

}  // namespace

void bind_render(py::module_& m) {
    const RenderSettings defaults;
    m.def("render", &render, py::arg("geometry"), py::arg("photons") = py::none(), py::kw_only(),
          py::arg("mode") = py::none(), py::arg("spp") = defaults.spp, py::arg("width") = 0, py::arg("height") = 0,
          py::arg("k") = 0, py::arg("max_radius") = py::none(), py::arg("light_samples") = defaults.light_samples,
          py::arg("max_depth") = defaults.max_depth, py::arg("max_bounces") = defaults.max_bounces,
          py::arg("passes") = py::none(), py::arg("gather_rays") = defaults.gather_rays,
          py::arg("gather_lookup") = gather_lookup_name(defaults.gather_lookup),
          py::arg("irradiance_cache") = defaults.irradiance_cache, py::arg("camera") = py::none(),
          py::arg("aovs") = std::vector<std::string>{}, py::arg("backend") = "cpu", py::arg("threads") = 0,
          py::arg("quiet") = false,
          "Renders a frame as kdpm-render does: linear radiance as a float32 (H, W, 3) array, row 0 at the top; "
          "mode None: kdpm-render's default (final-gather with an irradiance map, photons, or direct). "
          "With aovs (depth, normal, position, triangle), a dict of 'color' and those arrays. width/height/k 0: "
          "the file's; camera: a dict overriding eye, lookat, up, vfov.");
}

}  // namespace kdpm::python
