#include "python/src/numpy_args.h"

#include <cmath>
#include <sstream>

namespace kdpm::python {

namespace {

std::string shape_text(const py::array& a) {
    std::ostringstream s;
    s << "(";
    for (py::ssize_t i = 0; i < a.ndim(); ++i) s << (i ? ", " : "") << a.shape(i);
    s << (a.ndim() == 1 ? ",)" : ")");
    return s.str();
}

py::array float_array(const py::handle& value, const char* name, const char* expected) {
    py::array a = py::array::ensure(value);
    if (!a) throw py::type_error(std::string(name) + " must be an array of " + expected);
    const char kind = a.dtype().kind();
    if (kind != 'f' || (a.itemsize() != 4 && a.itemsize() != 8))
        throw py::type_error(std::string(name) + " must hold float32 or float64 values, not " +
                             py::str(a.dtype()).cast<std::string>());
    return a;
}

}  // namespace

FloatRows points_arg(const py::handle& value, const char* name) {
    py::array a = float_array(value, name, "shape (N, 3)");
    if (a.ndim() != 2 || a.shape(1) != 3)
        throw py::value_error(std::string(name) + " must have shape (N, 3), not " + shape_text(a));
    FloatRows rows = FloatRows::ensure(a);
    if (!rows) throw py::error_already_set();
    const float* p = rows.data();
    const std::size_t n = static_cast<std::size_t>(rows.size());
    for (std::size_t i = 0; i < n; ++i)
        if (!std::isfinite(p[i]))
            throw py::value_error(std::string(name) + " holds a NaN or infinity in row " + std::to_string(i / 3));
    return rows;
}

std::vector<float> per_row_arg(const py::handle& value, const char* name, std::size_t rows, float fallback) {
    if (value.is_none()) return std::vector<float>(rows, fallback);
    std::vector<float> out;
    if (py::isinstance<py::float_>(value) || py::isinstance<py::int_>(value)) {
        out.assign(rows, value.cast<float>());
    } else {
        py::array a = float_array(value, name, "shape (N,)");
        if (a.ndim() != 1 || static_cast<std::size_t>(a.shape(0)) != rows)
            throw py::value_error(std::string(name) + " must have shape (" + std::to_string(rows) + ",), not " +
                                  shape_text(a));
        auto f = py::array_t<float, py::array::c_style | py::array::forcecast>::ensure(a);
        out.assign(f.data(), f.data() + rows);
    }
    for (std::size_t i = 0; i < out.size(); ++i)
        if (std::isnan(out[i]) || out[i] < 0.0f)
            throw py::value_error(std::string(name) + " must be >= 0 and not NaN (row " + std::to_string(i) + ")");
    return out;
}

py::array file_view(const py::dtype& dtype, std::uint64_t count, const void* data, const py::handle& owner,
                    const std::vector<py::ssize_t>& inner) {
    std::vector<py::ssize_t> shape{static_cast<py::ssize_t>(count)};
    shape.insert(shape.end(), inner.begin(), inner.end());
    if (count == 0 || data == nullptr) {
        shape[0] = 0;
        return py::array(dtype, shape);
    }
    py::array view(dtype, shape, std::vector<py::ssize_t>{}, data, owner);
    view.attr("flags").attr("writeable") = false;
    return view;
}

void check_range(const char* name, long long value, long long lo, long long hi) {
    if (value < lo || value > hi)
        throw py::value_error(std::string(name) + " " + std::to_string(value) + " is outside " + std::to_string(lo) +
                              ".." + std::to_string(hi));
}

void check_real_range(const char* name, double value, double lo, double hi) {
    if (!(value >= lo && value <= hi)) {
        std::ostringstream s;
        s << name << " " << value << " is outside " << lo << ".." << hi;
        throw py::value_error(s.str());
    }
}

}  // namespace kdpm::python
