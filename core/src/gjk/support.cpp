// Support mappings of the convex cores: point (sphere), segment (capsule), box, scaled convex hull, custom.
#include <cmath>

#include "common/unit_vector.h"
#include "gjk/gjk.h"
#include "gjk/support_map.h"

namespace gq::kernels {
using namespace detail;  // core's internal helpers
namespace {

// Scaled hull: points are S v with S symmetric, so argmax_v d.(S v) = argmax_v (S d).v.
template <class T> Vec3<T> supportHull(const ConvexShape<T>& s, const Vec3<T>& d) {
  const ConvexMesh<T>& hull = *s.hull;
  const Vec3<T> dm = s.hullScaled ? Vec3<T>(s.hullScale * d) : d;
  const bool climb = hull.vertices.size() > kHillClimbMinVertices && hasAdjacency(hull);
  bool cold = false;  // single calls keep the shape's running hint
  const std::uint32_t v = hullVertex(hull, s.startTable, climb, dm, s.climbStart, cold);
  return s.hullScaled ? Vec3<T>(s.hullScale * hull.vertices[v]) : hull.vertices[v];
}

// Range-safe: a float custom shape 2e19+ across has a squared radius past FLT_MAX (its size was inf, so GJK's
// tolerance was too and any pair with it "overlapped" at once, 0 deep).
template <class T> T boundsRadius(const Bounds3<T>& b) {
  return rangeSafeNorm(Vec3<T>(b.min.cwiseAbs().cwiseMax(b.max.cwiseAbs())));
}

}  // namespace

template <class T> Vec3<T> ConvexShape<T>::supportLocal(const Vec3<T>& d) const {
  switch (kind) {
    case Kind::Point: return Vec3<T>::Zero();
    case Kind::Segment: return supportSegment(halfExtents.x(), d);
    case Kind::Box: return supportBox(halfExtents, d);
    case Kind::Hull: return supportHull(*this, d);
    case Kind::Custom: return custom->support(d);
  }
  return Vec3<T>::Zero();
}

template <class T> Vec3<T> ConvexShape<T>::center() const {
  switch (kind) {
    case Kind::Hull:
      return toWorld(Vec3<T>(localScale * (hullScaled ? Vec3<T>(hullScale * hull->center) : hull->center)));
    case Kind::Custom: return toWorld(Vec3<T>(localScale * custom->localBounds().center()));
    default: return position;
  }
}

bool isConvexShapeType(GeometryType type) {
  switch (type) {
    case GeometryType::Sphere:
    case GeometryType::Capsule:
    case GeometryType::Box:
    case GeometryType::ConvexMesh:
    case GeometryType::Custom: return true;
    default: return false;
  }
}

template <class T>
ConvexShape<T> makeConvexShape(const Geometry<T>& geom, const Mat3<T>& rotation, const Vec3<T>& position) {
  using Kind = typename ConvexShape<T>::Kind;
  ConvexShape<T> s;
  s.rotation = rotation;
  s.position = position;
  if (const auto* g = geom.template getIf<SphereGeometry<T>>()) {
    s.kind = Kind::Point;
    s.margin = g->radius;
    s.size = g->radius;
  } else if (const auto* g = geom.template getIf<CapsuleGeometry<T>>()) {
    s.kind = Kind::Segment;
    s.margin = g->radius;
    s.halfExtents = Vec3<T>(g->halfHeight, T(0), T(0));
    s.size = g->halfHeight + g->radius;
  } else if (const auto* g = geom.template getIf<BoxGeometry<T>>()) {
    s.kind = Kind::Box;
    s.halfExtents = g->halfExtents;
    s.size = g->halfExtents.norm();
  } else if (const auto* g = geom.template getIf<ConvexMeshGeometry<T>>()) {
    s.kind = Kind::Hull;
    s.hull = g->mesh.get();
    s.startTable = supportStartTable(g->mesh);
    s.hullScaled = !g->scale.isIdentity();
    if (s.hullScaled) s.hullScale = g->scale.toMatrix();
    s.size = boundsRadius(s.hull->localBounds) * g->scale.scale.cwiseAbs().maxCoeff();
  } else if (const auto* g = geom.template getIf<CustomGeometry<T>>()) {
    s.kind = Kind::Custom;
    s.custom = g->callbacks.get();
    s.size = boundsRadius(s.custom->localBounds());
  }
  return s;
}

// A sphere's rotation moves none of its points: its shape keeps the identity (no conversion).
template <class T> ConvexShape<T> makeConvexShape(const Geometry<T>& geom, const Transform<T>& pose) {
  const bool sphere = geom.type() == GeometryType::Sphere;
  return makeConvexShape(geom, sphere ? Mat3<T>(Mat3<T>::Identity()) : Mat3<T>(pose.q.toRotationMatrix()), pose.p);
}

template struct ConvexShape<float>;
template struct ConvexShape<double>;
template ConvexShape<float> makeConvexShape<float>(const Geometry<float>&, const Transform<float>&);
template ConvexShape<double> makeConvexShape<double>(const Geometry<double>&, const Transform<double>&);
template ConvexShape<float> makeConvexShape<float>(const Geometry<float>&, const Mat3<float>&, const Vec3<float>&);
template ConvexShape<double> makeConvexShape<double>(const Geometry<double>&, const Mat3<double>&, const Vec3<double>&);

}  // namespace gq::kernels
