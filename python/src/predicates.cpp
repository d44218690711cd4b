// dtlab.predicates: orient2d, incircle, orient3d, insphere (kernel/predicates.hpp) over arrays of
// points, each stage callable on its own (STYLE.md guideline 1) so that a fuzzing script can see
// which stage decides what, and this thread's stage counters (kernel/stats.hpp) readable.
#include <pybind11/stl.h>

#include <cstdint>

#include "kernel/coordinate_range.hpp"
#include "kernel/error.hpp"
#include "kernel/predicates.hpp"
#include "python/src/arrays.hpp"

namespace dtlab::python {

namespace {

// What a single stage returns where it cannot decide.
constexpr std::int8_t kUndecided = 2;

enum class Stage { Filtered, SemiStatic, Dynamic, Expansion, Exact };

Stage parse_stage(const std::string& s) {
  if (s == "filtered") return Stage::Filtered;
  if (s == "semi_static") return Stage::SemiStatic;
  if (s == "dynamic") return Stage::Dynamic;
  if (s == "expansion") return Stage::Expansion;
  if (s == "exact") return Stage::Exact;
  throw InputError("stage: one of 'filtered', 'semi_static', 'dynamic', 'expansion', 'exact', not '" + s + "'");
}

std::int8_t code(Sign s) { return static_cast<std::int8_t>(to_int(s)); }
std::int8_t code(FilteredSign s) { return s ? static_cast<std::int8_t>(to_int(*s)) : kUndecided; }

// Evaluates f on rows i of the N point arrays (each (n, dim), or one point (dim,) used for every
// row): an int8 array of n signs, or a Python int when every argument is a single point.
template <class V, std::size_t N, class F>
py::object vectorised(const std::array<py::handle, N>& args, F f) {
  constexpr py::ssize_t dim = sizeof(V) / sizeof(double);
  static const char* const names[] = {"a", "b", "c", "d", "e"};
  std::array<DoubleArray, N> arrays;
  std::array<const V*, N> data{};
  std::array<bool, N> single{};
  py::ssize_t n = -1;
  for (std::size_t k = 0; k < N; ++k) {
    const py::array raw = py::array::ensure(args[k]);
    if (!raw || (raw.dtype().kind() != 'f' && raw.dtype().kind() != 'i' && raw.dtype().kind() != 'u'))
      throw InputError(std::string(names[k]) + ": a float array of points is required");
    arrays[k] = DoubleArray::ensure(raw);
    const DoubleArray& a = arrays[k];
    if (a.ndim() == 1 && a.shape(0) == dim) {
      single[k] = true;
    } else if (a.ndim() == 2 && a.shape(1) == dim) {
      if (n >= 0 && a.shape(0) != n)
        throw InputError(std::string(names[k]) + ": " + std::to_string(a.shape(0)) + " points where the others have " + std::to_string(n));
      n = a.shape(0);
    } else {
      throw InputError(std::string(names[k]) + ": shape (n, " + std::to_string(dim) + ") or (" + std::to_string(dim) + ",) expected");
    }
    data[k] = reinterpret_cast<const V*>(a.data());
    check_coordinates(std::span<const V>(data[k], single[k] ? 1 : static_cast<std::size_t>(a.shape(0))),
                      std::string("argument ") + names[k] + ", point");
  }
  const bool scalar = n < 0;
  if (scalar) n = 1;
  std::vector<std::int8_t> out(static_cast<std::size_t>(n));
  {
    py::gil_scoped_release nogil;
    std::array<V, N> p;
    for (py::ssize_t i = 0; i < n; ++i) {
      for (std::size_t k = 0; k < N; ++k) p[k] = data[k][single[k] ? 0 : i];
      out[static_cast<std::size_t>(i)] = std::apply(f, p);
    }
  }
  if (scalar) return py::int_(out[0]);
  return adopt<std::int8_t>(std::move(out), 0);
}

py::object orient2d_py(py::handle a, py::handle b, py::handle c, const std::string& stage_name) {
  const std::array<py::handle, 3> args{a, b, c};
  switch (parse_stage(stage_name)) {
    case Stage::Filtered: return vectorised<Vec2, 3>(args, [](auto&... p) { return code(orient2d(p...)); });
    case Stage::SemiStatic: return vectorised<Vec2, 3>(args, [](auto&... p) { return code(stage::orient2d_semistatic(p...)); });
    case Stage::Dynamic: return vectorised<Vec2, 3>(args, [](auto&... p) { return code(stage::orient2d_adaptive(p...)); });
    case Stage::Expansion: return vectorised<Vec2, 3>(args, [](auto&... p) { return code(stage::orient2d_expansion(p...)); });
    case Stage::Exact: return vectorised<Vec2, 3>(args, [](auto&... p) { return code(stage::orient2d_exact(p...)); });
  }
  return py::none();
}

py::object incircle_py(py::handle a, py::handle b, py::handle c, py::handle d, const std::string& stage_name, bool perturbed) {
  const std::array<py::handle, 4> args{a, b, c, d};
  const Stage s = parse_stage(stage_name);
  if (perturbed && s != Stage::Filtered) throw InputError("perturbed: only with stage='filtered'");
  switch (s) {
    case Stage::Filtered:
      if (perturbed) return vectorised<Vec2, 4>(args, [](auto&... p) { return code(incircle_perturbed(p...)); });
      return vectorised<Vec2, 4>(args, [](auto&... p) { return code(incircle(p...)); });
    case Stage::SemiStatic: return vectorised<Vec2, 4>(args, [](auto&... p) { return code(stage::incircle_semistatic(p...)); });
    case Stage::Dynamic: return vectorised<Vec2, 4>(args, [](auto&... p) { return code(stage::incircle_adaptive(p...)); });
    case Stage::Expansion: return vectorised<Vec2, 4>(args, [](auto&... p) { return code(stage::incircle_expansion(p...)); });
    case Stage::Exact: return vectorised<Vec2, 4>(args, [](auto&... p) { return code(stage::incircle_exact(p...)); });
  }
  return py::none();
}

py::object orient3d_py(py::handle a, py::handle b, py::handle c, py::handle d, const std::string& stage_name) {
  const std::array<py::handle, 4> args{a, b, c, d};
  switch (parse_stage(stage_name)) {
    case Stage::Filtered: return vectorised<Vec3, 4>(args, [](auto&... p) { return code(orient3d(p...)); });
    case Stage::SemiStatic: return vectorised<Vec3, 4>(args, [](auto&... p) { return code(stage::orient3d_semistatic(p...)); });
    case Stage::Dynamic: return vectorised<Vec3, 4>(args, [](auto&... p) { return code(stage::orient3d_adaptive(p...)); });
    case Stage::Expansion: return vectorised<Vec3, 4>(args, [](auto&... p) { return code(stage::orient3d_expansion(p...)); });
    case Stage::Exact: return vectorised<Vec3, 4>(args, [](auto&... p) { return code(stage::orient3d_exact(p...)); });
  }
  return py::none();
}

py::object insphere_py(py::handle a, py::handle b, py::handle c, py::handle d, py::handle e, const std::string& stage_name,
                       bool perturbed) {
  const std::array<py::handle, 5> args{a, b, c, d, e};
  const Stage s = parse_stage(stage_name);
  if (perturbed && s != Stage::Filtered) throw InputError("perturbed: only with stage='filtered'");
  switch (s) {
    case Stage::Filtered:
      if (perturbed) return vectorised<Vec3, 5>(args, [](auto&... p) { return code(insphere_perturbed(p...)); });
      return vectorised<Vec3, 5>(args, [](auto&... p) { return code(insphere(p...)); });
    case Stage::SemiStatic: return vectorised<Vec3, 5>(args, [](auto&... p) { return code(stage::insphere_semistatic(p...)); });
    case Stage::Dynamic: return vectorised<Vec3, 5>(args, [](auto&... p) { return code(stage::insphere_adaptive(p...)); });
    case Stage::Expansion: return vectorised<Vec3, 5>(args, [](auto&... p) { return code(stage::insphere_expansion(p...)); });
    case Stage::Exact: return vectorised<Vec3, 5>(args, [](auto&... p) { return code(stage::insphere_exact(p...)); });
  }
  return py::none();
}

}  // namespace

void bind_predicates(py::module_& m) {
  m.attr("UNDECIDED") = kUndecided;
  m.def("orient2d", &orient2d_py, py::arg("a"), py::arg("b"), py::arg("c"), py::kw_only(), py::arg("stage") = "filtered");
  m.def("incircle", &incircle_py, py::arg("a"), py::arg("b"), py::arg("c"), py::arg("d"), py::kw_only(),
        py::arg("stage") = "filtered", py::arg("perturbed") = false);
  m.def("orient3d", &orient3d_py, py::arg("a"), py::arg("b"), py::arg("c"), py::arg("d"), py::kw_only(),
        py::arg("stage") = "filtered");
  m.def("insphere", &insphere_py, py::arg("a"), py::arg("b"), py::arg("c"), py::arg("d"), py::arg("e"), py::kw_only(),
        py::arg("stage") = "filtered", py::arg("perturbed") = false);
  m.def("stats", [] { return predicate_stats_dict(predicate_stats()); });
  m.def("reset_stats", [] { reset_predicate_stats(); });
}

}  // namespace dtlab::python
