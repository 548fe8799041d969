#include "bullet_backend.h"

#include <cmath>
#include <map>
#include <memory>

#include <BulletCollision/CollisionDispatch/btCollisionObject.h>
#include <BulletCollision/CollisionDispatch/btCollisionWorld.h>
#include <BulletCollision/CollisionShapes/btBoxShape.h>
#include <BulletCollision/CollisionShapes/btBvhTriangleMeshShape.h>
#include <BulletCollision/CollisionShapes/btCapsuleShape.h>
#include <BulletCollision/CollisionShapes/btConeShape.h>
#include <BulletCollision/CollisionShapes/btConvexHullShape.h>
#include <BulletCollision/CollisionShapes/btCylinderShape.h>
#include <BulletCollision/CollisionShapes/btHeightfieldTerrainShape.h>
#include <BulletCollision/CollisionShapes/btSphereShape.h>
#include <BulletCollision/CollisionShapes/btStaticPlaneShape.h>
#include <BulletCollision/CollisionShapes/btTriangleMesh.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkEpaPenetrationDepthSolver.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkPairDetector.h>
#include <BulletCollision/NarrowPhaseCollision/btPointCollector.h>
#include <BulletCollision/NarrowPhaseCollision/btRaycastCallback.h>
#include <BulletCollision/NarrowPhaseCollision/btVoronoiSimplexSolver.h>

#ifdef GQ_HAVE_BULLET_ADAPTER
#include "gq/bullet/collision_configuration.h"
#include "gq/bullet/collision_world.h"
#endif
#include "gq/hit.h"
#include "native_shapes.h"
#include "timing.h"

namespace gq::cases {
namespace {

constexpr Precision kNativePrecision = sizeof(btScalar) == sizeof(double) ? Precision::Double : Precision::Float;

btVector3 toBt(const Vec3d& v) { return btVector3(btScalar(v.x()), btScalar(v.y()), btScalar(v.z())); }
Vec3d fromBt(const btVector3& v) { return Vec3d(double(v.x()), double(v.y()), double(v.z())); }
btTransform toBt(const PoseDesc& p) {
  return btTransform(btQuaternion(btScalar(p.q.x()), btScalar(p.q.y()), btScalar(p.q.z()), btScalar(p.q.w())),
                     toBt(p.p));
}

// A Bullet shape plus the offset of gq's local frame inside it (non-zero for heightfields, which Bullet centres
// on their bounding box).
struct BulletShape {
  std::shared_ptr<btCollisionShape> shape;
  std::shared_ptr<btTriangleMesh> triangles;  // keeps a mesh shape's data alive
  std::vector<btScalar> heights;              // keeps a heightfield's samples alive
  Vec3d gqOriginInShape = Vec3d::Zero();
  bool isHeightField = false;

  btConvexShape* convex() const { return shape->isConvex() ? static_cast<btConvexShape*>(shape.get()) : nullptr; }
  // World transform of the Bullet shape for a gq pose.
  btTransform placed(const PoseDesc& pose) const {
    return toBt(pose) * btTransform(btQuaternion::getIdentity(), toBt(-gqOriginInShape));
  }
};

template <class S> std::shared_ptr<btCollisionShape> withZeroMargin(S* s) {
  s->setMargin(0);
  return std::shared_ptr<btCollisionShape>(s);
}

class BulletShapes {
 public:
  // False with an "unsupported: ..." or cooking message.
  bool build(const ShapeDesc& d, BulletShape& out, std::string& error) {
    switch (d.kind) {
      // Sphere and capsule keep their margin: Bullet models them as a point / segment with margin = radius.
      case ShapeKind::Sphere: out.shape = std::make_shared<btSphereShape>(btScalar(d.radius)); return true;
      case ShapeKind::Capsule:
        out.shape = std::make_shared<btCapsuleShapeX>(btScalar(d.radius), btScalar(2 * d.halfHeight));
        return true;
      case ShapeKind::Box: out.shape = withZeroMargin(new btBoxShape(toBt(d.halfExtents))); return true;
      case ShapeKind::Cylinder:
        out.shape = withZeroMargin(new btCylinderShapeX(toBt(Vec3d(d.halfHeight, d.radius, d.radius))));
        return true;
      case ShapeKind::Cone:  // btConeShapeX: apex at +height/2 on X, like the case format's cone
        out.shape = withZeroMargin(new btConeShapeX(btScalar(d.radius), btScalar(2 * d.halfHeight)));
        return true;
      case ShapeKind::Plane: out.shape = std::make_shared<btStaticPlaneShape>(btVector3(1, 0, 0), btScalar(0)); return true;
      case ShapeKind::Convex: return cached(d, out, error, &BulletShapes::convex);
      case ShapeKind::Mesh: return cached(d, out, error, &BulletShapes::mesh);
      case ShapeKind::HeightField: return cached(d, out, error, &BulletShapes::heightField);
    }
    error = "unknown shape";
    return false;
  }

