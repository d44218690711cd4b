// What every binding file of the Python module shares: numpy arrays in (viewed in place when
// they are C-contiguous float64 / uint32 already, converted once otherwise) and out (a C++
// vector handed over to numpy without a copy), and the conversion of report strings to dicts.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "kernel/interrupt.hpp"
#include "kernel/stats.hpp"
#include "kernel/vec.hpp"

namespace dtlab::python {

namespace py = pybind11;

using DoubleArray = py::array_t<double, py::array::c_style | py::array::forcecast>;
using IndexArray = py::array_t<std::uint32_t, py::array::c_style>;

// An (n, columns) float64 C-contiguous array: `obj` itself when it is one, else a converted
// copy. Throws InputError naming `what` for another shape or a non-numeric dtype, and naming
// `what`, the row and the column (0-based, as numpy indexes) for a value that is not finite.
DoubleArray double_rows(const py::handle& obj, py::ssize_t columns, const char* what);
// An (n, 2) or (n, 3) float64 array of points; `dimension` receives 2 or 3.
DoubleArray point_rows(const py::handle& obj, int& dimension, const char* what = "points");
// An (m, columns) uint32 array of indices: `obj` itself when it is one, else converted after
// checking that it holds integers in [0, 2^32 - 2] (InputError naming the offending rows).
IndexArray index_rows(const py::handle& obj, py::ssize_t columns, const char* what);
// A 1-D int32 array of m references (None: empty). InputError for another length.
std::vector<int> int_values(const py::handle& obj, py::ssize_t m, const char* what);

template <class V>
std::span<const V> as_points(const DoubleArray& a) {
  static_assert(sizeof(V) == sizeof(double) * (sizeof(V) / sizeof(double)));
  return {reinterpret_cast<const V*>(a.data()), static_cast<std::size_t>(a.shape(0))};
}
template <std::size_t K>
std::span<const std::array<std::uint32_t, K>> as_cells(const IndexArray& a) {
  return {reinterpret_cast<const std::array<std::uint32_t, K>*>(a.data()), static_cast<std::size_t>(a.shape(0))};
}

// Hands `v` over to numpy without copying: an array of dtype Elem and shape (v.size(), columns)
// (columns == 0: 1-D), owned by a capsule that deletes the vector.
template <class Elem, class T>
py::array adopt(std::vector<T>&& v, py::ssize_t columns) {
  static_assert(sizeof(T) % sizeof(Elem) == 0);
  const auto rows = static_cast<py::ssize_t>(v.size());
  const py::ssize_t per = static_cast<py::ssize_t>(sizeof(T) / sizeof(Elem));
  std::vector<py::ssize_t> shape = columns == 0 ? std::vector<py::ssize_t>{rows * per}
                                                : std::vector<py::ssize_t>{rows * per / columns, columns};
  if (v.empty()) return py::array_t<Elem>(shape);
  auto* owned = new std::vector<T>(std::move(v));
  py::capsule owner(owned, [](void* p) { delete static_cast<std::vector<T>*>(p); });
  return py::array_t<Elem>(shape, reinterpret_cast<const Elem*>(owned->data()), owner);
}

// {"orient2d": {"semistatic": .., "adaptive": .., "exact": .., "perturbed": .., "gmp": ..}, ...}
py::dict predicate_stats_dict(const PredicateStats& stats);
// json.loads(text): the reports' own JSON (verify/, mesh/mesh_quality.hpp) as a dict.
py::object parse_json(const std::string& text);
// Raises KeyboardInterrupt (through py::error_already_set) if a signal came while C++ ran.
void check_signals();
// The InterruptCheck (kernel/interrupt.hpp) of a long call that runs with the GIL released: it
// takes the GIL and runs the interpreter's signal handlers; when one raises (Ctrl-C:
// KeyboardInterrupt), the exception stays set and the check answers yes, so the algorithm stops
// by throwing Interrupted, which the module's translator turns back into that exception.
InterruptCheck python_interrupt_check();

// The binding groups, one file each.
void bind_errors(py::module_& m);
void bind_triangulate(py::module_& m);  // delaunay, constrain
void bind_mesh2d(py::module_& m);       // mesh, optimize
void bind_measures(py::module_& m);     // quality, verify, Medit io
void bind_predicates(py::module_& m);   // the predicates and their counters

}  // namespace dtlab::python
