#pragma once
// Shared pieces of the geomquery extension: the geometry object (a prepared shape in float or double), poses,
// Status -> Python exception, and numpy array checks.
#include <pybind11/eigen.h>  // in every file: one type_caster for Eigen types across the module
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstdint>
#include <memory>
#include <string>
#include <utility>

#include "gq/cooking.h"
#include "gq/geometry.h"
#include "gq/shape.h"
#include "gq/status.h"
#include "gq/transform.h"

namespace gqpy {

namespace py = pybind11;

// A geometry as Python holds it: validated once (gq::Shape) in the scalar type its inputs chose.
struct GeometryObject {
  bool f32 = false;
  gq::Shape<double> d;
  gq::Shape<float> f;
  bool hasCookReport = false;
  gq::MeshCookReport cookReport;
  // Custom shapes defined in Python: the first error their callables raised (see custom_callbacks.h).
  std::shared_ptr<struct CallbackErrors> callbackErrors;

  template <class T> const gq::Shape<T>& shape() const {
    if constexpr (std::is_same_v<T, float>) return f; else return d;
  }
  template <class T> const gq::Geometry<T>& geometry() const { return shape<T>().geometry(); }
  const char* typeName() const;
  std::string dtypeName() const { return f32 ? "float32" : "float64"; }
};

// A pose: position + unit quaternion (x, y, z, w), kept in both scalar types so one pose serves either geometry.
struct Pose {
  gq::Transform<double> d;
  gq::Transform<float> f;
  Pose() = default;
  explicit Pose(const gq::Transform<double>& t) : d(t), f(t.cast<float>()) {}
  template <class T> const gq::Transform<T>& get() const {
    if constexpr (std::is_same_v<T, float>) return f; else return d;
  }
};

// Raises the Python exception for a failed Status: ValueError (invalid argument, degenerate mesh, parse error),
// UnsupportedError (an unsupported pair or geometry), NotConvergedError, FileNotFoundError, RuntimeError.
[[noreturn]] void raiseStatus(const gq::Status& s, const std::string& context = std::string());
inline void check(const gq::Status& s, const char* context = nullptr) {
  if (!s.ok()) raiseStatus(s, context ? std::string(context) : std::string());
}
void registerExceptions(py::module_& m);

inline std::string dtypeText(const py::dtype& dt) { return py::cast<std::string>(dt.attr("name")); }

// Scalar type from a dtype-like (None: float64); TypeError for anything but float32 and float64.
bool isFloat32(const py::handle& dtype);
// The scalar type of an array-like: float32 arrays are float32; float64, integer and Python sequences are float64;
// other dtypes: TypeError naming `what`.
bool arrayIsFloat32(const py::handle& obj, const char* what);

// A float array of the given scalar type checked for shape (N, cols) (cols 0: a 1-D array of N) and a contiguous last
// axis; rows may be strided. TypeError for a wrong dtype, ValueError for a wrong shape or layout.
template <class T> py::array_t<T> rowsArray(const py::handle& obj, py::ssize_t cols, const char* what);

// One 3-vector from a sequence or an array of 3 numbers (ValueError otherwise; NaN passes: the queries reject it).
template <class T> gq::Vec3<T> vec3(const py::handle& obj, const char* what);
// None (identity), a Pose, or 7 numbers (px, py, pz, qx, qy, qz, qw).
template <class T> gq::Transform<T> pose(const py::handle& obj, const char* what);
gq::Transform<double> poseFromSequence(const py::handle& obj, const char* what);

template <class T> py::array_t<T> newArray(std::initializer_list<py::ssize_t> shape) {
  return py::array_t<T>(std::vector<py::ssize_t>(shape));
}

// Same scalar type for both geometries (mixing is an error).
void requireSameDtype(const GeometryObject& a, const GeometryObject& b, const char* what);

void bindGeometry(py::module_& m);
void bindQueries(py::module_& m);
void bindBatches(py::module_& m);
void bindScene(py::module_& m);
void bindUrdf(py::module_& m);

}  // namespace gqpy
