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

// Closest point to p on a convex polygon `pts` (counter-clockwise about n), p given with its plane projection.
template <class T>
Vec3<T> closestPointOnPolygon(const std::vector<Vec3<T>>& pts, const Vec3<T>& n, const Vec3<T>& p,
                              const Vec3<T>& projected) {
  bool inside = true;
  for (std::size_t k = 0; k < pts.size() && inside; ++k) {
    const Vec3<T>& a = pts[k];
    const Vec3<T>& b = pts[(k + 1) % pts.size()];
    if ((b - a).cross(projected - a).dot(n) < T(0)) inside = false;
  }
  if (inside) return projected;
  Vec3<T> best = pts[0];
  T bestDist2 = std::numeric_limits<T>::infinity();
  for (std::size_t k = 0; k < pts.size(); ++k) {
    const Vec3<T> c = closestPointOnSegment(pts[k], pts[(k + 1) % pts.size()], p);
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
  std::vector<Vec3<T>> pts;
  for (const HullPolygon<T>& poly : hull.polygons) {
    pts.clear();
    for (std::uint32_t k = 0; k < poly.indexCount; ++k)
      pts.push_back(scale.pointToShape(hull.vertices[hull.polygonVertices[poly.indexBase + k]]));
    const Vec3<T> n = scale.normalToShape(poly.normal);
    const T height = n.dot(p - pts[0]);
    if (height <= T(0)) continue;  // behind this face: it cannot hold the closest point
    const Vec3<T> c = closestPointOnPolygon(pts, n, p, Vec3<T>(p - height * n));
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
