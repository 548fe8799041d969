#include "gq/geometry.h"

#include <cmath>
#include <string>

#include "gq/cooking.h"
#include "gq/custom.h"
#include "gq/tolerances.h"
#include "common/validate.h"
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

using detail::Problem;

template <class T> Problem scaleProblem(const MeshScale<T>& s, bool allowNegative) {
  if (!isFinite(s.scale) || !isFinite(s.rotation)) return Problem::invalid("mesh scale is not finite");
  if (!detail::isUnitQuaternion(s.rotation)) return Problem::invalid("mesh scale rotation is not a unit quaternion");
  if ((s.scale.array() == T(0)).any()) return Problem::invalid("mesh scale has a zero factor");
  if (!allowNegative && (s.scale.array() < T(0)).any())
    return Problem::invalid("negative mesh scale is only allowed for triangle meshes");
  return {};
}

template <class T> struct Validator {
  Problem operator()(const SphereGeometry<T>& g) const {
    return positive(g.radius) ? Problem() : Problem::invalid("sphere radius must be finite and > 0");
  }
  Problem operator()(const PlaneGeometry<T>&) const { return {}; }
  Problem operator()(const CapsuleGeometry<T>& g) const {
    if (!positive(g.radius)) return Problem::invalid("capsule radius must be finite and > 0");
    if (!std::isfinite(g.halfHeight) || g.halfHeight < T(0))
      return Problem::invalid("capsule halfHeight must be finite and >= 0");
    return {};
  }
  Problem operator()(const BoxGeometry<T>& g) const {
    if (!isFinite(g.halfExtents) || (g.halfExtents.array() <= T(0)).any())
      return Problem::invalid("box halfExtents must be finite and > 0");
    return {};
  }
  Problem operator()(const ConvexMeshGeometry<T>& g) const {
    if (!g.mesh) return Problem::invalid("convex geometry has no cooked mesh");
    if (g.mesh->vertices.size() < 4 || g.mesh->polygons.empty())
      return Problem::degenerate("convex mesh is empty (cook it with cookConvexMesh)");
    return scaleProblem(g.scale, false);
  }
  Problem operator()(const TriangleMeshGeometry<T>& g) const {
    if (!g.mesh) return Problem::invalid("triangle mesh geometry has no cooked mesh");
    if (g.mesh->triangles.empty() || g.mesh->bvh.rootChild == Bvh4Node::kEmpty)
      return Problem::degenerate("triangle mesh is empty (cook it with cookTriangleMesh)");
    return scaleProblem(g.scale, true);
  }
  Problem operator()(const HeightFieldGeometry<T>& g) const {
    if (!g.heightField) return Problem::invalid("heightfield geometry has no cooked heightfield");
    if (!detail::heightFieldIsWellFormed(*g.heightField))
      return Problem::degenerate("heightfield is empty or malformed (cook it with cookHeightField)");
    if (!positive(g.heightScale) || !positive(g.rowScale) || !positive(g.columnScale))
      return Problem::invalid("heightfield scales must be finite and > 0");
    return {};
  }
  Problem operator()(const CustomGeometry<T>& g) const {
    return g.callbacks ? Problem() : Problem::invalid("custom geometry has no callbacks");
  }
};

}  // namespace

namespace detail {
template <class T> Problem geometryProblem(const Geometry<T>& geom) { return std::visit(Validator<T>{}, geom.variant()); }
template Problem geometryProblem<float>(const Geometry<float>&);
template Problem geometryProblem<double>(const Geometry<double>&);
}  // namespace detail

template <class T> Status validateGeometry(const Geometry<T>& geom) { return detail::geometryProblem(geom).status(); }

template Status validateGeometry<float>(const Geometry<float>&);
template Status validateGeometry<double>(const Geometry<double>&);

}  // namespace gq
