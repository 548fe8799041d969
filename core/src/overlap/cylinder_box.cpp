// Cylinder/box overlap certificates, in the box's frame (box centred at the origin, half extents h; cylinder centre
// c, unit axis a, radius r, half height hh). GJK decides every pair; most pairs have a cheaper proof:
//  - apart: a separating axis among the box's face normals e_k, the cylinder's axis a and the edge directions
//    a x e_k. The cylinder's half-width along a unit n is r sqrt(1 - (a.n)^2) + hh |a.n| (its rim disks' extent plus
//    the axis'); the box's is sum_k h_k |n_k|. A gap up to GJK's tolerance for the pair is left to GJK, which
//    calls it touching.
//  - overlapping: a point in both among a few candidates: either centre, the box point nearest the cylinder's
//    centre, the axis point nearest the box's centre and the box point nearest that one.
// Neither (~4 % of random poses of unit-sized shapes overlapping half the time): Unknown, GJK decides.
#include <algorithm>
#include <cmath>

#include "gjk/gjk.h"
#include "overlap/overlap.h"

namespace gq::kernels {
using namespace detail;  // core's internal helpers
namespace {

template <class T> struct CylinderInBox {
  Vec3<T> c, a;
  T r, hh;
  Vec3<T> h;
};

// |c.n| beyond both half-widths (n unit; an = |a.n|) by more than the tolerance.
template <class T> bool apartAlong(const CylinderInBox<T>& s, T cn, T an, T boxHalfWidth, T tolerance) {
  const T cylinderHalfWidth = s.r * std::sqrt(std::max(T(0), T(1) - an * an)) + s.hh * an;
  return std::abs(cn) - cylinderHalfWidth - boxHalfWidth > tolerance;
}

template <class T> bool separatingAxis(const CylinderInBox<T>& s, T tolerance) {
  for (int k = 0; k < 3; ++k)
    if (apartAlong(s, s.c[k], std::abs(s.a[k]), s.h[k], tolerance)) return true;
  if (apartAlong(s, s.c.dot(s.a), T(1), s.h.dot(s.a.cwiseAbs()), tolerance)) return true;
  for (int k = 0; k < 3; ++k) {
    const Vec3<T> edge = s.a.cross(Vec3<T>::Unit(k));  // |a x e_k|^2 = 1 - a_k^2; near 0: the face axis covers it
    const T lengthSq = edge.squaredNorm();
    if (!(lengthSq > T(1e-6))) continue;
    const Vec3<T> n = edge / std::sqrt(lengthSq);
    if (apartAlong(s, s.c.dot(n), T(0), s.h.dot(n.cwiseAbs()), tolerance)) return true;
  }
  return false;
}

template <class T> bool inBox(const CylinderInBox<T>& s, const Vec3<T>& p) {
  return (p.cwiseAbs() - s.h).maxCoeff() <= T(0);
}

template <class T> bool inCylinder(const CylinderInBox<T>& s, const Vec3<T>& p) {
  const Vec3<T> d = p - s.c;
  const T t = d.dot(s.a);
  return std::abs(t) <= s.hh && d.squaredNorm() - t * t <= s.r * s.r;
}

template <class T> bool commonPoint(const CylinderInBox<T>& s) {
  const auto inBoth = [&](const Vec3<T>& p) { return inBox(s, p) && inCylinder(s, p); };
  const auto nearestInBox = [&](const Vec3<T>& p) { return Vec3<T>(p.cwiseMax(-s.h).cwiseMin(s.h)); };
  const Vec3<T> axisPoint = s.c + std::clamp(-s.c.dot(s.a), -s.hh, s.hh) * s.a;
  return inBoth(s.c) || inBoth(Vec3<T>::Zero()) || inBoth(nearestInBox(s.c)) || inBoth(axisPoint) ||
         inBoth(nearestInBox(axisPoint));
}

}  // namespace

template <class T> T cylinderBoxLength(const Vec3<T>& h, const Vec3<T>& c, T radius, T halfHeight) {
  return std::max({Vec3<T>(halfHeight, radius, radius).norm(), h.norm(), c.norm()});
}

template <class T> T cylinderBoxTolerance(const Vec3<T>& h, const Vec3<T>& c, T radius, T halfHeight) {
  return gjkRelativeTolerance<T>() * cylinderBoxLength(h, c, radius, halfHeight);
}

template <class T>
OverlapCertificate cylinderBoxCertificate(const Vec3<T>& c, const Vec3<T>& a, T radius, T halfHeight,
                                          const Vec3<T>& h) {
  const CylinderInBox<T> s{c, a, radius, halfHeight, h};
  const T tolerance = cylinderBoxTolerance(h, c, radius, halfHeight);
  if (separatingAxis(s, tolerance)) return OverlapCertificate::Apart;
  if (commonPoint(s)) return OverlapCertificate::Overlapping;
  return OverlapCertificate::Unknown;
}

template float cylinderBoxLength<float>(const Vec3<float>&, const Vec3<float>&, float, float);
template double cylinderBoxLength<double>(const Vec3<double>&, const Vec3<double>&, double, double);
template float cylinderBoxTolerance<float>(const Vec3<float>&, const Vec3<float>&, float, float);
template double cylinderBoxTolerance<double>(const Vec3<double>&, const Vec3<double>&, double, double);
template OverlapCertificate cylinderBoxCertificate<float>(const Vec3<float>&, const Vec3<float>&, float, float,
                                                          const Vec3<float>&);
template OverlapCertificate cylinderBoxCertificate<double>(const Vec3<double>&, const Vec3<double>&, double, double,
                                                           const Vec3<double>&);

}  // namespace gq::kernels
