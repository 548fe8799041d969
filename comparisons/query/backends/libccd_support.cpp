#include "libccd_support.h"

#include <cmath>

#include "native_shapes.h"

namespace gq::cases::native {
namespace {

double signOf(double x) { return x < 0 ? -1.0 : 1.0; }

// Sphere of radius r: r d / |d| (the centre for d = 0).
Vec3d sphereSupport(double r, const Vec3d& d) { return r * unitOrZero(d); }

// Disc of radius r in the YZ plane: r (0, dy, dz) / |(dy, dz)|.
Vec3d discSupport(double r, const Vec3d& d) { return r * unitOrZero(Vec3d(0, d.y(), d.z())); }

Vec3d localSupport(const SupportShape& s, const Vec3d& d) {
  switch (s.kind) {
    case ShapeKind::Sphere: return sphereSupport(s.radius, d);
    case ShapeKind::Capsule: return Vec3d(signOf(d.x()) * s.halfHeight, 0, 0) + sphereSupport(s.radius, d);
    case ShapeKind::Box: return Vec3d(signOf(d.x()), signOf(d.y()), signOf(d.z())).cwiseProduct(s.halfExtents);
    case ShapeKind::Cylinder: return Vec3d(signOf(d.x()) * s.halfHeight, 0, 0) + discSupport(s.radius, d);
    case ShapeKind::Cone: {
      // Apex at +halfHeight on X, base disc at -halfHeight: the better of the two candidates.
      const Vec3d apex(s.halfHeight, 0, 0);
      const Vec3d rim = Vec3d(-s.halfHeight, 0, 0) + discSupport(s.radius, d);
      return d.dot(apex) >= d.dot(rim) ? apex : rim;
    }
    case ShapeKind::Convex: {
      const Vec3d* best = &s.points.front();
      for (const Vec3d& p : s.points)
        if (p.dot(d) > best->dot(d)) best = &p;
      return *best;
    }
    default: return Vec3d::Zero();
  }
}

}  // namespace

Vec3d SupportShape::support(const Vec3d& d) const {
  return rotation * localSupport(*this, rotation.transpose() * d) + position;
}

Vec3d SupportShape::center() const {
  if (kind != ShapeKind::Convex) return position;  // symmetric shapes, and the cone's axis midpoint is inside
  Vec3d sum = Vec3d::Zero();
  for (const Vec3d& p : points) sum += p;
  return rotation * (sum / double(points.size())) + position;
}

bool makeSupportShape(const ShapeDesc& d, const PoseDesc& pose, SupportShape& out, std::string& error) {
  switch (d.kind) {
    case ShapeKind::Plane:
    case ShapeKind::Mesh:
    case ShapeKind::HeightField:
      error = std::string("unsupported: libccd needs a support mapping; ") + toString(d.kind) + " has none";
      return false;
    default: break;
  }
  out.kind = d.kind;
  out.radius = d.radius;
  out.halfHeight = d.halfHeight;
  out.halfExtents = d.halfExtents;
  if (d.kind == ShapeKind::Convex) {
    out.points = scaledPoints(d);
    if (out.points.empty()) {
      error = "convex shape without points";
      return false;
    }
  }
  out.rotation = pose.q.toRotationMatrix();
  out.position = pose.p;
  return true;
}

}  // namespace gq::cases::native
