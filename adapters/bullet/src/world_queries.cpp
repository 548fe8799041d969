// rayTest and convexSweepTest through gq: Bullet's broadphase finds the candidate objects, gq answers per object.
#include <BulletCollision/CollisionShapes/btCompoundShape.h>
#include <BulletCollision/CollisionShapes/btConvexShape.h>
#include <BulletCollision/NarrowPhaseCollision/btRaycastCallback.h>

#include <cmath>

#include "gq/bullet/collision_world.h"
#include "gq/query.h"
#include "shape_view.h"

namespace gq::bullet {
namespace {

using RayCallback = btCollisionWorld::RayResultCallback;
using SweepCallback = btCollisionWorld::ConvexResultCallback;

// Bullet's broadphase ray walk reads the inverse unit direction, its signs and the ray length.
void prepareRay(btBroadphaseRayCallback& cb, const btVector3& from, const btVector3& to) {
  btVector3 dir = to - from;
  dir.normalize();
  for (int i = 0; i < 3; ++i) {
    cb.m_rayDirectionInverse[i] = dir[i] == btScalar(0) ? btScalar(BT_LARGE_FLOAT) : btScalar(1) / dir[i];
    cb.m_signs[i] = cb.m_rayDirectionInverse[i] < btScalar(0);
  }
  cb.m_lambda_max = dir.dot(to - from);
}

// What Bullet's per-object tests read from the callback they are given: the host's filter and closest fraction.
template <class Callback> void copyFilter(const Callback& host, Callback& to) {
  to.m_closestHitFraction = host.m_closestHitFraction;
  to.m_collisionFilterGroup = host.m_collisionFilterGroup;
  to.m_collisionFilterMask = host.m_collisionFilterMask;
}

// Bullet's own per-object tests answer for the shapes gq leaves to Bullet; these pass their results on to the
// host's callback only when finite, so a gq world never hands a NaN fraction, normal or point to a callback.
class FiniteRayResults final : public RayCallback {
 public:
  explicit FiniteRayResults(RayCallback& host) : host_(host) {
    copyFilter<RayCallback>(host, *this);
    m_flags = host.m_flags;
  }
  bool needsCollision(btBroadphaseProxy* proxy) const override { return host_.needsCollision(proxy); }
  btScalar addSingleResult(btCollisionWorld::LocalRayResult& r, bool normalInWorldSpace) override {
    if (!std::isfinite(r.m_hitFraction) || !isFinite(r.m_hitNormalLocal)) return m_closestHitFraction;
    const btScalar answer = host_.addSingleResult(r, normalInWorldSpace);
    m_closestHitFraction = host_.m_closestHitFraction;
    return answer;
  }

 private:
  RayCallback& host_;
};

class FiniteSweepResults final : public SweepCallback {
 public:
  explicit FiniteSweepResults(SweepCallback& host) : host_(host) { copyFilter<SweepCallback>(host, *this); }
  bool needsCollision(btBroadphaseProxy* proxy) const override { return host_.needsCollision(proxy); }
  btScalar addSingleResult(btCollisionWorld::LocalConvexResult& r, bool normalInWorldSpace) override {
    if (!std::isfinite(r.m_hitFraction) || !isFinite(r.m_hitNormalLocal) || !isFinite(r.m_hitPointLocal))
      return m_closestHitFraction;
    const btScalar answer = host_.addSingleResult(r, normalInWorldSpace);
    m_closestHitFraction = host_.m_closestHitFraction;
    return answer;
  }

