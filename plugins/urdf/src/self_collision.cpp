// Self-collision and self-distance. Everything that does not depend on the configuration is done once: the link
// pairs the allowed-collision matrix leaves (checkedPairs_), an enclosing sphere per shape and per link (in the link
// frame) and an enclosing box per shape (shape_bounds.cpp). Per configuration: forward kinematics, world sphere
// centres (one rotation each), then for each checked link pair the link spheres, the shape spheres, the shapes'
// oriented boxes (15-axis SAT) and only then the narrow phase, gq::overlap (GJK boolean for hulls and custom
// cylinders, exact kernels for primitives, convex hulls then dual BVH for meshes). Full shape poses are computed
// lazily, for shapes that reach the oriented-box test. No allocation per check once the buffers have grown.
#include <algorithm>
#include <cmath>
#include <limits>

#include "gq/urdf/self_collision.h"
#include "internal.h"

namespace gq::urdf {
namespace {

// Culling compares world placements computed in T: spheres and boxes grow by this many ulps of the robot's size so
// that rounding never culls a touching pair (touching counts as colliding).
constexpr double kCullSlackUlps = 64.0;

// Lower bound of the distance between two shapes from their enclosing spheres (0 when the spheres overlap).
template <class T> T sphereGap(const Vec3<T>& ca, T ra, const Vec3<T>& cb, T rb) {
  return std::max(T(0), (ca - cb).norm() - ra - rb);
}

template <class T> bool spheresOverlap(const Vec3<T>& ca, T ra, const Vec3<T>& cb, T rb) {
  return (ca - cb).squaredNorm() <= (ra + rb) * (ra + rb);
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

// Length scale of the robot: the sum of its joint offsets and prismatic travels (bounds any link origin's distance
// from the root) plus the largest shape sphere.
template <class T> T robotSize(const RobotModel<T>& model, T largestShape) {
  T size = largestShape;
  for (const auto& j : model.joints) {
    size += j.origin.p.norm();
    if (j.type == JointType::Prismatic) size += std::max(std::abs(j.lower), std::abs(j.upper));
  }
  return size;
}

}  // namespace

template <class T>
SelfCollisionChecker<T>::SelfCollisionChecker(std::shared_ptr<const RobotModel<T>> model) : model_(std::move(model)) {
  const RobotModel<T>& m = *model_;
  const std::size_t links = m.links.size(), shapes = m.shapes.size();
  shapeBounds_.resize(shapes);
  T largest = T(0);
  for (std::size_t i = 0; i < shapes; ++i) {
    ShapeBound& b = shapeBounds_[i];
    detail::CullVolume<T> v;  // invalid geometry keeps a point volume: the narrow phase reports it
    (void)detail::shapeCullVolume(m.shapes[i].geometry, v);
    b.centreInLink = m.shapes[i].origin.transform(v.sphereCentre);
    b.radius = v.radius;
    b.boxCentre = v.boxCentre;
    b.boxAxes = v.boxAxes;
    b.halfExtents = v.halfExtents;
    if (m.shapes[i].boundingHull) {
      b.hull = ConvexMeshGeometry<T>(m.shapes[i].boundingHull);
      b.hasHull = true;
    }
    largest = std::max(largest, b.centreInLink.norm() + b.radius);
  }
  slack_ = T(kCullSlackUlps) * std::numeric_limits<T>::epsilon() * robotSize(m, largest);
  for (auto& b : shapeBounds_) {
    b.radius += slack_;
    b.halfExtents.array() += slack_;
  }
  linkCentreInLink_.assign(links, Vec3<T>::Zero());
  linkRadius_.assign(links, T(0));
  for (std::size_t l = 0; l < links; ++l) {
    const auto& own = m.links[l].shapes;
    if (own.empty()) continue;
    Bounds3<T> centres;
    for (std::uint32_t s : own) centres.include(shapeBounds_[s].centreInLink);
    linkCentreInLink_[l] = own.size() == 1 ? shapeBounds_[own[0]].centreInLink : centres.center();
    for (std::uint32_t s : own)
      linkRadius_[l] = std::max(linkRadius_[l], (shapeBounds_[s].centreInLink - linkCentreInLink_[l]).norm() +
                                                    shapeBounds_[s].radius);
  }
  for (std::uint32_t a = 0; a < links; ++a)
    for (std::uint32_t b = a + 1; b < links; ++b)
      if (!m.links[a].shapes.empty() && !m.links[b].shapes.empty() && !m.isAllowed(a, b)) checkedPairs_.push_back({a, b});
  linkPoses_.resize(links);
  for (std::uint32_t l = 0; l < links; ++l)
    if (!m.links[l].shapes.empty()) shapedLinks_.push_back(l);
  linkCentres_.resize(links);
  shapeCentres_.resize(shapes);
  shapePoses_.resize(shapes);
  shapeBoxes_.resize(shapes);
  placedStamp_.assign(shapes, 0);
  candidates_.reserve(checkedPairs_.size());
}

// World sphere centre of every link with shapes; shape sphere centres only where a link has several shapes (a
// single shape's sphere is its link's).
template <class T> Status SelfCollisionChecker<T>::placeLinks(const std::vector<T>& q) {
  Status s = forwardKinematics(*model_, q, linkPoses_);
  if (!s.ok()) return s;
  if (++stamp_ == 0) {  // wrapped: forget every placement
    std::fill(placedStamp_.begin(), placedStamp_.end(), 0u);
    stamp_ = 1;
  }
  for (const std::uint32_t l : shapedLinks_) {
    const auto& own = model_->links[l].shapes;
    linkCentres_[l] = linkPoses_[l].transform(linkCentreInLink_[l]);
    if (own.size() == 1) {
      shapeCentres_[own[0]] = linkCentres_[l];
      continue;
    }
    const Mat3<T> r = linkPoses_[l].q.toRotationMatrix();
    for (std::uint32_t i : own) shapeCentres_[i] = r * shapeBounds_[i].centreInLink + linkPoses_[l].p;
  }
  return {};
}

template <class T> void SelfCollisionChecker<T>::placeShape(std::uint32_t i) {
  if (placedStamp_[i] == stamp_) return;
  placedStamp_[i] = stamp_;
  const Shape<T>& shape = model_->shapes[i];
  shapePoses_[i] = linkPoses_[shape.link] * shape.origin;
  const Mat3<T> r = shapePoses_[i].q.toRotationMatrix();
  OrientedBox<T>& box = shapeBoxes_[i];
  box.axes = r * shapeBounds_[i].boxAxes;
  box.centre = shapePoses_[i].p + r * shapeBounds_[i].boxCentre;
  box.halfExtents = shapeBounds_[i].halfExtents;
}

template <class T> void SelfCollisionChecker<T>::broadphase() {
  candidates_.clear();
  for (const LinkPair& p : checkedPairs_)
    if (spheresOverlap(linkCentres_[p.a], linkRadius_[p.a], linkCentres_[p.b], linkRadius_[p.b])) candidates_.push_back(p);
}

template <class T> bool SelfCollisionChecker<T>::shapesMayTouch(std::uint32_t sa, std::uint32_t sb) {
  const bool sameAsLinkSpheres = model_->links[model_->shapes[sa].link].shapes.size() == 1 &&
                                 model_->links[model_->shapes[sb].link].shapes.size() == 1;
  if (!sameAsLinkSpheres &&
      !spheresOverlap(shapeCentres_[sa], shapeBounds_[sa].radius, shapeCentres_[sb], shapeBounds_[sb].radius))
    return false;
  placeShape(sa);
  placeShape(sb);
  return !orientedBoxesDisjoint(shapeBoxes_[sa], shapeBoxes_[sb]);
}

// Mesh shapes first meet as their convex hulls (GJK): disjoint hulls prove disjoint meshes.
template <class T> Status SelfCollisionChecker<T>::narrowPhase(std::uint32_t sa, std::uint32_t sb, bool& hit) {
  const Geometry<T>& ga = model_->shapes[sa].geometry;
  const Geometry<T>& gb = model_->shapes[sb].geometry;
  if (shapeBounds_[sa].hasHull || shapeBounds_[sb].hasHull) {
    const Geometry<T>& ha = shapeBounds_[sa].hasHull ? shapeBounds_[sa].hull : ga;
    const Geometry<T>& hb = shapeBounds_[sb].hasHull ? shapeBounds_[sb].hull : gb;
    bool hullsTouch = false;
    if (Status s = overlap(ha, shapePoses_[sa], hb, shapePoses_[sb], hullsTouch); !s.ok()) return s;
    if (!hullsTouch) {
      hit = false;
      return {};
    }
  }
  return overlap(ga, shapePoses_[sa], gb, shapePoses_[sb], hit);
}

template <class T> Status SelfCollisionChecker<T>::collide(const CollisionRequest& request, CollisionResult& result) {
  lastNarrow_ = 0;
  hits_.clear();
  for (const LinkPair& pair : candidates_) {
    bool hit = false;
    for (std::uint32_t sa : model_->links[pair.a].shapes) {
      for (std::uint32_t sb : model_->links[pair.b].shapes) {
        if (!shapesMayTouch(sa, sb)) continue;
        ++lastNarrow_;
        Status s = narrowPhase(sa, sb, hit);
        if (!s.ok()) return s;
        if (hit) break;
      }
      if (hit) break;
    }
    if (!hit) continue;
    hits_.push_back(pair);
    if (!request.allPairs) break;
  }
  result.colliding = !hits_.empty();
  result.pairs.assign(hits_.begin(), hits_.end());  // reuses the caller's capacity
  return {};
}

template <class T>
Status SelfCollisionChecker<T>::checkSelfCollision(const std::vector<T>& q, CollisionResult& result,
                                                   const CollisionRequest& request) {
  Status s = placeLinks(q);
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
  CollisionResult r;
  for (std::size_t i = 0; i < qs.size(); ++i) {
    Status s = checkSelfCollision(qs[i], r, firstOnly);
    if (!s.ok()) return Status(s.code, "configuration " + std::to_string(i) + ": " + s.message);
    out[i] = r.colliding ? 1 : 0;
  }
  colliding = std::move(out);
  return {};
}

// Every checked shape pair, nearest enclosing spheres first, so the best distance found early prunes the rest.
template <class T> Status SelfCollisionChecker<T>::selfDistance(const std::vector<T>& q, SelfDistanceResult<T>& result) {
  Status s = placeLinks(q);
  if (!s.ok()) return s;
  struct Candidate {
    T bound;
    std::uint32_t sa, sb;
  };
  std::vector<Candidate> pairs;
  for (const LinkPair& p : checkedPairs_)
    for (std::uint32_t sa : model_->links[p.a].shapes)
      for (std::uint32_t sb : model_->links[p.b].shapes)
        pairs.push_back({sphereGap(shapeCentres_[sa], shapeBounds_[sa].radius, shapeCentres_[sb], shapeBounds_[sb].radius),
                         sa, sb});
  std::sort(pairs.begin(), pairs.end(), [](const Candidate& x, const Candidate& y) { return x.bound < y.bound; });
  SelfDistanceResult<T> best;
  best.distance = std::numeric_limits<T>::infinity();
  lastNarrow_ = 0;
  for (const Candidate& c : pairs) {
    if (c.bound > best.distance) break;
    ++lastNarrow_;
    placeShape(c.sa);
    placeShape(c.sb);
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
