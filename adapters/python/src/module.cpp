// The geomquery extension module: common helpers and the module definition.
#include <cmath>

#include "common.h"

namespace gqpy {

namespace {
PyObject* gUnsupportedError = nullptr;
PyObject* gNotConvergedError = nullptr;
}  // namespace

const char* GeometryObject::typeName() const { return gq::toString(f32 ? f.type() : d.type()); }

void raiseStatus(const gq::Status& s, const std::string& context) {
  std::string message = s.detailedMessage();
  if (!context.empty()) message = context + ": " + message;
  PyObject* type = PyExc_ValueError;
  switch (s.code) {
    case gq::StatusCode::Unsupported: type = gUnsupportedError; break;
    case gq::StatusCode::NotConverged: type = gNotConvergedError; break;
    case gq::StatusCode::FileError: type = PyExc_FileNotFoundError; break;
    case gq::StatusCode::InternalError: type = PyExc_RuntimeError; break;
    default: break;
  }
  PyErr_SetString(type, message.c_str());
  throw py::error_already_set();
}

void registerExceptions(py::module_& m) {
  gUnsupportedError = PyErr_NewExceptionWithDoc(
      "geomquery.UnsupportedError", "The query is not defined for this pair of geometry types.",
      PyExc_NotImplementedError, nullptr);
  gNotConvergedError = PyErr_NewExceptionWithDoc(
      "geomquery.NotConvergedError", "An iterative solver stopped without a certified answer.", PyExc_RuntimeError,
      nullptr);
  m.add_object("UnsupportedError", py::handle(gUnsupportedError));
  m.add_object("NotConvergedError", py::handle(gNotConvergedError));
}

bool isFloat32(const py::handle& dtype) {
  if (dtype.is_none()) return false;
  const py::dtype dt = py::dtype::from_args(py::reinterpret_borrow<py::object>(dtype));
  if (dt.is(py::dtype::of<float>()) || dt.equal(py::dtype::of<float>())) return true;
  if (dt.equal(py::dtype::of<double>())) return false;
  throw py::type_error("dtype must be float32 or float64, not " + dtypeText(dt));
}

bool arrayIsFloat32(const py::handle& obj, const char* what) {
  if (!py::isinstance<py::array>(obj)) return false;
  const py::dtype dt = py::reinterpret_borrow<py::array>(obj).dtype();
  if (dt.equal(py::dtype::of<float>())) return true;
  const char kind = dt.kind();
  if (dt.equal(py::dtype::of<double>()) || kind == 'i' || kind == 'u' || kind == 'b') return false;
  throw py::type_error(std::string(what) + ": dtype must be float32 or float64, not " + dtypeText(dt));
}

template <class T> py::array_t<T> rowsArray(const py::handle& obj, py::ssize_t cols, const char* what) {
  py::array arr;
  if (py::isinstance<py::array>(obj)) {
    arr = py::reinterpret_borrow<py::array>(obj);
    const bool want32 = std::is_same_v<T, float>;
    if (arrayIsFloat32(obj, what) != want32)
      throw py::type_error(std::string(what) + ": dtype " + dtypeText(arr.dtype()) + " mixed with " +
                           (want32 ? "float32" : "float64") + " geometry (convert with .astype)");
    if (!arr.dtype().equal(py::dtype::of<T>())) arr = py::array_t<T, py::array::c_style | py::array::forcecast>(arr);
  } else {
    arr = py::array_t<T, py::array::c_style | py::array::forcecast>::ensure(obj);
    if (!arr) {
      PyErr_Clear();
      throw py::type_error(std::string(what) + ": expected an array of numbers");
    }
  }
  const auto shapeText = [&] {
    std::string s = "(";
    for (py::ssize_t i = 0; i < arr.ndim(); ++i) s += (i ? ", " : "") + std::to_string(arr.shape(i));
    return s + (arr.ndim() == 1 ? ",)" : ")");
  };
  if (cols == 0) {
    if (arr.ndim() != 1) throw py::value_error(std::string(what) + ": expected shape (N,), got " + shapeText());
  } else if (arr.ndim() != 2 || arr.shape(1) != cols) {
    throw py::value_error(std::string(what) + ": expected shape (N, " + std::to_string(cols) + "), got " +
                          shapeText());
  }
  const py::ssize_t inner = cols == 0 ? 0 : 1;
  if (arr.shape(inner) > 1 && arr.strides(inner) != py::ssize_t(sizeof(T)))
    throw py::value_error(std::string(what) +
                          ": the last axis is not contiguous (pass np.ascontiguousarray(...) instead of a view)");
  if (arr.shape(0) > 0 && (arr.strides(0) <= 0 ||
                           reinterpret_cast<std::uintptr_t>(arr.data()) % alignof(T) != 0 ||
                           arr.strides(0) % py::ssize_t(alignof(T)) != 0))
    throw py::value_error(std::string(what) + ": rows must be stored forward and aligned (pass np.ascontiguousarray)");
  return py::reinterpret_borrow<py::array_t<T>>(arr);
}
template py::array_t<float> rowsArray<float>(const py::handle&, py::ssize_t, const char*);
template py::array_t<double> rowsArray<double>(const py::handle&, py::ssize_t, const char*);

template <class T> gq::Vec3<T> vec3(const py::handle& obj, const char* what) {
  if (PyTuple_Check(obj.ptr()) || PyList_Check(obj.ptr())) {
    const py::sequence seq = py::reinterpret_borrow<py::sequence>(obj);
    if (seq.size() != 3) throw py::value_error(std::string(what) + ": expected 3 numbers");
    gq::Vec3<T> v;
    for (int i = 0; i < 3; ++i) {
      const double x = PyFloat_AsDouble(seq[i].ptr());
      if (x == -1.0 && PyErr_Occurred()) {
        PyErr_Clear();
        throw py::type_error(std::string(what) + ": expected 3 numbers");
      }
      v[i] = T(x);
    }
    return v;
  }
  const auto arr = py::array_t<double, py::array::forcecast>::ensure(obj);
  if (!arr) {
    PyErr_Clear();
    throw py::type_error(std::string(what) + ": expected 3 numbers");
  }
  if (arr.size() != 3 || arr.ndim() != 1) throw py::value_error(std::string(what) + ": expected shape (3,)");
  return gq::Vec3<T>(T(arr.at(0)), T(arr.at(1)), T(arr.at(2)));
}
template gq::Vec3<float> vec3<float>(const py::handle&, const char*);
template gq::Vec3<double> vec3<double>(const py::handle&, const char*);

gq::Transform<double> poseFromSequence(const py::handle& obj, const char* what) {
  const auto arr = py::array_t<double, py::array::forcecast>::ensure(obj);
  if (!arr) {
    PyErr_Clear();
    throw py::type_error(std::string(what) + ": expected a Pose, None or 7 numbers (px, py, pz, qx, qy, qz, qw)");
  }
  if (arr.ndim() != 1 || arr.size() != 7)
    throw py::value_error(std::string(what) + ": expected 7 numbers (px, py, pz, qx, qy, qz, qw)");
  const double* v = arr.data();
  return gq::Transform<double>(gq::Vec3<double>(v[0], v[1], v[2]), gq::Quat<double>(v[6], v[3], v[4], v[5]));
}

template <class T> gq::Transform<T> pose(const py::handle& obj, const char* what) {
  if (obj.is_none()) return gq::Transform<T>();
  if (py::isinstance<Pose>(obj)) return obj.cast<const Pose&>().get<T>();
  return poseFromSequence(obj, what).template cast<T>();
}
template gq::Transform<float> pose<float>(const py::handle&, const char*);
template gq::Transform<double> pose<double>(const py::handle&, const char*);

void requireSameDtype(const GeometryObject& a, const GeometryObject& b, const char* what) {
  if (a.f32 != b.f32)
    throw py::type_error(std::string(what) + ": mixing a " + a.dtypeName() + " and a " + b.dtypeName() +
                         " geometry (make both with the same dtype)");
}

}  // namespace gqpy

PYBIND11_MODULE(_geomquery, m) {
  m.doc() = "GeomQuery: geometry queries (raycast, sweep, overlap, penetration, distance) in float32 and float64.";
  gqpy::registerExceptions(m);
  gqpy::bindGeometry(m);
  gqpy::bindQueries(m);
  gqpy::bindBatches(m);
  gqpy::bindScene(m);
  gqpy::bindUrdf(m);
}