 private:
  SweepCallback& host_;
};

bool isSurface(const ShapeView& v) { return v.kind == ShapeKind::Mesh || v.kind == ShapeKind::HeightField; }

// The shape info Bullet's result callbacks read: a compound child's index (part -1), or the part and triangle of a
// mesh face; null for a plain convex, as Bullet passes.
btCollisionWorld::LocalShapeInfo* shapeInfo(const ShapeView& view, int child, std::uint32_t face,
                                            btCollisionWorld::LocalShapeInfo& info) {
  const TriangleIds ids = view.triangleIds(face);
  info.m_shapePart = child >= 0 ? -1 : ids.part;
  info.m_triangleIndex = child >= 0 ? child : ids.index;
  return child >= 0 || isSurface(view) ? &info : nullptr;
}

// Rounding radius a query sees: only convex shapes carry Bullet's outside margin into rays and sweeps.
Real roundingOf(const ShapeView& v) { return v.kind == ShapeKind::Convex ? v.margin : Real(0); }

struct Hit {
  Real distance = 0;
  V3 normal = V3::Zero();
  V3 position = V3::Zero();
  std::uint32_t face = kInvalidFaceIndex;
};

// A ray against a rounded shape is a sphere of the rounding radius swept against its core.
bool castRay(const V3& origin, const V3& dir, Real maxDist, const ShapeView& view, const Pose& pose, bool twoSided,
             Hit& out) {
  const Real rounding = roundingOf(view);
  if (rounding > Real(0)) {
    SweepHit<Real> h;
    bool has = false;
    if (!sweep(dir, maxDist, Geometry<Real>(SphereGeometry<Real>(rounding)), Pose(origin), view.geom, pose, h, has,
               HitFlag::Position | HitFlag::Normal)
             .ok() ||
        !has)
      return false;
    out = Hit{h.distance, h.normal, origin + dir * h.distance, kInvalidFaceIndex};
    return true;
  }
  HitFlags flags = HitFlag::Position | HitFlag::Normal | HitFlag::FaceIndex;
  if (twoSided && isSurface(view)) flags |= HitFlag::MeshBothSides;
  RaycastHit<Real> h;
  std::uint32_t n = 0;
  if (!raycast(origin, dir, view.geom, pose, maxDist, flags, 1, &h, n).ok() || n == 0) return false;
  out = Hit{h.distance, h.normal, h.position, h.faceIndex};
  return true;
}

// Whether gq answers for every child of a compound (bad children are answered too: they report nothing).
bool answeredByGq(const btCompoundShape& compound) {
  ShapeView view;
  for (int i = 0; i < compound.getNumChildShapes(); ++i)
    if (viewShape(compound.getChildShape(i), view) == Support::Bullet) return false;
  return true;
}

class RayVisitor final : public btBroadphaseRayCallback {
 public:
  // The ray against one gq shape at `world`; `child` >= 0 names a compound child (reported as Bullet does: part -1,
  // triangle index = child index). False when Bullet answers for the shape; bad input is answered: no hit.
  bool shapeRay(btCollisionObject* object, const btCollisionShape* shape, const btTransform& world, int child) {
    ShapeView view;
    const Support support = viewShape(shape, view);
    if (support != Support::Gq) return support == Support::Invalid;
    const V3 delta = toGq(to_ - from_);
    const Real length = delta.norm();
    if (!isFinite(world) || !(length > Real(0))) return true;  // no hit (a length that underflows has no direction)
    const bool twoSided = (cb_.m_flags & btTriangleRaycastCallback::kF_FilterBackfaces) == 0;
    const Pose pose = toGq(world) * view.localPose;
    Hit hit;
    if (!castRay(toGq(from_), delta / length, length * cb_.m_closestHitFraction, view, pose, twoSided, hit)) return true;
    const Real fraction = hit.distance / length;
    if (!(fraction < cb_.m_closestHitFraction)) return true;
    btCollisionWorld::LocalShapeInfo info;
    btCollisionWorld::LocalRayResult result(object, shapeInfo(view, child, hit.face, info), toBt(hit.normal), fraction);
    cb_.addSingleResult(result, true);
    return true;
  }

  // A compound whose children all have gq views or are bad input (one level; nested compounds go to Bullet).
  bool compoundRay(btCollisionObject* object, const btCompoundShape* compound) {
    if (!answeredByGq(*compound)) return false;
    for (int i = 0; i < compound->getNumChildShapes(); ++i)
      shapeRay(object, compound->getChildShape(i), object->getWorldTransform() * compound->getChildTransform(i), i);
    return true;
  }

