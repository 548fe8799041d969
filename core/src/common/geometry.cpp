#include "gq/geometry.h"

#include <cmath>
#include <string>

#include "gq/cooking.h"
#include "gq/custom.h"
#include "gq/tolerances.h"
#include "cook/height_field_layout.h"

namespace gq {

const char* toString(GeometryType type) {
  switch (type) {
    case GeometryType::Sphere: return "sphere";
    case GeometryType::Plane: return "plane";
    case GeometryType::Capsule: return "capsule";
    case GeometryType::Box: return "box";
    case GeometryType::ConvexMesh: return "convex";
    case GeometryType::TriangleMesh: return "mesh";
    case GeometryType::HeightField: return "heightfield";
    case GeometryType::Custom: return "custom";
  }
  return "unknown";
}

namespace {

template <class T> bool positive(T x) { return std::isfinite(x) && x > T(0); }

template <class T> Status checkScale(const MeshScale<T>& s, bool allowNegative) {
  if (!isFinite(s.scale) || !isFinite(s.rotation)) return Status::invalid("mesh scale is not finite");
  if (std::abs(double(s.rotation.norm()) - 1.0) > tol::kUnitQuaternion)
    return Status::invalid("mesh scale rotation is not a unit quaternion");
  if ((s.scale.array() == T(0)).any()) return Status::invalid("mesh scale has a zero factor");
  if (!allowNegative && (s.scale.array() < T(0)).any())
    return Status::invalid("negative mesh scale is only allowed for triangle meshes");
  return {};
}

template <class T> struct Validator {
  Status operator()(const SphereGeometry<T>& g) const {
    return positive(g.radius) ? Status() : Status::invalid("sphere radius must be finite and > 0");
  }
  Status operator()(const PlaneGeometry<T>&) const { return {}; }
  Status operator()(const CapsuleGeometry<T>& g) const {
    if (!positive(g.radius)) return Status::invalid("capsule radius must be finite and > 0");
    if (!std::isfinite(g.halfHeight) || g.halfHeight < T(0))
      return Status::invalid("capsule halfHeight must be finite and >= 0");
    return {};
  }
  Status operator()(const BoxGeometry<T>& g) const {
    if (!isFinite(g.halfExtents) || (g.halfExtents.array() <= T(0)).any())
      return Status::invalid("box halfExtents must be finite and > 0");
    return {};
  }
  Status operator()(const ConvexMeshGeometry<T>& g) const {
    if (!g.mesh) return Status::invalid("convex geometry has no cooked mesh");
    if (g.mesh->vertices.size() < 4 || g.mesh->polygons.empty())
      return Status::degenerate("convex mesh is empty (cook it with cookConvexMesh)");
    return checkScale(g.scale, false);
  }
  Status operator()(const TriangleMeshGeometry<T>& g) const {
    if (!g.mesh) return Status::invalid("triangle mesh geometry has no cooked mesh");
    if (g.mesh->triangles.empty() || g.mesh->bvh.rootChild == Bvh4Node::kEmpty)
      return Status::degenerate("triangle mesh is empty (cook it with cookTriangleMesh)");
    return checkScale(g.scale, true);
  }
  Status operator()(const HeightFieldGeometry<T>& g) const {
    if (!g.heightField) return Status::invalid("heightfield geometry has no cooked heightfield");
    if (!detail::heightFieldIsWellFormed(*g.heightField))
      return Status::degenerate("heightfield is empty or malformed (cook it with cookHeightField)");
    if (!positive(g.heightScale) || !positive(g.rowScale) || !positive(g.columnScale))
      return Status::invalid("heightfield scales must be finite and > 0");
    return {};
  }
  Status operator()(const CustomGeometry<T>& g) const {
    return g.callbacks ? Status() : Status::invalid("custom geometry has no callbacks");
  }
};

}  // namespace

template <class T> Status validateGeometry(const Geometry<T>& geom) { return std::visit(Validator<T>{}, geom.variant()); }

template Status validateGeometry<float>(const Geometry<float>&);
template Status validateGeometry<double>(const Geometry<double>&);

}  // namespace gq
