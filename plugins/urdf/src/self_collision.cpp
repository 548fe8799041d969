// Self-collision and self-distance: forward kinematics places every shape; the broadphase sorts the links with
// shapes by the x of their world AABB and sweeps (an AABB pair overlaps only if its x-intervals do), keeping pairs
// that the allowed-collision matrix does not exclude; the narrow phase tests shape pairs whose world AABBs and
// oriented boxes (the shape's local AABB carried by its pose) overlap.
// Narrow phase: gq::overlap for primitive pairs (closed forms); for pairs with a convex hull the sign of the GJK
// distance, warm-started per shape pair, because the core's hull overlap runs SAT over all edge pairs, O(E^2 V),
// which costs ~100x more on the 200-300 face hulls of real robot links.
#include <algorithm>
#include <cmath>
#include <limits>

#include "gq/urdf/self_collision.h"
#include "internal.h"

namespace gq::urdf {
namespace {

// Euclidean distance between two AABBs (0 when they overlap): a lower bound of any distance between their contents.
template <class T> T boundsDistance(const Bounds3<T>& a, const Bounds3<T>& b) {
  const Vec3<T> gap = (a.min - b.max).cwiseMax(b.min - a.max).cwiseMax(Vec3<T>::Zero());
  return gap.norm();
}

// Oriented boxes (centre c, rotation columns r, half extents e, all world) are disjoint when one of the 15 axes of
// the separating-axis theorem (3 + 3 face normals, 9 edge cross products) separates their projections. A cheap
// midphase before GJK: the AABBs of rotated link boxes overlap far more often than the boxes themselves.
template <class T> bool orientedBoxesDisjoint(const OrientedBox<T>& a, const OrientedBox<T>& b) {
  const Mat3<T> r = a.axes.transpose() * b.axes;           // b's axes in a's frame
  // Unitless guard on |R|: near-parallel edges give a near-zero cross product, whose axis must not cull.
  const T parallelGuard = T(16) * std::numeric_limits<T>::epsilon();
  const Mat3<T> absR = r.cwiseAbs().array() + parallelGuard;
  const Vec3<T> t = a.axes.transpose() * (b.centre - a.centre);
  for (int i = 0; i < 3; ++i)
    if (std::abs(t[i]) > a.halfExtents[i] + absR.row(i).dot(b.halfExtents)) return true;
  for (int j = 0; j < 3; ++j)
    if (std::abs(t.dot(r.col(j))) > absR.col(j).dot(a.halfExtents) + b.halfExtents[j]) return true;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const int i1 = (i + 1) % 3, i2 = (i + 2) % 3, j1 = (j + 1) % 3, j2 = (j + 2) % 3;
      const T ra = a.halfExtents[i1] * absR(i2, j) + a.halfExtents[i2] * absR(i1, j);
      const T rb = b.halfExtents[j1] * absR(i, j2) + b.halfExtents[j2] * absR(i, j1);
      if (std::abs(t[i2] * r(i1, j) - t[i1] * r(i2, j)) > ra + rb) return true;
    }
  return false;
}

}  // namespace

template <class T>
SelfCollisionChecker<T>::SelfCollisionChecker(std::shared_ptr<const RobotModel<T>> model) : model_(std::move(model)) {
  linkPoses_.resize(model_->links.size());
  shapePoses_.resize(model_->shapes.size());
  shapeBounds_.resize(model_->shapes.size());
  linkBounds_.resize(model_->links.size());
  caches_.resize(model_->shapes.size() * model_->shapes.size());
  localBounds_.resize(model_->shapes.size());
  shapeBoxes_.resize(model_->shapes.size());
  for (std::size_t i = 0; i < model_->shapes.size(); ++i)
    if (!computeGeomBounds(localBounds_[i], model_->shapes[i].geometry, Transform<T>(), T(0), T(1)).ok())
      localBounds_[i] = Bounds3<T>::fromCenterExtents(Vec3<T>::Zero(), Vec3<T>::Constant(T(0)));  // the narrow phase reports the invalid geometry
  for (std::uint32_t i = 0; i < model_->links.size(); ++i)
    if (!model_->links[i].shapes.empty()) order_.push_back(i);
}

template <class T> Status SelfCollisionChecker<T>::placeShapes(const std::vector<T>& q) {
  Status s = forwardKinematics(*model_, q, linkPoses_);
  if (!s.ok()) return s;
  for (std::uint32_t l : order_) linkBounds_[l] = Bounds3<T>();
  for (std::size_t i = 0; i < model_->shapes.size(); ++i) {
    const Shape<T>& shape = model_->shapes[i];
    shapePoses_[i] = linkPoses_[shape.link] * shape.origin;
    shapeBoxes_[i].axes = shapePoses_[i].q.toRotationMatrix();
    shapeBoxes_[i].centre = shapePoses_[i].transform(localBounds_[i].center());
    shapeBoxes_[i].halfExtents = localBounds_[i].extents();
    shapeBounds_[i] = Bounds3<T>::fromCenterExtents(shapeBoxes_[i].centre,
                                                    shapeBoxes_[i].axes.cwiseAbs() * shapeBoxes_[i].halfExtents);
    linkBounds_[shape.link].include(shapeBounds_[i]);
  }
  return {};
}