 private:
  using Maker = bool (BulletShapes::*)(const ShapeDesc&, BulletShape&, std::string&);
  bool cached(const ShapeDesc& d, BulletShape& out, std::string& error, Maker make) {
    std::string key = native::scaledKey(d);
    if (d.kind == ShapeKind::HeightField)
      key += "|" + std::to_string(d.rowScale) + "," + std::to_string(d.heightScale) + "," + std::to_string(d.columnScale);
    if (auto it = cache_.find(key); it != cache_.end()) {
      out = it->second;
      return true;
    }
    if (!(this->*make)(d, out, error)) return false;
    cache_.emplace(key, out);
    return true;
  }

  bool convex(const ShapeDesc& d, BulletShape& out, std::string& error) {
    native::HullPolygons hull;  // the same hull vertices every backend uses
    if (!native::cookHullPolygons(native::scaledPoints(d), hull, error)) return false;
    auto* s = new btConvexHullShape();
    for (const Vec3d& v : hull.vertices) s->addPoint(toBt(v), false);
    s->recalcLocalAabb();
    out.shape = withZeroMargin(s);
    return true;
  }

  bool mesh(const ShapeDesc& d, BulletShape& out, std::string&) {
    const std::vector<Vec3d> v = native::scaledPoints(d);
    out.triangles = std::make_shared<btTriangleMesh>(true, false);
    for (const auto& t : native::scaledTriangles(d))
      out.triangles->addTriangle(toBt(v[t[0]]), toBt(v[t[1]]), toBt(v[t[2]]), false);
    out.shape = std::make_shared<btBvhTriangleMeshShape>(out.triangles.get(), true);
    return true;
  }

  bool heightField(const ShapeDesc& d, BulletShape& out, std::string& error) {
    if (!d.holes.empty()) {
      error = "unsupported: btHeightfieldTerrainShape has no holes";
      return false;
    }
    if (d.rowScale <= 0 || d.columnScale <= 0 || d.heightScale <= 0) {
      error = "unsupported: btHeightfieldTerrainShape needs positive scales";
      return false;
    }
    // Bullet indexes samples as data[z * width + x] with x along the width (gq rows, local X), z along the length
    // (gq columns, local Z): the transpose of gq's row-major layout. Cell triangles split along the same diagonal.
    const std::uint32_t rows = d.rows, columns = d.columns;
    out.heights.resize(std::size_t(rows) * columns);
    double lo = d.heights.front(), hi = d.heights.front();
    for (std::uint32_t r = 0; r < rows; ++r)
      for (std::uint32_t c = 0; c < columns; ++c) {
        const double h = d.heights[std::size_t(r) * columns + c];
        out.heights[std::size_t(c) * rows + r] = btScalar(h);
        lo = std::min(lo, h);
        hi = std::max(hi, h);
      }
    auto* s = new btHeightfieldTerrainShape(int(rows), int(columns), out.heights.data(), btScalar(lo), btScalar(hi),
                                            1, false);
    s->setLocalScaling(toBt(Vec3d(d.rowScale, d.heightScale, d.columnScale)));
    out.shape = withZeroMargin(s);
    // Bullet centres the field on its bounding box: gq's sample (0,0) at height 0 is at -centre.
    out.gqOriginInShape = -Vec3d(0.5 * (rows - 1) * d.rowScale, 0.5 * (lo + hi) * d.heightScale,
                                 0.5 * (columns - 1) * d.columnScale);
    out.isHeightField = true;
    return true;
  }

