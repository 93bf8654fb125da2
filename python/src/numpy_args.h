#pragma once
// The module's checks of what Python hands it, and its zero-copy views: every array argument is
// checked for shape, dtype and finiteness before any kernel reads it (a clean exception, never a
// crash), and every view of a mapped file is read-only with the file object as its base, so the
// mapping outlives the last array that points into it.
#include <cstdint>
#include <string>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

namespace kdpm::python {

namespace py = pybind11;

using FloatRows = py::array_t<float, py::array::c_style | py::array::forcecast>;

// `value` as an (N, 3) C-ordered float32 array (converted from float64 when needed). TypeError
// for a non-float dtype, ValueError for another shape or a NaN or infinity.
FloatRows points_arg(const py::handle& value, const char* name);

// One float per row: None -> `fallback` for all, a number, or an (N,) float array. ValueError for
// NaN, a negative value or the wrong length.
std::vector<float> per_row_arg(const py::handle& value, const char* name, std::size_t rows, float fallback);

// A read-only view of `count` records of `dtype` at `data` (shape {count} + `inner`), kept alive
// by `owner`; an empty array when there are none.
py::array file_view(const py::dtype& dtype, std::uint64_t count, const void* data, const py::handle& owner,
                    const std::vector<py::ssize_t>& inner = {});

// ValueError "NAME V is outside LO..HI" unless lo <= value <= hi.
void check_range(const char* name, long long value, long long lo, long long hi);
void check_real_range(const char* name, double value, double lo, double hi);

// A new C-ordered array of `shape`, to be filled by a kernel with the GIL released.
template <class T>
py::array_t<T> new_array(const std::vector<py::ssize_t>& shape) {
    return py::array_t<T>(shape);
}

}  // namespace kdpm::python
