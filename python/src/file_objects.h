#pragma once
// The Python objects that own a mapped file: every array view of the file keeps one alive.
#include <filesystem>
#include <string>

#include <pybind11/pybind11.h>

#include "runtime/geometry/geometry_file.h"
#include "runtime/photons/photon_map_file.h"

namespace kdpm::python {

namespace py = pybind11;

struct PyGeometryFile {
    GeometryFile file;
    std::string path;
};

struct PyPhotonMapFile {
    PhotonMapFile file;
    std::string path;
};

// One photon map of a .kdp (global or caustic), with the file object it points into.
struct PyPhotonMap {
    py::object owner;  // the PhotonMapFile
    PhotonMapView view;
    PhotonTreeInfo info;
    std::string name;  // "global" or "caustic"
};

void bind_geometry(py::module_& m);
void bind_photons(py::module_& m);
void bind_jobs(py::module_& m);
void bind_render(py::module_& m);

// The file's metadata section as a dict (tool, version, source, parameters, statistics).
py::dict metadata_dict(const Metadata& meta);

}  // namespace kdpm::python
