#pragma once
// Input checks shared by the query façades. Each returns Ok or an InvalidArgument status naming the field.
#include <cmath>
#include <string>

#include "gq/geometry.h"
#include "gq/status.h"
#include "gq/tolerances.h"
#include "gq/transform.h"

namespace gq::detail {

template <class T> Status checkFinite(const Vec3<T>& v, const char* what) {
  if (!isFinite(v)) return Status::invalid(std::string(what) + " is not finite");
  return {};
}

template <class T> Status checkUnitDirection(const Vec3<T>& d, const char* what) {
  if (!isFinite(d)) return Status::invalid(std::string(what) + " is not finite");
  const double len = std::sqrt(double(d.squaredNorm()));
  if (std::abs(len - 1.0) > tol::kUnitDirection)
    return Status::invalid(std::string(what) + " is not a unit vector (length " + std::to_string(len) + ")");
  return {};
}

template <class T> Status checkPose(const Transform<T>& pose, const char* what) {
  if (!pose.isFinite()) return Status::invalid(std::string(what) + " is not finite");
  const double n = std::sqrt(double(pose.q.squaredNorm()));
  if (std::abs(n - 1.0) > tol::kUnitQuaternion)
    return Status::invalid(std::string(what) + " rotation is not a unit quaternion (norm " + std::to_string(n) + ")");
  return {};
}

template <class T> Status checkNonNegative(T x, const char* what) {
  if (!std::isfinite(x) && !(x > 0)) return Status::invalid(std::string(what) + " is NaN or -inf");
  if (!(x >= T(0))) return Status::invalid(std::string(what) + " is negative");
  return {};
}

// Geometry + pose, the pair every query takes.
template <class T> Status checkGeometryAndPose(const Geometry<T>& g, const Transform<T>& pose, const char* poseName) {
  Status s = validateGeometry(g);
  if (!s.ok()) return s;
  return checkPose(pose, poseName);
}

// Runs `body` (returning Status) and turns any escaping exception into InternalError: nothing throws out.
template <class F> Status guarded(F&& body) noexcept {
  try {
    return body();
  } catch (const std::exception& e) {
    return Status::internal(e.what());
  } catch (...) {
    return Status::internal("unknown exception");
  }
}

}  // namespace gq::detail
