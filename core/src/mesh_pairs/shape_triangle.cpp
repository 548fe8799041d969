// Convex query shape vs one triangle (see shape_triangle.h).
#include "mesh_pairs/shape_triangle.h"

#include <cmath>

#include "bounds/bounds.h"
#include "mesh_pairs/surface.h"
#include "mesh_pairs/triangle_tests.h"
#include "mesh/triangle.h"
#include "common/unit_vector.h"

namespace gq::kernels {
using namespace detail;  // core's internal helpers

template <class T> SurfaceTriangleSupport<T>::SurfaceTriangleSupport(const Triangle<T>& t) {
  centroid_ = (t.verts[0] + t.verts[1] + t.verts[2]) / T(3);
  for (int k = 0; k < 3; ++k) local_[k] = t.verts[k] - centroid_;
}

template <class T> Bounds3<T> SurfaceTriangleSupport<T>::localBounds() const {
  Bounds3<T> b;
  for (const auto& v : local_) b.include(v);
  return b;
}

template <class T> Vec3<T> SurfaceTriangleSupport<T>::support(const Vec3<T>& dir) const {
  int best = 0;
  for (int k = 1; k < 3; ++k)
    if (local_[k].dot(dir) > local_[best].dot(dir)) best = k;
  return local_[best];
}

template <class T> ConvexShape<T> SurfaceTriangleSupport<T>::shape() const {
  ConvexShape<T> s;
  s.kind = ConvexShape<T>::Kind::Custom;
  s.custom = this;
  s.position = centroid_;
  s.size = std::max({local_[0].norm(), local_[1].norm(), local_[2].norm()});
  return s;
}

namespace {

template <class T> Bounds3<T> shapeBounds(const Geometry<T>& g, const Transform<T>& pose) {
  switch (g.type()) {
    case GeometryType::Sphere: return boundsSphere(g.template get<SphereGeometry<T>>(), pose);
    case GeometryType::Capsule: return boundsCapsule(g.template get<CapsuleGeometry<T>>(), pose);
    case GeometryType::Box: return boundsBox(g.template get<BoxGeometry<T>>(), pose);
    case GeometryType::ConvexMesh: return boundsConvex(g.template get<ConvexMeshGeometry<T>>(), pose);
    default: return boundsCustom(g.template get<CustomGeometry<T>>(), pose);
  }
}

// Unit normal of the triangle (its winding's side).
// Scaled before squaring: a tiny triangle's cross product squares to 0 in float (1e-25^2 underflows), and Eigen's
// normalized() then returns it unscaled, a push direction of length 0.97 (found by fuzz_pair_queries).
template <class T> Vec3<T> unitNormal(const Triangle<T>& tri) {
  return (tri.verts[1] - tri.verts[0]).cross(tri.verts[2] - tri.verts[0]).stableNormalized();
}

}  // namespace

template <class T>
TriangleQueryShape<T>::TriangleQueryShape(const Geometry<T>& geom, const Transform<T>& pose)
    : type_(geom.type()), pose_(pose), convex_(makeConvexShape(geom, pose)) {
  segA_ = segB_ = pose.p;
  if (const auto* s = geom.template getIf<SphereGeometry<T>>()) radius_ = s->radius;
  if (const auto* c = geom.template getIf<CapsuleGeometry<T>>()) {
    radius_ = c->radius;
    const Vec3<T> axis = pose.rotate(Vec3<T>(c->halfHeight, T(0), T(0)));
    segA_ = pose.p - axis;
    segB_ = pose.p + axis;
  }
  if (const auto* b = geom.template getIf<BoxGeometry<T>>()) {
    halfExtents_ = b->halfExtents;
    ballCentre_ = pose.p;
    ballRadius_ = b->halfExtents.norm();
  }
  hull_ = geom.template getIf<ConvexMeshGeometry<T>>();
  ballPending_ = boundsPending_ = hull_ != nullptr;
  if (!boundsPending_) bounds_ = shapeBounds(geom, pose);
  centre_ = convex_.center();
}

template <class T> const Bounds3<T>& TriangleQueryShape<T>::worldBounds() const {
  if (boundsPending_) {
    bounds_ = boundsConvex(*hull_, pose_);
    boundsPending_ = false;
  }
  return bounds_;
}

template <class T> T TriangleQueryShape<T>::distanceLowerBound(const Triangle<T>& tri) const {
  if (ballPending_) {  // the hull's vertices' farthest from their centroid
    const Mat3<T> scale = hull_->scale.toMatrix();
    const Vec3<T> centre = scale * hull_->mesh->center;
    T r2 = T(0);
    for (const Vec3<T>& v : hull_->mesh->vertices) r2 = std::max(r2, (scale * v - centre).squaredNorm());
    ballCentre_ = pose_.transform(centre);
    ballRadius_ = std::sqrt(r2) * (T(1) + T(8) * std::numeric_limits<T>::epsilon());  // rounding: never inside
    ballPending_ = false;
  }
  if (!(ballRadius_ < std::numeric_limits<T>::infinity())) return -std::numeric_limits<T>::infinity();
  const Vec3<T> q = closestPointOnTriangle(ballCentre_, tri.verts[0], tri.verts[1], tri.verts[2]);
  return (q - ballCentre_).norm() - ballRadius_;
}

namespace {
// cullBounds' growth: a relative epsilon of the shape's size and coordinates.
template <class T> T cullGrowth(const Bounds3<T>& b, T size) {
  const T scale = std::max({size, b.min.cwiseAbs().maxCoeff(), b.max.cwiseAbs().maxCoeff()});
  return T(tol::Rel<T>::kEpsilon) * scale;
}
}  // namespace

template <class T> Bounds3<T> TriangleQueryShape<T>::cullBounds() const {
  const Bounds3<T>& b = worldBounds();
  const T grow = cullGrowth(b, size());
  return Bounds3<T>::fromMinMax(b.min.array() - grow, b.max.array() + grow);
}

template <class T> Bounds3<T> TriangleQueryShape<T>::cullBoundsIn(const Mat3<T>& linear, const Vec3<T>& origin) const {
  if (type_ != GeometryType::Sphere && type_ != GeometryType::Capsule && type_ != GeometryType::Box)
    return mapBox(cullBounds(), linear, Vec3<T>(-(linear * origin)));
  const T grow = cullGrowth(worldBounds(), size());
  Vec3<T> lo, hi, half;
  if (type_ == GeometryType::Box) {
    lo = hi = linear * (pose_.p - origin);
    half = (linear * pose_.q.toRotationMatrix()).cwiseAbs() * (halfExtents_.array() + grow).matrix();
  } else {  // the segment [segA, segB] (a point for a sphere) grown by the radius
    const Vec3<T> a = linear * (segA_ - origin), b = linear * (segB_ - origin);
    lo = a.cwiseMin(b);
    hi = a.cwiseMax(b);
    half = (radius_ + grow) * linear.rowwise().norm();
  }
  return Bounds3<T>::fromMinMax(lo - half, hi + half);
}

template <class T> bool TriangleQueryShape<T>::overlaps(const Triangle<T>& tri) const {
  switch (type_) {
    case GeometryType::Sphere: return overlapSphereTriangle(segA_, radius_, tri);
    case GeometryType::Capsule: return overlapCapsuleTriangle(segA_, segB_, radius_, tri);
    case GeometryType::Box: {
      Triangle<T> local;
      for (int k = 0; k < 3; ++k) local.verts[k] = pose_.transformInv(tri.verts[k]);
      return overlapBoxTriangle(halfExtents_, local);
    }
    default: {
      const SurfaceTriangleSupport<T> support(tri);
      const ConvexShape<T> triangle = support.shape();
      const Vec3<T> start = centre_ - triangle.position;  // the shape's centre minus the triangle's centroid
      return gjkOverlap(convex_, triangle, static_cast<GjkOverlapWitness<T>*>(nullptr), &start);
    }
  }
}

template <class T>
bool TriangleQueryShape<T>::distanceTo(const Triangle<T>& tri, DistanceResult<T>& out, T farEnough) const {
  if (type_ == GeometryType::Sphere || type_ == GeometryType::Capsule) {
    const SegmentTriangleClosest<T> c = closestSegmentTriangle(segA_, segB_, tri);
    const T len = std::sqrt(c.distSq);
    if (len > radius_) {
      if (!tryUnit(Vec3<T>(c.onTriangle - c.onSegment), out.normal)) out.normal = unitNormal(tri);
      out.distance = len - radius_;
      out.point0 = c.onSegment + radius_ * out.normal;
    } else {
      // Contact: the normal is the segment-to-triangle direction, or the face normal facing away from the centre.
      if (!tryUnit(Vec3<T>(c.onTriangle - c.onSegment), out.normal)) {
        const Vec3<T> n = unitNormal(tri);
        out.normal = n.dot(pose_.p - tri.verts[0]) >= T(0) ? Vec3<T>(-n) : n;
      }
      out.distance = T(0);
      out.point0 = c.onTriangle;
    }
    out.point1 = c.onTriangle;
    return true;
  }
  const SurfaceTriangleSupport<T> support(tri);
  const ConvexShape<T> triShape = support.shape();
  const GjkResult<T> g = gjkDistance(convex_, triShape, &warm_, T(0), static_cast<const Vec3<T>*>(nullptr), farEnough);
  if (g.beyond) return false;
  if (!g.coresOverlap && g.distance > T(0)) {
    writeSeparated(g, out);
    return true;
  }
  const EpaResult<T> epa = epaPenetration(convex_, triShape, &g.simplex);
  out.distance = T(0);
  out.point0 = out.point1 = epa.point1;
  out.normal = epa.normal;
  return true;
}

template <class T> TrianglePush<T> TriangleQueryShape<T>::pushOut(const Triangle<T>& tri, bool oneSided) const {
  TrianglePush<T> push;
  if (type_ == GeometryType::Sphere || type_ == GeometryType::Capsule) {
    // Away from the closest triangle point is exact for a disjoint segment but undefined once it touches (a capsule
    // lying on a face went to EPA, which answered 0.35 instead of r = 0.25): the exact exit covers both.
    const SegmentTriangleClosest<T> c = closestSegmentTriangle(segA_, segB_, tri);
    Vec3<T> away;
    const bool disjoint = tryUnit(Vec3<T>(c.onSegment - c.onTriangle), away);
    const SegmentTriangleExit<T> e = segmentTriangleExit(segA_, segB_, tri, disjoint ? &away : nullptr);
    push.direction = e.direction;
    push.depth = std::max(T(0), radius_ + e.exit);
  } else {
    const SurfaceTriangleSupport<T> support(tri);
    const EpaResult<T> epa = epaPenetration(convex_, support.shape());
    push.direction = -epa.normal;  // EPA's normal points from the shape to the triangle
    push.depth = epa.depth;
  }
  if (oneSided) {
    const Vec3<T> n = unitNormal(tri);
    if (push.direction.dot(n) < T(0)) {
      // Lowest point of the shape along n: core support along -n, minus the margin.
      const T lowest = n.dot(convex_.support(-n)) - convex_.margin;
      push.direction = n;
      push.depth = std::max(T(0), n.dot(tri.verts[0]) - lowest);
    }
  }
  return push;
}

template class SurfaceTriangleSupport<float>;
template class SurfaceTriangleSupport<double>;
template class TriangleQueryShape<float>;
template class TriangleQueryShape<double>;

}  // namespace gq::kernels
