#include "shape_view.h"

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

bool viewCapsule(const btCapsuleShape& s, ShapeView& v) {
  v.geom = CapsuleGeometry<Real>(s.getRadius(), s.getHalfHeight());
  v.localPose = Pose(V3::Zero(), xToAxis(s.getUpAxis()));
  v.size = s.getRadius() + s.getHalfHeight();
  return true;
}

bool viewCylinder(const btCylinderShape& s, ShapeView& v) {
  const Real halfHeight = s.getHalfExtentsWithMargin()[s.getUpAxis()];
  CustomGeometry<Real> cylinder;
  if (!makeCylinder(s.getRadius(), halfHeight, cylinder)) return false;
  v.geom = cylinder;
  v.localPose = Pose(V3::Zero(), xToAxis(s.getUpAxis()));
  v.size = std::max(s.getRadius(), halfHeight);
  return true;
}

// Bullet's cone is centred on its axis midpoint with the apex at +height/2 along the up axis, as gq's (along X).
bool viewCone(const btConeShape& s, ShapeView& v) {
  CustomGeometry<Real> cone;
  if (!makeCone(s.getRadius(), s.getHeight() / 2, cone)) return false;
  v.geom = cone;
  v.localPose = Pose(V3::Zero(), xToAxis(s.getConeUpIndex()));
  v.margin = s.getMargin();
  v.size = std::max(s.getRadius(), s.getHeight() / 2);
  return true;
}

bool viewHull(const btConvexHullShape& s, ShapeView& v) {
  auto hull = cachedHull(s);
  if (!hull) return false;
  const V3 scale = toGq(s.getLocalScaling());
  v.geom = ConvexMeshGeometry<Real>(hull, MeshScale<Real>(scale));
  v.margin = s.getMargin();
  v.size = (hull->localBounds.extents().cwiseProduct(scale.cwiseAbs())).maxCoeff();
  return true;
}

// btStaticPlaneShape is the plane dot(n, x) = c; gq's plane is x = 0 with normal +X.
bool viewPlane(const btStaticPlaneShape& s, ShapeView& v) {
  const V3 n = toGq(s.getPlaneNormal()).normalized();
  v.geom = PlaneGeometry<Real>();
  v.localPose = Pose(n * s.getPlaneConstant(), Quat<Real>::FromTwoVectors(V3::UnitX(), n));
  v.kind = ShapeKind::Plane;
  v.margin = s.getMargin();
  return true;
}

bool viewMesh(const btTriangleMeshShape& s, const btVector3& extraScale, ShapeView& v) {
  CookedMesh cooked;
  if (!cachedMesh(*s.getMeshInterface(), cooked)) return false;
  const V3 scale = toGq(s.getLocalScaling()).cwiseProduct(toGq(extraScale));
  v.geom = TriangleMeshGeometry<Real>(cooked.mesh, MeshScale<Real>(scale));
  v.partStarts = cooked.partStarts;
  v.kind = ShapeKind::Mesh;
  v.margin = s.getMargin();
  v.size = (cooked.mesh->localBounds.extents().cwiseProduct(scale.cwiseAbs())).maxCoeff();
  return true;
}

bool viewHeightField(const btHeightfieldTerrainShape& s, ShapeView& v) {
  CookedHeightField cooked;
  if (!cachedHeightField(s, cooked)) return false;
  v.geom = HeightFieldGeometry<Real>(cooked.heightField, Real(1), cooked.rowScale, cooked.columnScale);
  v.localPose = cooked.localPose;
  v.kind = ShapeKind::HeightField;
  v.heightFieldColumns = cooked.heightField->columns;
  v.heightFieldRowsAreX = cooked.rowsAreX;
  v.margin = s.getMargin();
  v.size = std::max(cooked.rowScale, cooked.columnScale);
  return true;
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

bool makeShapeView(const btCollisionShape* shape, ShapeView& v) {
  if (!shape) return false;
  v = ShapeView();
  switch (shape->getShapeType()) {
    case SPHERE_SHAPE_PROXYTYPE: {
      const Real r = static_cast<const btSphereShape*>(shape)->getRadius();
      v.geom = SphereGeometry<Real>(r);
      v.size = r;
      break;
    }
    case CAPSULE_SHAPE_PROXYTYPE:
      if (!viewCapsule(*static_cast<const btCapsuleShape*>(shape), v)) return false;
      break;
    case BOX_SHAPE_PROXYTYPE: {
      const V3 he = toGq(static_cast<const btBoxShape*>(shape)->getHalfExtentsWithMargin());
      v.geom = BoxGeometry<Real>(he);
      v.size = he.maxCoeff();
      break;
    }
    case CONVEX_HULL_SHAPE_PROXYTYPE:
      if (!viewHull(*static_cast<const btConvexHullShape*>(shape), v)) return false;
      break;
    case CYLINDER_SHAPE_PROXYTYPE:
      if (!viewCylinder(*static_cast<const btCylinderShape*>(shape), v)) return false;
      break;
    case CONE_SHAPE_PROXYTYPE:
      if (!viewCone(*static_cast<const btConeShape*>(shape), v)) return false;
      break;
    case MULTI_SPHERE_SHAPE_PROXYTYPE: {
      auto spheres = cachedMultiSphere(*static_cast<const btMultiSphereShape*>(shape));
      if (!spheres) return false;
      v.size = spheres->localBounds().extents().maxCoeff();
      v.geom = CustomGeometry<Real>(std::move(spheres));
      break;
    }
    case STATIC_PLANE_PROXYTYPE:
      return viewPlane(*static_cast<const btStaticPlaneShape*>(shape), v);
    case TRIANGLE_MESH_SHAPE_PROXYTYPE:
      return viewMesh(*static_cast<const btTriangleMeshShape*>(shape), btVector3(1, 1, 1), v);
    case SCALED_TRIANGLE_MESH_SHAPE_PROXYTYPE: {
      const auto* scaled = static_cast<const btScaledBvhTriangleMeshShape*>(shape);
      return viewMesh(*scaled->getChildShape(), scaled->getLocalScaling(), v);
    }
    case TERRAIN_SHAPE_PROXYTYPE:
      return viewHeightField(*static_cast<const btHeightfieldTerrainShape*>(shape), v);
    default:
      return false;
  }
  return validateGeometry(v.geom).ok() && v.size > Real(0);
}

}  // namespace gq::bullet
