// The _kdpm extension: kdpm's files, kernels and jobs for Python (the `kdpm` package wraps it).
#include <pybind11/pybind11.h>

#include "formats/format_error.h"
#include "formats/metadata.h"
#include "python/src/file_objects.h"

namespace kdpm::python {

py::dict metadata_dict(const Metadata& meta) {
    py::dict d;
    d["tool"] = meta.tool;
    d["tool_version"] = meta.tool_version;
    d["source_path"] = meta.source_path;
    d["source_hash"] = meta.source_hash;
    py::dict parameters, statistics;
    for (const auto& [k, v] : meta.parameters) parameters[py::str(k)] = v;
    for (const auto& [k, v] : meta.statistics) statistics[py::str(k)] = v;
    d["parameters"] = parameters;
    d["statistics"] = statistics;
    return d;
}

}  // namespace kdpm::python

PYBIND11_MODULE(_kdpm, m) {
    namespace py = pybind11;
    m.doc() = "kdpm: SAH geometry kd-trees, VVH photon kd-trees and photon-mapped renders over NumPy arrays";
    m.attr("__version__") = kdpm::kdpm_version();
    // A corrupt, truncated or foreign file: the tools' one-line message, as a ValueError.
    py::register_exception<kdpm::FormatError>(m, "FormatError", PyExc_ValueError);
    kdpm::python::bind_geometry(m);
    kdpm::python::bind_photons(m);
    kdpm::python::bind_jobs(m);
    kdpm::python::bind_render(m);
}
