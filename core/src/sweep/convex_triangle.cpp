// Sweep of a support-mapped shape against one triangle (the building block of mesh, heightfield and triangle-array
// sweeps): the triangle is a support mapping (argmax of its three vertices), culling follows the raycast rules, and
// the time of impact comes from conservative advancement (sweep/convex_convex.cpp).
#include "sweep/sweep.h"
#include "common/unit_vector.h"

namespace gq::detail {

template <class T> Bounds3<T> TriangleSupport<T>::localBounds() const {
  Bounds3<T> b;
  for (const Vec3<T>& v : tri_.verts) b.include(v);
  return b;
}

template <class T> Vec3<T> TriangleSupport<T>::support(const Vec3<T>& dir) const {
  const T d0 = tri_.verts[0].dot(dir), d1 = tri_.verts[1].dot(dir), d2 = tri_.verts[2].dot(dir);
  if (d0 >= d1 && d0 >= d2) return tri_.verts[0];
  return d1 >= d2 ? tri_.verts[1] : tri_.verts[2];
}

template <class T> ConvexShape<T> TriangleSupport<T>::shape() const {
  ConvexShape<T> s;
  s.kind = ConvexShape<T>::Kind::Custom;
  s.custom = this;
  s.size = std::max({tri_.verts[0].norm(), tri_.verts[1].norm(), tri_.verts[2].norm()});
  return s;
}

template <class T> Vec3<T> faceNormal(const Triangle<T>& tri) {
  const Vec3<T> n = (tri.verts[1] - tri.verts[0]).cross(tri.verts[2] - tri.verts[0]);
  return unitOr(n, Vec3<T>(Vec3<T>::Zero()));
}

template <class T>
bool sweepOneTriangle(const ConvexShape<T>& a, const Triangle<T>& tri, const SweepQuery<T>& q, bool,
                      ToiResult<T>& toi, T& facing) {
  facing = faceNormal(tri).dot(q.dir);
  // Back faces (normal along the sweep) are culled before the overlap test, as for raycasts.
  if (q.cullBackFaces && facing > T(0)) return false;
  // A two-sided triangle faces the sweep with whichever side is towards it.
  if (!q.cullBackFaces) facing = -std::abs(facing);
  const TriangleSupport<T> support(tri);
  toi = sweepConvexShapes(a, support.shape(), q.dir, q.maxDist, q.testInitialOverlap);
  return true;
}

template <class T> bool TriangleHitPicker<T>::offer(const ToiResult<T>& toi, T facing, std::uint32_t index, bool anyHit) {
  using Kind = typename ToiResult<T>::Kind;
  if (toi.kind == Kind::Miss) return false;
  if (toi.kind == Kind::InitialOverlap) {
    // Initial overlaps win over hits; among them the smallest triangle index (deterministic "first found").
    if (!overlap || index < bestIndex) { best = toi; bestIndex = index; bestFacing = facing; }
    overlap = found = true;
    return anyHit;
  }
  if (overlap) return false;
  const bool closer = !found || toi.distance < best.distance - tieTolerance;
  const bool tie = found && std::abs(toi.distance - best.distance) <= tieTolerance;
  // Equal distances: the triangle facing the sweep most wins, then the smaller index.
  const bool betterTie = tie && (facing < bestFacing || (facing == bestFacing && index < bestIndex));
  if (closer || betterTie) {
    best = toi;
    bestFacing = facing;
    bestIndex = index;
    found = true;
  }
  return anyHit;
}

template <class T>
void TriangleMtdPicker<T>::offer(const ConvexShape<T>& a, const Triangle<T>& tri, std::uint32_t triIndex,
                                 bool doubleSided) {
  const Vec3<T> n = faceNormal(tri);
  // Second culling of the mtd: a single-sided triangle with the swept shape's centre behind it is skipped.
  if (!doubleSided && n.dot(a.center() - tri.verts[0]) < T(0)) return;
  const TriangleSupport<T> support(tri);
  const ConvexShape<T> b = support.shape();
  if (!gjkOverlap(a, b)) return;
  const EpaResult<T> e = epaPenetration(a, b);
  if (!isFinite(e.normal) || !std::isfinite(e.depth)) return;
  if (found && !(e.depth > depth)) return;
  found = true;
  depth = std::max(T(0), e.depth);
  normal = -e.normal;
  position = e.point0;
  index = triIndex;
}

template <class T> void TriangleMtdPicker<T>::writeTo(SweepOutcome<T>& out, const Vec3<T>&) const {
  if (!found) return;  // nothing left after culling: the façade reports distance 0 and normal -dir
  out.mtdValid = true;
  out.mtdDepth = depth;
  out.mtdNormal = normal;
  out.mtdPosition = position;
  out.faceIndex = index;
}

template class TriangleSupport<float>;
template class TriangleSupport<double>;
template struct TriangleHitPicker<float>;
template struct TriangleHitPicker<double>;
template struct TriangleMtdPicker<float>;
template struct TriangleMtdPicker<double>;
template bool sweepOneTriangle<float>(const ConvexShape<float>&, const Triangle<float>&, const SweepQuery<float>&, bool,
                                      ToiResult<float>&, float&);
template bool sweepOneTriangle<double>(const ConvexShape<double>&, const Triangle<double>&, const SweepQuery<double>&,
                                       bool, ToiResult<double>&, double&);

}  // namespace gq::detail

namespace gq::detail {

template <class T>
Bounds3<T> sweptBoundsInFrame(const ConvexShape<T>& a, const Transform<T>& frame, const Vec3<T>& dir, T reach) {
  Bounds3<T> b;
  // Padding for the rounding of support points and of the frame change (relative to the extent involved).
  const T pad = T(16) * std::numeric_limits<T>::epsilon() * (a.size + a.position.norm() + frame.p.norm() + reach);
  for (int i = 0; i < 3; ++i) {
    const Vec3<T> axis = frame.rotate(Vec3<T>::Unit(i));
    const T origin = axis.dot(frame.p);
    const T hi = axis.dot(a.support(axis)) + a.margin - origin;
    const T lo = axis.dot(a.support(-axis)) - a.margin - origin;
    const T travel = reach * axis.dot(dir);
    b.min[i] = lo + std::min(T(0), travel) - pad;
    b.max[i] = hi + std::max(T(0), travel) + pad;
  }
  return b;
}

template <class T> T triangleTieTolerance(const ConvexShape<T>& a, const Bounds3<T>& box) {
  ConvexShape<T> extent;
  extent.size = box.extents().norm() + box.center().norm();
  return T(kSweepTieFactor * kSweepTouchFactor) * gjkTolerance(a, extent);
}

template float triangleTieTolerance<float>(const ConvexShape<float>&, const Bounds3<float>&);
template double triangleTieTolerance<double>(const ConvexShape<double>&, const Bounds3<double>&);
template Bounds3<float> sweptBoundsInFrame<float>(const ConvexShape<float>&, const Transform<float>&,
                                                  const Vec3<float>&, float);
template Bounds3<double> sweptBoundsInFrame<double>(const ConvexShape<double>&, const Transform<double>&,
                                                    const Vec3<double>&, double);

}  // namespace gq::detail
