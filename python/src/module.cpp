// The `dtlab._dtlab` extension module: the C++ entry points of dtlab on numpy arrays. The Python
// package (python/dtlab/__init__.py) wraps the results in a Mesh and documents the API.
#include <pybind11/stl.h>

#include <cmath>
#include <limits>
#include <sstream>

#include "kernel/error.hpp"
#include "python/src/arrays.hpp"

namespace dtlab::python {

DoubleArray double_rows(const py::handle& obj, py::ssize_t columns, const char* what) {
  if (obj.is_none()) throw InputError(std::string(what) + ": an array is required, not None");
  const py::array raw = py::array::ensure(obj);
  if (!raw) throw InputError(std::string(what) + ": not convertible to a numpy array");
  const char kind = raw.dtype().kind();
  if (kind != 'f' && kind != 'i' && kind != 'u')
    throw InputError(std::string(what) + ": a float array is required, not dtype " + std::string(py::str(raw.dtype())));
  DoubleArray a = DoubleArray::ensure(raw);
  if (!a) throw py::error_already_set();
  if (a.ndim() == 1 && a.shape(0) == 0 && columns > 0) return DoubleArray(std::vector<py::ssize_t>{0, columns});
  if (a.ndim() != 2 || (columns > 0 && a.shape(1) != columns))
    throw InputError(std::string(what) + ": shape (n, " + std::to_string(columns) + ") expected");
  // Up front, before any algorithm: a NaN coordinate reached optimize as "triangle 1 is not
  // strictly counter-clockwise" and element_quality as a NaN quality.
  const py::ssize_t width = a.shape(1);
  for (py::ssize_t k = 0; k < a.shape(0) * width; ++k)
    if (!std::isfinite(a.data()[k])) {
      std::ostringstream text;
      text << what << ": row " << k / width << ", column " << k % width << " is " << a.data()[k]
           << " (" << what << "[" << k / width << ", " << k % width << "]): every value must be finite";
      throw InputError(text.str(), {static_cast<std::uint64_t>(k / width)});
    }
  return a;
}

DoubleArray point_rows(const py::handle& obj, int& dimension, const char* what) {
  DoubleArray a = double_rows(obj, 0, what);
  if (a.ndim() != 2 || (a.shape(1) != 2 && a.shape(1) != 3))
    throw InputError(std::string(what) + ": shape (n, 2) or (n, 3) expected");
  dimension = static_cast<int>(a.shape(1));
  return a;
}

IndexArray index_rows(const py::handle& obj, py::ssize_t columns, const char* what) {
  const std::string name(what);
  if (obj.is_none()) return IndexArray(std::vector<py::ssize_t>{0, columns});
  const py::array raw = py::array::ensure(obj);
  if (!raw) throw InputError(name + ": not convertible to a numpy array");
  if (raw.ndim() == 1 && raw.shape(0) == 0) return IndexArray(std::vector<py::ssize_t>{0, columns});
  if (raw.ndim() != 2 || raw.shape(1) != columns)
    throw InputError(name + ": shape (m, " + std::to_string(columns) + ") expected");
  const char kind = raw.dtype().kind();
  if (kind != 'i' && kind != 'u')
    throw InputError(name + ": an integer array is required, not dtype " + std::string(py::str(raw.dtype())));
  if (py::isinstance<IndexArray>(raw) && (raw.flags() & py::array::c_style)) return py::reinterpret_borrow<IndexArray>(raw);
  // Range check on a 64-bit copy, then the uint32 array the C++ side reads.
  const auto wide = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(raw);
  const std::int64_t* v = wide.data();
  std::vector<std::uint64_t> bad;
  for (py::ssize_t i = 0; i < wide.shape(0); ++i)
    for (py::ssize_t j = 0; j < columns; ++j)
      if (v[i * columns + j] < 0 || v[i * columns + j] >= std::int64_t{0xFFFFFFFE}) {
        bad.push_back(static_cast<std::uint64_t>(i));
        break;
      }
  if (!bad.empty())
    throw InputError(name + ": " + std::to_string(bad.size()) + " row(s) with an index below 0 or above 2^32 - 3, first row " +
                         std::to_string(bad.front()),
                     bad);
  IndexArray out(std::vector<py::ssize_t>{wide.shape(0), columns});
  std::uint32_t* o = out.mutable_data();
  for (py::ssize_t k = 0; k < wide.shape(0) * columns; ++k) o[k] = static_cast<std::uint32_t>(v[k]);
  return out;
}

std::vector<int> int_values(const py::handle& obj, py::ssize_t m, const char* what) {
  if (obj.is_none()) return {};
  const py::array raw = py::array::ensure(obj);
  const std::string name(what);
  if (!raw || raw.ndim() != 1 || raw.shape(0) != m)
    throw InputError(name + ": one integer per item expected (" + std::to_string(m) + ")");
  const char kind = raw.dtype().kind();
  if (kind != 'i' && kind != 'u' && !(kind == 'b' && m == 0))
    throw InputError(name + ": an integer array is required, not dtype " + std::string(py::str(raw.dtype())));
  const auto wide = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(raw);
  std::vector<int> out(static_cast<std::size_t>(m));
  std::vector<std::uint64_t> bad;
  for (py::ssize_t i = 0; i < m; ++i) {
    const std::int64_t x = wide.data()[i];
    if (x < std::numeric_limits<int>::min() + 1 || x > std::numeric_limits<int>::max()) bad.push_back(static_cast<std::uint64_t>(i));
    out[static_cast<std::size_t>(i)] = static_cast<int>(x);
  }
  if (!bad.empty()) throw InputError(name + ": values outside the 32-bit range", bad);
  return out;
}

py::dict predicate_stats_dict(const PredicateStats& stats) {
  py::dict out;
  for (std::size_t p = 0; p < kPredicateCount; ++p) {
    const StageCounts& c = stats.counts[p];
    py::dict d;
    d["semistatic"] = c.semistatic;
    d["adaptive"] = c.adaptive;
    d["exact"] = c.exact;
    d["perturbed"] = c.perturbed;
    d["gmp"] = c.gmp;
    d["calls"] = c.calls();
    out[to_string(static_cast<Predicate>(p))] = d;
  }
  return out;
}

py::object parse_json(const std::string& text) { return py::module_::import("json").attr("loads")(text); }

void check_signals() {
  if (PyErr_CheckSignals() != 0) throw py::error_already_set();
}

InterruptCheck python_interrupt_check() {
  return [] {
    py::gil_scoped_acquire gil;
    if (PyErr_Occurred() != nullptr) return true;  // a handler raised at an earlier check
    return PyErr_CheckSignals() != 0;
  };
}

namespace {

// The exception classes, made once at import and kept for the interpreter's life.
PyObject* g_error = nullptr;
PyObject* g_input_error = nullptr;
PyObject* g_parse_error = nullptr;
PyObject* g_internal_error = nullptr;

PyObject* new_exception(py::module_& m, const char* name, PyObject* bases, const char* doc) {
  const std::string qualified = std::string("dtlab.") + name;
  PyObject* type = PyErr_NewExceptionWithDoc(qualified.c_str(), doc, bases, nullptr);
  if (type == nullptr) throw py::error_already_set();
  m.attr(name) = py::reinterpret_borrow<py::object>(type);
  return type;
}

void raise(PyObject* type, const char* message, const py::dict& fields) {
  py::object exc = py::reinterpret_borrow<py::object>(type)(message);
  for (auto [k, v] : fields) exc.attr(k) = v;
  PyErr_SetObject(type, exc.ptr());
}

}  // namespace

void bind_errors(py::module_& m) {
  g_error = new_exception(m, "Error", PyExc_Exception, "Base of every error dtlab raises.");
  {
    py::tuple bases = py::make_tuple(py::handle(g_error), py::handle(PyExc_ValueError));
    g_input_error = new_exception(m, "InputError", bases.ptr(),
                                  "Input dtlab refuses; `items` lists the offending input indices (0-based).");
  }
  {
    py::tuple bases = py::make_tuple(py::handle(g_error), py::handle(PyExc_ValueError));
    g_parse_error = new_exception(m, "ParseError", bases.ptr(), "A file that cannot be read; `file` and `line` say where.");
  }
  {
    py::tuple bases = py::make_tuple(py::handle(g_error), py::handle(PyExc_RuntimeError));
    g_internal_error = new_exception(m, "InternalError", bases.ptr(), "A broken invariant inside dtlab (a bug): please report it.");
  }
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const InputError& e) {
      py::dict fields;
      fields["items"] = py::cast(e.items());
      raise(g_input_error, e.what(), fields);
    } catch (const ParseError& e) {
      py::dict fields;
      fields["file"] = e.file();
      fields["line"] = e.line();
      raise(g_parse_error, e.what(), fields);
    } catch (const Interrupted& e) {
      // The exception a signal handler raised (KeyboardInterrupt) is set: it goes on, with a
      // note saying where the run stopped. Without one, a check answered yes of its own accord.
      if (PyErr_Occurred() != nullptr) {
        PyObject *type = nullptr, *value = nullptr, *trace = nullptr;
        PyErr_Fetch(&type, &value, &trace);
        PyErr_NormalizeException(&type, &value, &trace);
        if (value != nullptr && PyObject_HasAttrString(value, "add_note")) {
          const std::string note = std::string("dtlab: ") + e.what();
          PyObject* r = PyObject_CallMethod(value, "add_note", "s", note.c_str());
          if (r == nullptr) PyErr_Clear();
          Py_XDECREF(r);
        }
        PyErr_Restore(type, value, trace);
      } else {
        raise(g_error, e.what(), py::dict());
      }
    } catch (const InternalError& e) {
      raise(g_internal_error, e.what(), py::dict());
    } catch (const Error& e) {
      raise(g_error, e.what(), py::dict());
    }
  });
}

}  // namespace dtlab::python

PYBIND11_MODULE(_dtlab, m) {
  m.doc() = "dtlab's C++ entry points on numpy arrays (use the `dtlab` package, which wraps them).";
  dtlab::python::bind_errors(m);
  dtlab::python::bind_triangulate(m);
  dtlab::python::bind_mesh2d(m);
  dtlab::python::bind_measures(m);
  pybind11::module_ predicates = m.def_submodule("predicates", "The staged exact predicates, vectorised.");
  dtlab::python::bind_predicates(predicates);
}
