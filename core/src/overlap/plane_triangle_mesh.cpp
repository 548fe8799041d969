// Plane vs triangle mesh (distance/plane_surface.h): a linear pass over the mesh's hull vertices. The lowest point of
// the mesh over any plane is a vertex on the convex hull of its used vertices (TriangleMesh::hullVertices, the same
// set that gives the mesh's exact world bounds), usually far fewer than the vertices and without the BVH's float
// boxes; an overlap stops at the first vertex on or below the plane.
#include "distance/plane_surface.h"
#include "gq/cooking.h"

namespace gq::detail {

template <class T>
LowestVertex<T> lowestVertexTriangleMesh(const TriangleMeshGeometry<T>& g, const Transform<T>& meshPose,
                                         const Transform<T>& planePose, T stopAtOrBelow) {
  const TriangleMesh<T>& mesh = *g.mesh;
  const Vec3<T> n = planePose.rotate(Vec3<T>::UnitX());
  // height(v) = n . (R S v + p - planeOrigin) = (S R^T n) . v + n . (p - planeOrigin), S symmetric.
  const Vec3<T> rn = meshPose.rotateInv(n);
  const Vec3<T> m = g.scale.isIdentity() ? rn : Vec3<T>(g.scale.toMatrix() * rn);
  const T k = n.dot(meshPose.p - planePose.p);
  LowestVertex<T> lowest;
  std::uint32_t at = 0;
  for (std::uint32_t i : mesh.hullVertices) {
    const T h = m.dot(mesh.vertices[i]) + k;
    if (h < lowest.height) {
      lowest.height = h;
      at = i;
      if (h <= stopAtOrBelow) break;
    }
  }
  if (lowest.height < std::numeric_limits<T>::infinity())
    lowest.point = meshPose.transform(Vec3<T>(g.scale.toMatrix() * mesh.vertices[at]));
  return lowest;
}

template <class T>
Status overlapPlaneTriangleMesh(const Geometry<T>&, const Transform<T>& p0, const Geometry<T>& g1,
                                const Transform<T>& p1, bool& overlapping) {
  overlapping = lowestVertexTriangleMesh(g1.template get<TriangleMeshGeometry<T>>(), p1, p0, T(0)).height <= T(0);
  return Status();
}

template LowestVertex<float> lowestVertexTriangleMesh<float>(const TriangleMeshGeometry<float>&,
                                                             const Transform<float>&, const Transform<float>&, float);
template LowestVertex<double> lowestVertexTriangleMesh<double>(const TriangleMeshGeometry<double>&,
                                                               const Transform<double>&, const Transform<double>&,
                                                               double);
template Status overlapPlaneTriangleMesh<float>(const Geometry<float>&, const Transform<float>&,
                                                const Geometry<float>&, const Transform<float>&, bool&);
template Status overlapPlaneTriangleMesh<double>(const Geometry<double>&, const Transform<double>&,
                                                 const Geometry<double>&, const Transform<double>&, bool&);

}  // namespace gq::detail