  std::map<std::string, BulletShape> cache_;
};

Result success(double ns, ResultFields fields) {
  Result r;
  r.ok = true;
  r.ns = ns;
  r.fields = std::move(fields);
  return r;
}

// Closest ray hit that also keeps the triangle index of mesh hits.
struct ClosestRayWithFace : btCollisionWorld::ClosestRayResultCallback {
  using ClosestRayResultCallback::ClosestRayResultCallback;
  int triangle = -1;
  btScalar addSingleResult(btCollisionWorld::LocalRayResult& r, bool normalInWorldSpace) override {
    triangle = r.m_localShapeInfo ? r.m_localShapeInfo->m_triangleIndex : -1;
    return ClosestRayResultCallback::addSingleResult(r, normalInWorldSpace);
  }
};

Result raycast(BulletShapes& shapes, const RaycastCase& q, int repeat) {
  const HitFlags flags(q.flags);
  if (flags.has(HitFlag::MeshMultiple)) return Result::failure("unsupported: bullet backend reports one hit (meshMultiple)");
  BulletShape target;
  std::string error;
  if (!shapes.build(q.geom, target, error)) return Result::failure(error);
  btCollisionObject object;
  object.setCollisionShape(target.shape.get());
  const btTransform world = target.placed(q.pose);
  object.setWorldTransform(world);
  const btVector3 from = toBt(q.origin), to = toBt(q.origin + q.maxDist * q.dir);
  const btTransform fromT(btQuaternion::getIdentity(), from), toT(btQuaternion::getIdentity(), to);
  const bool cull = (q.geom.kind == ShapeKind::Mesh || q.geom.kind == ShapeKind::HeightField) && !q.geom.doubleSided &&
                    !flags.has(HitFlag::MeshBothSides);
  ClosestRayWithFace cb(from, to);
  const double ns = medianNanoseconds(repeat, [&] {
    cb = ClosestRayWithFace(from, to);
    if (cull) cb.m_flags |= btTriangleRaycastCallback::kF_FilterBackfaces;
    btCollisionWorld::rayTestSingle(fromT, toT, &object, target.shape.get(), world, cb);
  });
  RaycastOut out;
  if (cb.hasHit()) {
    RayHitOut hit;
    hit.distance = double(cb.m_closestHitFraction) * q.maxDist;
    if (flags.has(HitFlag::Position)) hit.position = fromBt(cb.m_hitPointWorld);
    if (flags.has(HitFlag::Normal)) hit.normal = native::unitOrZero(fromBt(cb.m_hitNormalWorld));
    if (q.geom.kind == ShapeKind::Mesh && cb.triangle >= 0) hit.faceIndex = std::uint32_t(cb.triangle);
    out.hits.push_back(hit);
  }
  return success(ns, std::move(out));
}

Result pair(BulletShapes& shapes, QueryKind kind, const PairCase& q, int repeat) {
  BulletShape a, b;
  std::string error;
  if (!shapes.build(q.geom0, a, error) || !shapes.build(q.geom1, b, error)) return Result::failure(error);
  if (!a.convex() || !b.convex())
    return native::unsupportedQuery("bullet (btGjkPairDetector)", kind, "non-convex shapes (plane, mesh, heightfield)");
  btVoronoiSimplexSolver simplex;
  btGjkEpaPenetrationDepthSolver epa;
  btGjkPairDetector::ClosestPointInput input;
  input.m_transformA = a.placed(q.pose0);
  input.m_transformB = b.placed(q.pose1);
  input.m_maximumDistanceSquared = BT_LARGE_FLOAT;
  btPointCollector result;
  const double ns = medianNanoseconds(repeat, [&] {
    result = btPointCollector();
    simplex.reset();
    btGjkPairDetector detector(a.convex(), b.convex(), &simplex, &epa);
    detector.getClosestPoints(input, result, nullptr);
  });
  if (!result.m_hasResult) return Result::failure("bullet: btGjkPairDetector found no result", ns);
  const double dist = double(result.m_distance);
  // Bullet's normal on B points from B towards A; its point lies on B.
  const Vec3d normalOnB = fromBt(result.m_normalOnBInWorld);
  if (kind == QueryKind::Overlap) return success(ns, OverlapOut{dist <= 0});
  if (kind == QueryKind::Penetration) {
    PenetrationOut out;
    out.penetrating = dist < 0;
    if (out.penetrating) {
      out.depth = -dist;
      out.direction = normalOnB;  // moving A along B's outward normal separates them
    }
    return success(ns, out);
  }
  DistanceOut out;
  out.distance = dist;
  out.point1 = fromBt(result.m_pointInWorld);
  out.point0 = out.point1 + dist * normalOnB;
  out.normal = -normalOnB;
  return success(ns, out);
}

Result sweep(BulletShapes& shapes, const SweepCase& q, int repeat) {
  if (q.inflation != 0) return Result::failure("unsupported: bullet sweeps have no inflation");
  BulletShape swept, target;
  std::string error;
  if (!shapes.build(q.geom0, swept, error) || !shapes.build(q.geom1, target, error)) return Result::failure(error);
  if (!swept.convex()) return native::unsupportedQuery("bullet (objectQuerySingle)", QueryKind::Sweep, "a non-convex swept shape");
  btCollisionObject object;
  object.setCollisionShape(target.shape.get());
  const btTransform world = target.placed(q.pose1);
  object.setWorldTransform(world);
  const btTransform fromT = swept.placed(q.pose0);
  btTransform toT = fromT;
  toT.setOrigin(fromT.getOrigin() + toBt(q.maxDist * q.dir));
  btCollisionWorld::ClosestConvexResultCallback cb(fromT.getOrigin(), toT.getOrigin());
  const double ns = medianNanoseconds(repeat, [&] {
    cb = btCollisionWorld::ClosestConvexResultCallback(fromT.getOrigin(), toT.getOrigin());
    btCollisionWorld::objectQuerySingle(swept.convex(), fromT, toT, &object, target.shape.get(), world, cb, 0);
  });
  SweepOut out;
  out.hit = cb.hasHit();
  if (out.hit) {
    out.distance = double(cb.m_closestHitFraction) * q.maxDist;
    const HitFlags flags(q.flags);
    if (flags.has(HitFlag::Position)) out.position = fromBt(cb.m_hitPointWorld);
    if (flags.has(HitFlag::Normal)) out.normal = native::unitOrZero(fromBt(cb.m_hitNormalWorld));
    out.initialOverlap = cb.m_closestHitFraction == 0;
  }
  return success(ns, out);
}

#ifdef GQ_HAVE_BULLET_ADAPTER
// A query-only world through the adapter; each case adds its objects, queries, and removes them.
struct AdapterWorld {
  gq::bullet::CollisionConfiguration config;
  gq::bullet::CollisionDispatcher dispatcher{&config};
  btDbvtBroadphase broadphase;
  gq::bullet::CollisionWorld world{&dispatcher, &broadphase, &config};
};

class ScopedObject {
 public:
  ScopedObject(btCollisionWorld& world, btCollisionShape* shape, const btTransform& pose) : world_(world) {
    object_.setCollisionShape(shape);
    object_.setWorldTransform(pose);
    world_.addCollisionObject(&object_);
  }
  ~ScopedObject() { world_.removeCollisionObject(&object_); }
  btCollisionObject* get() { return &object_; }

