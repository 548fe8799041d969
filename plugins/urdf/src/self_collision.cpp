// Self-collision and self-distance. Everything that does not depend on the configuration is done once: the link
// pairs the allowed-collision matrix leaves (checkedPairs_, most often touching first: pair_order.h), the compiled
// kinematics (kinematic_chain.h), each shape's validation and hull start table and, in the frame of each rigid
// body, an enclosing sphere per shape and per link, an enclosing capsule and box per shape (shape_bounds.cpp).
// Per configuration: the body frames (rotation matrices), world link-sphere centres, then for each checked link
// pair the link spheres, the shape spheres, the capsules (segment distance), the oriented boxes (15-axis SAT) and
// only then the narrow phase: core's convex kernel for hull pairs, gq::overlap for the rest (exact kernels for
// primitives, GJK for custom cylinders, convex hulls then dual BVH for meshes). Capsules, boxes and poses are
// placed lazily, the body quaternion only for shapes that reach the narrow phase. No allocation per check once the
// buffers have grown.
#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>

#include "gq/kernels/gjk.h"      // hull start tables
#include "gq/kernels/overlap.h"  // the convex overlap kernel
#include "gq/urdf/self_collision.h"
#include "internal.h"
#include "cull_tests.h"
#include "kinematic_chain.h"
#include "pair_order.h"

