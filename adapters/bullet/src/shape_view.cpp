#include "shape_view.h"

#include <algorithm>
#include <cmath>

#include <BulletCollision/BroadphaseCollision/btBroadphaseProxy.h>
#include <BulletCollision/CollisionShapes/btBoxShape.h>
#include <BulletCollision/CollisionShapes/btBvhTriangleMeshShape.h>
#include <BulletCollision/CollisionShapes/btCapsuleShape.h>
#include <BulletCollision/CollisionShapes/btConeShape.h>
#include <BulletCollision/CollisionShapes/btCylinderShape.h>
#include <BulletCollision/CollisionShapes/btScaledBvhTriangleMeshShape.h>
#include <BulletCollision/CollisionShapes/btSphereShape.h>
#include <BulletCollision/CollisionShapes/btStaticPlaneShape.h>

#include "gq/custom_shapes.h"
#include "shape_cache.h"

namespace gq::bullet {
namespace {

// gq's capsule, cylinder and cone run along local X; Bullet's along `upAxis`. The rotation takes X to that axis.
Quat<Real> xToAxis(int upAxis) {
  V3 axis = V3::Zero();
  axis[upAxis] = Real(1);
  return Quat<Real>::FromTwoVectors(V3::UnitX(), axis);
}

bool positive(Real x) { return std::isfinite(x) && x > Real(0); }
Support supportIf(bool valid) { return valid ? Support::Gq : Support::Invalid; }

Support viewSphere(const btSphereShape& s, ShapeView& v) {
  const Real r = s.getRadius();  // includes the local scaling
  if (!positive(r)) return Support::Invalid;
  v.geom = SphereGeometry<Real>(r);
  v.size = r;
  return Support::Gq;
}

Support viewCapsule(const btCapsuleShape& s, ShapeView& v) {
  const Real r = s.getRadius(), h = s.getHalfHeight();
  if (!positive(r) || !std::isfinite(h) || h < Real(0)) return Support::Invalid;
  v.geom = CapsuleGeometry<Real>(r, h);
  v.localPose = Pose(V3::Zero(), xToAxis(s.getUpAxis()));
  v.size = r + h;
  return Support::Gq;
}

Support viewBox(const btBoxShape& s, ShapeView& v) {
  const V3 he = toGq(s.getHalfExtentsWithMargin());
  if (!positive(he.x()) || !positive(he.y()) || !positive(he.z())) return Support::Invalid;
  v.geom = BoxGeometry<Real>(he);
  v.size = he.maxCoeff();
  return Support::Gq;
}

// makeCylinder / makeCone refuse radii and heights that are not finite and positive.
Support viewCylinder(const btCylinderShape& s, ShapeView& v) {
  const Real halfHeight = s.getHalfExtentsWithMargin()[s.getUpAxis()];
  CustomGeometry<Real> cylinder;
  if (!makeCylinder(s.getRadius(), halfHeight, cylinder)) return Support::Invalid;
  v.geom = cylinder;
  v.localPose = Pose(V3::Zero(), xToAxis(s.getUpAxis()));
  v.size = std::max(s.getRadius(), halfHeight);
  return Support::Gq;
}

// Bullet's cone is centred on its axis midpoint with the apex at +height/2 along the up axis, as gq's (along X).
Support viewCone(const btConeShape& s, ShapeView& v) {
  CustomGeometry<Real> cone;
  if (!makeCone(s.getRadius(), s.getHeight() / 2, cone)) return Support::Invalid;
  v.geom = cone;
  v.localPose = Pose(V3::Zero(), xToAxis(s.getConeUpIndex()));
  v.margin = s.getMargin();
  v.size = std::max(s.getRadius(), s.getHeight() / 2);
  return Support::Gq;
}

Support viewHull(const btConvexHullShape& s, ShapeView& v) {
  std::shared_ptr<const ConvexMesh<Real>> hull;
  const Support support = cachedHull(s, hull);
  if (support != Support::Gq) return support;
  const V3 scale = toGq(s.getLocalScaling());
  if ((scale.array() < Real(0)).any()) return Support::Bullet;  // a mirrored hull: gq takes positive convex scales
  v.geom = ConvexMeshGeometry<Real>(hull, MeshScale<Real>(scale));
  v.margin = s.getMargin();
  v.size = (hull->localBounds.extents().cwiseProduct(scale.cwiseAbs())).maxCoeff();
  return Support::Gq;
}

Support viewMultiSphere(const btMultiSphereShape& s, ShapeView& v) {
  std::shared_ptr<const MultiSphereShape> spheres;
  const Support support = cachedMultiSphere(s, spheres);
  if (support != Support::Gq) return support;
  v.size = spheres->localBounds().extents().maxCoeff();
  v.geom = CustomGeometry<Real>(std::move(spheres));
  return Support::Gq;
}

// btStaticPlaneShape is the plane dot(n, x) = c; gq's plane is x = 0 with normal +X.
Support viewPlane(const btStaticPlaneShape& s, ShapeView& v) {
  const V3 normal = toGq(s.getPlaneNormal());
  const Real length = normal.norm();
  if (!positive(length) || !std::isfinite(s.getPlaneConstant())) return Support::Invalid;
  const V3 n = normal / length;
  v.geom = PlaneGeometry<Real>();
  v.localPose = Pose(n * s.getPlaneConstant(), Quat<Real>::FromTwoVectors(V3::UnitX(), n));
  v.kind = ShapeKind::Plane;
  v.margin = s.getMargin();
  return Support::Gq;
}

Support viewMesh(const btTriangleMeshShape& s, const btVector3& extraScale, ShapeView& v) {
  CookedMesh cooked;
  if (!isUsableScaling(extraScale) || !s.getMeshInterface()) return Support::Invalid;
  const Support support = cachedMesh(*s.getMeshInterface(), cooked);
  if (support != Support::Gq) return support;
  const V3 scale = toGq(s.getLocalScaling()).cwiseProduct(toGq(extraScale));
  v.geom = TriangleMeshGeometry<Real>(cooked.mesh, MeshScale<Real>(scale));
  v.partStarts = cooked.partStarts;
  v.kind = ShapeKind::Mesh;
  v.margin = s.getMargin();
  v.size = (cooked.mesh->localBounds.extents().cwiseProduct(scale.cwiseAbs())).maxCoeff();
  return Support::Gq;
}

Support viewHeightField(const btHeightfieldTerrainShape& s, ShapeView& v) {
  CookedHeightField cooked;
  const Support support = cachedHeightField(s, cooked);
  if (support != Support::Gq) return support;
  v.geom = HeightFieldGeometry<Real>(cooked.heightField, Real(1), cooked.rowScale, cooked.columnScale);
  v.localPose = cooked.localPose;
  v.kind = ShapeKind::HeightField;
  v.heightFieldColumns = cooked.heightField->columns;
  v.heightFieldRowsAreX = cooked.rowsAreX;
  v.margin = s.getMargin();
  v.size = std::max(cooked.rowScale, cooked.columnScale);
  return Support::Gq;
}

// The shape's own view, before the checks every view must pass.
Support viewByType(const btCollisionShape* shape, ShapeView& v) {
  switch (shape->getShapeType()) {
    case SPHERE_SHAPE_PROXYTYPE: return viewSphere(*static_cast<const btSphereShape*>(shape), v);
    case CAPSULE_SHAPE_PROXYTYPE: return viewCapsule(*static_cast<const btCapsuleShape*>(shape), v);
    case BOX_SHAPE_PROXYTYPE: return viewBox(*static_cast<const btBoxShape*>(shape), v);
    case CONVEX_HULL_SHAPE_PROXYTYPE: return viewHull(*static_cast<const btConvexHullShape*>(shape), v);
    case CYLINDER_SHAPE_PROXYTYPE: return viewCylinder(*static_cast<const btCylinderShape*>(shape), v);
    case CONE_SHAPE_PROXYTYPE: return viewCone(*static_cast<const btConeShape*>(shape), v);
    case MULTI_SPHERE_SHAPE_PROXYTYPE: return viewMultiSphere(*static_cast<const btMultiSphereShape*>(shape), v);
    case STATIC_PLANE_PROXYTYPE: return viewPlane(*static_cast<const btStaticPlaneShape*>(shape), v);
    case TRIANGLE_MESH_SHAPE_PROXYTYPE:
      return viewMesh(*static_cast<const btTriangleMeshShape*>(shape), btVector3(1, 1, 1), v);
    case SCALED_TRIANGLE_MESH_SHAPE_PROXYTYPE: {
      const auto* scaled = static_cast<const btScaledBvhTriangleMeshShape*>(shape);
      if (!scaled->getChildShape()) return Support::Invalid;
      return viewMesh(*scaled->getChildShape(), scaled->getLocalScaling(), v);
    }
    case TERRAIN_SHAPE_PROXYTYPE: return viewHeightField(*static_cast<const btHeightfieldTerrainShape*>(shape), v);
    default: return Support::Bullet;
  }
}

}  // namespace

TriangleIds ShapeView::triangleIds(std::uint32_t gqTriangle) const {
  TriangleIds ids;
  if (kind == ShapeKind::Mesh && partStarts) {
    int part = 0;
    while (part + 1 < int(partStarts->size()) && (*partStarts)[part + 1] <= gqTriangle) ++part;
    ids.part = part;
    ids.index = int(gqTriangle - (*partStarts)[part]);
  } else if (kind == ShapeKind::HeightField && heightFieldColumns > 1) {
    const std::uint32_t cell = gqTriangle / 2;
    const int r = int(cell / (heightFieldColumns - 1)), c = int(cell % (heightFieldColumns - 1));
    ids.part = heightFieldRowsAreX ? r : c;  // Bullet reports (x, j) of the quad
    ids.index = heightFieldRowsAreX ? c : r;
  }
  return ids;
}

bool isGqConvexType(int t) {
  return t == SPHERE_SHAPE_PROXYTYPE || t == CAPSULE_SHAPE_PROXYTYPE || t == BOX_SHAPE_PROXYTYPE ||
         t == CONVEX_HULL_SHAPE_PROXYTYPE || t == CYLINDER_SHAPE_PROXYTYPE || t == CONE_SHAPE_PROXYTYPE ||
         t == MULTI_SPHERE_SHAPE_PROXYTYPE;
}

bool isGqShapeType(int t) {
  return isGqConvexType(t) || t == STATIC_PLANE_PROXYTYPE || t == TRIANGLE_MESH_SHAPE_PROXYTYPE ||
         t == SCALED_TRIANGLE_MESH_SHAPE_PROXYTYPE || t == TERRAIN_SHAPE_PROXYTYPE;
}

Support viewShape(const btCollisionShape* shape, ShapeView& v) {
  if (!shape) return Support::Invalid;
  v = ShapeView();
  // A margin that rounds the shape must be a length; every shape's scaling must be finite without a zero factor.
  if (!isUsableScaling(shape->getLocalScaling()) || !std::isfinite(shape->getMargin()) ||
      shape->getMargin() < Real(0))
    return isGqShapeType(shape->getShapeType()) ? Support::Invalid : Support::Bullet;
  const Support support = viewByType(shape, v);
  if (support != Support::Gq) return support;
  // Whatever the checks above missed (e.g. sizes whose products overflow) the core's validation catches.
  const bool sized = v.kind != ShapeKind::Convex || positive(v.size);
  return supportIf(sized && validateGeometry(v.geom).ok() && std::isfinite(v.margin));
}

}  // namespace gq::bullet
