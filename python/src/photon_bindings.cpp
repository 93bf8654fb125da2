// kdpm.PhotonMapFile and kdpm.PhotonMap: a mapped .kdp whose photon arrays are read-only NumPy
// views, with batched k-nearest queries (like SciPy's cKDTree.query) and radiance estimates.
#include <cmath>
#include <memory>

#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "python/src/file_objects.h"
#include "python/src/numpy_args.h"
#include "python/src/photon_batch.h"

namespace kdpm::python {

namespace {

PyPhotonMap map_of(const py::object& file, PhotonMapKind kind) {
    const PhotonMapFile& f = file.cast<const PyPhotonMapFile&>().file;
    return PyPhotonMap{file, f.view(kind), f.info(kind), kind == PhotonMapKind::global ? "global" : "caustic"};
}

py::dict tree_info_dict(const PhotonTreeInfo& info) {
    py::dict d;
    d["photon_count"] = info.photon_count;
    d["node_count"] = info.node_count;
    d["leaf_count"] = info.leaf_count;
    d["max_depth"] = info.max_depth;
    d["max_leaf_size"] = info.max_leaf_size;
    d["builder"] = info.builder == static_cast<std::uint32_t>(PhotonTreeBuilder::balanced) ? "balanced" : "vvh";
    d["query_radius"] = info.query_radius;
    d["max_bounces"] = info.max_bounces;
    d["emitted_count"] = info.emitted_count;
    d["bounds_min"] = py::make_tuple(info.bounds_min[0], info.bounds_min[1], info.bounds_min[2]);
    d["bounds_max"] = py::make_tuple(info.bounds_max[0], info.bounds_max[1], info.bounds_max[2]);
    return d;
}

// Unit normals, one per point: ValueError for a zero one.
FloatRows unit_normals(const py::handle& value, std::size_t rows) {
    FloatRows normals = points_arg(value, "normals");
    if (static_cast<std::size_t>(normals.shape(0)) != rows)
        throw py::value_error("normals must have as many rows as points (" + std::to_string(normals.shape(0)) +
                              " and " + std::to_string(rows) + ")");
    FloatRows unit(std::vector<py::ssize_t>{static_cast<py::ssize_t>(rows), 3});
    const float* n = normals.data();
    float* u = unit.mutable_data();
    for (std::size_t i = 0; i < rows; ++i) {
        const float len = std::sqrt(n[3 * i] * n[3 * i] + n[3 * i + 1] * n[3 * i + 1] + n[3 * i + 2] * n[3 * i + 2]);
        if (!(len > 0.0f)) throw py::value_error("normals row " + std::to_string(i) + " is zero");
        for (int c = 0; c < 3; ++c) u[3 * i + c] = n[3 * i + c] / len;
    }
    return unit;
}

float radius_arg(const py::handle& value) {
    if (value.is_none()) return 0.0f;
    const double r = value.cast<double>();
    check_real_range("max_radius", r, 0.0, 1e30);
    return static_cast<float>(r);
}

py::tuple knn(const PyPhotonMap& map, const py::handle& points, int k, const py::handle& normals,
              const py::handle& max_radius, double min_normal_cos) {
    check_range("k", k, 1, static_cast<long long>(kMaxGatherK));
    check_real_range("min_normal_cos", min_normal_cos, -1.0, 1.0);
    const FloatRows q = points_arg(points, "points");
    const std::size_t n = static_cast<std::size_t>(q.shape(0));
    FloatRows unit;
    if (!normals.is_none()) unit = unit_normals(normals, n);
    py::array_t<float> dist(std::vector<py::ssize_t>{static_cast<py::ssize_t>(n), k});
    py::array_t<std::int64_t> index(std::vector<py::ssize_t>{static_cast<py::ssize_t>(n), k});
    const KnnQueries queries{q.data(), normals.is_none() ? nullptr : unit.data(), n, static_cast<std::uint32_t>(k),
                             radius_arg(max_radius), static_cast<float>(min_normal_cos)};
    float* d = dist.mutable_data();
    std::int64_t* x = index.mutable_data();
    {
        py::gil_scoped_release release;
        knn_batch(map.view, queries, d, x);
    }
    return py::make_tuple(dist, index);
}

py::array_t<float> radiance(const PyPhotonMap& map, const py::handle& points, const py::handle& normals, int k,
                            const py::handle& albedo, const py::handle& max_radius, double min_normal_cos) {
    check_range("k", k, 1, static_cast<long long>(kMaxGatherK));
    check_real_range("min_normal_cos", min_normal_cos, -1.0, 1.0);
    const FloatRows q = points_arg(points, "points");
    const std::size_t n = static_cast<std::size_t>(q.shape(0));
    const FloatRows unit = unit_normals(normals, n);
    glm::vec3 rho(1.0f);
    if (py::isinstance<py::float_>(albedo) || py::isinstance<py::int_>(albedo)) {
        rho = glm::vec3(albedo.cast<float>());
    } else {
        const auto a = albedo.cast<std::vector<float>>();
        if (a.size() != 3) throw py::value_error("albedo must be a number or 3 numbers");
        rho = glm::vec3(a[0], a[1], a[2]);
    }
    for (int c = 0; c < 3; ++c) check_real_range("albedo", rho[c], 0.0, 1.0);
    RadianceEstimateParams params;
    params.k = static_cast<std::uint32_t>(k);
    params.max_radius = radius_arg(max_radius);
    params.min_normal_cos = static_cast<float>(min_normal_cos);
    py::array_t<float> out(std::vector<py::ssize_t>{static_cast<py::ssize_t>(n), 3});
    float* r = out.mutable_data();
    {
        py::gil_scoped_release release;
        radiance_batch(map.view, q.data(), unit.data(), n, rho, params, r);
    }
    return out;
}

// Decoded copies, (N, 3) float32: positions, power (W) and the two packed unit vectors.
py::array_t<float> positions(const PyPhotonMap& map) {
    py::array_t<float> out(std::vector<py::ssize_t>{map.view.photon_count, 3});
    float* p = out.mutable_data();
    for (std::uint32_t i = 0; i < map.view.photon_count; ++i) {
        p[3 * i] = map.view.x[i];
        p[3 * i + 1] = map.view.y[i];
        p[3 * i + 2] = map.view.z[i];
    }
    return out;
}

py::array_t<float> powers(const PyPhotonMap& map) {
    py::array_t<float> out(std::vector<py::ssize_t>{map.view.photon_count, 3});
    float* p = out.mutable_data();
    for (std::uint32_t i = 0; i < map.view.photon_count; ++i) decode_rgbe(map.view.power[i], p + 3 * i);
    return out;
}

py::array_t<float> unit_vectors(const PyPhotonMap& map, bool normal) {
    py::array_t<float> out(std::vector<py::ssize_t>{map.view.photon_count, 3});
    float* p = out.mutable_data();
    for (std::uint32_t i = 0; i < map.view.photon_count; ++i)
        decode_octahedral(normal ? map.view.directions[i].normal : map.view.directions[i].direction, p + 3 * i);
    return out;
}

py::dtype directions_dtype() {
    py::list names, formats, offsets;
    names.append("direction");
    names.append("normal");
    formats.append("<u4");
    formats.append("<u4");
    offsets.append(offsetof(PackedPhotonDirections, direction));
    offsets.append(offsetof(PackedPhotonDirections, normal));
    return py::dtype(names, formats, offsets, sizeof(PackedPhotonDirections));
}

// The methods of a photon map, on PhotonMap and (for the global map) on PhotonMapFile itself.
template <class Class, class MapOf>
void bind_map_methods(Class& cls, MapOf of) {
    auto field = [of](auto member) {
        return [of, member](py::object self) {
            const PyPhotonMap map = of(self);
            return file_view(py::dtype::of<std::remove_cv_t<std::remove_pointer_t<
                                 std::remove_cvref_t<decltype(map.view.*member)>>>>(),
                             map.view.photon_count, map.view.*member, map.owner);
        };
    };
    cls.def_property_readonly("x", field(&PhotonMapView::x), "photon x coordinates (float32, leaf order), a view")
        .def_property_readonly("y", field(&PhotonMapView::y))
        .def_property_readonly("z", field(&PhotonMapView::z))
        .def_property_readonly("power_rgbe", field(&PhotonMapView::power), "packed RGBE power (uint32), a view")
        .def_property_readonly("flags", field(&PhotonMapView::flags),
                               "bit 0: caustic; bits 8-15: bounces before the hit (uint32), a view")
        .def_property_readonly("directions",
                               [of](py::object self) {
                                   const PyPhotonMap map = of(self);
                                   return file_view(directions_dtype(), map.view.photon_count, map.view.directions,
                                                    map.owner);
                               },
                               "octahedral incoming direction and surface normal (uint32 pairs), a view")
        .def_property_readonly("nodes",
                               [of](py::object self) {
                                   const PyPhotonMap map = of(self);
                                   return file_view(py::dtype::of<std::uint32_t>(), map.view.node_count, map.view.nodes,
                                                    map.owner, {2});
                               },
                               "kd-tree nodes as (payload, bits) uint32 pairs, a view")
        .def_property_readonly("photon_count", [of](py::object self) { return of(self).view.photon_count; })
        .def_property_readonly("emitted_count", [of](py::object self) { return of(self).view.emitted_count; })
        .def_property_readonly("info", [of](py::object self) { return tree_info_dict(of(self).info); })
        .def("positions", [of](py::object self) { return positions(of(self)); }, "(N, 3) float32 copy")
        .def("power", [of](py::object self) { return powers(of(self)); }, "(N, 3) float32 decoded power (W)")
        .def("incoming", [of](py::object self) { return unit_vectors(of(self), false); },
             "(N, 3) unit directions of travel (into the surface)")
        .def("normals", [of](py::object self) { return unit_vectors(of(self), true); },
             "(N, 3) unit surface normals on the side the photon arrived from")
        .def("knn",
             [of](py::object self, const py::handle& points, int k, const py::handle& normals,
                  const py::handle& max_radius, double min_normal_cos) {
                 return knn(of(self), points, k, normals, max_radius, min_normal_cos);
             },
             py::arg("points"), py::arg("k"), py::arg("normals") = py::none(), py::arg("max_radius") = py::none(),
             py::arg("min_normal_cos") = 0.7,
             "The k nearest photons of each point, as cKDTree.query: (distances (N, k) ascending, indices into "
             "the photon arrays); missing neighbours are inf and photon_count. With normals, only photons that "
             "arrived from the front of that surface with a stored normal within min_normal_cos of it.")
        .def("radiance",
             [of](py::object self, const py::handle& points, const py::handle& normals, int k,
                  const py::handle& albedo, const py::handle& max_radius, double min_normal_cos) {
                 return radiance(of(self), points, normals, k, albedo, max_radius, min_normal_cos);
             },
             py::arg("points"), py::arg("normals"), py::arg("k") = 64, py::arg("albedo") = 1.0,
             py::arg("max_radius") = py::none(), py::arg("min_normal_cos") = 0.7,
             "Outgoing radiance (N, 3) of a diffuse surface of albedo at each point: the photon map estimate "
             "albedo / pi * sum(power) / (pi r^2) over the k nearest photons that may light it.");
}

}  // namespace

void bind_photons(py::module_& m) {
    py::class_<PyPhotonMap> map(m, "PhotonMap", "One photon map (global or caustic) of a PhotonMapFile.");
    map.def_readonly("name", &PyPhotonMap::name);
    bind_map_methods(map, [](const py::object& self) { return self.cast<PyPhotonMap>(); });
    map.def("__repr__", [](const PyPhotonMap& p) {
        return "<kdpm.PhotonMap " + p.name + ": " + std::to_string(p.view.photon_count) + " photons>";
    });

    py::class_<PyPhotonMapFile> file(m, "PhotonMapFile",
                                     "A photon kd-tree file (.kdp), memory-mapped and checked on open. Its arrays "
                                     "are read-only views of the mapping; the photon methods read the global map.");
    file.def(py::init([](const std::filesystem::path& path) {
                 py::gil_scoped_release release;
                 return std::make_unique<PyPhotonMapFile>(PyPhotonMapFile{PhotonMapFile::open(path), path.string()});
             }),
             py::arg("path"))
        .def_readonly("path", &PyPhotonMapFile::path)
        .def_property_readonly("metadata", [](const PyPhotonMapFile& p) { return metadata_dict(p.file.metadata()); })
        .def_property_readonly("global_map", [](py::object self) { return map_of(self, PhotonMapKind::global); })
        .def_property_readonly("caustic_map",
                               [](py::object self) -> py::object {
                                   if (!self.cast<const PyPhotonMapFile&>().file.has_map(PhotonMapKind::caustic))
                                       return py::none();
                                   return py::cast(map_of(self, PhotonMapKind::caustic));
                               })
        .def_property_readonly("has_irradiance",
                               [](const PyPhotonMapFile& p) { return p.file.irradiance_map().present(); });
    bind_map_methods(file, [](const py::object& self) { return map_of(self, PhotonMapKind::global); });
    file.def("__repr__", [](const PyPhotonMapFile& p) {
        return "<kdpm.PhotonMapFile '" + p.path + "': " + std::to_string(p.file.info().photon_count) + " photons>";
    });
}

}  // namespace kdpm::python
