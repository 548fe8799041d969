#include "contact_algorithm.h"

#include <array>
#include <cstdint>
#include <cstring>
#include <new>

#include <BulletCollision/CollisionDispatch/btCollisionObjectWrapper.h>
#include <BulletCollision/CollisionDispatch/btManifoldResult.h>
#include <BulletCollision/CollisionShapes/btCapsuleShape.h>
#include <BulletCollision/CollisionShapes/btConeShape.h>
#include <BulletCollision/CollisionShapes/btConvexHullShape.h>
#include <BulletCollision/CollisionShapes/btCylinderShape.h>
#include <BulletCollision/CollisionShapes/btStaticPlaneShape.h>
#include <BulletCollision/CollisionShapes/btTriangleMeshShape.h>
#include <BulletCollision/NarrowPhaseCollision/btPersistentManifold.h>

#include "contacts.h"
#include "gq/bullet/collision_configuration.h"
#include "shape_cache.h"

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

// Every parameter a view of a primitive, hull, BVH mesh, heightfield or plane is made of (the hull's points by
// their buffer and count, which change when points are added). Equal keys (bytewise, so a NaN matches itself) give
// equal views. No padding: the key is compared as whole words, inline (it is checked for both shapes of every pair
// every frame).
struct ShapeKey {
  const btCollisionShape* shape = nullptr;
  const void* points = nullptr;
  int type = -1;
  int count = 0;  // an up axis, or a hull's point count
  btScalar values[8] = {};
  bool operator==(const ShapeKey& o) const {
    std::uint64_t a[sizeof(ShapeKey) / 8], b[sizeof(ShapeKey) / 8];
    std::memcpy(a, this, sizeof a);
    std::memcpy(b, &o, sizeof b);
    std::uint64_t differ = 0;
    for (std::size_t i = 0; i < sizeof a / 8; ++i) differ |= a[i] ^ b[i];
    return differ == 0;
  }
};
static_assert(sizeof(ShapeKey) == 2 * sizeof(void*) + 2 * sizeof(int) + 8 * sizeof(btScalar) &&
                  sizeof(ShapeKey) % 8 == 0,
              "ShapeKey has no padding");

void putVector(btScalar* v, const btVector3& x) { v[0] = x.x(), v[1] = x.y(), v[2] = x.z(); }

// False for the shapes whose views are rebuilt every frame (scaled meshes, multi-spheres: their cache lookups
// check their own data) and for a malformed mesh or heightfield.
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
      key.count = static_cast<const btCapsuleShape*>(shape)->getUpAxis();
      return true;
    case CYLINDER_SHAPE_PROXYTYPE:
      putVector(key.values + 4, static_cast<const btConvexInternalShape*>(shape)->getImplicitShapeDimensions());
      key.count = static_cast<const btCylinderShape*>(shape)->getUpAxis();
      return true;
    case CONE_SHAPE_PROXYTYPE: {
      const auto* cone = static_cast<const btConeShape*>(shape);
      key.values[4] = cone->getRadius(), key.values[5] = cone->getHeight();
      key.count = cone->getConeUpIndex();
      return true;
    }
    case CONVEX_HULL_SHAPE_PROXYTYPE: {
      const auto* hull = static_cast<const btConvexHullShape*>(shape);
      key.points = hull->getUnscaledPoints();
      key.count = hull->getNumPoints();
      return true;
    }
    case TRIANGLE_MESH_SHAPE_PROXYTYPE: {
      // A BVH mesh by its interface and the fingerprint its cooked data is cached under (buffers, counts, types).
      const btStridingMeshInterface* mesh = static_cast<const btTriangleMeshShape*>(shape)->getMeshInterface();
      std::uint64_t fingerprint = 0;
      if (!mesh || !meshFingerprint(*mesh, fingerprint)) return false;
      key.points = mesh;
      std::memcpy(static_cast<void*>(key.values + 4), &fingerprint, sizeof fingerprint);
      return true;
    }
    case TERRAIN_SHAPE_PROXYTYPE: {
      // A heightfield by the fingerprint its cooked data is cached under (data pointer, sizes, axis, scaling).
      std::uint64_t fingerprint = 0;
      if (!heightFieldFingerprint(*static_cast<const btHeightfieldTerrainShape*>(shape), fingerprint)) return false;
      std::memcpy(static_cast<void*>(key.values + 4), &fingerprint, sizeof fingerprint);
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

// The cooked data a mesh or heightfield view points to (its identity: it changes when the shape re-cooks).
const void* surfaceData(const Geometry<Real>& g) {
  if (const auto* mesh = g.getIf<TriangleMeshGeometry<Real>>()) return mesh->mesh.get();
  if (const auto* field = g.getIf<HeightFieldGeometry<Real>>()) return field->heightField.get();
  return nullptr;
}

}  // namespace

