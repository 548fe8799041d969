// Support mappings of the convex cores: point (sphere), segment (capsule), box, scaled convex hull, custom.
#include <cmath>

#include "gjk/gjk.h"

namespace gq::detail {
namespace {

// Box: the corner whose signs match the direction (ties resolve to +).
template <class T> Vec3<T> supportBox(const Vec3<T>& halfExtents, const Vec3<T>& d) {
  return Vec3<T>(d.x() < T(0) ? -halfExtents.x() : halfExtents.x(), d.y() < T(0) ? -halfExtents.y() : halfExtents.y(),
                 d.z() < T(0) ? -halfExtents.z() : halfExtents.z());
}

// Segment along X from -h to +h.
template <class T> Vec3<T> supportSegment(T halfHeight, const Vec3<T>& d) {
  return Vec3<T>(d.x() < T(0) ? -halfHeight : halfHeight, T(0), T(0));
}

template <class T> std::uint32_t bruteForceVertex(const ConvexMesh<T>& hull, const Vec3<T>& d) {
  std::uint32_t best = 0;
  T bestDot = -std::numeric_limits<T>::infinity();
  for (std::uint32_t i = 0; i < hull.vertices.size(); ++i) {
    const T s = hull.vertices[i].dot(d);
    if (s > bestDot) { bestDot = s; best = i; }
  }
  return best;
}

// Hill-climbing: move to any strictly better neighbour until none is. On a convex polytope a vertex with no
// improving edge is a global maximum of the linear function, so the climb is exact.
template <class T> std::uint32_t climbVertex(const ConvexMesh<T>& hull, const Vec3<T>& d, std::uint32_t start) {
  std::uint32_t current = start < hull.vertices.size() ? start : 0;
  T currentDot = hull.vertices[current].dot(d);
  for (bool moved = true; moved;) {
    moved = false;
    for (std::uint32_t k = hull.adjacencyOffsets[current]; k < hull.adjacencyOffsets[current + 1]; ++k) {
      const std::uint32_t n = hull.adjacency[k];
      const T s = hull.vertices[n].dot(d);
      if (s > currentDot) { current = n; currentDot = s; moved = true; }
    }
  }
  return current;
}

template <class T> bool hasAdjacency(const ConvexMesh<T>& hull) {
  return hull.adjacencyOffsets.size() == hull.vertices.size() + 1 && !hull.adjacency.empty();
}

// Scaled hull: points are S v with S symmetric, so argmax_v d.(S v) = argmax_v (S d).v.
template <class T> Vec3<T> supportHull(const ConvexShape<T>& s, const Vec3<T>& d) {
  const ConvexMesh<T>& hull = *s.hull;
  const Vec3<T> dm = s.hullScaled ? Vec3<T>(s.hullScale * d) : d;
  std::uint32_t v;
  if (hull.vertices.size() > kHillClimbMinVertices && hasAdjacency(hull)) {
    v = climbVertex(hull, dm, s.climbStart);
    s.climbStart = v;
  } else {
    v = bruteForceVertex(hull, dm);
  }
  return s.hullScaled ? Vec3<T>(s.hullScale * hull.vertices[v]) : hull.vertices[v];
}

template <class T> T boundsRadius(const Bounds3<T>& b) { return b.min.cwiseAbs().cwiseMax(b.max.cwiseAbs()).norm(); }

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
    case Kind::Hull: return pose.transform(hullScaled ? Vec3<T>(hullScale * hull->center) : hull->center);
    case Kind::Custom: return pose.transform(custom->localBounds().center());
    default: return pose.p;
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

template <class T> ConvexShape<T> makeConvexShape(const Geometry<T>& geom, const Transform<T>& pose) {
  using Kind = typename ConvexShape<T>::Kind;
  ConvexShape<T> s;
  s.pose = pose;
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

template <class T> T gjkTolerance(const ConvexShape<T>& a, const ConvexShape<T>& b) {
  const T rel = std::max(T(tol::Rel<T>::kGjkTolerance), T(kGjkRoundoffUlps) * std::numeric_limits<T>::epsilon());
  // Rounding of world-space support points grows with their distance from the origin too.
  const T scale = std::max({a.size, b.size, (a.pose.p - b.pose.p).norm()});
  return rel * std::max(scale, std::numeric_limits<T>::min());
}

template struct ConvexShape<float>;
template struct ConvexShape<double>;
template ConvexShape<float> makeConvexShape<float>(const Geometry<float>&, const Transform<float>&);
template ConvexShape<double> makeConvexShape<double>(const Geometry<double>&, const Transform<double>&);
template float gjkTolerance<float>(const ConvexShape<float>&, const ConvexShape<float>&);
template double gjkTolerance<double>(const ConvexShape<double>&, const ConvexShape<double>&);

}  // namespace gq::detail
