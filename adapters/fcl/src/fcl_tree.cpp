// Queries of a BVHModel on FCL's own BV tree (see fcl_tree.h). FCL 0.7 keeps every BV in the model's frame (its
// traversals use them so; makeParentRelative is never called by FCL), a leaf holds one triangle whose id is
// primitiveId() (an index into tri_indices, FCL's triangle id), and a node's children are first_child and
// first_child + 1. Each BV is bounded by a box in the model frame; the shape is expressed in the model frame, so no
// triangle is transformed until it is a contact.
#include "fcl_tree.h"

#include <fcl/geometry/bvh/BVH_model.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "geometry_cache.h"
#include "gq/kernels/mesh.h"

namespace gq::fcl::internal {
namespace {

template <class T> Bounds3<T> orientedBox(const Mat3<T>& axes, const Vec3<T>& centre, const Vec3<T>& half) {
  return Bounds3<T>::fromCenterExtents(centre, axes.cwiseAbs() * half);
}
template <class T> Bounds3<T> boxOf(const ::fcl::AABB<T>& b) { return Bounds3<T>::fromMinMax(b.min_, b.max_); }
template <class T> Bounds3<T> boxOf(const ::fcl::OBB<T>& b) { return orientedBox<T>(b.axis, b.To, b.extent); }
// RSS: a rectangle [0, l0] x [0, l1] from To along its first two axes, swept by a ball of radius r.
template <class T> Bounds3<T> boxOf(const ::fcl::RSS<T>& b) {
  return orientedBox<T>(b.axis, b.center(), Vec3<T>(b.l[0] / 2 + b.r, b.l[1] / 2 + b.r, b.r));
}
template <class T> Bounds3<T> boxOf(const ::fcl::OBBRSS<T>& b) { return boxOf(b.obb); }
template <class T> Bounds3<T> boxOf(const ::fcl::kIOS<T>& b) { return boxOf(b.obb); }  // the volume is inside its OBB
template <class T, std::size_t N> Bounds3<T> boxOf(const ::fcl::KDOP<T, N>& b) {
  return Bounds3<T>::fromMinMax(Vec3<T>(b.dist(0), b.dist(1), b.dist(2)),
                                Vec3<T>(b.dist(N / 2), b.dist(N / 2 + 1), b.dist(N / 2 + 2)));
}

// A node's box grown by a relative epsilon: FCL fits its BVs with its own rounding, so a touching triangle is never
// culled by it.
template <class BV> Bounds3<typename BV::S> nodeBox(const BV& bv) {
  using T = typename BV::S;
  Bounds3<T> b = boxOf(bv);
  const T pad = T(16) * std::numeric_limits<T>::epsilon() * (b.min.cwiseAbs().maxCoeff() + b.max.cwiseAbs().maxCoeff());
  b.min.array() -= pad;
  b.max.array() += pad;
  return b;
}

template <class T> T boxDistance(const Bounds3<T>& a, const Bounds3<T>& b) {
  const Vec3<T> gap = (a.min - b.max).cwiseMax(b.min - a.max).cwiseMax(Vec3<T>::Zero());
  return gap.norm();
}

template <class T> Transform<T> inverse(const Transform<T>& t) {
  const Quat<T> qi = t.q.conjugate();
  return Transform<T>(qi * -t.p, qi);
}

template <class BV> Triangle<typename BV::S> localTriangle(const ::fcl::BVHModel<BV>& m, int id) {
  const ::fcl::Triangle& t = m.tri_indices[id];
  return Triangle<typename BV::S>{{m.vertices[t[0]], m.vertices[t[1]], m.vertices[t[2]]}};
}

template <class T> Triangle<T> placed(const Triangle<T>& t, const Transform<T>& pose) {
  return Triangle<T>{{pose.transform(t.verts[0]), pose.transform(t.verts[1]), pose.transform(t.verts[2])}};
}

// Depth-first in FCL's order (left child first), every triangle the shape overlaps.
template <class BV, class T = typename BV::S>
Status contactsOn(const ::fcl::BVHModel<BV>& m, const Transform<T>& meshPose, const Converted<T>& shape,
                  const Transform<T>& shapePose, bool withGeometry, std::size_t room, std::vector<PairContact<T>>& out,
                  std::uint64_t& work) {
  const gq::kernels::TriangleQueryShape<T> query(shape.geometry(), inverse(meshPose) * shapePose);
  const Bounds3<T> cull = query.cullBounds();
  thread_local std::vector<int> stack;
  stack.assign(1, 0);
  const std::size_t first = out.size();
  while (!stack.empty()) {
    const ::fcl::BVNode<BV>& node = m.getBV(stack.back());
    stack.pop_back();
    work += kNodeWork;
    if (!nodeBox(node.bv).overlaps(cull)) continue;
    if (!node.isLeaf()) {
      stack.push_back(node.rightChild());
      stack.push_back(node.leftChild());
      continue;
    }
    const int id = node.primitiveId();
    const Triangle<T> triangle = localTriangle(m, id);
    work += kTriangleTestWork;
    if (!query.overlaps(triangle)) continue;
    PairContact<T> c;
    if (withGeometry) {
      work += kTriangleGjkWork;
      bool hit = false;
      const Status s = triangleContact(shape.geometry(), shapePose, placed(triangle, meshPose), c, hit);
      if (!s.ok()) return s;
      if (!hit) continue;
    }
    c.b1 = id;
    out.push_back(c);
    if (out.size() - first >= room) break;
  }
  return {};
}

// Best first: a subtree or triangle whose lower bound is not below the nearest distance so far is skipped.
template <class BV, class T = typename BV::S>
Status distanceOn(const ::fcl::BVHModel<BV>& m, const Transform<T>& meshPose, const Converted<T>& shape,
                  const Transform<T>& shapePose, PairDistance<T>& out, T farEnough, std::uint64_t& work) {
  const gq::kernels::TriangleQueryShape<T> query(shape.geometry(), inverse(meshPose) * shapePose);
  const Bounds3<T> box = query.cullBounds();
  thread_local std::vector<std::pair<int, T>> stack;  // node, lower bound of its distance
  stack.assign(1, {0, boxDistance(nodeBox(m.getBV(0).bv), box)});
  T best = farEnough, skipped = std::numeric_limits<T>::infinity();
  DistanceResult<T> nearest;
  int nearestId = kNoPrimitive;
  while (!stack.empty()) {
    const auto [index, bound] = stack.back();
    stack.pop_back();
    if (bound >= best) {
      skipped = std::min(skipped, bound);
      continue;
    }
    const ::fcl::BVNode<BV>& node = m.getBV(index);
    work += kNodeWork;
    if (!node.isLeaf()) {
      const int l = node.leftChild(), r = node.rightChild();
      const T dl = boxDistance(nodeBox(m.getBV(l).bv), box), dr = boxDistance(nodeBox(m.getBV(r).bv), box);
      if (dl <= dr) stack.push_back({r, dr}), stack.push_back({l, dl});  // the nearer child on top
      else stack.push_back({l, dl}), stack.push_back({r, dr});
      continue;
    }
    const int id = node.primitiveId();
    const Triangle<T> triangle = localTriangle(m, id);
    if (query.distanceRunsGjk()) {
      work += kTriangleTestWork;
      const T lower = query.distanceLowerBound(triangle);
      if (lower >= best) {
        skipped = std::min(skipped, lower);
        continue;
      }
    }
    work += kTriangleGjkWork;
    DistanceResult<T> d;
    if (!query.distanceTo(triangle, d, best) || !(d.distance < best)) {
      skipped = std::min(skipped, best);
      continue;
    }
    best = d.distance;
    nearest = d;
    nearestId = id;
    if (best <= T(0)) break;  // touching or crossing: the surface distance is 0
  }
  if (nearestId == kNoPrimitive) {
    out = PairDistance<T>{std::max(skipped, farEnough), Vec3<T>::Zero(), Vec3<T>::Zero(), kNoPrimitive, kNoPrimitive};
    return {};
  }
  out = PairDistance<T>{std::max(best, T(0)), meshPose.transform(nearest.point1), meshPose.transform(nearest.point0),
                        nearestId, kNoPrimitive};
  return {};
}

// Calls f with the model as its BVHModel<BV> (the BV types FCL 0.7 builds triangle models with).
template <class T, class F> Status onModel(const MeshTree<T>& tree, F&& f) {
  const auto* g = tree.model;
  switch (::fcl::NODE_TYPE(tree.type)) {
    case ::fcl::BV_AABB: return f(*static_cast<const ::fcl::BVHModel<::fcl::AABB<T>>*>(g));
    case ::fcl::BV_OBB: return f(*static_cast<const ::fcl::BVHModel<::fcl::OBB<T>>*>(g));
    case ::fcl::BV_RSS: return f(*static_cast<const ::fcl::BVHModel<::fcl::RSS<T>>*>(g));
    case ::fcl::BV_kIOS: return f(*static_cast<const ::fcl::BVHModel<::fcl::kIOS<T>>*>(g));
    case ::fcl::BV_OBBRSS: return f(*static_cast<const ::fcl::BVHModel<::fcl::OBBRSS<T>>*>(g));
    case ::fcl::BV_KDOP16: return f(*static_cast<const ::fcl::BVHModel<::fcl::KDOP<T, 16>>*>(g));
    case ::fcl::BV_KDOP18: return f(*static_cast<const ::fcl::BVHModel<::fcl::KDOP<T, 18>>*>(g));
    case ::fcl::BV_KDOP24: return f(*static_cast<const ::fcl::BVHModel<::fcl::KDOP<T, 24>>*>(g));
    default: return Status::unsupported("BVHModel of an unknown BV type");
  }
}

}  // namespace

template <class T>
Status treeContacts(const MeshTree<T>& mesh, const Transform<T>& meshPose, const Converted<T>& shape,
                    const Transform<T>& shapePose, bool withGeometry, std::size_t room, std::vector<PairContact<T>>& out) {
  std::uint64_t work = 0;
  const Status s = onModel(mesh, [&](const auto& m) {
    return contactsOn(m, meshPose, shape, shapePose, withGeometry, room, out, work);
  });
  chargeTree(mesh, work);
  return s;
}

template <class T>
Status treeDistance(const MeshTree<T>& mesh, const Transform<T>& meshPose, const Converted<T>& shape,
                    const Transform<T>& shapePose, PairDistance<T>& out, T farEnough) {
  std::uint64_t work = 0;
  const Status s = onModel(mesh, [&](const auto& m) {
    return distanceOn(m, meshPose, shape, shapePose, out, farEnough, work);
  });
  chargeTree(mesh, work);
  return s;
}

template <class T> Bounds3<T> treeBounds(const MeshTree<T>& mesh, const Transform<T>& pose) {
  Bounds3<T> world;
  const Status s = onModel(mesh, [&](const auto& m) {
    const Bounds3<T> local = nodeBox(m.getBV(0).bv);
    world = orientedBox<T>(pose.q.toRotationMatrix(), pose.transform(local.center()), local.extents());
    return Status{};
  });
  if (s.ok()) return world;
  const T inf = std::numeric_limits<T>::infinity();  // not finite: the caller takes FCL's own AABB
  return Bounds3<T>::fromMinMax(Vec3<T>::Constant(-inf), Vec3<T>::Constant(inf));
}

template Status treeContacts<float>(const MeshTree<float>&, const Transform<float>&, const Converted<float>&,
                                    const Transform<float>&, bool, std::size_t, std::vector<PairContact<float>>&);
template Status treeContacts<double>(const MeshTree<double>&, const Transform<double>&, const Converted<double>&,
                                     const Transform<double>&, bool, std::size_t, std::vector<PairContact<double>>&);
template Status treeDistance<float>(const MeshTree<float>&, const Transform<float>&, const Converted<float>&,
                                    const Transform<float>&, PairDistance<float>&, float);
template Status treeDistance<double>(const MeshTree<double>&, const Transform<double>&, const Converted<double>&,
                                     const Transform<double>&, PairDistance<double>&, double);
template Bounds3<float> treeBounds<float>(const MeshTree<float>&, const Transform<float>&);
template Bounds3<double> treeBounds<double>(const MeshTree<double>&, const Transform<double>&);

}  // namespace gq::fcl::internal