  RayVisitor(const btVector3& from, const btVector3& to, RayCallback& cb) : from_(from), to_(to), cb_(cb) {
    fromT_.setIdentity();
    fromT_.setOrigin(from);
    toT_.setIdentity();
    toT_.setOrigin(to);
    prepareRay(*this, from, to);
  }
  bool process(const btBroadphaseProxy* proxy) override {
    if (cb_.m_closestHitFraction == btScalar(0)) return false;
    auto* object = static_cast<btCollisionObject*>(proxy->m_clientObject);
    if (!cb_.needsCollision(object->getBroadphaseHandle())) return true;
    const btCollisionShape* shape = object->getCollisionShape();
    if (shape->isCompound() ? !compoundRay(object, static_cast<const btCompoundShape*>(shape))
                            : !shapeRay(object, shape, object->getWorldTransform(), -1)) {
      FiniteRayResults finite(cb_);
      btCollisionWorld::rayTestSingle(fromT_, toT_, object, shape, object->getWorldTransform(), finite);
    }
    return true;
  }

 private:
  btVector3 from_, to_;
  btTransform fromT_, toT_;
  RayCallback& cb_;
};

class SweepVisitor final : public btBroadphaseRayCallback {
 public:
  SweepVisitor(const btConvexShape* cast, const btTransform& from, const btTransform& to, SweepCallback& cb,
               btScalar allowedPenetration)
      : cast_(cast), from_(from), to_(to), cb_(cb), allowed_(allowedPenetration) {
    // gq sweeps spheres, capsules, boxes and hulls; custom cast shapes (cylinder, cone, multi-sphere) go to Bullet.
    castOk_ = viewShape(cast, castView_) == Support::Gq && castView_.kind == ShapeKind::Convex &&
              castView_.geom.type() != GeometryType::Custom;
    prepareRay(*this, from.getOrigin(), to.getOrigin());
  }
  bool process(const btBroadphaseProxy* proxy) override {
    if (cb_.m_closestHitFraction == btScalar(0)) return false;
    auto* object = static_cast<btCollisionObject*>(proxy->m_clientObject);
    if (!cb_.needsCollision(object->getBroadphaseHandle())) return true;
    const btCollisionShape* shape = object->getCollisionShape();
    const bool handled = castOk_ && (shape->isCompound()
                                         ? compoundSweep(object, static_cast<const btCompoundShape*>(shape))
                                         : shapeSweep(object, shape, object->getWorldTransform(), -1));
    if (!handled) {
      FiniteSweepResults finite(cb_);
      btCollisionWorld::objectQuerySingle(cast_, from_, to_, object, shape, object->getWorldTransform(), finite,
                                          allowed_);
    }
    return true;
  }

  // The cast shape swept against one gq shape at `world` (`child` >= 0: a compound child, reported as Bullet
  // does). False when Bullet answers for the target or the sweep has no length; a bad target is answered: no hit.
  bool shapeSweep(btCollisionObject* object, const btCollisionShape* shape, const btTransform& world, int child) {
    ShapeView target;
    const V3 delta = toGq(to_.getOrigin() - from_.getOrigin());
    const Real length = delta.norm();
    if (!(length > Real(0))) return false;
    const Support support = viewShape(shape, target);
    if (support != Support::Gq) return support == Support::Invalid;
    if (!isFinite(world)) return true;
    HitFlags flags = HitFlag::Position | HitFlag::Normal | HitFlag::FaceIndex;
    if (isSurface(target)) flags |= HitFlag::MeshBothSides;
    SweepHit<Real> hit;
    bool has = false;
    const Pose castPose = toGq(from_) * castView_.localPose;
    const Pose targetPose = toGq(world) * target.localPose;
    if (!sweep(V3(delta / length), length * cb_.m_closestHitFraction, castView_.geom, castPose, target.geom,
               targetPose, hit, has, flags, roundingOf(castView_) + roundingOf(target))
             .ok() ||
        !has)
      return true;
    const Real fraction = hit.distance / length;
    if (!(fraction < cb_.m_closestHitFraction)) return true;
    btCollisionWorld::LocalShapeInfo info;
    btCollisionWorld::LocalConvexResult result(object, shapeInfo(target, child, hit.faceIndex, info), toBt(hit.normal),
                                               toBt(hit.position), fraction);
    cb_.addSingleResult(result, true);
    return true;
  }

