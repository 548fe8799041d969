// Point vs scaled convex hull, exact. Scale maps the hull to another convex polytope with the same faces
// (vertices S v, plane normals S^-T n), so we work in shape space where distances are Euclidean. Inside (behind
// every plane): distance 0 and the point itself. Outside: the closest boundary point lies on a face whose plane
// the point is in front of (the offset to it is a non-negative combination of the normals of the faces holding
// it), so only those faces are searched: the projection onto the plane if it falls inside the polygon, else the
// closest point on the polygon's edges.
#include <limits>

#include "gq/cooking.h"
#include "point_distance/point_distance.h"
#include "shapes/hull_scale.h"
#include "shapes/segment.h"

namespace gq::detail {
namespace {

// Closest point to p on a convex polygon of `count` vertices `vertex(k)` (counter-clockwise about n), given p's
// projection onto the polygon's plane.
template <class T, class VertexFn>
Vec3<T> closestPointOnPolygon(std::uint32_t count, const VertexFn& vertex, const Vec3<T>& n, const Vec3<T>& p,
                              const Vec3<T>& projected) {
  bool inside = true;
  for (std::uint32_t k = 0; k < count && inside; ++k) {
    const Vec3<T> a = vertex(k);
    if ((vertex((k + 1) % count) - a).cross(projected - a).dot(n) < T(0)) inside = false;
  }
  if (inside) return projected;
  Vec3<T> best = vertex(0);
  T bestDist2 = std::numeric_limits<T>::infinity();
  for (std::uint32_t k = 0; k < count; ++k) {
    const Vec3<T> c = closestPointOnSegment(vertex(k), vertex((k + 1) % count), p);
    const T d2 = (c - p).squaredNorm();
    if (d2 < bestDist2) {
      bestDist2 = d2;
      best = c;
    }
  }
  return best;
}

}  // namespace

template <class T>
void pointDistanceConvex(const ConvexMeshGeometry<T>& g, const Transform<T>& pose, const Vec3<T>& point,
                         PointDistanceResult<T>& out) {
  const ConvexMesh<T>& hull = *g.mesh;
  const HullScale<T> scale(g.scale);
  const Vec3<T> p = pose.transformInv(point);
  out.closestIndex = kInvalidFaceIndex;
  T bestDist2 = std::numeric_limits<T>::infinity();
  Vec3<T> best = p;
  for (const HullPolygon<T>& poly : hull.polygons) {
    const auto vertex = [&](std::uint32_t k) {
      return scale.pointToShape(hull.vertices[hull.polygonVertices[poly.indexBase + k]]);
    };
    const Vec3<T> n = scale.normalToShape(poly.normal);
    const T height = n.dot(p - vertex(0));
    if (height <= T(0)) continue;  // behind this face: it cannot hold the closest point
    const Vec3<T> c = closestPointOnPolygon(poly.indexCount, vertex, n, p, Vec3<T>(p - height * n));
    const T d2 = (c - p).squaredNorm();
    if (d2 < bestDist2) {
      bestDist2 = d2;
      best = c;
    }
  }
  if (bestDist2 == std::numeric_limits<T>::infinity()) {  // behind every face: inside
    out.distance = T(0);
    out.closestPoint = point;
    return;
  }
  out.distance = std::sqrt(bestDist2);
  out.closestPoint = pose.transform(best);
}

template void pointDistanceConvex<float>(const ConvexMeshGeometry<float>&, const Transform<float>&, const Vec3<float>&, PointDistanceResult<float>&);
template void pointDistanceConvex<double>(const ConvexMeshGeometry<double>&, const Transform<double>&, const Vec3<double>&, PointDistanceResult<double>&);

}  // namespace gq::detail
