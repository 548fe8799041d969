#include "mesh_fitting.h"

#include <BulletCollision/CollisionDispatch/btActivatingCollisionAlgorithm.h>
#include <BulletCollision/CollisionDispatch/btCollisionObjectWrapper.h>
#include <BulletCollision/CollisionDispatch/btManifoldResult.h>
#include <BulletCollision/CollisionShapes/btBoxShape.h>
#include <BulletCollision/CollisionShapes/btCapsuleShape.h>
#include <BulletCollision/CollisionShapes/btCompoundShape.h>
#include <BulletCollision/CollisionShapes/btSphereShape.h>
#include <BulletCollision/Gimpact/btGImpactShape.h>

#include <cmath>
#include <map>
#include <memory>
#include <mutex>
#include <tuple>
#include <vector>

#include "gq/bullet/collision_configuration.h"
#include "gq/fit.h"
#include "shape_cache.h"

namespace gq::bullet {
namespace {

// A fit as a compound shape; the child shapes live as long as the compound.
struct FittedMesh {
  std::vector<std::unique_ptr<btCollisionShape>> children;
  std::unique_ptr<btCompoundShape> compound;
};

// Bullet shapes for the parts of a fit, margins 0; false for a part Bullet has no shape for. A hull part's points
// are the fit's hull vertices, and the fit's cooked hull (the one its bound is certified for) goes to the hull
// cache as that shape's hull: no qhull run again when the child pairs reach gq.
bool addPart(const Geometry<Real>& g, const Transform<Real>& pose, FittedMesh& out) {
  std::unique_ptr<btCollisionShape> shape;
  if (const auto* s = g.getIf<SphereGeometry<Real>>()) {
    shape = std::make_unique<btSphereShape>(s->radius);
  } else if (const auto* c = g.getIf<CapsuleGeometry<Real>>()) {
    shape = std::make_unique<btCapsuleShapeX>(c->radius, 2 * c->halfHeight);  // gq: axis X
  } else if (const auto* b = g.getIf<BoxGeometry<Real>>()) {
    shape = std::make_unique<btBoxShape>(toBt(b->halfExtents));
  } else if (const auto* h = g.getIf<ConvexMeshGeometry<Real>>()) {
    if (!h->mesh || !h->scale.isIdentity()) return false;
    auto hull = std::make_unique<btConvexHullShape>();
    for (const V3& v : h->mesh->vertices) hull->addPoint(toBt(v), false);
    hull->recalcLocalAabb();
    if (!shareHull(*hull, h->mesh)) return false;
    shape = std::move(hull);
  } else {
    return false;
  }
  // A sphere's and a capsule's margin is their radius (Bullet's convention); the others get none.
  if (g.type() != GeometryType::Sphere && g.type() != GeometryType::Capsule) shape->setMargin(0);
  out.compound->addChildShape(toBt(pose), shape.get());
  out.children.push_back(std::move(shape));
  return true;
}

// The fit of one mesh at one scaling under one set of settings.
struct Key {
  const void* mesh;  // the cooked mesh (held by the entry, so the address is not reused while cached)
  btScalar sx, sy, sz;
  double tolerance;
  FitRepresentationSet allowed;
  std::uint32_t maxParts;
  std::uint32_t maxBoundPatches;
  bool contain;
  bool operator<(const Key& o) const {
    return std::tie(mesh, sx, sy, sz, tolerance, allowed, maxParts, maxBoundPatches, contain) <
           std::tie(o.mesh, o.sx, o.sy, o.sz, o.tolerance, o.allowed, o.maxParts, o.maxBoundPatches, o.contain);
  }
};
struct Entry {
  std::shared_ptr<const TriangleMesh<Real>> mesh;
  std::shared_ptr<const FittedMesh> fit;  // null: the fit failed, Bullet's algorithm answers
};

std::mutex& cacheLock() {
  static std::mutex m;
  return m;
}
std::map<Key, Entry>& cache() {
  static std::map<Key, Entry> c;
  return c;
}

// The fitted compound of a GImpact mesh shape, fitted on first use; null when gq cannot fit it.
std::shared_ptr<const FittedMesh> fittedMesh(const btGImpactMeshShape& shape, const FitOptions<double>& settings) {
  if (shape.getMeshPartCount() < 1 || !shape.getMeshInterface()) return nullptr;
  CookedMesh cooked;
  if (cachedMesh(*shape.getMeshInterface(), cooked) != Support::Gq || !cooked.mesh) return nullptr;
  const btVector3 scaling = shape.getMeshPart(0)->getLocalScaling();  // what GImpact applies to the vertices
  // Keys must order (no NaN): a scaling or tolerance fitShape would refuse leaves the pair to Bullet.
  if (!isUsableScaling(scaling) || !std::isfinite(settings.tolerance) || !(settings.tolerance > 0)) return nullptr;
  // Fitted in Bullet's scalar: the hull parts are then the cooked hulls the adapter answers with.
  FitOptions<Real> options;
  options.tolerance = Real(settings.tolerance);
  options.allowed = settings.allowed;
  options.maxParts = settings.maxParts;
  options.contain = settings.contain;
  options.maxBoundPatches = settings.maxBoundPatches;
  options.measureCost = false;
  // The compound takes convex parts only: not the mesh itself, nor the cylinder (a gq custom geometry).
  options.allowed &= ~(fitBit(FitRepresentation::Mesh) | fitBit(FitRepresentation::Cylinder));
  const Key key{cooked.mesh.get(), scaling.x(), scaling.y(), scaling.z(), settings.tolerance,
                options.allowed, options.maxParts, options.maxBoundPatches, options.contain};
  {
    std::lock_guard<std::mutex> lock(cacheLock());
    auto it = cache().find(key);
    if (it != cache().end()) return it->second.fit;
  }
  // Fitted outside the lock (a large mesh takes seconds); two threads fitting the same key keep the first entry.
  MeshData<Real> mesh;
  for (const V3& v : cooked.mesh->vertices) mesh.vertices.push_back(v.cwiseProduct(toGq(scaling)));
  mesh.triangles = cooked.mesh->triangles;
  FitResult<Real> result;
  const Status s = fitShape(mesh, options, result);
  std::shared_ptr<FittedMesh> fit;
  if ((s.ok() || s.code == StatusCode::Warning) && !result.parts.empty()) {
    fit = std::make_shared<FittedMesh>();
    fit->compound = std::make_unique<btCompoundShape>(true, int(result.parts.size()));
    for (const auto& [g, pose] : result.parts)
      if (!addPart(g, pose, *fit)) {
        fit.reset();
        break;
      }
  }
  std::lock_guard<std::mutex> lock(cacheLock());
  return cache().try_emplace(key, Entry{cooked.mesh, fit}).first->second.fit;
}

}  // namespace

void clearFittedMeshes() {
  std::lock_guard<std::mutex> lock(cacheLock());
  cache().clear();
}

namespace {

// Answers a pair with either side a fitted GImpact mesh: that side stands as its compound, and the algorithm the
// dispatcher has for the compound pair (Bullet's compound algorithm) does the rest.
class FittedMeshAlgorithm final : public btActivatingCollisionAlgorithm {
 public:
  FittedMeshAlgorithm(const btCollisionAlgorithmConstructionInfo& ci, const btCollisionObjectWrapper* body0,
                      const btCollisionObjectWrapper* body1, std::shared_ptr<const FittedMesh> fit0,
                      std::shared_ptr<const FittedMesh> fit1, ebtDispatcherQueryType queryType)
      : btActivatingCollisionAlgorithm(ci, body0, body1),
        fit0_(std::move(fit0)),
        fit1_(std::move(fit1)),
        queryType_(queryType) {}
  ~FittedMeshAlgorithm() override {
    if (child_) {
      child_->~btCollisionAlgorithm();
      m_dispatcher->freeCollisionAlgorithm(child_);
    }
  }

