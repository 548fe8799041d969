#pragma once
// Result objects of the single queries (double precision fields whatever the geometry's dtype).
#include <cstdint>

#include "common.h"
#include "gq/hit.h"
#include "gq/query.h"

namespace gqpy {

inline std::int64_t faceIndex(std::uint32_t i) { return i == gq::kInvalidFaceIndex ? -1 : std::int64_t(i); }

struct PyRaycastHit {
  double distance = 0, u = 0, v = 0;
  gq::Vec3<double> position, normal;
  std::int64_t faceIndex = -1;
  template <class T> static PyRaycastHit from(const gq::RaycastHit<T>& h) {
    PyRaycastHit r;
    r.distance = double(h.distance);
    r.position = h.position.template cast<double>();
    r.normal = h.normal.template cast<double>();
    r.faceIndex = gqpy::faceIndex(h.faceIndex);
    r.u = double(h.u);
    r.v = double(h.v);
    return r;
  }
};

struct PySweepHit {
  double distance = 0;
  gq::Vec3<double> position, normal;
  std::int64_t faceIndex = -1;
  bool initialOverlap = false;
  template <class T> static PySweepHit from(const gq::SweepHit<T>& h) {
    PySweepHit r;
    r.distance = double(h.distance);
    r.position = h.position.template cast<double>();
    r.normal = h.normal.template cast<double>();
    r.faceIndex = gqpy::faceIndex(h.faceIndex);
    r.initialOverlap = h.initialOverlap;
    return r;
  }
};

struct PyPenetration {
  bool penetrating = false;
  gq::Vec3<double> direction = gq::Vec3<double>::Zero();
  double depth = 0;
  std::uint32_t iterations = 0;
  template <class T> static PyPenetration from(const gq::PenetrationResult<T>& p) {
    PyPenetration r;
    r.penetrating = p.penetrating;
    r.direction = p.direction.template cast<double>();
    r.depth = double(p.depth);
    return r;
  }
};

struct PyDistance {
  double distance = 0;
  gq::Vec3<double> point0, point1, normal;
  template <class T> static PyDistance from(const gq::DistanceResult<T>& d) {
    PyDistance r;
    r.distance = double(d.distance);
    r.point0 = d.point0.template cast<double>();
    r.point1 = d.point1.template cast<double>();
    r.normal = d.normal.template cast<double>();
    return r;
  }
};

}  // namespace gqpy
