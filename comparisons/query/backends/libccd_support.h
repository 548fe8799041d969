#pragma once
// Support mappings of gq's convex shapes in world space, for libccd (s(d) = argmax over the shape of dot(d, x)).
#include <string>
#include <vector>

#include "case.h"

namespace gq::cases::native {

struct SupportShape {
  ShapeKind kind = ShapeKind::Sphere;
  double radius = 0, halfHeight = 0;
  Vec3d halfExtents = Vec3d::Zero();
  std::vector<Vec3d> points;  // convex: scaled hull points
  Mat3<double> rotation = Mat3<double>::Identity();
  Vec3d position = Vec3d::Zero();

  // World-space support point in direction `d` (need not be unit).
  Vec3d support(const Vec3d& d) const;
  // A point strictly inside (MPR's starting portal).
  Vec3d center() const;
};

// False with "unsupported: ..." for shapes without a support mapping (plane, mesh, heightfield).
bool makeSupportShape(const ShapeDesc& d, const PoseDesc& pose, SupportShape& out, std::string& error);

}  // namespace gq::cases::native
