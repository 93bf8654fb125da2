// kdpm.GeometryFile: a mapped .kdg whose sections are read-only NumPy views, and batched rays
// through its kd-tree.
#include <chrono>
#include <cstddef>
#include <memory>
#include <vector>

#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "formats/camera_check.h"
#include "python/src/camera_arg.h"
#include "python/src/file_objects.h"
#include "python/src/numpy_args.h"
#include "python/src/ray_batch.h"
#include "runtime/render/camera.h"

namespace kdpm::python {

namespace {

// A structured dtype from (name, format, offset) triples, laid out as the C++ record.
py::dtype record_dtype(std::initializer_list<std::tuple<const char*, const char*, std::size_t>> fields,
                       std::size_t itemsize) {
    py::list names, formats, offsets;
    for (const auto& [name, format, offset] : fields) {
        names.append(name);
        formats.append(format);
        offsets.append(offset);
    }
    return py::dtype(names, formats, offsets, static_cast<py::ssize_t>(itemsize));
}

py::dtype node_dtype() {
    return record_dtype({{"payload", "<u4", offsetof(KdNode, payload)}, {"bits", "<u4", offsetof(KdNode, bits)}},
                        sizeof(KdNode));
}

py::dtype triangle_dtype() {
    return record_dtype({{"v0", "(3,)<f4", offsetof(TriangleRecord, v0)},
                         {"material", "<u4", offsetof(TriangleRecord, material)},
                         {"e1", "(3,)<f4", offsetof(TriangleRecord, e1)},
                         {"source_index", "<u4", offsetof(TriangleRecord, source_index)},
                         {"e2", "(3,)<f4", offsetof(TriangleRecord, e2)},
                         {"flags", "<u4", offsetof(TriangleRecord, flags)}},
                        sizeof(TriangleRecord));
}

py::dtype material_dtype() {
    return record_dtype({{"diffuse", "(3,)<f4", offsetof(MaterialRecord, diffuse)},
                         {"kind", "<u4", offsetof(MaterialRecord, kind)},
                         {"specular", "(3,)<f4", offsetof(MaterialRecord, specular)},
                         {"ior", "<f4", offsetof(MaterialRecord, ior)},
                         {"transmission", "(3,)<f4", offsetof(MaterialRecord, transmission)},
                         {"diffuse_texture", "<u4", offsetof(MaterialRecord, diffuse_texture)},
                         {"emission", "(3,)<f4", offsetof(MaterialRecord, emission)}},
                        sizeof(MaterialRecord));
}

py::dtype light_dtype() {
    return record_dtype({{"p0", "(3,)<f4", offsetof(AreaLightRecord, p0)},
                         {"shape", "<u4", offsetof(AreaLightRecord, shape)},
                         {"e1", "(3,)<f4", offsetof(AreaLightRecord, e1)},
                         {"triangle", "<u4", offsetof(AreaLightRecord, triangle)},
                         {"e2", "(3,)<f4", offsetof(AreaLightRecord, e2)},
                         {"area", "<f4", offsetof(AreaLightRecord, area)},
                         {"radiance", "(3,)<f4", offsetof(AreaLightRecord, radiance)},
                         {"power", "<f4", offsetof(AreaLightRecord, power)}},
                        sizeof(AreaLightRecord));
}

py::tuple vec3(const float* v) { return py::make_tuple(v[0], v[1], v[2]); }

py::dict info_dict(const GeometryInfo& info) {
    py::dict d;
    d["bounds_min"] = vec3(info.bounds_min);
    d["bounds_max"] = vec3(info.bounds_max);
    d["triangle_count"] = info.triangle_count;
    d["node_count"] = info.node_count;
    d["leaf_index_count"] = info.leaf_index_count;
    d["max_depth"] = info.max_depth;
    d["default_photons"] = info.default_photons;
    d["default_bounces"] = info.default_bounces;
    d["default_k"] = info.default_k;
    d["up_axis"] = info.up_axis;
    return d;
}

py::dict camera_dict(const CameraRecord& c) {
    py::dict d;
    d["eye"] = vec3(c.eye);
    d["lookat"] = vec3(c.lookat);
    d["up"] = vec3(c.up);
    d["vfov"] = c.vfov_degrees;
    d["width"] = c.width;
    d["height"] = c.height;
    return d;
}

// The rays of one intersect/occluded call, checked, and tmax per ray.
struct CheckedRays {
    FloatRows origins, directions;
    std::vector<float> tmax;
    RayBatch batch() const {
        return RayBatch{origins.data(), directions.data(), tmax.data(), static_cast<std::uint64_t>(origins.shape(0))};
    }
};

CheckedRays checked_rays(const py::handle& origins, const py::handle& directions, const py::handle& tmax) {
    CheckedRays r{points_arg(origins, "origins"), points_arg(directions, "directions"), {}};
    if (r.origins.shape(0) != r.directions.shape(0))
        throw py::value_error("origins and directions must have as many rows (" + std::to_string(r.origins.shape(0)) +
                              " and " + std::to_string(r.directions.shape(0)) + ")");
    const std::size_t n = static_cast<std::size_t>(r.origins.shape(0));
    const float* d = r.directions.data();
    for (std::size_t i = 0; i < n; ++i)
        if (d[3 * i] == 0.0f && d[3 * i + 1] == 0.0f && d[3 * i + 2] == 0.0f)
            throw py::value_error("directions row " + std::to_string(i) + " is zero");
    r.tmax = per_row_arg(tmax, "tmax", n, __builtin_inff());
    return r;
}

// Output arrays of one intersect call and the kernel's pointers into them.
struct HitResult {
    py::array_t<float> t, u, v, normal;
    py::array_t<std::int64_t> triangle, material;
    explicit HitResult(py::ssize_t n)
        : t(n), u(n), v(n), normal(std::vector<py::ssize_t>{n, 3}), triangle(n), material(n) {}
    HitArrays arrays() {
        return HitArrays{t.mutable_data(), triangle.mutable_data(), u.mutable_data(), v.mutable_data(),
                         normal.mutable_data(), material.mutable_data()};
    }
    py::dict dict() const {
        py::dict d;
        d["t"] = t;
        d["triangle"] = triangle;
        d["u"] = u;
        d["v"] = v;
        d["normal"] = normal;
        d["material"] = material;
        return d;
    }
};

py::dict intersect(const PyGeometryFile& g, const py::handle& origins, const py::handle& directions,
                   const py::handle& tmax) {
    const CheckedRays rays = checked_rays(origins, directions, tmax);
    HitResult result(static_cast<py::ssize_t>(rays.tmax.size()));
    const HitArrays out = result.arrays();
    {
        py::gil_scoped_release release;
        intersect_batch(g.file.view(), rays.batch(), out);
    }
    return result.dict();
}

py::array_t<bool> occluded_rays(const PyGeometryFile& g, const py::handle& origins, const py::handle& directions,
                                const py::handle& tmax) {
    const CheckedRays rays = checked_rays(origins, directions, tmax);
    py::array_t<bool> out(static_cast<py::ssize_t>(rays.tmax.size()));
    bool* data = out.mutable_data();
    {
        py::gil_scoped_release release;
        occluded_batch(g.file.view(), rays.batch(), data);
    }
    return out;
}

// The renderer's rays through the pixel centres (PinholeCamera, one sample), row by row from the top.
py::tuple camera_rays(const PyGeometryFile& g, int width, int height, const py::object& camera) {
    check_range("width", width, 0, kMaxImageSide);
    check_range("height", height, 0, kMaxImageSide);
    const CameraRecord c = camera_arg(g.file.camera(), camera);
    const std::uint32_t w = width > 0 ? static_cast<std::uint32_t>(width) : c.width;
    const std::uint32_t h = height > 0 ? static_cast<std::uint32_t>(height) : c.height;
    const PinholeCamera pinhole = PinholeCamera::from_record(c, w, h, 1);
    const py::ssize_t n = static_cast<py::ssize_t>(w) * h;
    FloatRows origins(std::vector<py::ssize_t>{n, 3}), directions(std::vector<py::ssize_t>{n, 3});
    float* o = origins.mutable_data();
    float* d = directions.mutable_data();
    for (py::ssize_t i = 0; i < n; ++i) {
        const CameraRay ray = pinhole.ray_at(static_cast<std::uint64_t>(i), w, 0);
        for (int a = 0; a < 3; ++a) {
            o[3 * i + a] = ray.origin[a];
            d[3 * i + a] = ray.direction[a];
        }
    }
    return py::make_tuple(origins, directions);
}

// The benchmark's reference: the same batch through the C++ loop on C++ vectors, `repeats`
// times; the seconds of each run.
std::vector<double> cpp_intersect_seconds(const PyGeometryFile& g, const py::handle& origins,
                                          const py::handle& directions, int repeats) {
    check_range("repeats", repeats, 1, 1000);
    const CheckedRays rays = checked_rays(origins, directions, py::none());
    const std::size_t n = rays.tmax.size();
    const std::vector<float> o(rays.origins.data(), rays.origins.data() + 3 * n),
        d(rays.directions.data(), rays.directions.data() + 3 * n);
    std::vector<float> t(n), u(n), v(n), normal(3 * n);
    std::vector<std::int64_t> triangle(n), material(n);
    std::vector<double> seconds;
    py::gil_scoped_release release;
    for (int r = 0; r < repeats; ++r) {
        const auto start = std::chrono::steady_clock::now();
        intersect_batch(g.file.view(), RayBatch{o.data(), d.data(), rays.tmax.data(), n},
                        HitArrays{t.data(), triangle.data(), u.data(), v.data(), normal.data(), material.data()});
        seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    }
    return seconds;
}

}  // namespace

void bind_geometry(py::module_& m) {
    py::class_<PyGeometryFile>(m, "GeometryFile",
                               "A geometry kd-tree file (.kdg), memory-mapped and checked on open. Its arrays are "
                               "read-only views of the mapping, valid while they are referenced.")
        .def(py::init([](const std::filesystem::path& path) {
                 py::gil_scoped_release release;
                 return std::make_unique<PyGeometryFile>(PyGeometryFile{GeometryFile::open(path), path.string()});
             }),
             py::arg("path"))
        .def_readonly("path", &PyGeometryFile::path)
        .def_property_readonly("info", [](const PyGeometryFile& g) { return info_dict(g.file.info()); })
        .def_property_readonly("camera", [](const PyGeometryFile& g) { return camera_dict(g.file.camera()); })
        .def_property_readonly("metadata", [](const PyGeometryFile& g) { return metadata_dict(g.file.metadata()); })
        .def_property_readonly("nodes",
                               [](py::object self) {
                                   const GeometryView& v = self.cast<const PyGeometryFile&>().file.view();
                                   return file_view(node_dtype(), v.node_count, v.nodes, self);
                               })
        .def_property_readonly("leaf_indices",
                               [](py::object self) {
                                   const GeometryView& v = self.cast<const PyGeometryFile&>().file.view();
                                   return file_view(py::dtype::of<std::uint32_t>(), v.leaf_index_count,
                                                    v.leaf_indices, self);
                               })
        .def_property_readonly("triangles",
                               [](py::object self) {
                                   const GeometryView& v = self.cast<const PyGeometryFile&>().file.view();
                                   return file_view(triangle_dtype(), v.triangle_count, v.triangles, self);
                               })
        .def_property_readonly("normals",
                               [](py::object self) -> py::object {
                                   const GeometryView& v = self.cast<const PyGeometryFile&>().file.view();
                                   if (v.normals == nullptr) return py::none();
                                   return file_view(py::dtype::of<float>(), v.triangle_count, v.normals, self, {3, 3});
                               })
        .def_property_readonly("uvs",
                               [](py::object self) -> py::object {
                                   const GeometryView& v = self.cast<const PyGeometryFile&>().file.view();
                                   if (v.uvs == nullptr) return py::none();
                                   return file_view(py::dtype::of<float>(), v.triangle_count, v.uvs, self, {3, 2});
                               })
        .def_property_readonly("materials",
                               [](py::object self) {
                                   const GeometryView& v = self.cast<const PyGeometryFile&>().file.view();
                                   return file_view(material_dtype(), v.material_count, v.materials, self);
                               })
        .def_property_readonly("lights",
                               [](py::object self) {
                                   const GeometryView& v = self.cast<const PyGeometryFile&>().file.view();
                                   return file_view(light_dtype(), v.light_count, v.lights, self);
                               })
        .def_property_readonly("texels",
                               [](py::object self) {
                                   const GeometryView& v = self.cast<const PyGeometryFile&>().file.view();
                                   return file_view(py::dtype::of<float>(), v.texel_count, v.texels, self, {3});
                               })
        .def("intersect", &intersect, py::arg("origins"), py::arg("directions"), py::arg("tmax") = py::none(),
             "Closest hits of rays origin + t * direction, t in (0, tmax): a dict of arrays t (inf on a miss), "
             "triangle (index into .triangles, -1), u, v (barycentrics of v1 and v2), normal (unit shading "
             "normal, (N, 3)) and material (-1). One call per batch, on all threads.")
        .def("occluded", &occluded_rays, py::arg("origins"), py::arg("directions"), py::arg("tmax") = py::none(),
             "Whether each ray hits anything with t in (0, tmax): a bool array.")
        .def("camera_rays", &camera_rays, py::arg("width") = 0, py::arg("height") = 0, py::arg("camera") = py::none(),
             "The renderer's rays through the pixel centres of the file's camera (or `camera`, a dict "
             "overriding eye, lookat, up, vfov): (origins, directions), (width * height, 3) float32 each, row "
             "0 at the top; width/height 0: the camera's.")
        .def("_cpp_intersect_seconds", &cpp_intersect_seconds, py::arg("origins"), py::arg("directions"),
             py::arg("repeats") = 1, "Benchmark reference: seconds of the same batch through the C++ loop.")
        .def("__repr__", [](const PyGeometryFile& g) {
            return "<kdpm.GeometryFile '" + g.path + "': " + std::to_string(g.file.info().triangle_count) +
                   " triangles, " + std::to_string(g.file.info().node_count) + " nodes>";
        });
}

}  // namespace kdpm::python
