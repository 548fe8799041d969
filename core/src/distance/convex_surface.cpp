// Convex shape vs triangle mesh / heightfield distance (see surface_distance.h). Computed in the surface's frame
// (the surface at the identity) and mapped back, so far-away poses keep their precision.
#include <cmath>
#include <vector>

#include "bvh/traverse.h"
#include "distance/surface_distance.h"
#include "mesh_pairs/shape_triangle.h"
#include "mesh_pairs/surface.h"
#include "mesh_pairs/triangle_tests.h"

namespace gq::detail {
namespace {

template <class T> struct Best {
  bool found = false;
  T limit = std::numeric_limits<T>::infinity();  // the caller's farEnough (>= 0): farther triangles are not wanted
  DistanceResult<T> result;
  // A triangle beyond the limit is not kept: triangles pruned by the limit before it may be nearer, so it would be
  // neither the answer nor a lower bound (a stop reports just above the limit instead).
  void offer(const DistanceResult<T>& r) {
    if (r.distance > limit) return;
    if (!found || r.distance < result.distance) result = r;
    found = true;
  }
  // Distance a triangle must not exceed to be kept, and its square for culling boxes (the limit until one is found).
  T bound() const { return found ? result.distance : limit; }
  T boundSq() const { return found ? result.distance * result.distance : limit * limit; }
  bool bounded() const { return found || limit < std::numeric_limits<T>::infinity(); }
};

// Best-first over the BVH: children nearest to the shape's box first, pruned by the best distance found; a triangle
// whose box passes is pruned by the shape's ball too before its GJK (hulls and boxes: the ball test takes mesh-convex30
// distance in the FCL adapter from ~206,000 to ~165,000 instructions).
template <class T> void nearestOnMesh(const TriangleQueryShape<T>& shape, const MeshSurface<T>& mesh, Best<T>& best) {
  const MeshBvh& bvh = mesh.mesh().accel->bvh;
  if (bvh.rootChild == MeshBvhNode::kEmpty) return;
  const Bounds3<T> box = shape.worldBounds();
  const bool ballBound = shape.distanceRunsGjk();  // a triangle's ball bound before its GJK
  struct Entry {
    std::uint32_t ref;
    T lower;
  };
  // A fixed stack (no allocation): at most 7 entries left per level of a BVH's bounded depth (bvh/traverse.h).
  Entry stack[kBvhStackSize];
  int top = 0;
  stack[top++] = {bvh.rootChild, T(0)};
  while (top > 0) {
    const Entry e = stack[--top];
    if (e.lower > best.boundSq()) continue;
    if (MeshBvhNode::isLeaf(e.ref)) {
      for (std::uint32_t k = 0; k < MeshBvhNode::leafCount(e.ref); ++k) {
        const Triangle<T> tri = mesh.leafTriangle(e.ref, k);
        if (boxDistanceSq(box, triangleBounds(tri)) > best.boundSq()) continue;
        if (ballBound && best.bounded() && shape.distanceLowerBound(tri) > best.bound()) continue;
        DistanceResult<T> r;
        if (!shape.distanceTo(tri, r, best.bound())) continue;
        best.offer(r);
        if (best.found && best.result.distance <= T(0)) return;
      }
      continue;
    }
    const MeshBvhNode& node = mesh.mesh().accel->bvh.nodes[e.ref];
    Entry children[MeshBvhNode::kWidth];
    int n = 0;
    for (int lane = 0; lane < MeshBvhNode::kWidth; ++lane) {
      if (node.child[lane] == MeshBvhNode::kEmpty) continue;
      const Entry c{node.child[lane], boxDistanceSq(box, mesh.childWorldBounds(node, lane))};
      if (!(c.lower > best.boundSq())) insertNearestLast(children, n, c);
    }
    for (int i = 0; i < n; ++i) stack[top++] = children[i];
  }
}

// Heightfield: cells under the shape's box grown by a radius that doubles until a triangle is found or the radius
// passes the caller's limit, then one pass with the radius grown to the best distance (every closer triangle lies in
// that box).
template <class T>
void nearestOnHeightField(const TriangleQueryShape<T>& shape, const HeightFieldSurface<T>& field, Best<T>& best) {
  const Bounds3<T> box = shape.worldBounds();
  const Bounds3<T> fieldBox = field.worldBounds();
  const T span = (fieldBox.max - fieldBox.min).norm();
  T radius = std::max(std::sqrt(boxDistanceSq(box, fieldBox)), std::max(shape.size(), span * T(1e-3)));
  const bool ballBound = shape.distanceRunsGjk();
  const auto visit = [&](std::uint32_t, const Triangle<T>& tri) {
    if (boxDistanceSq(box, triangleBounds(tri)) > best.boundSq()) return false;
    if (ballBound && best.bounded() && shape.distanceLowerBound(tri) > best.bound()) return false;
    DistanceResult<T> r;
    if (!shape.distanceTo(tri, r, best.bound())) return false;
    best.offer(r);
    return best.found && best.result.distance <= T(0);
  };
  // Beyond this radius the grown box holds the whole heightfield: nothing found means every cell is a hole.
  const T limit = std::sqrt(boxDistanceSq(box, fieldBox)) + span;
  for (;;) {
    field.forEachTriangle(grown(box, radius), visit);
    // !(radius <= limit) also ends NaN bounds, and an infinite radius has just visited every cell (coordinates
    // beyond the scalar range made `limit` infinite and this loop endless; found by fuzz_pair_queries).
    if (best.found || !(radius <= limit) || !std::isfinite(radius)) break;
    if (radius >= best.limit) return;  // every triangle within the caller's limit has been visited
    radius *= T(2);
  }
  if (best.found && best.result.distance > radius) field.forEachTriangle(grown(box, best.result.distance), visit);
}

}  // namespace

template <class T>
Status distanceConvexSurface(const Geometry<T>& g0, const Transform<T>& p0, const Geometry<T>& g1,
                             const Transform<T>& p1, GjkCache<T>* cache, DistanceResult<T>& out, T farEnough) {
  const TriangleQueryShape<T> shape(g0, p0.relativeTo(p1));
  Best<T> best;
  const auto* m = g1.template getIf<TriangleMeshGeometry<T>>();
  // An empty mesh keeps its status; a heightfield without a cell within the bound (holes included) is beyond it.
  const bool searchable = !m || m->mesh->accel->bvh.rootChild != MeshBvhNode::kEmpty;
  if (cache) cache->iterations = 0;
  if (farEnough < T(0) && searchable) {  // nothing of a surface is closer than 0
    out.distance = surfaceBoundBeyond(farEnough);
    return Status();
  }
  best.limit = farEnough;
  if (m) nearestOnMesh(shape, MeshSurface<T>(*m, Transform<T>()), best);
  else nearestOnHeightField(shape, HeightFieldSurface<T>(g1.template get<HeightFieldGeometry<T>>(), Transform<T>()), best);
  if (!best.found && searchable && farEnough < std::numeric_limits<T>::infinity()) {
    out.distance = surfaceBoundBeyond(farEnough);
    return Status();
  }
  if (!best.found) return Status::degenerate("the surface has no triangles (every heightfield cell is a hole)");
  out.distance = best.result.distance;
  out.point0 = p1.transform(best.result.point0);
  out.point1 = p1.transform(best.result.point1);
  out.normal = p1.rotate(best.result.normal);
  return Status();
}

template Status distanceConvexSurface<float>(const Geometry<float>&, const Transform<float>&, const Geometry<float>&,
                                             const Transform<float>&, GjkCache<float>*, DistanceResult<float>&, float);
template Status distanceConvexSurface<double>(const Geometry<double>&, const Transform<double>&,
                                              const Geometry<double>&, const Transform<double>&, GjkCache<double>*,
                                              DistanceResult<double>&, double);

}  // namespace gq::detail
