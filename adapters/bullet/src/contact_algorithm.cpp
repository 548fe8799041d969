#include "contact_algorithm.h"

#include <cstring>
#include <new>

#include <BulletCollision/CollisionDispatch/btCollisionObjectWrapper.h>
#include <BulletCollision/CollisionDispatch/btManifoldResult.h>
#include <BulletCollision/CollisionShapes/btCapsuleShape.h>
#include <BulletCollision/CollisionShapes/btConeShape.h>
#include <BulletCollision/CollisionShapes/btConvexHullShape.h>
#include <BulletCollision/CollisionShapes/btCylinderShape.h>
#include <BulletCollision/CollisionShapes/btStaticPlaneShape.h>
#include <BulletCollision/NarrowPhaseCollision/btPersistentManifold.h>

#include "contacts.h"
#include "gq/bullet/collision_configuration.h"

namespace gq::bullet {
namespace {

// Writes contacts into Bullet's manifold result (which stores them in the persistent manifold, or hands them to a
// contactTest callback), naming the mesh/heightfield triangle as Bullet's own algorithms do.
class ManifoldSink final : public ContactSink {
 public:
  explicit ManifoldSink(btManifoldResult& result) : result_(result) {}
  void add(const V3& normalOnB, const V3& pointOnB, Real depth, TriangleIds ids, bool surfaceIsB) override {
    if (ids.part >= 0 || ids.index >= 0) {
      if (surfaceIsB)
        result_.setShapeIdentifiersB(ids.part, ids.index);
      else
        result_.setShapeIdentifiersA(ids.part, ids.index);
    }
    result_.addContactPoint(toBt(normalOnB), toBt(pointOnB), depth);
  }

 private:
  btManifoldResult& result_;
};

bool pairHasGqPath(ShapeKind a, ShapeKind b) { return a == ShapeKind::Convex || b == ShapeKind::Convex; }

// Every parameter a view of a primitive, hull or plane is made of (the hull's points by their buffer and count,
// which change when points are added). Equal keys (bytewise, so a NaN matches itself) give equal views.
struct ShapeKey {
  const btCollisionShape* shape = nullptr;
  int type = -1;
  const void* points = nullptr;
  int ints[2] = {0, 0};
  btScalar values[12] = {};
  bool operator==(const ShapeKey& o) const { return std::memcmp(this, &o, sizeof(ShapeKey)) == 0; }
};

void putVector(btScalar* v, const btVector3& x) { v[0] = x.x(), v[1] = x.y(), v[2] = x.z(); }

// False for the shapes whose views are rebuilt every frame (meshes, heightfields, multi-spheres: their cache
// lookups check their own data).
bool keyOf(const btCollisionShape* shape, ShapeKey& key) {
  std::memset(static_cast<void*>(&key), 0, sizeof key);
  key.shape = shape;
  key.type = shape->getShapeType();
  putVector(key.values, shape->getLocalScaling());
  key.values[3] = shape->getMargin();
  switch (key.type) {
    case SPHERE_SHAPE_PROXYTYPE:
    case BOX_SHAPE_PROXYTYPE:
      putVector(key.values + 4, static_cast<const btConvexInternalShape*>(shape)->getImplicitShapeDimensions());
      return true;
    case CAPSULE_SHAPE_PROXYTYPE:
      putVector(key.values + 4, static_cast<const btConvexInternalShape*>(shape)->getImplicitShapeDimensions());
      key.ints[0] = static_cast<const btCapsuleShape*>(shape)->getUpAxis();
      return true;
    case CYLINDER_SHAPE_PROXYTYPE:
      putVector(key.values + 4, static_cast<const btConvexInternalShape*>(shape)->getImplicitShapeDimensions());
      key.ints[0] = static_cast<const btCylinderShape*>(shape)->getUpAxis();
      return true;
    case CONE_SHAPE_PROXYTYPE: {
      const auto* cone = static_cast<const btConeShape*>(shape);
      key.values[4] = cone->getRadius(), key.values[5] = cone->getHeight();
      key.ints[0] = cone->getConeUpIndex();
      return true;
    }
    case CONVEX_HULL_SHAPE_PROXYTYPE: {
      const auto* hull = static_cast<const btConvexHullShape*>(shape);
      key.points = hull->getUnscaledPoints();
      key.ints[0] = hull->getNumPoints();
      return true;
    }
    case STATIC_PLANE_PROXYTYPE: {
      const auto* plane = static_cast<const btStaticPlaneShape*>(shape);
      putVector(key.values + 4, plane->getPlaneNormal());
      key.values[7] = plane->getPlaneConstant();
      return true;
    }
    default: return false;
  }
}

}  // namespace

// One side of a pair: the view of its shape (and the prepared geometry) as of `key`.
struct PairSide {
  ShapeKey key;
  bool keyed = false;
  Support support = Support::Invalid;
  ShapeView view;
  Shape<Real> prepared;

