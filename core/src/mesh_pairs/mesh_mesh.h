#pragma once
// Dual BVH traversal of two triangle-mesh instances: visits the pairs of triangles whose world boxes, grown by
// `margin`, overlap. At each step the node with the larger box is split (so both trees descend at the same pace),
// and a child is pushed only when it still meets the other side's node on the six face axes: the frame's axes
// (callers put mesh A's frame there, so A's boxes are exact) and B's mesh axes (A's box mapped into B's mesh space
// against B's own node box). Inline template: the pair callable is inlined into the leaf loop.
#include <vector>

#include "common/thread_scratch.h"
#include "mesh_pairs/surface.h"
#include "mesh_pairs/triangle_tests.h"

namespace gq::detail {

template <class T> T boxVolume(const Bounds3<T>& b) {
  const Vec3<T> e = b.max - b.min;
  return e.x() * e.y() * e.z();
}

// Volume of the intersection of two boxes (0 when they are apart).
template <class T> T sharedVolume(const Bounds3<T>& a, const Bounds3<T>& b) {
  const Vec3<T> e = (a.max.cwiseMin(b.max) - a.min.cwiseMax(b.min)).cwiseMax(Vec3<T>::Zero());
  return e.x() * e.y() * e.z();
}

// The world box of a BVH reference: the mesh's bounds for the root, else the box stored in its parent's lane.
template <class T> struct BvhPairEntry {
  std::uint32_t refA, refB;
  Bounds3<T> boxA, boxB;
};

// Node pair of the boolean traversal: also B's node box in B's mesh space, for the test on B's axes.
template <class T> struct BvhOverlapEntry {
  std::uint32_t refA, refB;
  Bounds3<T> boxA, boxB, localB;
};

// fn(cookedA, triA, cookedB, triB) returns true to stop; returns whether it stopped.
template <class T, class PairFn>
bool forEachTrianglePair(const MeshSurface<T>& a, const MeshSurface<T>& b, T margin, PairFn&& fn) {
  const MeshBvh& bvhA = a.mesh().accel->bvh;
  const MeshBvh& bvhB = b.mesh().accel->bvh;
  if (bvhA.rootChild == MeshBvhNode::kEmpty || bvhB.rootChild == MeshBvhNode::kEmpty) return false;
  const auto meets = [margin](const Bounds3<T>& x, const Bounds3<T>& y) { return grown(x, margin).overlaps(y); };
  // A's box against B's node on both sets of face axes (a separating plane on either set proves the nodes apart).
  const auto nodesMeet = [&](const Bounds3<T>& boxA, const Bounds3<T>& boxB, const Bounds3<T>& localB) {
    return meets(boxA, boxB) && b.toLocalBox(grown(boxA, margin)).overlaps(localB);
  };
  ThreadScratch<BvhOverlapEntry<T>> scratch;  // `fn` may be a user callback that queries again: see ThreadScratch
  std::vector<BvhOverlapEntry<T>>& stack = scratch.get();
  // Root boxes from the cooked mesh-space bounds (one box map each, not a pass over the hull vertices).
  const Bounds3<T> rootA = a.toWorldBox(a.mesh().localBounds), rootB = b.toWorldBox(b.mesh().localBounds);
  if (!nodesMeet(rootA, rootB, b.mesh().localBounds)) return false;
  stack.push_back({bvhA.rootChild, bvhB.rootChild, rootA, rootB, b.mesh().localBounds});
  Triangle<T> trisA[MeshBvhNode::kMaxLeafSize], trisB[MeshBvhNode::kMaxLeafSize];
  Bounds3<T> boxesA[MeshBvhNode::kMaxLeafSize], boxesB[MeshBvhNode::kMaxLeafSize];
  while (!stack.empty()) {
    const BvhOverlapEntry<T> e = stack.back();
    stack.pop_back();
    const bool leafA = MeshBvhNode::isLeaf(e.refA), leafB = MeshBvhNode::isLeaf(e.refB);
    if (leafA && leafB) {
      const std::uint32_t firstA = MeshBvhNode::leafFirst(e.refA), countA = MeshBvhNode::leafCount(e.refA);
      const std::uint32_t firstB = MeshBvhNode::leafFirst(e.refB), countB = MeshBvhNode::leafCount(e.refB);
      for (std::uint32_t i = 0; i < countA; ++i) {
        trisA[i] = a.leafTriangle(e.refA, i);
        boxesA[i] = triangleBounds(trisA[i]);
      }
      for (std::uint32_t j = 0; j < countB; ++j) {
        trisB[j] = b.leafTriangle(e.refB, j);
        boxesB[j] = triangleBounds(trisB[j]);
      }
      for (std::uint32_t i = 0; i < countA; ++i)
        for (std::uint32_t j = 0; j < countB; ++j)
          if (meets(boxesA[i], boxesB[j]) && fn(firstA + i, trisA[i], firstB + j, trisB[j])) return true;
      continue;
    }
    // Split the larger box; children are pushed so that the one sharing the most volume with the other side is
    // popped first (a boolean query ends at the first intersecting pair, which deep overlaps reach sooner).
    const bool splitA = !leafA && (leafB || boxVolume(e.boxA) >= boxVolume(e.boxB));
    const MeshBvhNode& node = splitA ? bvhA.nodes[e.refA] : bvhB.nodes[e.refB];
    BvhOverlapEntry<T> children[MeshBvhNode::kWidth];
    T shared[MeshBvhNode::kWidth];
    int n = 0;
    for (int lane = 0; lane < MeshBvhNode::kWidth; ++lane) {
      if (node.child[lane] == MeshBvhNode::kEmpty) continue;
      BvhOverlapEntry<T> c = e;
      if (splitA) {
        c.refA = node.child[lane];
        c.boxA = a.childWorldBounds(node, lane);
      } else {
        c.refB = node.child[lane];
        c.localB = MeshSurface<T>::childLocalBounds(node, lane);
        c.boxB = b.toWorldBox(c.localB);
      }
      if (!nodesMeet(c.boxA, c.boxB, c.localB)) continue;
      const T v = sharedVolume(c.boxA, c.boxB);
      int j = n++;
      while (j > 0 && shared[j - 1] > v) {  // ascending: the largest ends on top of the stack
        children[j] = children[j - 1];
        shared[j] = shared[j - 1];
        --j;
      }
      children[j] = c;
      shared[j] = v;
    }
    for (int i = 0; i < n; ++i) stack.push_back(children[i]);
  }
  return false;
}

// Closest pair of triangles of two meshes: best-first on box distances, pruned by the best distance found so far.
// Returns the cooked indices and closest points; distSq = 0 when the meshes touch. `limitSq`: pairs at or beyond it
// are not wanted (found stays false when every pair is).
template <class T> struct MeshPairClosest {
  T distSq = std::numeric_limits<T>::infinity();
  std::uint32_t cookedA = 0, cookedB = 0;
  Vec3<T> onA = Vec3<T>::Zero(), onB = Vec3<T>::Zero();
  bool found = false;
};

template <class T>
MeshPairClosest<T> closestMeshPair(const MeshSurface<T>& a, const MeshSurface<T>& b,
                                   T limitSq = std::numeric_limits<T>::infinity()) {
  MeshPairClosest<T> best;
  best.distSq = limitSq;
  const MeshBvh& bvhA = a.mesh().accel->bvh;
  const MeshBvh& bvhB = b.mesh().accel->bvh;
  if (bvhA.rootChild == MeshBvhNode::kEmpty || bvhB.rootChild == MeshBvhNode::kEmpty) return best;
  struct Entry {
    BvhPairEntry<T> pair;
    T lower;
  };
  ThreadScratch<Entry> scratch;
  std::vector<Entry>& stack = scratch.get();
  const Bounds3<T> rootA = a.toWorldBox(a.mesh().localBounds), rootB = b.toWorldBox(b.mesh().localBounds);
  stack.push_back({{bvhA.rootChild, bvhB.rootChild, rootA, rootB}, boxDistanceSq(rootA, rootB)});
  while (!stack.empty() && best.distSq > T(0)) {
    const Entry e = stack.back();
    stack.pop_back();
    if (e.lower > best.distSq) continue;
    const BvhPairEntry<T>& p = e.pair;
    const bool leafA = MeshBvhNode::isLeaf(p.refA), leafB = MeshBvhNode::isLeaf(p.refB);
    if (leafA && leafB) {
      for (std::uint32_t i = 0; i < MeshBvhNode::leafCount(p.refA); ++i) {
        const std::uint32_t ia = MeshBvhNode::leafFirst(p.refA) + i;
        const Triangle<T> ta = a.leafTriangle(p.refA, i);
        for (std::uint32_t j = 0; j < MeshBvhNode::leafCount(p.refB); ++j) {
          const std::uint32_t ib = MeshBvhNode::leafFirst(p.refB) + j;
          const Triangle<T> tb = b.leafTriangle(p.refB, j);
          if (boxDistanceSq(triangleBounds(ta), triangleBounds(tb)) > best.distSq) continue;
          const TrianglePairClosest<T> c = closestTriangleTriangle(ta, tb);
          if (c.distSq < best.distSq) best = {c.distSq, ia, ib, c.onA, c.onB, true};
        }
      }
      continue;
    }
    // Split the larger box; push children farthest first so the nearest is popped next.
    const bool splitA = !leafA && (leafB || boxVolume(p.boxA) >= boxVolume(p.boxB));
    Entry children[MeshBvhNode::kWidth];
    int n = 0;
    const MeshBvhNode& node = splitA ? bvhA.nodes[p.refA] : bvhB.nodes[p.refB];
    for (int lane = 0; lane < MeshBvhNode::kWidth; ++lane) {
      if (node.child[lane] == MeshBvhNode::kEmpty) continue;
      Entry c;
      if (splitA) {
        const Bounds3<T> box = a.childWorldBounds(node, lane);
        c = {{node.child[lane], p.refB, box, p.boxB}, boxDistanceSq(box, p.boxB)};
      } else {
        const Bounds3<T> box = b.childWorldBounds(node, lane);
        c = {{p.refA, node.child[lane], p.boxA, box}, boxDistanceSq(p.boxA, box)};
      }
      if (!(c.lower > best.distSq)) insertNearestLast(children, n, c);
    }
    for (int i = 0; i < n; ++i) stack.push_back(children[i]);
  }
  return best;
}

}  // namespace gq::detail
