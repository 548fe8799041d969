// Sweep of a support-mapped shape against a triangle mesh: a front-to-back BVH traversal of the swept shape's box
// moving along the sweep (a "fat ray", in mesh space) visits the triangles in order of the parameter at which that box
// can first touch them, each is culled and swept (sweep/convex_triangle.cpp), and the picker keeps the closest hit
// (initial overlaps first; ties to the triangle facing the sweep most). Subtrees and triangles that the box could only
// reach beyond the current closest hit are skipped. faceIndex is the input triangle.
#include <algorithm>
#include <array>
#include <limits>
#include <vector>

#include "gq/cooking.h"
#include "bvh/traverse.h"
#include "mesh/mesh_instance.h"
#include "mesh_pairs/surface.h"
#include "sweep/sweep.h"

namespace gq::detail {
namespace {

// Visits the cooked triangle indices in leaves whose boxes overlap `q`. A fixed stack (no allocation): at most 7
// entries left per level of a BVH's bounded depth (bvh/traverse.h's kBvhStackSize).
template <class Visit> void forTrianglesInBox(const MeshBvh& bvh, const FloatBounds& q, Visit&& visit) {
  if (bvh.rootChild == MeshBvhNode::kEmpty) return;
  std::uint32_t stack[kBvhStackSize];
  int top = 0;
  stack[top++] = bvh.rootChild;
  while (top > 0) {
    const std::uint32_t ref = stack[--top];
    if (MeshBvhNode::isLeaf(ref)) {
      for (std::uint32_t k = 0; k < MeshBvhNode::leafCount(ref); ++k) visit(MeshBvhNode::leafFirst(ref) + k);
      continue;
    }
    const MeshBvhNode& node = bvh.nodes[ref];
    for (int lane = 0; lane < MeshBvhNode::kWidth; ++lane)
      if (node.child[lane] != MeshBvhNode::kEmpty && childOverlapsBox(node, lane, q)) stack[top++] = node.child[lane];
  }
}

template <class T> T childEntry(const FatRay<T>& ray, const MeshBvhNode& n, int lane, T tMax) {
  return ray.entry(Vec3<T>(T(n.minX[lane]), T(n.minY[lane]), T(n.minZ[lane])),
                   Vec3<T>(T(n.maxX[lane]), T(n.maxY[lane]), T(n.maxZ[lane])), tMax);
}

// Visits cooked triangles nearest-entry first; `visit(cooked, entry)` returns false to stop, `tMax()` gives the
// current pruning distance.
template <class T, class TMax, class Visit>
void traverseFatRay(const TriangleMesh<T>& mesh, const FatRay<T>& ray, TMax&& tMax, Visit&& visit) {
  const MeshBvh& bvh = mesh.accel->bvh;
  if (bvh.rootChild == MeshBvhNode::kEmpty) return;
  struct Entry {
    std::uint32_t ref;
    T t;
  };
  std::array<Entry, kBvhStackSize> stack;
  int top = 0;
  stack[top++] = {bvh.rootChild, T(0)};
  while (top > 0) {
    const Entry e = stack[--top];
    if (e.t > tMax()) continue;
    if (MeshBvhNode::isLeaf(e.ref)) {
      for (std::uint32_t k = 0; k < MeshBvhNode::leafCount(e.ref); ++k) {
        const std::uint32_t cooked = MeshBvhNode::leafFirst(e.ref) + k;
        const TriangleIndices& idx = mesh.triangles[cooked];
        Bounds3<T> box;
        for (const std::uint32_t v : idx) box.include(mesh.vertices[v]);
        const T t = ray.entry(box.min, box.max, tMax());
        if (t <= tMax() && !visit(cooked)) return;
      }
      continue;
    }
    const MeshBvhNode& node = bvh.nodes[e.ref];
    std::array<Entry, MeshBvhNode::kWidth> hit;
    int n = 0;
    for (int lane = 0; lane < MeshBvhNode::kWidth; ++lane) {
      if (node.child[lane] == MeshBvhNode::kEmpty) continue;
      const T t = childEntry(ray, node, lane, tMax());
      if (t <= tMax()) hit[n++] = {node.child[lane], t};
    }
    if (n > MeshBvhNode::kWidth) __builtin_unreachable();  // tells GCC that std::sort's 16-element prefix pass is dead
    std::sort(hit.begin(), hit.begin() + n, [](const Entry& x, const Entry& y) { return x.t > y.t; });
    for (int i = 0; i < n && top < kBvhStackSize; ++i) stack[top++] = hit[i];  // nearest pushed last, popped first
  }
}

// Mesh-space box of a shape-space box: the 8 corners through S^-1.
template <class T> Bounds3<T> toMeshSpace(const Bounds3<T>& b, const Mat3<T>& invScale) {
  Bounds3<T> m;
  for (int c = 0; c < 8; ++c) {
    const Vec3<T> corner((c & 1) ? b.max.x() : b.min.x(), (c & 2) ? b.max.y() : b.min.y(), (c & 4) ? b.max.z() : b.min.z());
    m.include(invScale * corner);
  }
  return m;
}

}  // namespace

template <class T>
void sweepConvexTriangleMesh(const Geometry<T>& g0, const Transform<T>& p0, const Geometry<T>& g1,
                             const Transform<T>& p1, const SweepQuery<T>& q, SweepOutcome<T>& out) {
  const auto& meshGeom = g1.template get<TriangleMeshGeometry<T>>();
  const MeshInstance<T> inst(meshGeom, p1);
  const ConvexShape<T> a = makeSweptShape(g0, p0, q.inflation);
  const Bounds3<T> shapeBox = sweptBoundsInFrame(a, p1, q.dir, q.maxDist);
  const Bounds3<T> startBox = toMeshSpace(sweptBoundsInFrame(a, p1, q.dir, T(0)), inst.invScale);
  const FatRay<T> ray{startBox.center(), Vec3<T>(inst.invScale * p1.rotateInv(q.dir)), startBox.extents()};

  const bool doubleSided = meshGeom.doubleSided();
  TriangleHitPicker<T> picker;
  picker.tieTolerance = triangleTieTolerance(a, shapeBox);
  // Initial overlaps win (the smallest index among them): once one is found only boxes touched at t = 0 matter.
  const auto tMax = [&] { return picker.found && picker.overlap ? T(0) : picker.earlyOut(q.maxDist); };
  SweepQuery<T> local = q;
  traverseFatRay(inst.mesh, ray, tMax, [&](std::uint32_t cooked) {
    local.maxDist = picker.earlyOut(q.maxDist);
    ToiResult<T> toi;
    T facing;
    if (!sweepOneTriangle(a, inst.worldTriangle(cooked), local, doubleSided, toi, facing)) return true;
    return !picker.offer(toi, facing, inst.mesh.inputIndex[cooked], q.anyHit);
  });
  if (!picker.found) return;
  outcomeFromToi(picker.best, out);
  out.faceIndex = picker.bestIndex;
  if (!(out.initialOverlap && q.mtd)) return;
  // The triangles overlapping at the start: those whose boxes meet the start box.
  TriangleMtdPicker<T> mtd;
  forTrianglesInBox(inst.mesh.accel->bvh, toFloatBounds(startBox), [&](std::uint32_t cooked) {
    const Triangle<T> tri = inst.worldTriangle(cooked);
    T facing;
    ToiResult<T> unused;
    SweepQuery<T> overlapOnly = q;
    overlapOnly.maxDist = T(0);
    if (!sweepOneTriangle(a, tri, overlapOnly, doubleSided, unused, facing)) return;  // culled along dir
    if (unused.kind == ToiResult<T>::Kind::InitialOverlap)
      mtd.offer(a, tri, inst.mesh.inputIndex[cooked], doubleSided || !q.cullBackFaces);
  });
  mtd.writeTo(out, q.dir);
}

template void sweepConvexTriangleMesh<float>(const Geometry<float>&, const Transform<float>&, const Geometry<float>&,
                                             const Transform<float>&, const SweepQuery<float>&, SweepOutcome<float>&);
template void sweepConvexTriangleMesh<double>(const Geometry<double>&, const Transform<double>&,
                                              const Geometry<double>&, const Transform<double>&,
                                              const SweepQuery<double>&, SweepOutcome<double>&);

}  // namespace gq::detail
