#include "python/src/camera_arg.h"

#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

#include <pybind11/stl.h>

#include "formats/camera_check.h"

namespace kdpm::python {

namespace py = pybind11;

namespace {

void read_vec3(const py::dict& d, const char* key, float out[3]) {
    if (!d.contains(key)) return;
    const auto v = d[key].cast<std::vector<float>>();
    if (v.size() != 3) throw py::value_error(std::string("camera[\"") + key + "\"] must be 3 numbers");
    std::memcpy(out, v.data(), sizeof(float) * 3);
}

}  // namespace

CameraRecord camera_arg(const CameraRecord& file_camera, const py::object& camera) {
    CameraRecord c = file_camera;
    if (camera.is_none()) return c;
    const py::dict d = camera.cast<py::dict>();
    for (const auto& item : d) {
        const std::string key = item.first.cast<std::string>();
        if (key != "eye" && key != "lookat" && key != "up" && key != "vfov")
            throw py::value_error("camera has no key '" + key + "' (eye, lookat, up, vfov)");
    }
    read_vec3(d, "eye", c.eye);
    read_vec3(d, "lookat", c.lookat);
    read_vec3(d, "up", c.up);
    if (d.contains("vfov")) c.vfov_degrees = d["vfov"].cast<float>();
    try {
        check_camera(c, "camera");
    } catch (const std::runtime_error& e) {
        throw py::value_error(e.what());
    }
    return c;
}

}  // namespace kdpm::python