  void processCollision(const btCollisionObjectWrapper* body0, const btCollisionObjectWrapper* body1,
                        const btDispatcherInfo& info, btManifoldResult* result) override {
    const btCollisionObjectWrapper w0(body0, fit0_ ? fit0_->compound.get() : body0->getCollisionShape(),
                                      body0->getCollisionObject(), body0->getWorldTransform(), -1, -1);
    const btCollisionObjectWrapper w1(body1, fit1_ ? fit1_->compound.get() : body1->getCollisionShape(),
                                      body1->getCollisionObject(), body1->getWorldTransform(), -1, -1);
    if (!child_) child_ = m_dispatcher->findAlgorithm(&w0, &w1, nullptr, queryType_);
    if (!child_) return;
    const btCollisionObjectWrapper* saved0 = result->getBody0Wrap();
    const btCollisionObjectWrapper* saved1 = result->getBody1Wrap();
    result->setBody0Wrap(&w0);
    result->setBody1Wrap(&w1);
    child_->processCollision(&w0, &w1, info, result);
    result->setBody0Wrap(saved0);
    result->setBody1Wrap(saved1);
  }
  // No time of impact, as Bullet's GImpact algorithm (its child would read the GImpact shape as a compound).
  btScalar calculateTimeOfImpact(btCollisionObject*, btCollisionObject*, const btDispatcherInfo&,
                                 btManifoldResult*) override {
    return btScalar(1);
  }
  void getAllContactManifolds(btManifoldArray& manifolds) override {
    if (child_) child_->getAllContactManifolds(manifolds);
  }