  // A compound whose children all have gq views or are bad input (one level; others go to Bullet).
  bool compoundSweep(btCollisionObject* object, const btCompoundShape* compound) {
    if (!answeredByGq(*compound)) return false;
    if ((to_.getOrigin() - from_.getOrigin()).fuzzyZero()) return false;
    for (int i = 0; i < compound->getNumChildShapes(); ++i)
      shapeSweep(object, compound->getChildShape(i), object->getWorldTransform() * compound->getChildTransform(i), i);
    return true;
  }

 private:
  const btConvexShape* cast_;
  ShapeView castView_;
  bool castOk_ = false;
  btTransform from_, to_;
  SweepCallback& cb_;
  btScalar allowed_;
};

btBroadphaseInterface* broadphaseOf(const btCollisionWorld& world) {
  return const_cast<btBroadphaseInterface*>(world.getBroadphase());  // Bullet's const queries walk it the same way
}

}  // namespace

// Bullet's convention for bad input, kept by gq: a ray with a non-finite end or no length, a sweep with a
// non-finite pose, no cast shape or a bad one reports no hit and leaves the callback untouched.
void gqRayTest(const btCollisionWorld& world, const btVector3& from, const btVector3& to, RayCallback& cb) {
  if (!isFinite(from) || !isFinite(to) || !isFinite(to - from) || from == to) return;
  RayVisitor visitor(from, to, cb);
  broadphaseOf(world)->rayTest(from, to, visitor);
}

void gqConvexSweepTest(const btCollisionWorld& world, const btConvexShape* castShape, const btTransform& from,
                       const btTransform& to, SweepCallback& cb, btScalar allowedCcdPenetration) {
  ShapeView castView;
  if (!castShape || !isFinite(from) || !isFinite(to) || !isFinite(to.getOrigin() - from.getOrigin()) ||
      viewShape(castShape, castView) == Support::Invalid)
    return;
  // The broadphase walks the swept box of the cast shape's bounds at the `from` rotation.
  btTransform rotation(from.getBasis(), btVector3(0, 0, 0));
  btVector3 aabbMin, aabbMax;
  castShape->getAabb(rotation, aabbMin, aabbMax);
  SweepVisitor visitor(castShape, from, to, cb, allowedCcdPenetration);
  broadphaseOf(world)->rayTest(from.getOrigin(), to.getOrigin(), visitor, aabbMin, aabbMax);
}

void CollisionWorld::rayTest(const btVector3& from, const btVector3& to, RayResultCallback& cb) const {
  gqRayTest(*this, from, to, cb);
}
void CollisionWorld::convexSweepTest(const btConvexShape* castShape, const btTransform& from, const btTransform& to,
                                     ConvexResultCallback& cb, btScalar allowedCcdPenetration) const {
  gqConvexSweepTest(*this, castShape, from, to, cb, allowedCcdPenetration);
}
void DiscreteDynamicsWorld::rayTest(const btVector3& from, const btVector3& to, RayResultCallback& cb) const {
  gqRayTest(*this, from, to, cb);
}
void DiscreteDynamicsWorld::convexSweepTest(const btConvexShape* castShape, const btTransform& from,
                                            const btTransform& to, ConvexResultCallback& cb,
                                            btScalar allowedCcdPenetration) const {
  gqConvexSweepTest(*this, castShape, from, to, cb, allowedCcdPenetration);
}

}  // namespace gq::bullet
