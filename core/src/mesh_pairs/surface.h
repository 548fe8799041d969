#pragma once
// Thin triangle surfaces (triangle-mesh and heightfield instances) seen through one interface by the pair queries:
//  - worldBounds(): the instance's world AABB;
//  - forEachTriangle(box, fn): calls fn(index, worldTriangle) for every triangle that may touch the world box `box`
//    (BVH culling for meshes, cell-range culling for heightfields; a superset, the caller runs the exact test) until
//    fn returns true; returns whether it stopped. `index` is what queries report: the input triangle index of a mesh,
//    the triangle index 2*cell+k of a heightfield.
// Inline templates on purpose: the per-triangle callable is inlined into the traversal loop.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

#include "bounds/bounds.h"
#include "bvh/bvh.h"
#include "cook/height_field_layout.h"
#include "gq/cooking.h"
#include "gq/mesh_query.h"
#include "mesh/mesh_instance.h"

namespace gq::detail {

// The next float below f: std::nextafter(f, -inf), inline (the libm call cost ~25 instructions, six a mesh query).
// On the bits of a finite nonzero float, one step towards -inf is one less for a positive value and one more for a
// negative one (+inf steps to the largest float, the largest negative float to -inf); -inf and NaN stay.
inline float floatBelow(float f) {
  if (!(f > -std::numeric_limits<float>::infinity())) return f;
  if (f == 0.0f) return -std::numeric_limits<float>::denorm_min();
  std::uint32_t bits;
  std::memcpy(&bits, &f, sizeof bits);
  bits = f > 0.0f ? bits - 1u : bits + 1u;
  std::memcpy(&f, &bits, sizeof bits);
  return f;
}
inline float floatAbove(float f) { return -floatBelow(-f); }

// A float box containing the T box (rounded outward), for tests against the BVH's float node boxes.
struct FloatBounds {
  float lo[3], hi[3];
};
template <class T> FloatBounds toFloatBounds(const Bounds3<T>& b) {
  FloatBounds f;
  for (int i = 0; i < 3; ++i) {
    f.lo[i] = floatBelow(static_cast<float>(b.min[i]));
    f.hi[i] = floatAbove(static_cast<float>(b.max[i]));
  }
  return f;
}

inline bool childOverlapsBox(const MeshBvhNode& n, int lane, const FloatBounds& q) {
  return n.minX[lane] <= q.hi[0] && n.maxX[lane] >= q.lo[0] && n.minY[lane] <= q.hi[1] && n.maxY[lane] >= q.lo[1] &&
         n.minZ[lane] <= q.hi[2] && n.maxZ[lane] >= q.lo[2];
}

// AABB of the image of box `b` under x -> linear * x + offset: centre maps, extents grow by |linear|.
template <class T> Bounds3<T> mapBox(const Bounds3<T>& b, const Mat3<T>& linear, const Vec3<T>& offset) {
  const Vec3<T> c = linear * b.center() + offset;
  const Vec3<T> e = linear.cwiseAbs() * b.extents();
  return Bounds3<T>::fromCenterExtents(c, e);
}

// The box grown by `margin` on every side.
template <class T> Bounds3<T> grown(const Bounds3<T>& b, T margin) {
  return Bounds3<T>::fromMinMax(b.min.array() - margin, b.max.array() + margin);
}

// Squared distance between two boxes (0 when they overlap).
template <class T> T boxDistanceSq(const Bounds3<T>& a, const Bounds3<T>& b) {
  const Vec3<T> gap = (a.min - b.max).cwiseMax(b.min - a.max).cwiseMax(Vec3<T>::Zero());
  return gap.squaredNorm();
}

// Best-first BVH descent: inserts `e` into children[0, n) kept in decreasing order of `e.lower` (a lower bound on
// the distance), so that pushing them in order onto a stack pops the nearest child first.
template <class Entry> void insertNearestLast(Entry* children, int& n, const Entry& e) {
  int j = n++;
  while (j > 0 && children[j - 1].lower < e.lower) {
    children[j] = children[j - 1];
    --j;
  }
  children[j] = e;
}

template <class T> class MeshSurface {
 public:
  MeshSurface(const TriangleMeshGeometry<T>& g, const Transform<T>& pose)
      : geom_(g),
        inst_(g, pose),
        linear_(pose.q.toRotationMatrix() * inst_.scale),
        invLinear_(inst_.invScale * pose.q.toRotationMatrix().transpose()),
        translationOnly_(linear_ == Mat3<T>::Identity()) {}

  const TriangleMesh<T>& mesh() const { return inst_.mesh; }
  Bounds3<T> worldBounds() const { return boundsTriangleMesh(geom_, inst_.pose); }
  std::uint32_t inputIndex(std::uint32_t cooked) const { return inst_.mesh.inputIndex[cooked]; }

  // World triangle of a cooked triangle (vertices 1 and 2 swapped under a mirrored scale, as getTriangle).
  // Without rotation or scale (the mesh queries' surface sits at the identity) the vertices are only moved: the
  // same values as the product with the identity, without its ~50 instructions a triangle.
  Triangle<T> triangle(std::uint32_t cooked) const {
    std::uint32_t stride;
    const T* values = inst_.mesh.triangleValues(cooked, stride);
    return placed(values, stride);
  }
  // triangle() of the leaf's triangle `lane` (cooked leafFirst(ref) + lane), read from the leaf's rows directly.
  // A full leaf (the common case) reads at constant offsets.
  [[gnu::always_inline]] Triangle<T> leafTriangle(std::uint32_t ref, std::uint32_t lane) const {
    const T* x = inst_.mesh.leafValues(MeshBvhNode::leafFirst(ref)) + lane;
    const std::uint32_t count = MeshBvhNode::leafCount(ref);
    return count == MeshBvhNode::kMaxLeafSize ? placed(x, MeshBvhNode::kMaxLeafSize) : placed(x, count);
  }

  // The cooked triangle's three mesh-space vertices (unscaled, in cooked order).
  std::array<Vec3<T>, 3> cookedVertices(std::uint32_t cooked) const {
    std::uint32_t s;
    const T* x = inst_.mesh.triangleValues(cooked, s);
    using Mesh = TriangleMesh<T>;
    return {Mesh::vertexIn(x, s, 0), Mesh::vertexIn(x, s, 1), Mesh::vertexIn(x, s, 2)};
  }
  // World point x to mesh space: worldToMesh() (x - position()). Mesh space to world: meshToWorld() v + position().
  const Mat3<T>& worldToMesh() const { return invLinear_; }
  const Mat3<T>& meshToWorld() const { return linear_; }
  const Vec3<T>& position() const { return inst_.pose.p; }

  // Mesh-space box of child `lane` of a BVH node.
  static Bounds3<T> childLocalBounds(const MeshBvhNode& n, int lane) {
    return Bounds3<T>::fromMinMax(Vec3<T>(T(n.minX[lane]), T(n.minY[lane]), T(n.minZ[lane])),
                                  Vec3<T>(T(n.maxX[lane]), T(n.maxY[lane]), T(n.maxZ[lane])));
  }

  // World AABB of child `lane` of a BVH node (the node's mesh-space box through scale and pose).
  Bounds3<T> childWorldBounds(const MeshBvhNode& n, int lane) const { return toWorldBox(childLocalBounds(n, lane)); }
  Bounds3<T> toWorldBox(const Bounds3<T>& local) const { return mapBox(local, linear_, inst_.pose.p); }

  // Mesh-space AABB of a world box: x_mesh = linear^-1 (x - p), linear^-1 = S^-1 R^T.
  Bounds3<T> toLocalBox(const Bounds3<T>& world) const { return mapBox(world, invLinear_, Vec3<T>(-(invLinear_ * inst_.pose.p))); }

  // Mesh-space box containing the world box: its 8 corners through pose^-1 and S^-1.
  Bounds3<T> toMeshSpace(const Bounds3<T>& world) const {
    Bounds3<T> m;
    for (int c = 0; c < 8; ++c) {
      const Vec3<T> corner((c & 1) ? world.max.x() : world.min.x(), (c & 2) ? world.max.y() : world.min.y(),
                           (c & 4) ? world.max.z() : world.min.z());
      m.include(Vec3<T>(inst_.invScale * inst_.pose.transformInv(corner)));
    }
    return m;
  }

  template <class Fn> bool forEachTriangle(const Bounds3<T>& worldBox, Fn&& fn) const {
    return forEachTriangleInMeshBox(toMeshSpace(worldBox), fn);
  }

  // forEachTriangle on a box given in mesh space (x_mesh = worldToMesh() (x - position())), for callers that bound
  // their shape there directly: tighter than the mesh-space box of a world box when the mesh is rotated.
  template <class Fn> bool forEachTriangleInMeshBox(const Bounds3<T>& meshBox, Fn&& fn) const {
    return forEachLeaf(meshBox, [&](std::uint32_t ref) {
      for (std::uint32_t lane = 0; lane < MeshBvhNode::leafCount(ref); ++lane)
        if (fn(inputIndex(MeshBvhNode::leafFirst(ref) + lane), leafTriangle(ref, lane))) return true;
      return false;
    }, [](const Bounds3<T>&) { return false; });
  }

  // fn(cooked) for every cooked triangle whose BVH leaf box meets the mesh-space box, until fn returns true.
  template <class Fn> bool forEachCookedTriangle(const Bounds3<T>& meshBox, Fn&& fn) const {
    return forEachCookedTriangle(meshBox, fn, [](const Bounds3<T>&) { return false; });
  }
  // The same, skipping every child whose mesh-space box `skip` proves holds no triangle fn would accept.
  template <class Fn, class Skip> bool forEachCookedTriangle(const Bounds3<T>& meshBox, Fn&& fn, Skip&& skip) const {
    return forEachLeaf(meshBox, [&](std::uint32_t ref) {
      const std::uint32_t first = MeshBvhNode::leafFirst(ref), count = MeshBvhNode::leafCount(ref);
      for (std::uint32_t k = first; k < first + count; ++k)
        if (fn(k)) return true;
      return false;
    }, skip);
  }

  // leafFn(ref) for every BVH leaf whose box meets the mesh-space box (children `skip` rejects left out), until it
  // returns true.
  template <class LeafFn, class Skip>
  bool forEachLeaf(const Bounds3<T>& meshBox, LeafFn&& leafFn, Skip&& skip) const {
    const MeshBvh& bvh = inst_.mesh.accel->bvh;
    if (bvh.rootChild == MeshBvhNode::kEmpty) return false;
    const FloatBounds q = toFloatBounds(meshBox);
    std::uint32_t stack[kStackSize];
    int top = 0;
    stack[top++] = bvh.rootChild;
    while (top > 0) {
      const std::uint32_t ref = stack[--top];
      if (MeshBvhNode::isLeaf(ref)) {
        if (leafFn(ref)) return true;
        continue;
      }
      const MeshBvhNode& node = bvh.nodes[ref];
      for (int lane = 0; lane < MeshBvhNode::kWidth; ++lane)
        if (node.child[lane] != MeshBvhNode::kEmpty && childOverlapsBox(node, lane, q) &&
            !skip(childLocalBounds(node, lane)))
          stack[top++] = node.child[lane];
    }
    return false;
  }

  // Depth-first stack bound: the build's depth limit (60 levels) times 7 siblings left behind per level, plus slack.
  static constexpr int kStackSize = 512;

 private:
  // The world triangle of the values at x (vertices 1 and 2 swapped under a mirrored scale). Forced inline, as its
  // callers: the leaf loops of the mesh pairs are otherwise left calls (about 10 % more instructions a query).
  [[gnu::always_inline]] Triangle<T> placed(const T* x, std::uint32_t stride) const {
    using Mesh = TriangleMesh<T>;
    const Vec3<T> v[3] = {Mesh::vertexIn(x, stride, 0), Mesh::vertexIn(x, stride, 1), Mesh::vertexIn(x, stride, 2)};
    Triangle<T> t;
    if (translationOnly_) {  // R S = I: det S = 1, no mirror
      for (int k = 0; k < 3; ++k) t.verts[k] = v[k] + inst_.pose.p;
      return t;
    }
    t.verts[0] = linear_ * v[0] + inst_.pose.p;
    t.verts[1] = linear_ * v[inst_.flips ? 2 : 1] + inst_.pose.p;
    t.verts[2] = linear_ * v[inst_.flips ? 1 : 2] + inst_.pose.p;
    return t;
  }

  const TriangleMeshGeometry<T>& geom_;
  MeshInstance<T> inst_;
  Mat3<T> linear_;     // rotation * S: mesh space -> world, before translation
  Mat3<T> invLinear_;  // S^-1 * rotation^T
  bool translationOnly_;  // linear_ is the identity
};

template <class T> class HeightFieldSurface {
 public:
  HeightFieldSurface(const HeightFieldGeometry<T>& g, const Transform<T>& pose)
      : geom_(g), hf_(*g.heightField), pose_(pose), unrotated_(pose.q.coeffs() == Quat<T>::Identity().coeffs()) {}

  Bounds3<T> worldBounds() const { return boundsHeightField(geom_, pose_); }

  // Unrotated (the mesh queries' surface sits at the identity), the vertices and the box corners are only moved: the
  // same values as the identity quaternion's products, without their ~30 instructions each.
  Triangle<T> triangle(std::uint32_t index) const {
    const std::array<std::uint32_t, 3> s = heightFieldTriangleSamples(hf_, index);
    Triangle<T> t;
    for (int k = 0; k < 3; ++k)
      t.verts[k] = unrotated_ ? Vec3<T>(heightFieldVertex(geom_, s[k]) + pose_.p)
                              : pose_.transform(heightFieldVertex(geom_, s[k]));
    return t;
  }

  template <class Fn> bool forEachTriangle(const Bounds3<T>& worldBox, Fn&& fn) const {
    // The box in the heightfield's frame, then the cells whose row/column spans meet it (one cell of slack each side:
    // the exact test decides).
    Bounds3<T> local;
    if (unrotated_)
      local = Bounds3<T>::fromMinMax(Vec3<T>(worldBox.min - pose_.p), Vec3<T>(worldBox.max - pose_.p));
    else
      for (int c = 0; c < 8; ++c)
        local.include(pose_.transformInv(Vec3<T>((c & 1) ? worldBox.max.x() : worldBox.min.x(),
                                                 (c & 2) ? worldBox.max.y() : worldBox.min.y(),
                                                 (c & 4) ? worldBox.max.z() : worldBox.min.z())));
    std::uint32_t r0, r1, c0, c1;
    if (!cellRange(local.min.x(), local.max.x(), geom_.rowScale, hf_.rows - 1, r0, r1)) return false;
    if (!cellRange(local.min.z(), local.max.z(), geom_.columnScale, hf_.columns - 1, c0, c1)) return false;
    const T yLo = local.min.y(), yHi = local.max.y();
    for (std::uint32_t r = r0; r <= r1; ++r) {
      for (std::uint32_t c = c0; c <= c1; ++c) {
        if (hf_.isHole(r, c)) continue;
        if (!cellHeightsMeet(r, c, yLo, yHi)) continue;
        const std::uint32_t cell = heightFieldCellIndex(hf_, r, c);
        if (fn(2 * cell, triangle(2 * cell)) || fn(2 * cell + 1, triangle(2 * cell + 1))) return true;
      }
    }
    return false;
  }

 private:
  // Cells [first, last] of `cells` whose span [i*scale, (i+1)*scale] (either sign of scale) may meet [lo, hi].
  static bool cellRange(T lo, T hi, T scale, std::uint32_t cells, std::uint32_t& first, std::uint32_t& last) {
    double a = double(lo) / double(scale), b = double(hi) / double(scale);
    // A NaN span (a box with inf - inf corners, from coordinates beyond the scalar range) would convert to a
    // garbage cell range (a near-endless loop, found by fuzz_pair_queries): take every cell, the exact test decides.
    if (std::isnan(a) || std::isnan(b)) {
      first = 0;
      last = cells - 1;
      return true;
    }
    if (a > b) std::swap(a, b);
    a = std::floor(a) - 1.0;
    b = std::floor(b) + 1.0;
    if (b < 0.0 || a > double(cells) - 1.0) return false;
    first = std::uint32_t(std::max(a, 0.0));
    last = std::uint32_t(std::min(b, double(cells) - 1.0));
    return true;
  }

  // Whether the cell's height range (its 4 samples, scaled) meets [yLo, yHi] of the local box.
  bool cellHeightsMeet(std::uint32_t r, std::uint32_t c, T yLo, T yHi) const {
    const T h[4] = {hf_.height(r, c), hf_.height(r, c + 1), hf_.height(r + 1, c), hf_.height(r + 1, c + 1)};
    T lo = std::numeric_limits<T>::max(), hi = -std::numeric_limits<T>::max();
    for (T x : h) {
      lo = std::min(lo, x * geom_.heightScale);
      hi = std::max(hi, x * geom_.heightScale);
    }
    return lo <= yHi && hi >= yLo;
  }

  const HeightFieldGeometry<T>& geom_;
  const HeightField<T>& hf_;
  Transform<T> pose_;
  bool unrotated_;  // pose_.q is exactly the identity quaternion
};

}  // namespace gq::detail
