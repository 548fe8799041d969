// Capsule and cylinder fits about candidate axes. For an axis, the cross-section is the smallest circle enclosing
// the hull vertices projected on the plane normal to it (exact, Welzl). The cylinder then spans the vertices'
// axial extent: the minimum-volume enclosing cylinder for that axis. The capsule keeps that radius (the smallest
// possible for the axis) and the shortest segment covering every vertex: a vertex at axial t and radial distance
// r is covered when t lies within sqrt(R^2 - r^2) of the segment; a larger radius could shorten the segment, so
// the capsule is the smallest of least radius for the axis. The axes tried: the columns of every candidate frame
// (the minimum-volume box's, the principal axes, the mesh frame); the least volume wins.
#include <cmath>
#include <limits>

#include "fit/fit_internal.h"

namespace gq::fit {
namespace {

struct Section {
  Vec3d centre;  // on the axis, at axial 0
  double radius;
  double lo, hi;  // axial extent of the vertices
};

Mat3d frameAbout(const Vec3d& axis) {
  Mat3d r;
  r.col(0) = axis.normalized();
  const Vec3d helper = std::abs(r(0, 0)) < 0.9 ? Vec3d::UnitX() : Vec3d::UnitY();
  r.col(1) = r.col(0).cross(helper).normalized();
  r.col(2) = r.col(0).cross(r.col(1));
  return r;
}

Section sectionAbout(const std::vector<Vec3d>& hull, const Mat3d& frame) {
  std::vector<Eigen::Vector2d> plane;
  plane.reserve(hull.size());
  Section s{Vec3d::Zero(), 0, std::numeric_limits<double>::max(), -std::numeric_limits<double>::max()};
  for (const Vec3d& p : hull) {
    const Vec3d l = frame.transpose() * p;
    plane.emplace_back(l.y(), l.z());
    s.lo = std::min(s.lo, l.x());
    s.hi = std::max(s.hi, l.x());
  }
  Eigen::Vector2d c;
  enclosingCircle(plane, c, s.radius);
  s.centre = frame * Vec3d(0, c.x(), c.y());
  return s;
}

std::vector<Mat3d> axisFrames(const std::vector<Mat3d>& candidates) {
  std::vector<Mat3d> frames;
  for (const Mat3d& f : candidates)
    for (int i = 0; i < 3; ++i) frames.push_back(frameAbout(f.col(i)));
  return frames;
}

}  // namespace

Solid fitCylinder(const std::vector<Vec3d>& hull, const std::vector<Mat3d>& axes) {
  Solid best;
  double bestVolume = std::numeric_limits<double>::infinity();
  for (const Mat3d& frame : axisFrames(axes)) {
    const Section s = sectionAbout(hull, frame);
    const double volume = M_PI * s.radius * s.radius * (s.hi - s.lo);
    if (volume >= bestVolume) continue;
    bestVolume = volume;
    best.kind = Solid::Kind::Cylinder;
    best.rotation = frame;
    best.radius = s.radius;
    best.halfHeight = 0.5 * (s.hi - s.lo);
    best.centre = s.centre + frame.col(0) * (0.5 * (s.lo + s.hi));
  }
  return best;
}

Solid fitCapsule(const std::vector<Vec3d>& hull, const std::vector<Mat3d>& axes) {
  Solid best;
  double bestVolume = std::numeric_limits<double>::infinity();
  for (const Mat3d& frame : axisFrames(axes)) {
    const Section s = sectionAbout(hull, frame);
    const Vec3d axis = frame.col(0);
    double a = std::numeric_limits<double>::max(), b = -std::numeric_limits<double>::max();
    for (const Vec3d& p : hull) {
      const double t = (p - s.centre).dot(axis);
      const double r2 = (p - s.centre - t * axis).squaredNorm();
      const double reach = std::sqrt(std::max(0.0, s.radius * s.radius - r2));
      a = std::min(a, t + reach);
      b = std::max(b, t - reach);
    }
    if (b < a) a = b = 0.5 * (a + b);
    const double volume = M_PI * s.radius * s.radius * ((b - a) + 4.0 / 3.0 * s.radius);
    if (volume >= bestVolume) continue;
    bestVolume = volume;
    best.kind = Solid::Kind::Capsule;
    best.rotation = frame;
    best.radius = s.radius;
    best.halfHeight = 0.5 * (b - a);
    best.centre = s.centre + axis * (0.5 * (a + b));
  }
  // The segment ends were placed for this radius; rounding can leave a vertex a hair outside, so the radius grows
  // to the largest distance of a vertex from the segment.
  double reach = best.radius;
  for (const Vec3d& p : hull) {
    const double t = std::clamp((p - best.centre).dot(best.rotation.col(0)), -best.halfHeight, best.halfHeight);
    reach = std::max(reach, (p - best.centre - t * best.rotation.col(0)).norm());
  }
  best.radius = reach;
  return best;
}

}  // namespace gq::fit