// One side of a pair, in two parts: what every call reads (the shape's key, checked each frame) and what only an
// exact frame reads (the view and the prepared geometry). The pair's state keeps the first parts of both sides and
// the reuse test's data together at its front, so a call that keeps its contacts touches a few cache lines of it:
// a pile has thousands of pairs whose states do not stay in cache from one frame to the next.
struct SideKey {
  ShapeKey key;
  // Changes whenever the view may have changed (a keyed shape rebuilt, a surface re-cooked or rescaled).
  std::uint32_t version = 0;
  bool keyed = false;
  // Whether `version` tracks every change of the view (keyed shapes and surfaces; not multi-spheres).
  bool versioned = false;
  Support support = Support::Invalid;
};

struct SideView {
  ShapeView view;
  Shape<Real> prepared;
  const void* surface = nullptr;
  btVector3 surfaceScaling{0, 0, 0};
};

namespace {

// Rebuilds the side's view from the shape (whose key is `now` when `keyed`).
Support rebuildSide(SideKey& k, SideView& s, const btCollisionShape* shape, const ShapeKey& now, bool keyed) {
  if (keyed) k.key = now;
  k.keyed = keyed;
  ++k.version;
  k.support = viewShape(shape, s.view);
  s.view.prepared = nullptr;
  // Only convex pairs read the prepared shape; a mesh or heightfield is not prepared (making a Shape bounds every
  // vertex, which cost a pair with a large ground more than its contacts).
  const GeometryType type = s.view.geom.type();
  const bool isSurface = type == GeometryType::TriangleMesh || type == GeometryType::HeightField;
  if (k.support == Support::Gq && !isSurface && Shape<Real>::make(s.view.geom, s.prepared).ok())
    s.view.prepared = &s.prepared;
  if (isSurface && k.support == Support::Gq && surfaceData(s.view.geom) == s.surface &&
      shape->getLocalScaling() == s.surfaceScaling)
    --k.version;  // the same cooked surface at the same scaling: the view is unchanged
  s.surface = isSurface ? surfaceData(s.view.geom) : nullptr;
  if (shape) s.surfaceScaling = shape->getLocalScaling();
  k.versioned = k.keyed || s.surface != nullptr;
  return k.support;
}

// The shape's view, rebuilt only when the shape's parameters changed since the last frame (the unchanged case,
// every frame of every pair, reads the key only).
inline Support refreshSide(SideKey& k, SideView& s, const btCollisionShape* shape) {
  ShapeKey now;
  const bool keyed = shape && keyOf(shape, now);
  if (keyed && k.keyed && now == k.key) return k.support;
  return rebuildSide(k, s, shape, now, keyed);
}

}  // namespace

// The contact set of a pair is a function of the shapes and of B's pose relative to A. A frame whose relative pose
// is within kReuseLength (times the smaller convex size) and kReuseAngle (radians) of the pose of the last exact
// frame keeps the manifold's points instead of recomputing them: each point stays on its two features (fixed in
// each body's frame), its normal turns with B and Bullet's refresh recomputes its depth from them, so a resting
// pair pays for its contacts once, not every frame.
constexpr Real kReuseLength = Real(1e-3);
constexpr Real kReuseAngle = Real(1e-3);

struct ReusedFrame {
  btTransform relative;  // B's pose in A's frame at the last exact frame
  std::array<btVector3, MANIFOLD_CACHE_SIZE> normalInB;
  Real threshold = 0;
  Real length = 0;  // the reuse tolerance on the relative origin
  std::uint32_t versions[2] = {0, 0};
  int points = 0;
  bool valid = false;
};

// 64-byte aligned: the hot part starts a cache line.
struct alignas(64) PairState {
  SideKey key[2];
  ReusedFrame reused;
  SideView side[2];
  PairMemory memory;
};