  // The shape's view, rebuilt only when the shape's parameters changed since the last frame.
  Support refresh(const btCollisionShape* shape) {
    ShapeKey now;
    if (shape && keyOf(shape, now)) {
      if (keyed && now == key) return support;
      key = now;
      keyed = true;
    } else {
      keyed = false;
    }
    support = viewShape(shape, view);
    view.prepared = nullptr;
    // Only convex pairs read the prepared shape; a mesh or heightfield is not prepared (making a Shape bounds every
    // vertex, which cost a pair with a large ground more than its contacts).
    const GeometryType type = view.geom.type();
    const bool surface = type == GeometryType::TriangleMesh || type == GeometryType::HeightField;
    if (support == Support::Gq && !surface && Shape<Real>::make(view.geom, prepared).ok()) view.prepared = &prepared;
    return support;
  }
};

struct PairState {
  PairSide side[2];
  PairMemory memory;
};

ContactAlgorithm::ContactAlgorithm(btPersistentManifold* sharedManifold, const btCollisionAlgorithmConstructionInfo& ci,
                                   const btCollisionObjectWrapper* body0, const btCollisionObjectWrapper* body1)
    : btActivatingCollisionAlgorithm(ci, body0, body1),
      manifold_(sharedManifold),
      ownManifold_(false),
      state_(new (std::nothrow) PairState()) {}

ContactAlgorithm::~ContactAlgorithm() {
  if (ownManifold_ && manifold_) m_dispatcher->releaseManifold(manifold_);
}

void ContactAlgorithm::processCollision(const btCollisionObjectWrapper* body0, const btCollisionObjectWrapper* body1,
                                        const btDispatcherInfo&, btManifoldResult* result) {
  const bool finite = isFinite(body0->getWorldTransform()) && isFinite(body1->getWorldTransform());
  if (state_) {
    const bool answerable = finite && state_->side[0].refresh(body0->getCollisionShape()) == Support::Gq &&
                            state_->side[1].refresh(body1->getCollisionShape()) == Support::Gq;
    collide(answerable, state_->side[0].view, state_->side[1].view, body0, body1, result);
    return;
  }
  ShapeView va, vb;  // views of this frame only
  const bool answerable = finite && viewShape(body0->getCollisionShape(), va) == Support::Gq &&
                          viewShape(body1->getCollisionShape(), vb) == Support::Gq;
  collide(answerable, va, vb, body0, body1, result);
}

void ContactAlgorithm::collide(bool answerable, const ShapeView& va, const ShapeView& vb,
                               const btCollisionObjectWrapper* body0, const btCollisionObjectWrapper* body1,
                               btManifoldResult* result) {
  if (!answerable) {
    // Bad input (or a shape edited into one gq does not model): no contact, and none kept from earlier frames.
    if (manifold_ && ownManifold_) manifold_->clearManifold();
    return;
  }
  if (!manifold_) {
    manifold_ = m_dispatcher->getNewManifold(body0->getCollisionObject(), body1->getCollisionObject());
    ownManifold_ = true;
  }
  result->setPersistentManifold(manifold_);
  const PlacedShape a{&va, toGq(body0->getWorldTransform()) * va.localPose};
  const PlacedShape b{&vb, toGq(body1->getWorldTransform()) * vb.localPose};
  // Bullet's algorithms report points up to the breaking threshold; contactTest widens it by its own threshold.
  const Real threshold = manifold_->getContactBreakingThreshold() + result->m_closestPointDistanceThreshold;
  ManifoldSink sink(*result);
  pairContacts(a, b, threshold, sink, state_ ? &state_->memory : nullptr);
  if (ownManifold_) result->refreshContactPoints();
}

void ContactAlgorithm::getAllContactManifolds(btManifoldArray& manifolds) {
  if (manifold_ && ownManifold_) manifolds.push_back(manifold_);
}

btCollisionAlgorithm* ContactCreateFunc::CreateCollisionAlgorithm(btCollisionAlgorithmConstructionInfo& ci,
                                                                  const btCollisionObjectWrapper* body0,
                                                                  const btCollisionObjectWrapper* body1) {
  ShapeView va, vb;
  const Support a = viewShape(body0->getCollisionShape(), va), b = viewShape(body1->getCollisionShape(), vb);
  // Invalid shapes get gq's algorithm too: it reports no contact while they stay invalid (Bullet's own algorithms
  // would report NaN contacts for some, or crash on a hull without points).
  const bool gqPath = (a == Support::Gq && b == Support::Gq && pairHasGqPath(va.kind, vb.kind)) ||
                      a == Support::Invalid || b == Support::Invalid;
  if (gqPath) {
    void* memory = ci.m_dispatcher1->allocateCollisionAlgorithm(sizeof(ContactAlgorithm));
    return new (memory) ContactAlgorithm(ci.m_manifold, ci, body0, body1);
  }
  btCollisionAlgorithmCreateFunc* bulletFunc = config_.bulletCreateFunc(
      body0->getCollisionShape()->getShapeType(), body1->getCollisionShape()->getShapeType(), closest_);
  return bulletFunc->CreateCollisionAlgorithm(ci, body0, body1);
}

}  // namespace gq::bullet