 private:
  std::shared_ptr<const FittedMesh> fit0_, fit1_;
  ebtDispatcherQueryType queryType_;
  btCollisionAlgorithm* child_ = nullptr;
};

std::shared_ptr<const FittedMesh> fitOf(const btCollisionObjectWrapper* body, const FitOptions<double>& options) {
  const btCollisionShape* shape = body->getCollisionShape();
  if (shape->getShapeType() != GIMPACT_SHAPE_PROXYTYPE) return nullptr;
  const auto* gimpact = static_cast<const btGImpactShapeInterface*>(shape);
  if (gimpact->getGImpactShapeType() != CONST_GIMPACT_TRIMESH_SHAPE) return nullptr;
  return fittedMesh(*static_cast<const btGImpactMeshShape*>(gimpact), options);
}

class FittedMeshCreateFunc final : public btCollisionAlgorithmCreateFunc {
 public:
  FittedMeshCreateFunc(CollisionConfiguration& config, bool closestPoints) : config_(config), closest_(closestPoints) {}
  btCollisionAlgorithm* CreateCollisionAlgorithm(btCollisionAlgorithmConstructionInfo& ci,
                                                 const btCollisionObjectWrapper* body0,
                                                 const btCollisionObjectWrapper* body1) override {
    const int t0 = body0->getCollisionShape()->getShapeType(), t1 = body1->getCollisionShape()->getShapeType();
    std::shared_ptr<const FittedMesh> fit0, fit1;
    if (const FitOptions<double>* options = config_.meshFitting) {
      fit0 = fitOf(body0, *options);
      fit1 = fitOf(body1, *options);
    }
    // A GImpact side that is not fitted stays a GImpact shape: without a fit on either side, Bullet's algorithm.
    if ((t0 == GIMPACT_SHAPE_PROXYTYPE && !fit0) || (t1 == GIMPACT_SHAPE_PROXYTYPE && !fit1))
      return config_.bulletCreateFunc(t0, t1, closest_)->CreateCollisionAlgorithm(ci, body0, body1);
    void* memory = ci.m_dispatcher1->allocateCollisionAlgorithm(sizeof(FittedMeshAlgorithm));
    return new (memory) FittedMeshAlgorithm(ci, body0, body1, std::move(fit0), std::move(fit1),
                                            closest_ ? BT_CLOSEST_POINT_ALGORITHMS : BT_CONTACT_POINT_ALGORITHMS);
  }

 private:
  CollisionConfiguration& config_;
  bool closest_;
};

}  // namespace

bool isFittedMeshPair(int proxyType0, int proxyType1) {
  return proxyType0 == GIMPACT_SHAPE_PROXYTYPE || proxyType1 == GIMPACT_SHAPE_PROXYTYPE;
}

btCollisionAlgorithmCreateFunc* newFittedMeshCreateFunc(CollisionConfiguration& config, bool closestPoints) {
  return new FittedMeshCreateFunc(config, closestPoints);
}

}  // namespace gq::bullet