template <class T> void SelfCollisionChecker<T>::broadphase() {
  std::sort(order_.begin(), order_.end(),
            [&](std::uint32_t a, std::uint32_t b) { return linkBounds_[a].min.x() < linkBounds_[b].min.x(); });
  candidates_.clear();
  for (std::size_t i = 0; i < order_.size(); ++i) {
    const Bounds3<T>& bi = linkBounds_[order_[i]];
    for (std::size_t j = i + 1; j < order_.size() && linkBounds_[order_[j]].min.x() <= bi.max.x(); ++j) {
      const std::uint32_t a = order_[i], b = order_[j];
      if (!model_->isAllowed(a, b) && bi.overlaps(linkBounds_[b])) candidates_.push_back({std::min(a, b), std::max(a, b)});
    }
  }
  std::sort(candidates_.begin(), candidates_.end());
}

template <class T> Status SelfCollisionChecker<T>::narrowPhase(std::uint32_t sa, std::uint32_t sb, bool& hit) {
  const Geometry<T>& ga = model_->shapes[sa].geometry;
  const Geometry<T>& gb = model_->shapes[sb].geometry;
  if (ga.type() != GeometryType::ConvexMesh && gb.type() != GeometryType::ConvexMesh)
    return overlap(ga, shapePoses_[sa], gb, shapePoses_[sb], hit);
  DistanceResult<T> d;
  Status s = distance(d, ga, shapePoses_[sa], gb, shapePoses_[sb], &caches_[std::size_t(sa) * shapePoses_.size() + sb]);
  if (s.ok()) hit = d.distance <= T(0);  // touching counts as colliding, as gq::overlap
  return s;
}

template <class T> Status SelfCollisionChecker<T>::collide(const CollisionRequest& request, CollisionResult& result) {
  CollisionResult out;
  lastNarrow_ = 0;
  for (const LinkPair& pair : candidates_) {
    bool hit = false;
    for (std::uint32_t sa : model_->links[pair.a].shapes) {
      for (std::uint32_t sb : model_->links[pair.b].shapes) {
        if (!shapeBounds_[sa].overlaps(shapeBounds_[sb]) || orientedBoxesDisjoint(shapeBoxes_[sa], shapeBoxes_[sb]))
          continue;
        ++lastNarrow_;
        Status s = narrowPhase(sa, sb, hit);
        if (!s.ok()) return s;
        if (hit) break;
      }
      if (hit) break;
    }
    if (!hit) continue;
    out.colliding = true;
    out.pairs.push_back(pair);
    if (!request.allPairs) break;
  }
  result = std::move(out);
  return {};
}

template <class T>
Status SelfCollisionChecker<T>::checkSelfCollision(const std::vector<T>& q, CollisionResult& result,
                                                   const CollisionRequest& request) {
  Status s = placeShapes(q);
  if (!s.ok()) return s;
  broadphase();
  return collide(request, result);
}

template <class T>
Status SelfCollisionChecker<T>::checkSelfCollisionBatch(const std::vector<std::vector<T>>& qs,
                                                        std::vector<std::uint8_t>& colliding) {
  std::vector<std::uint8_t> out(qs.size(), 0);
  CollisionRequest firstOnly;
  firstOnly.allPairs = false;
  for (std::size_t i = 0; i < qs.size(); ++i) {
    CollisionResult r;
    Status s = checkSelfCollision(qs[i], r, firstOnly);
    if (!s.ok()) return Status(s.code, "configuration " + std::to_string(i) + ": " + s.message);
    out[i] = r.colliding ? 1 : 0;
  }
  colliding = std::move(out);
  return {};
}

// Every checked shape pair, nearest AABBs first so the best distance found early prunes the rest by bounds.
template <class T> Status SelfCollisionChecker<T>::selfDistance(const std::vector<T>& q, SelfDistanceResult<T>& result) {
  Status s = placeShapes(q);
  if (!s.ok()) return s;
  struct Candidate {
    T bound;
    std::uint32_t sa, sb;
  };
  std::vector<Candidate> pairs;
  for (std::uint32_t a = 0; a < model_->links.size(); ++a)
    for (std::uint32_t b = a + 1; b < model_->links.size(); ++b) {
      if (model_->isAllowed(a, b)) continue;
      for (std::uint32_t sa : model_->links[a].shapes)
        for (std::uint32_t sb : model_->links[b].shapes)
          pairs.push_back({boundsDistance(shapeBounds_[sa], shapeBounds_[sb]), sa, sb});
    }
  std::sort(pairs.begin(), pairs.end(), [](const Candidate& x, const Candidate& y) { return x.bound < y.bound; });
  SelfDistanceResult<T> best;
  best.distance = std::numeric_limits<T>::infinity();
  lastNarrow_ = 0;
  for (const Candidate& c : pairs) {
    if (c.bound > best.distance) break;
    ++lastNarrow_;
    DistanceResult<T> d;
    s = distance(d, model_->shapes[c.sa].geometry, shapePoses_[c.sa], model_->shapes[c.sb].geometry, shapePoses_[c.sb]);
    if (!s.ok()) return s;
    if (d.distance < best.distance) {
      best.distance = d.distance;
      best.pair = {model_->shapes[c.sa].link, model_->shapes[c.sb].link};
      best.point0 = d.point0;
      best.point1 = d.point1;
    }
  }
  result = best;
  return {};
}

template class SelfCollisionChecker<float>;
template class SelfCollisionChecker<double>;

}  // namespace gq::urdf