 private:
  btCollisionWorld& world_;
  btCollisionObject object_;
};

Result adapterRaycast(AdapterWorld& w, BulletShapes& shapes, const RaycastCase& q, int repeat) {
  const HitFlags flags(q.flags);
  if (flags.has(HitFlag::MeshMultiple)) return Result::failure("unsupported: rayTest reports one hit (meshMultiple)");
  BulletShape target;
  std::string error;
  if (!shapes.build(q.geom, target, error)) return Result::failure(error);
  ScopedObject object(w.world, target.shape.get(), target.placed(q.pose));
  const btVector3 from = toBt(q.origin), to = toBt(q.origin + q.maxDist * q.dir);
  const bool cull = (q.geom.kind == ShapeKind::Mesh || q.geom.kind == ShapeKind::HeightField) && !q.geom.doubleSided &&
                    !flags.has(HitFlag::MeshBothSides);
  ClosestRayWithFace cb(from, to);
  const double ns = medianNanoseconds(repeat, [&] {
    cb = ClosestRayWithFace(from, to);
    if (cull) cb.m_flags |= btTriangleRaycastCallback::kF_FilterBackfaces;
    w.world.rayTest(from, to, cb);
  });
  RaycastOut out;
  if (cb.hasHit()) {
    RayHitOut hit;
    hit.distance = double(cb.m_closestHitFraction) * q.maxDist;
    if (flags.has(HitFlag::Position)) hit.position = fromBt(cb.m_hitPointWorld);
    if (flags.has(HitFlag::Normal)) hit.normal = native::unitOrZero(fromBt(cb.m_hitNormalWorld));
    if (q.geom.kind == ShapeKind::Mesh && cb.triangle >= 0) hit.faceIndex = std::uint32_t(cb.triangle);
    out.hits.push_back(hit);
  }
  return success(ns, std::move(out));
}

// The deepest contactPairTest point, re-expressed with A = the first object.
struct DeepestPoint : btCollisionWorld::ContactResultCallback {
  const btCollisionObject* a = nullptr;
  bool found = false;
  double distance = 0;
  Vec3d normalOnB = Vec3d::Zero(), pointOnA = Vec3d::Zero(), pointOnB = Vec3d::Zero();
  btScalar addSingleResult(btManifoldPoint& cp, const btCollisionObjectWrapper* w0, int, int,
                           const btCollisionObjectWrapper*, int, int) override {
    if (found && double(cp.getDistance()) >= distance) return 0;
    const bool swapped = w0->getCollisionObject() != a;
    found = true;
    distance = double(cp.getDistance());
    normalOnB = fromBt(swapped ? -cp.m_normalWorldOnB : cp.m_normalWorldOnB);
    pointOnA = fromBt(swapped ? cp.getPositionWorldOnB() : cp.getPositionWorldOnA());
    pointOnB = fromBt(swapped ? cp.getPositionWorldOnA() : cp.getPositionWorldOnB());
    return 0;
  }
};

// contactPairTest reports points up to this distance (the suites' shapes are within a few units of each other).
constexpr btScalar kPairReach = btScalar(1e3);

Result adapterPair(AdapterWorld& w, BulletShapes& shapes, QueryKind kind, const PairCase& q, int repeat) {
  BulletShape a, b;
  std::string error;
  if (!shapes.build(q.geom0, a, error) || !shapes.build(q.geom1, b, error)) return Result::failure(error);
  if (!gq::bullet::CollisionConfiguration::routesToGq(a.shape->getShapeType(), b.shape->getShapeType()))
    return native::unsupportedQuery("gq-bullet", kind, "pairs the adapter leaves to Bullet (two non-convex shapes)");
  ScopedObject objectA(w.world, a.shape.get(), a.placed(q.pose0));
  ScopedObject objectB(w.world, b.shape.get(), b.placed(q.pose1));
  DeepestPoint cb;
  const double ns = medianNanoseconds(repeat, [&] {
    cb = DeepestPoint();
    cb.a = objectA.get();
    cb.m_closestDistanceThreshold = kPairReach;
    w.world.contactPairTest(objectA.get(), objectB.get(), cb);
  });
  if (kind == QueryKind::Overlap) return success(ns, OverlapOut{cb.found && cb.distance <= 0});
  if (kind == QueryKind::Penetration) {
    PenetrationOut out;
    out.penetrating = cb.found && cb.distance < 0;
    if (out.penetrating) {
      out.depth = -cb.distance;
      out.direction = cb.normalOnB;  // moving A along B's outward normal separates them
    }
    return success(ns, out);
  }
  if (!cb.found) return Result::failure("gq-bullet: no contact point within reach", ns);
  DistanceOut out;
  out.distance = cb.distance;
  out.point0 = cb.pointOnA;
  out.point1 = cb.pointOnB;
  out.normal = -cb.normalOnB;
  return success(ns, out);
}

Result adapterSweep(AdapterWorld& w, BulletShapes& shapes, const SweepCase& q, int repeat) {
  if (q.inflation != 0) return Result::failure("unsupported: Bullet's convexSweepTest has no inflation");
  BulletShape swept, target;
  std::string error;
  if (!shapes.build(q.geom0, swept, error) || !shapes.build(q.geom1, target, error)) return Result::failure(error);
  if (!swept.convex()) return native::unsupportedQuery("gq-bullet (convexSweepTest)", QueryKind::Sweep, "a non-convex swept shape");
  ScopedObject object(w.world, target.shape.get(), target.placed(q.pose1));
  const btTransform fromT = swept.placed(q.pose0);
  btTransform toT = fromT;
  toT.setOrigin(fromT.getOrigin() + toBt(q.maxDist * q.dir));
  btCollisionWorld::ClosestConvexResultCallback cb(fromT.getOrigin(), toT.getOrigin());
  const double ns = medianNanoseconds(repeat, [&] {
    cb = btCollisionWorld::ClosestConvexResultCallback(fromT.getOrigin(), toT.getOrigin());
    w.world.convexSweepTest(swept.convex(), fromT, toT, cb);
  });
  SweepOut out;
  out.hit = cb.hasHit();
  if (out.hit) {
    out.distance = double(cb.m_closestHitFraction) * q.maxDist;
    const HitFlags flags(q.flags);
    if (flags.has(HitFlag::Position)) out.position = fromBt(cb.m_hitPointWorld);
    if (flags.has(HitFlag::Normal)) out.normal = native::unitOrZero(fromBt(cb.m_hitNormalWorld));
    out.initialOverlap = cb.m_closestHitFraction == 0;
  }
  return success(ns, out);
}
#endif

// A Bullet build answers its btScalar's precision; the other one names the program that answers it.
Result otherPrecision(Precision p) {
  return Result::failure(std::string(kBulletPrecisionUnsupported) + (p == Precision::Float
                                                                         ? "float is answered by gq-query-bullet"
                                                                         : "double is answered by gq-query-bullet64"));
}

}  // namespace

struct BulletBackend::Impl {
  BulletShapes shapes;
};

BulletBackend::BulletBackend() : impl_(new Impl) {}
BulletBackend::~BulletBackend() { delete impl_; }

Result BulletBackend::run(const Case& c, int repeat) {
  if (c.precision != kNativePrecision) return otherPrecision(c.precision);
  switch (c.query) {
    case QueryKind::Raycast: return raycast(impl_->shapes, std::get<RaycastCase>(c.input), repeat);
    case QueryKind::Overlap:
    case QueryKind::Penetration:
    case QueryKind::Distance: return pair(impl_->shapes, c.query, std::get<PairCase>(c.input), repeat);
    case QueryKind::Sweep: return sweep(impl_->shapes, std::get<SweepCase>(c.input), repeat);
    default: return native::unsupportedQuery("bullet", c.query, "any geometry");
  }
}

#ifdef GQ_HAVE_BULLET_ADAPTER
struct GqBulletBackend::Impl {
  BulletShapes shapes;
  AdapterWorld world;
};

GqBulletBackend::GqBulletBackend() : impl_(new Impl) {}
GqBulletBackend::~GqBulletBackend() { delete impl_; }

Result GqBulletBackend::run(const Case& c, int repeat) {
  if (c.precision != kNativePrecision) return otherPrecision(c.precision);
  switch (c.query) {
    case QueryKind::Raycast: return adapterRaycast(impl_->world, impl_->shapes, std::get<RaycastCase>(c.input), repeat);
    case QueryKind::Overlap:
    case QueryKind::Penetration:
    case QueryKind::Distance:
      return adapterPair(impl_->world, impl_->shapes, c.query, std::get<PairCase>(c.input), repeat);
    case QueryKind::Sweep: return adapterSweep(impl_->world, impl_->shapes, std::get<SweepCase>(c.input), repeat);
    default: return native::unsupportedQuery("gq-bullet", c.query, "any geometry");
  }
}
#endif

}  // namespace gq::cases
