// Triangle mesh vs triangle mesh distance: best-first dual BVH traversal (mesh_pairs/mesh_mesh.h) with the exact
// triangle-triangle distance; the second mesh is expressed in the first's frame.
#include "distance/surface_distance.h"
#include "mesh_pairs/mesh_mesh.h"

namespace gq::detail {

template <class T>
Status distanceTriangleMeshTriangleMesh(const Geometry<T>& g0, const Transform<T>& p0, const Geometry<T>& g1,
                                        const Transform<T>& p1, GjkCache<T>* cache, DistanceResult<T>& out,
                                        T farEnough) {
  if (cache) cache->iterations = 0;
  const MeshSurface<T> a(g0.template get<TriangleMeshGeometry<T>>(), Transform<T>());
  const MeshSurface<T> b(g1.template get<TriangleMeshGeometry<T>>(), p1.relativeTo(p0));
  const bool bounded = farEnough < std::numeric_limits<T>::infinity();
  const bool empty = a.mesh().accel->bvh.rootChild == MeshBvhNode::kEmpty || b.mesh().accel->bvh.rootChild == MeshBvhNode::kEmpty;
  if (bounded && !empty && farEnough < T(0)) {  // surfaces are >= 0 apart
    out.distance = surfaceBoundBeyond(farEnough);
    return Status();
  }
  const MeshPairClosest<T> c = closestMeshPair(a, b, bounded ? farEnough * farEnough : farEnough);
  if (bounded && !empty && !c.found) {  // every pair proven at or beyond the bound
    out.distance = surfaceBoundBeyond(farEnough);
    return Status();
  }
  const T dist = std::sqrt(c.distSq);
  out.distance = dist;
  out.point0 = p0.transform(c.onA);
  out.point1 = p0.transform(c.onB);
  // Separated: along the witness difference; touching: the first mesh's triangle normal.
  const Vec3<T> local = dist > T(0) ? Vec3<T>((c.onB - c.onA) / dist) : a.triangle(c.cookedA).normal();
  out.normal = p0.rotate(local);
  return Status();
}

template Status distanceTriangleMeshTriangleMesh<float>(const Geometry<float>&, const Transform<float>&,
                                                        const Geometry<float>&, const Transform<float>&,
                                                        GjkCache<float>*, DistanceResult<float>&, float);
template Status distanceTriangleMeshTriangleMesh<double>(const Geometry<double>&, const Transform<double>&,
                                                         const Geometry<double>&, const Transform<double>&,
                                                         GjkCache<double>*, DistanceResult<double>&, double);

}  // namespace gq::detail
