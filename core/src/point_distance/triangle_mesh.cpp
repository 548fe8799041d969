// Distance from a point to a triangle mesh surface: best-first BVH traversal in shape space (scale applied,
// pose removed; distances are world distances there). A child's mesh-space box maps to the box
// center' = S c, extents' = |S| e, which contains the scaled child, so the point's distance to it is a lower bound.
#include <limits>

#include "bvh/traverse.h"
#include "mesh/mesh_instance.h"
#include "mesh/triangle.h"
#include "point_distance/point_distance.h"

namespace gq::detail {
namespace {

template <class T> T squaredDistanceToBox(const Vec3<T>& p, const Vec3<T>& center, const Vec3<T>& extents) {
  const Vec3<T> d = ((p - center).cwiseAbs() - extents).cwiseMax(T(0));
  return d.squaredNorm();
}

}  // namespace

template <class T>
void pointDistanceTriangleMesh(const TriangleMeshGeometry<T>& g, const Transform<T>& pose, const Vec3<T>& point,
                               PointDistanceResult<T>& out) {
  const MeshInstance<T> inst(g, pose);
  const TriangleMesh<T>& mesh = inst.mesh;
  const Vec3<T> p = pose.transformInv(point);
  const Mat3<T> absScale = inst.scale.cwiseAbs();
  // Shrinks lower bounds by a few ulps so rounding never prunes a child that holds the answer.
  constexpr T kBoundSafety = T(1) - T(16) * std::numeric_limits<T>::epsilon();

  T bestSq = std::numeric_limits<T>::infinity();
  Vec3<T> bestPoint = Vec3<T>::Zero();
  std::uint32_t bestCooked = 0;
  auto lowerBound = [&](const MeshBvhNode& node, int i) {
    const Vec3<T> lo(T(node.minX[i]), T(node.minY[i]), T(node.minZ[i]));
    const Vec3<T> hi(T(node.maxX[i]), T(node.maxY[i]), T(node.maxZ[i]));
    const Vec3<T> c = inst.scale * ((lo + hi) * T(0.5));
    const Vec3<T> e = absScale * ((hi - lo) * T(0.5));
    return squaredDistanceToBox(p, c, e) * kBoundSafety;
  };
  auto leaf = [&](std::uint32_t first, std::uint32_t count) {
    for (std::uint32_t c = first; c < first + count; ++c) {
      const TriangleIndices& idx = mesh.triangles[c];
      const Vec3<T> a = inst.scale * mesh.vertices[idx[0]], b = inst.scale * mesh.vertices[idx[1]],
                    d = inst.scale * mesh.vertices[idx[2]];
      const Vec3<T> q = closestPointOnTriangle(p, a, b, d);
      const T distSq = (q - p).squaredNorm();
      const bool tieLowerIndex = distSq == bestSq && mesh.inputIndex[c] < mesh.inputIndex[bestCooked];
      if (distSq < bestSq || tieLowerIndex) {
        bestSq = distSq;
        bestPoint = q;
        bestCooked = c;
      }
    }
  };
  traverseNearest(mesh.accel->bvh, bestSq, lowerBound, leaf);
  out.distance = std::sqrt(bestSq);
  out.closestPoint = pose.transform(bestPoint);
  out.closestIndex = mesh.inputIndex[bestCooked];
}

template void pointDistanceTriangleMesh<float>(const TriangleMeshGeometry<float>&, const Transform<float>&,
                                               const Vec3<float>&, PointDistanceResult<float>&);
template void pointDistanceTriangleMesh<double>(const TriangleMeshGeometry<double>&, const Transform<double>&,
                                                const Vec3<double>&, PointDistanceResult<double>&);

}  // namespace gq::detail