namespace gq::urdf {
namespace {

using internal::capsulesDisjoint;
using internal::orientedBoxesDisjoint;
using internal::spheresOverlap;

// Culling compares world placements computed in T: spheres and boxes grow by this many ulps of the robot's size so
// that rounding never culls a touching pair (touching counts as colliding).
constexpr double kCullSlackUlps = 64.0;

// Lower bound of the signed distance between two shapes from their enclosing spheres, negative when they overlap:
// moving the spheres apart moves the shapes apart, so no penetration is deeper than the spheres' overlap. (Clamped
// at 0, as it was, every overlapping pair's bound was 0 and selfDistance stopped at the first penetration it met,
// not the deepest: -0.017 instead of -0.068 on a colliding Panda configuration.)
template <class T> T sphereGap(const Vec3<T>& ca, T ra, const Vec3<T>& cb, T rb) {
  return (ca - cb).norm() - ra - rb;
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

// The capsule enclosing the balls at the ends of every shape's capsule (a shape without one: its sphere); the
// capsule is kept only when thinner than the link sphere. Its radius grows by the culling slack, like the shapes'.
template <class T, class ShapeBound, class LinkCapsule>
LinkCapsule linkCapsuleOf(const std::vector<std::uint32_t>& shapes, const std::vector<ShapeBound>& bounds, T linkRadius,
                          T slack) {
  LinkCapsule out;
  if (shapes.empty()) return out;
  std::vector<Vec3<double>> centres;
  std::vector<double> radii;
  for (std::uint32_t s : shapes) {
    const ShapeBound& b = bounds[s];
    for (const Vec3<T>& end : {b.capsuleStart, Vec3<T>(b.capsuleStart + b.capsuleSpan)}) {
      centres.push_back(end.template cast<double>());
      radii.push_back(double(b.capsuleRadius));
    }
  }
  Vec3<double> mean;
  const internal::EnclosingCapsule c = internal::enclosingCapsule(centres, internal::principalAxes(centres, mean), 0.0, &radii);
  const Vec3<double> span = 2.0 * c.halfHeight * c.axis;
  const double rounding = 8.0 * double(std::numeric_limits<T>::epsilon()) * (c.halfHeight + c.radius + c.centre.norm());
  const T radius = T(c.radius + rounding) + slack;
  if (!(radius < linkRadius)) return out;
  out.used = true;
  out.start = (c.centre - 0.5 * span).cast<T>();
  out.span = span.cast<T>();
  out.radius = radius;
  return out;
}

// Pairs whose cell in core's overlap table is the convex kernel overlapConvexShapes (GJK, exact SAT within the band
// of touching): a convex hull against a hull, box, sphere or capsule.
template <class T> bool convexKernelPair(const Geometry<T>& a, const Geometry<T>& b) {
  const auto solid = [](GeometryType t) {
    return t == GeometryType::Sphere || t == GeometryType::Capsule || t == GeometryType::Box || t == GeometryType::ConvexMesh;
  };
  return solid(a.type()) && solid(b.type()) &&
         (a.type() == GeometryType::ConvexMesh || b.type() == GeometryType::ConvexMesh);
}

// A box shape whose culling box is the box itself (local AABB, not grown): the midphase SAT decides the pair.
template <class T> bool cullBoxIsTheBox(const Geometry<T>& g, const internal::CullVolume<T>& v) {
  const auto* box = g.template getIf<BoxGeometry<T>>();
  return box && v.boxCentre == Vec3<T>::Zero() && v.boxAxes == Mat3<T>::Identity() && v.halfExtents == box->halfExtents;
}

}  // namespace

template <class T> struct SelfCollisionChecker<T>::Impl {
  Impl(std::shared_ptr<const RobotModel<T>> model, const CheckerOptions& options);
  Status checkSelfCollision(const std::vector<T>& q, CollisionResult& result, const CollisionRequest& request);
  Status selfDistance(const std::vector<T>& q, SelfDistanceResult<T>& result);
  Status checkSelfCollisionBatch(const std::vector<std::vector<T>>& qs, std::vector<std::uint8_t>& colliding);

  // Fixed per shape, in the frame of its rigid body (the links joined to it by fixed joints): an enclosing sphere
  // and an enclosing box, both grown by the culling slack; the box is carried to the world as an oriented box.
  struct ShapeBound {
    std::uint32_t body = 0;
    Transform<T> poseInBody;
    Vec3<T> centreInBody = Vec3<T>::Zero();
    T radius = T(0);
    Vec3<T> boxCentre = Vec3<T>::Zero();   // body frame
    Mat3<T> boxAxes = Mat3<T>::Identity();  // columns: box axes in the body frame
    Vec3<T> halfExtents = Vec3<T>::Zero();
    bool hasCapsule = false;  // an enclosing capsule (body frame) tighter than the sphere; else the sphere
    Vec3<T> capsuleStart = Vec3<T>::Zero(), capsuleSpan = Vec3<T>::Zero();
    T capsuleRadius = T(0);
    bool hasHull = false;  // mesh shapes: `hull` is their convex hull, tested before the triangles
    Geometry<T> hull;
    bool valid = false;     // validateGeometry passed (shape and hull): core's kernels may be called directly
    bool exactBox = false;  // a box whose culling box is itself: the oriented-box SAT decides box-box pairs
  };
  // Capsule enclosing every shape of a link (body frame), when tighter than the link sphere.
  struct LinkCapsule {
    bool used = false;
    Vec3<T> start = Vec3<T>::Zero(), span = Vec3<T>::Zero();
    T radius = T(0);
  };
  // A link pair the allowed-collision matrix leaves, with what its shape loop needs.
  struct CheckedPair {
    LinkPair links;
    T reach2 = T(0);            // (sum of the link sphere radii)^2: centres farther apart than this cull the pair
    bool shapeSpheres = false;  // a link has several shapes: test shape spheres and capsules before the boxes
    bool linkCapsules = false;  // a link has a capsule: test link capsules after the link spheres
  };

  void orderPairsByContactFrequency(std::uint32_t samples);
  Status placeBodies(const std::vector<T>& q);
  void placeLinkSpheres();
  void placeShapeSpheres();
  void placeShape(std::uint32_t shape);
  void placeCapsule(std::uint32_t shape);
  void placeLinkCapsule(std::uint32_t link);
  bool linkCapsulesDisjoint(std::uint32_t linkA, std::uint32_t linkB);
  const Transform<T>& shapePose(std::uint32_t shape);
  bool shapesMayTouch(std::uint32_t shapeA, std::uint32_t shapeB, bool shapeSpheres);
  Status overlapShapes(const Geometry<T>& a, const Transform<T>& poseA, const Geometry<T>& b, const Transform<T>& poseB,
                       bool valid, bool& hit);
  Status narrowPhase(std::uint32_t shapeA, std::uint32_t shapeB, bool& hit);
  Status linkPairCollides(const CheckedPair& pair, bool& hit);

  std::shared_ptr<const RobotModel<T>> model_;
  std::shared_ptr<const internal::KinematicChain<T>> chain_;  // compiled forward kinematics (immutable, shared)
  std::vector<CheckedPair> checkedPairs_;    // link pairs with shapes that the allowed-collision matrix leaves,
                                             // most often touching first (orderPairsByContactFrequency)
  std::vector<std::uint32_t> shapedLinks_;   // links with at least one shape
  std::vector<ShapeBound> shapeBounds_;
  std::vector<std::uint32_t> linkBody_;
  std::vector<Vec3<T>> linkCentreInBody_;    // per link: sphere enclosing its shapes' spheres
  std::vector<T> linkRadius_;
  std::vector<LinkCapsule> linkCapsules_;
  T slack_ = T(0);                           // absolute culling slack (rounding of world placements)
  // Per configuration.
  std::vector<Mat3<T>> bodyRotations_;
  std::vector<Vec3<T>> bodyPositions_;
  std::vector<Quat<T>> bodyQuats_;                   // valid when quatStamp_[b] == stamp_
  std::vector<Vec3<T>> linkCentres_, shapeCentres_;  // world sphere centres
  std::vector<Transform<T>> shapePoses_;             // valid when poseStamp_[s] == stamp_
  std::vector<OrientedBox<T>> shapeBoxes_;           // valid when boxStamp_[s] == stamp_
  std::vector<Vec3<T>> capsuleStarts_, capsuleSpans_;  // world; valid when capsuleStamp_[s] == stamp_
  std::vector<Vec3<T>> linkCapsuleStarts_, linkCapsuleSpans_;  // world; valid when linkCapsuleStamp_[l] == stamp_
  std::vector<std::uint32_t> boxStamp_, poseStamp_, quatStamp_, capsuleStamp_, linkCapsuleStamp_;
  std::uint32_t stamp_ = 0;
  std::vector<LinkPair> hits_;              // colliding pairs found so far in this call
  std::size_t lastNarrow_ = 0;
};

template <class T>
SelfCollisionChecker<T>::Impl::Impl(std::shared_ptr<const RobotModel<T>> model, const CheckerOptions& options)
    : model_(std::move(model)), chain_(std::make_shared<internal::KinematicChain<T>>(*model_)) {
  const RobotModel<T>& m = *model_;
  const std::size_t links = m.links.size(), shapes = m.shapes.size();
  linkBody_.resize(links);
  for (std::uint32_t l = 0; l < links; ++l) linkBody_[l] = chain_->bodyOf(l);
  shapeBounds_.resize(shapes);
  T largest = T(0);
  for (std::size_t i = 0; i < shapes; ++i) {
    const Shape<T>& shape = m.shapes[i];
    ShapeBound& b = shapeBounds_[i];
    internal::CullVolume<T> v;  // invalid geometry keeps a point volume: the narrow phase reports it
    (void)internal::shapeCullVolume(shape.geometry, v);
    b.body = linkBody_[shape.link];
    b.poseInBody = chain_->linkInBody(shape.link) * shape.origin;
    const Mat3<T> r = b.poseInBody.q.toRotationMatrix();
    b.centreInBody = b.poseInBody.transform(v.sphereCentre);
    b.radius = v.radius;
    b.boxCentre = b.poseInBody.transform(v.boxCentre);
    b.boxAxes = r * v.boxAxes;
    b.halfExtents = v.halfExtents;
    // A shape without a capsule takes its sphere as one (zero span).
    b.hasCapsule = v.hasCapsule;
    b.capsuleStart = v.hasCapsule ? b.poseInBody.transform(v.capsuleStart) : b.centreInBody;
    b.capsuleSpan = v.hasCapsule ? Vec3<T>(r * v.capsuleSpan) : Vec3<T>::Zero();
    b.capsuleRadius = v.hasCapsule ? v.capsuleRadius : v.radius;
    if (shape.boundingHull) {
      b.hull = ConvexMeshGeometry<T>(shape.boundingHull);
      b.hasHull = true;
    }
    // Checked once here, so that the narrow phase may call core's kernels without the façade's per-call checks.
    b.valid = validateGeometry(shape.geometry).ok() && (!b.hasHull || validateGeometry(b.hull).ok());
    // Core builds a hull's support start table on its first GJK query; build it here, with the model, not
    // inside the first check.
    for (const Geometry<T>* g : {&shape.geometry, static_cast<const Geometry<T>*>(&b.hull)})
      if (const auto* hull = g->template getIf<ConvexMeshGeometry<T>>(); hull && hull->mesh)
        (void)gq::kernels::supportStartTable(hull->mesh);
    // In double the slack is ~1e-14 of the robot's size, so the SAT's answer is the box kernel's but for gaps
    // below it; in float it is ~1e-5 m on a 1 m arm and gaps that size would read as contact (measured: 6 of
    // 10,000 UR5 configurations against FCL), so float keeps the box kernel.
    b.exactBox = std::is_same_v<T, double> && b.valid && cullBoxIsTheBox(shape.geometry, v);
    largest = std::max(largest, shape.origin.transform(v.sphereCentre).norm() + b.radius);
  }
  slack_ = T(kCullSlackUlps) * std::numeric_limits<T>::epsilon() * robotSize(m, largest);
  for (auto& b : shapeBounds_) {
    b.radius += slack_;
    b.halfExtents.array() += slack_;
    b.capsuleRadius += slack_;  // the segment distance is within rounding of the minimum (cull_tests.h)
  }
  linkCentreInBody_.assign(links, Vec3<T>::Zero());
  linkRadius_.assign(links, T(0));
  for (std::size_t l = 0; l < links; ++l) {
    const auto& own = m.links[l].shapes;
    if (own.empty()) continue;
    Bounds3<T> centres;
    for (std::uint32_t s : own) centres.include(shapeBounds_[s].centreInBody);
    linkCentreInBody_[l] = own.size() == 1 ? shapeBounds_[own[0]].centreInBody : centres.center();
    for (std::uint32_t s : own)
      linkRadius_[l] = std::max(linkRadius_[l], (shapeBounds_[s].centreInBody - linkCentreInBody_[l]).norm() +
                                                    shapeBounds_[s].radius);
  }
  linkCapsules_.assign(links, LinkCapsule());
  for (std::size_t l = 0; l < links; ++l) linkCapsules_[l] = linkCapsuleOf<T, ShapeBound, LinkCapsule>(
                                                        m.links[l].shapes, shapeBounds_, linkRadius_[l], slack_);
  for (std::uint32_t a = 0; a < links; ++a)
    for (std::uint32_t b = a + 1; b < links; ++b)
      if (!m.links[a].shapes.empty() && !m.links[b].shapes.empty() && !m.isAllowed(a, b))
        checkedPairs_.push_back({{a, b}, (linkRadius_[a] + linkRadius_[b]) * (linkRadius_[a] + linkRadius_[b]),
                                 m.links[a].shapes.size() > 1 || m.links[b].shapes.size() > 1,
                                 linkCapsules_[a].used || linkCapsules_[b].used});
  for (std::uint32_t l = 0; l < links; ++l)
    if (!m.links[l].shapes.empty()) shapedLinks_.push_back(l);
  bodyRotations_.assign(chain_->bodyCount(), Mat3<T>::Identity());
  bodyPositions_.assign(chain_->bodyCount(), Vec3<T>::Zero());
  bodyQuats_.resize(chain_->bodyCount());
  quatStamp_.assign(chain_->bodyCount(), 0);
  linkCentres_.resize(links);
  shapeCentres_.resize(shapes);
  shapePoses_.resize(shapes);
  shapeBoxes_.resize(shapes);
  capsuleStarts_.resize(shapes);
  capsuleSpans_.resize(shapes);
  capsuleStamp_.assign(shapes, 0);
  linkCapsuleStarts_.resize(links);
  linkCapsuleSpans_.resize(links);
  linkCapsuleStamp_.assign(links, 0);
  boxStamp_.assign(shapes, 0);
  poseStamp_.assign(shapes, 0);
  orderPairsByContactFrequency(options.orderingSamples);
}

// Pairs that touch often go first (pair_order.h); checks in the constructor's sampling see the link order.
template <class T> void SelfCollisionChecker<T>::Impl::orderPairsByContactFrequency(std::uint32_t samples) {
  CollisionRequest all;
  all.allPairs = true;
  internal::orderByContactFrequency(
      *model_, checkedPairs_, [](const CheckedPair& p) { return p.links; },
      [&](const std::vector<T>& q, CollisionResult& r) { return checkSelfCollision(q, r, all); }, samples);
}

template <class T> Status SelfCollisionChecker<T>::Impl::placeBodies(const std::vector<T>& q) {
  Status s = chain_->place(q, bodyRotations_, bodyPositions_);
  if (!s.ok()) return s;
  if (++stamp_ == 0) {  // wrapped: forget every placement
    std::fill(boxStamp_.begin(), boxStamp_.end(), 0u);
    std::fill(capsuleStamp_.begin(), capsuleStamp_.end(), 0u);
    std::fill(linkCapsuleStamp_.begin(), linkCapsuleStamp_.end(), 0u);
    std::fill(poseStamp_.begin(), poseStamp_.end(), 0u);
    std::fill(quatStamp_.begin(), quatStamp_.end(), 0u);
    stamp_ = 1;
  }
  return {};
}

// Local pointers and a local result: the stores cannot alias the inputs, so nothing is reloaded per link.
template <class T> void SelfCollisionChecker<T>::Impl::placeLinkSpheres() {
  const Mat3<T>* rotations = bodyRotations_.data();
  const Vec3<T>* positions = bodyPositions_.data();
  const std::uint32_t* bodies = linkBody_.data();
  const Vec3<T>* local = linkCentreInBody_.data();
  Vec3<T>* world = linkCentres_.data();
  for (const std::uint32_t l : shapedLinks_) {
    const std::uint32_t b = bodies[l];
    const Vec3<T> c = rotations[b] * local[l] + positions[b];
    world[l] = c;
  }
}

template <class T> void SelfCollisionChecker<T>::Impl::placeShapeSpheres() {
  for (std::size_t i = 0; i < shapeBounds_.size(); ++i) {
    const ShapeBound& sb = shapeBounds_[i];
    shapeCentres_[i].noalias() = bodyRotations_[sb.body] * sb.centreInBody;
    shapeCentres_[i] += bodyPositions_[sb.body];
  }
}

// The shape's oriented box in the world (for the midphase).
template <class T> void SelfCollisionChecker<T>::Impl::placeShape(std::uint32_t i) {
  if (boxStamp_[i] == stamp_) return;
  boxStamp_[i] = stamp_;
  const ShapeBound& sb = shapeBounds_[i];
  const Mat3<T>& r = bodyRotations_[sb.body];
  OrientedBox<T>& box = shapeBoxes_[i];
  box.axes.noalias() = r * sb.boxAxes;
  box.centre.noalias() = r * sb.boxCentre;
  box.centre += bodyPositions_[sb.body];
  box.halfExtents = sb.halfExtents;
}

template <class T> void SelfCollisionChecker<T>::Impl::placeCapsule(std::uint32_t i) {
  if (capsuleStamp_[i] == stamp_) return;
  capsuleStamp_[i] = stamp_;
  const ShapeBound& sb = shapeBounds_[i];
  const Mat3<T>& r = bodyRotations_[sb.body];
  capsuleStarts_[i].noalias() = r * sb.capsuleStart;
  capsuleStarts_[i] += bodyPositions_[sb.body];
  capsuleSpans_[i].noalias() = r * sb.capsuleSpan;
}

// A link without a capsule of its own is its sphere: a capsule of zero span.
template <class T> void SelfCollisionChecker<T>::Impl::placeLinkCapsule(std::uint32_t l) {
  if (linkCapsuleStamp_[l] == stamp_) return;
  linkCapsuleStamp_[l] = stamp_;
  const LinkCapsule& c = linkCapsules_[l];
  if (!c.used) {
    linkCapsuleStarts_[l] = linkCentres_[l];
    linkCapsuleSpans_[l].setZero();
    return;
  }
  const Mat3<T>& r = bodyRotations_[linkBody_[l]];
  linkCapsuleStarts_[l].noalias() = r * c.start;
  linkCapsuleStarts_[l] += bodyPositions_[linkBody_[l]];
  linkCapsuleSpans_[l].noalias() = r * c.span;
}

template <class T> bool SelfCollisionChecker<T>::Impl::linkCapsulesDisjoint(std::uint32_t a, std::uint32_t b) {
  placeLinkCapsule(a);
  placeLinkCapsule(b);
  return capsulesDisjoint(linkCapsuleStarts_[a], linkCapsuleSpans_[a],
                          linkCapsules_[a].used ? linkCapsules_[a].radius : linkRadius_[a], linkCapsuleStarts_[b],
                          linkCapsuleSpans_[b], linkCapsules_[b].used ? linkCapsules_[b].radius : linkRadius_[b]);
}

// The shape's pose for the narrow phase: the body's rotation as a quaternion (once per body and configuration)
// composed with the shape's constant pose in the body.
template <class T> const Transform<T>& SelfCollisionChecker<T>::Impl::shapePose(std::uint32_t i) {
  if (poseStamp_[i] == stamp_) return shapePoses_[i];
  poseStamp_[i] = stamp_;
  const std::uint32_t b = shapeBounds_[i].body;
  if (quatStamp_[b] != stamp_) {
    quatStamp_[b] = stamp_;
    bodyQuats_[b] = Quat<T>(bodyRotations_[b]).normalized();
  }
  shapePoses_[i] = Transform<T>(bodyPositions_[b], bodyQuats_[b]) * shapeBounds_[i].poseInBody;
  return shapePoses_[i];
}

// Shape spheres and capsules (only when a link has several shapes: a single shape's sphere and capsule are its
// link's, tested already; a sphere stands in for a shape without a capsule), then oriented boxes.
template <class T> bool SelfCollisionChecker<T>::Impl::shapesMayTouch(std::uint32_t sa, std::uint32_t sb, bool shapeSpheres) {
  if (shapeSpheres) {
    const ShapeBound& a = shapeBounds_[sa];
    const ShapeBound& b = shapeBounds_[sb];
    const Vec3<T> ca = bodyRotations_[a.body] * a.centreInBody + bodyPositions_[a.body];
    const Vec3<T> cb = bodyRotations_[b.body] * b.centreInBody + bodyPositions_[b.body];
    if (!spheresOverlap(ca, a.radius, cb, b.radius)) return false;
  }
  if (shapeSpheres && (shapeBounds_[sa].hasCapsule || shapeBounds_[sb].hasCapsule)) {
    placeCapsule(sa);
    placeCapsule(sb);
    if (capsulesDisjoint(capsuleStarts_[sa], capsuleSpans_[sa], shapeBounds_[sa].capsuleRadius, capsuleStarts_[sb],
                         capsuleSpans_[sb], shapeBounds_[sb].capsuleRadius))
      return false;
  }
  placeShape(sa);
  placeShape(sb);
  return !orientedBoxesDisjoint(shapeBoxes_[sa], shapeBoxes_[sb]);
}

// gq::overlap, or for convex-hull pairs of validated shapes core's convex kernel directly (the same answer without
// the façade's validation and relative pose: ~500 instructions per call).
template <class T>
Status SelfCollisionChecker<T>::Impl::overlapShapes(const Geometry<T>& ga, const Transform<T>& pa, const Geometry<T>& gb,
                                              const Transform<T>& pb, bool valid, bool& hit) {
  if (valid && convexKernelPair(ga, gb)) {
    hit = gq::kernels::overlapConvexShapes(ga, pa, gb, pb);
    return {};
  }
  return overlap(ga, pa, gb, pb, hit);
}

// Mesh shapes first meet as their convex hulls (GJK): disjoint hulls prove disjoint meshes.
template <class T> Status SelfCollisionChecker<T>::Impl::narrowPhase(std::uint32_t sa, std::uint32_t sb, bool& hit) {
  const Geometry<T>& ga = model_->shapes[sa].geometry;
  const Geometry<T>& gb = model_->shapes[sb].geometry;
  const Transform<T>& pa = shapePose(sa);
  const Transform<T>& pb = shapePose(sb);
  const bool valid = shapeBounds_[sa].valid && shapeBounds_[sb].valid;
  if (shapeBounds_[sa].hasHull || shapeBounds_[sb].hasHull) {
    const Geometry<T>& ha = shapeBounds_[sa].hasHull ? shapeBounds_[sa].hull : ga;
    const Geometry<T>& hb = shapeBounds_[sb].hasHull ? shapeBounds_[sb].hull : gb;
    bool hullsTouch = false;
    if (Status s = overlapShapes(ha, pa, hb, pb, valid, hullsTouch); !s.ok()) return s;
    if (!hullsTouch) {
      hit = false;
      return {};
    }
  }
  return overlapShapes(ga, pa, gb, pb, valid, hit);
}

template <class T> Status SelfCollisionChecker<T>::Impl::linkPairCollides(const CheckedPair& pair, bool& hit) {
  hit = false;
  for (std::uint32_t sa : model_->links[pair.links.a].shapes)
    for (std::uint32_t sb : model_->links[pair.links.b].shapes) {
      if (!shapesMayTouch(sa, sb, pair.shapeSpheres)) continue;
      // Two boxes: the midphase SAT just ran on the boxes themselves (grown by the rounding slack only).
      if (shapeBounds_[sa].exactBox && shapeBounds_[sb].exactBox) {
        hit = true;
        return {};
      }
      ++lastNarrow_;
      if (Status s = narrowPhase(sa, sb, hit); !s.ok()) return s;
      if (hit) return {};
    }
  return {};
}

template <class T>
Status SelfCollisionChecker<T>::Impl::checkSelfCollision(const std::vector<T>& q, CollisionResult& result,
                                                   const CollisionRequest& request) {
  Status s = placeBodies(q);
  if (!s.ok()) return s;
  placeLinkSpheres();
  lastNarrow_ = 0;
  hits_.clear();
  for (const CheckedPair& pair : checkedPairs_) {
    const LinkPair& p = pair.links;
    if ((linkCentres_[p.a] - linkCentres_[p.b]).squaredNorm() > pair.reach2) continue;  // link spheres apart
    if (pair.linkCapsules && linkCapsulesDisjoint(p.a, p.b)) continue;
    bool hit = false;
    if (s = linkPairCollides(pair, hit); !s.ok()) return s;
    if (!hit) continue;
    hits_.push_back(p);
    if (!request.allPairs) break;
  }
  result.colliding = !hits_.empty();
  std::sort(hits_.begin(), hits_.end());  // the pair order is by contact frequency, the result is sorted
  result.pairs.assign(hits_.begin(), hits_.end());  // reuses the caller's capacity
  return {};
}

template <class T>
Status SelfCollisionChecker<T>::Impl::checkSelfCollisionBatch(const std::vector<std::vector<T>>& qs,
                                                        std::vector<std::uint8_t>& colliding) {
  std::vector<std::uint8_t> out(qs.size(), 0);
  CollisionRequest firstOnly;
  firstOnly.allPairs = false;
  CollisionResult r;
  for (std::size_t i = 0; i < qs.size(); ++i) {
    Status s = checkSelfCollision(qs[i], r, firstOnly);
    if (!s.ok()) return Status::owned(s.code, "configuration " + std::to_string(i) + ": " + s.detailedMessage());
    out[i] = r.colliding ? 1 : 0;
  }
  colliding = std::move(out);
  return {};
}

// Every checked shape pair, nearest lower bound first, so the best distance found early prunes the rest: a pair's
// bound is its enclosing spheres' gap, or for mesh shapes their hulls' distance (a mesh lies in its hull; GJK on two
// hulls costs a fraction of a dual BVH traversal), and each pair's search (GJK, a mesh's traversal) is bounded by
// the best so far (distanceWithin).
template <class T> Status SelfCollisionChecker<T>::Impl::selfDistance(const std::vector<T>& q, SelfDistanceResult<T>& result) {
  Status s = placeBodies(q);
  if (!s.ok()) return s;
  placeShapeSpheres();
  struct Candidate {
    T bound;
    std::uint32_t sa, sb;
  };
  std::vector<Candidate> pairs;
  for (const CheckedPair& p : checkedPairs_)
    for (std::uint32_t sa : model_->links[p.links.a].shapes)
      for (std::uint32_t sb : model_->links[p.links.b].shapes)
        pairs.push_back({sphereGap(shapeCentres_[sa], shapeBounds_[sa].radius, shapeCentres_[sb], shapeBounds_[sb].radius),
                         sa, sb});
  DistanceResult<T> d;
  for (Candidate& c : pairs) {
    if (!shapeBounds_[c.sa].hasHull && !shapeBounds_[c.sb].hasHull) continue;
    const Geometry<T>& ha = shapeBounds_[c.sa].hasHull ? shapeBounds_[c.sa].hull : model_->shapes[c.sa].geometry;
    const Geometry<T>& hb = shapeBounds_[c.sb].hasHull ? shapeBounds_[c.sb].hull : model_->shapes[c.sb].geometry;
    s = distance(d, ha, shapePose(c.sa), hb, shapePose(c.sb));
    if (!s.ok()) return s;
    c.bound = std::max(c.bound, d.distance);
  }
  std::sort(pairs.begin(), pairs.end(), [](const Candidate& x, const Candidate& y) { return x.bound < y.bound; });
  SelfDistanceResult<T> best;
  best.distance = std::numeric_limits<T>::infinity();
  lastNarrow_ = 0;
  for (const Candidate& c : pairs) {
    if (c.bound > best.distance) break;
    ++lastNarrow_;
    const Transform<T>& pa = shapePose(c.sa);
    const Transform<T>& pb = shapePose(c.sb);
    bool beyond = false;
    s = distanceWithin(d, beyond, best.distance, model_->shapes[c.sa].geometry, pa, model_->shapes[c.sb].geometry, pb);
    if (!s.ok()) return s;
    if (!beyond && d.distance < best.distance) {
      best.distance = d.distance;
      best.pair = {model_->shapes[c.sa].link, model_->shapes[c.sb].link};
      best.point0 = d.point0;
      best.point1 = d.point1;
    }
  }
  result = best;
  return {};
}

template <class T>
SelfCollisionChecker<T>::SelfCollisionChecker(std::shared_ptr<const RobotModel<T>> model, const CheckerOptions& options)
    : impl_(std::make_unique<Impl>(std::move(model), options)) {}
template <class T> SelfCollisionChecker<T>::~SelfCollisionChecker() = default;
template <class T> SelfCollisionChecker<T>::SelfCollisionChecker(SelfCollisionChecker&&) noexcept = default;
template <class T>
SelfCollisionChecker<T>& SelfCollisionChecker<T>::operator=(SelfCollisionChecker&&) noexcept = default;
template <class T> const RobotModel<T>& SelfCollisionChecker<T>::model() const { return *impl_->model_; }
template <class T> std::size_t SelfCollisionChecker<T>::lastNarrowPhasePairs() const { return impl_->lastNarrow_; }
template <class T>
Status SelfCollisionChecker<T>::checkSelfCollision(const std::vector<T>& q, CollisionResult& result,
                                                   const CollisionRequest& request) {
  return impl_->checkSelfCollision(q, result, request);
}
template <class T>
Status SelfCollisionChecker<T>::selfDistance(const std::vector<T>& q, SelfDistanceResult<T>& result) {
  return impl_->selfDistance(q, result);
}
template <class T>
Status SelfCollisionChecker<T>::checkSelfCollisionBatch(const std::vector<std::vector<T>>& qs,
                                                        std::vector<std::uint8_t>& colliding) {
  return impl_->checkSelfCollisionBatch(qs, colliding);
}

template class SelfCollisionChecker<float>;
template class SelfCollisionChecker<double>;

}  // namespace gq::urdf