namespace {

// The manifold's own B (Bullet may have made it with the two objects the other way round).
const btTransform& manifoldB(const btPersistentManifold& m, const btTransform& trA, const btTransform& trB,
                             const btCollisionObject* objectB) {
  return m.getBody1() == objectB ? trB : trA;
}

// The length the reuse tolerance is relative to: the smaller convex side (planes and surfaces are unbounded).
Real reuseSize(const ShapeView& va, const ShapeView& vb) {
  if (va.kind != ShapeKind::Convex) return vb.size;
  if (vb.kind != ShapeKind::Convex) return va.size;
  return std::min(va.size, vb.size);
}

// The world pose of a view's geometry (Bullet's pose times the view's local pose, skipped when that is the identity,
// as for boxes and spheres: the product would be the same numbers).
Pose worldPose(const btTransform& tr, const ShapeView& v) {
  const Pose& local = v.localPose;
  const bool identity = local.q.w() == Real(1) && local.q.x() == Real(0) && local.q.y() == Real(0) &&
                        local.q.z() == Real(0) && local.p.x() == Real(0) && local.p.y() == Real(0) &&
                        local.p.z() == Real(0);
  return identity ? toGq(tr) : toGq(tr) * local;
}

}  // namespace

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
    PairState& st = *state_;
    const bool answerable = finite && refreshSide(st.key[0], st.side[0], body0->getCollisionShape()) == Support::Gq &&
                            refreshSide(st.key[1], st.side[1], body1->getCollisionShape()) == Support::Gq;
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
    if (state_) state_->reused.valid = false;
    return;
  }
  if (!manifold_) {
    manifold_ = m_dispatcher->getNewManifold(body0->getCollisionObject(), body1->getCollisionObject());
    ownManifold_ = true;
  }
  result->setPersistentManifold(manifold_);
  // Bullet's algorithms report points up to the breaking threshold; contactTest widens it by its own threshold.
  const Real threshold = manifold_->getContactBreakingThreshold() + result->m_closestPointDistanceThreshold;
  const btTransform& trA = body0->getWorldTransform();
  const btTransform& trB = body1->getWorldTransform();
  const bool reusable = state_ && ownManifold_ && result->m_closestPointDistanceThreshold == Real(0) &&
                        state_->key[0].versioned && state_->key[1].versioned;
  // B's pose in A's frame, for the reuse test and for the next frame's (computed once: both need it).
  btTransform relative;
  if (reusable) relative = trA.inverseTimes(trB);
  const btTransform& poseB = manifoldB(*manifold_, trA, trB, body1->getCollisionObject());
  if (reusable && reuseContacts(relative, threshold, poseB)) {
    result->refreshContactPoints();
    return;
  }
  const PlacedShape a{&va, worldPose(trA, va)};
  const PlacedShape b{&vb, worldPose(trB, vb)};
  ManifoldSink sink(*result);
  // The manifold merges points closer than its breaking threshold (btPersistentManifold::getCacheEntry); a widened
  // distance threshold (contactTest) asks for the points still apart too.
  const HandOver handOver{manifold_->getContactBreakingThreshold(), result->m_closestPointDistanceThreshold == Real(0)};
  pairContacts(a, b, threshold, handOver, sink, state_ ? &state_->memory : nullptr);
  if (ownManifold_) result->refreshContactPoints();
  if (reusable) rememberContacts(reuseSize(va, vb), relative, threshold, poseB);
}

bool ContactAlgorithm::reuseContacts(const btTransform& relative, Real threshold, const btTransform& manifoldPoseB) {
  ReusedFrame& r = state_->reused;
  if (!r.valid || r.threshold != threshold || r.versions[0] != state_->key[0].version ||
      r.versions[1] != state_->key[1].version || manifold_->getNumContacts() != r.points)
    return false;
  if ((relative.getOrigin() - r.relative.getOrigin()).length2() > r.length * r.length) return false;
  const btMatrix3x3& now = relative.getBasis();
  const btMatrix3x3& then = r.relative.getBasis();
  const Real turn2 = (now[0] - then[0]).length2() + (now[1] - then[1]).length2() + (now[2] - then[2]).length2();
  if (turn2 > kReuseAngle * kReuseAngle) return false;
  const btMatrix3x3& basisB = manifoldPoseB.getBasis();
  for (int i = 0; i < r.points; ++i) manifold_->getContactPoint(i).m_normalWorldOnB = basisB * r.normalInB[i];
  return true;
}

void ContactAlgorithm::rememberContacts(Real size, const btTransform& relative, Real threshold,
                                        const btTransform& manifoldPoseB) {
  ReusedFrame& r = state_->reused;
  r.valid = true;
  r.relative = relative;
  r.threshold = threshold;
  r.length = kReuseLength * size;
  r.versions[0] = state_->key[0].version;
  r.versions[1] = state_->key[1].version;
  r.points = manifold_->getNumContacts();
  const btMatrix3x3& basisB = manifoldPoseB.getBasis();
  for (int i = 0; i < r.points; ++i)
    r.normalInB[i] = manifold_->getContactPoint(i).m_normalWorldOnB * basisB;  // basisB^T n
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
