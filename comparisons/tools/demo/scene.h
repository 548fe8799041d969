#pragma once
// The embedded default scene: one instance of every geometry type, built in code (no files).
#include <functional>
#include <string>
#include <vector>

#include "exact_ray.h"
#include "gq/geometry.h"
#include "gq/status.h"
#include "gq/transform.h"

namespace gq::demo {

// Exact local-frame ray distance (-1 = miss), or empty where no closed form exists.
using ExactRay = std::function<Real(const VecR& origin, const VecR& dir, Real maxDist)>;

template <class T> struct DemoShape {
  std::string name;
  Status status;  // why the shape could not be built (cooking not available, ...)
  Geometry<T> geom;
  Transform<T> pose;
  Vec3<double> localCenter = Vec3<double>::Zero();  // bounding sphere, for aiming rays
  double boundingRadius = 1;
  ExactRay exact;
};

template <class T> std::vector<DemoShape<T>> buildScene();

}  // namespace gq::demo
