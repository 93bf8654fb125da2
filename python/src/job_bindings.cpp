// kdpm.build_geometry, kdpm.shoot_photons, kdpm.build_photons: the pipeline's steps as the tools
// run them (tools/jobs), file to file, through the same checks and output discipline.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "builders/geometry/geometry_file_builder.h"
#include "builders/photons/photon_tree_builder.h"
#include "runtime/backend/backend_kind.h"
#include "runtime/backend/cuda_device.h"
#include "runtime/backend/thread_limit.h"
#include "runtime/photons/knn_best.h"
#include "tools/cli/progress.h"
#include "tools/jobs/geometry_job.h"
#include "tools/jobs/photon_jobs.h"
#include "python/src/file_objects.h"
#include "python/src/numpy_args.h"

namespace kdpm::python {

namespace {

// A scene from (vertices (V, 3), faces (F, 3) integer indices): one white diffuse material, no
// lights, a framed camera.
Scene scene_from_arrays(const py::handle& source) {
    const py::sequence pair = source.cast<py::sequence>();
    if (pair.size() != 2) throw py::value_error("a mesh is (vertices, faces)");
    const FloatRows vertices = points_arg(pair[0], "vertices");
    py::array faces_any = py::array::ensure(pair[1]);
    if (!faces_any || (faces_any.dtype().kind() != 'i' && faces_any.dtype().kind() != 'u'))
        throw py::type_error("faces must be an integer array of shape (F, 3)");
    if (faces_any.ndim() != 2 || faces_any.shape(1) != 3) throw py::value_error("faces must have shape (F, 3)");
    const auto faces = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(faces_any);
    const std::int64_t v_count = vertices.shape(0);
    const float* v = vertices.data();
    const std::int64_t* f = faces.data();
    std::vector<TriangleRecord> triangles;
    triangles.reserve(static_cast<std::size_t>(faces.shape(0)));
    for (py::ssize_t i = 0; i < faces.shape(0); ++i) {
        float corner[3][3];
        for (int c = 0; c < 3; ++c) {
            const std::int64_t index = f[3 * i + c];
            if (index < 0 || index >= v_count)
                throw py::value_error("faces row " + std::to_string(i) + " names vertex " + std::to_string(index) +
                                      " of " + std::to_string(v_count));
            for (int a = 0; a < 3; ++a) corner[c][a] = v[3 * index + a];
        }
        triangles.push_back(make_triangle(corner[0], corner[1], corner[2], 0, static_cast<std::uint32_t>(i)));
    }
    if (triangles.empty()) throw py::value_error("faces is empty: no triangle to build a tree over");
    Scene scene = scene_from_triangles(std::move(triangles));
    check_scene_extent(scene);
    return scene;
}

bool is_path(const py::handle& value) {
    return py::isinstance<py::str>(value) || py::hasattr(value, "__fspath__");
}

py::dict geometry_result(const GeometryJobResult& r) {
    py::dict d;
    d["triangles"] = r.triangles;
    d["nodes"] = r.stats.nodes;
    d["leaves"] = r.stats.leaves;
    d["empty_leaves"] = r.stats.empty_leaves;
    d["max_depth"] = r.stats.max_depth;
    d["mean_leaf_triangles"] = r.stats.mean_leaf_triangles;
    d["sah_cost"] = r.stats.sah_cost;
    d["warnings"] = r.warnings;
    d["import_ms"] = r.import_ms;
    d["build_ms"] = r.build_ms;
    return d;
}

py::dict build_geometry(const py::object& source, const std::filesystem::path& output, const std::string& quality,
                        double traversal_cost, double intersection_cost, double empty_bonus, int max_depth,
                        int leaf_size, int threads, bool quiet) {
    KdBuildParams params;
    const auto q = parse_quality(quality);
    if (!q) throw py::value_error("quality '" + quality + "' is not high or fast");
    params.quality = *q;
    check_real_range("traversal_cost", traversal_cost, 1e-6, 1e6);
    check_real_range("intersection_cost", intersection_cost, 1e-6, 1e6);
    check_real_range("empty_bonus", empty_bonus, 0.0, 1.0);
    check_range("max_depth", max_depth, 0, static_cast<long long>(kMaxKdTreeDepth) - 1);
    check_range("leaf_size", leaf_size, 0, 1 << 20);
    check_range("threads", threads, 0, 4096);
    params.traversal_cost = static_cast<float>(traversal_cost);
    params.intersection_cost = static_cast<float>(intersection_cost);
    params.empty_bonus = static_cast<float>(empty_bonus);
    params.max_depth = max_depth;
    params.leaf_size = leaf_size;
    const bool from_file = is_path(source);
    std::filesystem::path input;
    Scene scene;
    if (from_file) input = source.cast<std::filesystem::path>();
    else scene = scene_from_arrays(source);
    GeometryJobResult result;
    {
        py::gil_scoped_release release;
        ThreadLimit limit(threads);
        cli::Progress progress("building kd-tree", quiet);
        auto update = [&](double f) { progress.update(f); };
        result = from_file ? build_geometry_job(input, output, params, update)
                           : build_geometry_job(scene, output, params, update);
        progress.finish();
    }
    return geometry_result(result);
}

py::dict shoot(const std::filesystem::path& geometry, const std::filesystem::path& output, long long photons,
               const py::object& bounces, long long seed, const std::string& paths, const std::string& backend,
               int threads, bool quiet) {
    check_range("photons", photons, 0, 1 << 30);
    check_range("seed", seed, 0, 1 << 30);
    check_range("threads", threads, 0, 4096);
    ShootJob job;
    job.photons = static_cast<std::uint64_t>(photons);
    if (!bounces.is_none()) {
        const long long b = bounces.cast<long long>();
        check_range("bounces", b, 0, 255);
        job.bounces = static_cast<int>(b);
    }
    job.seed = static_cast<std::uint32_t>(seed);
    job.paths = paths;
    const BackendSelection selected = select_backend(parse_backend_request(backend));
    job.backend = selected.kind;
    ShootJobResult r;
    {
        py::gil_scoped_release release;
        ThreadLimit limit(threads);
        if (selected.kind == BackendKind::cuda) start_cuda_device();
        cli::Progress progress("shooting photons", quiet);
        r = shoot_photons_job(geometry, output, job, [&](double f) { progress.update(f); });
        progress.finish();
    }
    py::dict d;
    d["emitted"] = r.emitted;
    d["bounces"] = r.bounces;
    d["paths"] = py::make_tuple(r.range.begin, r.range.end);
    d["stored"] = r.info.stored_count;
    d["caustic"] = r.info.caustic_count;
    d["direct_hits"] = r.direct_hits;
    d["rays"] = r.rays;
    d["seconds"] = r.seconds;
    d["backend"] = backend_name(selected.kind);
    if (!selected.notice.empty()) d["notice"] = selected.notice;
    return d;
}

py::dict build_photons(const std::filesystem::path& hits, const std::filesystem::path& output, bool balanced,
                       int leaf_size, double radius, int irradiance_every, int irradiance_k, int threads, bool quiet) {
    check_range("leaf_size", leaf_size, 0, 4096);
    check_real_range("radius", radius, 0.0, 1e30);
    check_range("irradiance_every", irradiance_every, 0, 1 << 30);
    check_range("irradiance_k", irradiance_k, 1, static_cast<long long>(kMaxGatherK));
    check_range("threads", threads, 0, 4096);
    PhotonMapJob job;
    job.balanced = balanced;
    job.leaf_size = static_cast<std::uint32_t>(leaf_size);
    job.radius = radius;
    job.irradiance_every = static_cast<std::uint32_t>(irradiance_every);
    job.irradiance_k = static_cast<std::uint32_t>(irradiance_k);
    PhotonMapJobResult r;
    {
        py::gil_scoped_release release;
        ThreadLimit limit(threads);
        cli::Progress progress("building photon trees", quiet);
        r = build_photon_map_job(hits, output, job);
        progress.finish();
    }
    py::dict d;
    d["photons"] = r.global.photon_count;
    d["caustic"] = r.caustic.photon_count;
    d["irradiance_photons"] = r.irradiance_photons;
    d["nodes"] = r.global.node_count;
    d["leaves"] = r.global.leaf_count;
    d["max_depth"] = r.global.max_depth;
    d["query_radius"] = r.global.query_radius;
    d["seconds"] = r.seconds;
    return d;
}

}  // namespace

void bind_jobs(py::module_& m) {
    const KdBuildParams defaults;
    m.def("build_geometry", &build_geometry, py::arg("source"), py::arg("output"), py::kw_only(),
          py::arg("quality") = "high", py::arg("traversal_cost") = defaults.traversal_cost,
          py::arg("intersection_cost") = defaults.intersection_cost, py::arg("empty_bonus") = defaults.empty_bonus,
          py::arg("max_depth") = 0, py::arg("leaf_size") = 0, py::arg("threads") = 0, py::arg("quiet") = false,
          "Builds the SAH geometry kd-tree file (.kdg) of a scene card, a mesh file or (vertices (V, 3), faces "
          "(F, 3)) arrays (one white diffuse material, no lights), as kdpm-build-geometry. Returns the tree's "
          "statistics and warnings.");
    m.def("shoot_photons", &shoot, py::arg("geometry"), py::arg("output"), py::kw_only(), py::arg("photons") = 0,
          py::arg("bounces") = py::none(), py::arg("seed") = 0, py::arg("paths") = "", py::arg("backend") = "cpu",
          py::arg("threads") = 0, py::arg("quiet") = false,
          "Shoots photons from the area lights of a .kdg into a photon hit file (.kdph), as kdpm-shoot-photons "
          "(photons 0 and bounces None: the scene card's).");
    m.def("build_photons", &build_photons, py::arg("hits"), py::arg("output"), py::kw_only(),
          py::arg("balanced") = false, py::arg("leaf_size") = 0, py::arg("radius") = 0.0,
          py::arg("irradiance_every") = kDefaultIrradianceEvery, py::arg("irradiance_k") = kDefaultIrradianceK,
          py::arg("threads") = 0, py::arg("quiet") = false,
          "Builds the photon kd-tree file (.kdp) from photon hits (.kdph), as kdpm-build-photons.");
}

}  // namespace kdpm::python
