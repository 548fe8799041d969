#include "gq/geometry.h"

#include <cmath>
#include <string>

#include "bvh/bvh.h"
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

// A length the kernels can raise to the fourth power (detail::kMaxMagnitude); NaN, Inf and x <= 0 fail.
template <class T> bool supportedSize(T x) { return x > T(0) && x <= detail::kMaxMagnitude<T>; }

using detail::Problem;

// A size must be finite and > 0 (`invalid`), and for a pair query within the supported magnitude (`tooLarge`).
template <class T> Problem sizeProblem(T x, bool pair, const char* invalid, const char* tooLarge) {
  if (pair ? supportedSize(x) : positive(x)) return {};
  return Problem::invalid(positive(x) ? tooLarge : invalid);
}

template <class T> T largestAbsCoordinate(const Bounds3<T>& b) {
  return std::max(b.min.cwiseAbs().maxCoeff(), b.max.cwiseAbs().maxCoeff());
}

// A cooked shape's farthest local coordinate under its scale (the largest |factor| bounds the scale's stretch).
template <class T> bool scaledExtentIsSupported(const Bounds3<T>& b, const MeshScale<T>& s) {
  return largestAbsCoordinate(b) * s.scale.cwiseAbs().maxCoeff() <= detail::kMaxMagnitude<T>;
}

template <class T> bool heightFieldExtentIsSupported(const HeightFieldGeometry<T>& g) {
  const HeightField<T>& h = *g.heightField;
  const T height = std::max(std::abs(h.minHeight), std::abs(h.maxHeight)) * g.heightScale;
  return T(h.rows) * g.rowScale <= detail::kMaxMagnitude<T> &&
         T(h.columns) * g.columnScale <= detail::kMaxMagnitude<T> && height <= detail::kMaxMagnitude<T>;
}

template <class T> Problem scaleProblem(const MeshScale<T>& s, bool allowNegative) {
  if (!isFinite(s.scale) || !isFinite(s.rotation)) return Problem::invalid("mesh scale is not finite");
  if (!detail::isUnitQuaternion(s.rotation)) return Problem::invalid("mesh scale rotation is not a unit quaternion");
  if ((s.scale.array() == T(0)).any()) return Problem::invalid("mesh scale has a zero factor");
  if (!allowNegative && (s.scale.array() < T(0)).any())
    return Problem::invalid("negative mesh scale is only allowed for triangle meshes");
  return {};
}

// The rules of one geometry. `pair`: also the size bound of pair queries (detail::kMaxMagnitude; single-geometry
// queries take any finite size: their kernels are guarded against overflow and fuzzed with sizes to the limit of T).
template <class T> struct Validator {
  bool pair = false;

  Problem operator()(const SphereGeometry<T>& g) const {
    return sizeProblem(g.radius, pair, "sphere radius must be finite and > 0",
                       "sphere radius exceeds the supported magnitude (1e9 in float, 1e75 in double)");
  }
  Problem operator()(const PlaneGeometry<T>&) const { return {}; }
  Problem operator()(const CapsuleGeometry<T>& g) const {
    if (const Problem p = sizeProblem(g.radius, pair, "capsule radius must be finite and > 0",
                                      "capsule radius exceeds the supported magnitude (1e9 in float, 1e75 in double)"))
      return p;
    if (!std::isfinite(g.halfHeight) || g.halfHeight < T(0))
      return Problem::invalid("capsule halfHeight must be finite and >= 0");
    if (pair && g.halfHeight > detail::kMaxMagnitude<T>)
      return Problem::invalid("capsule halfHeight exceeds the supported magnitude (1e9 in float, 1e75 in double)");
    return {};
  }
  Problem operator()(const BoxGeometry<T>& g) const {
    if (!isFinite(g.halfExtents) || (g.halfExtents.array() <= T(0)).any())
      return Problem::invalid("box halfExtents must be finite and > 0");
    if (pair && (g.halfExtents.array() > detail::kMaxMagnitude<T>).any())
      return Problem::invalid("box halfExtents exceed the supported magnitude (1e9 in float, 1e75 in double)");
    return {};
  }
  Problem operator()(const ConvexMeshGeometry<T>& g) const {
    if (!g.mesh) return Problem::invalid("convex geometry has no cooked mesh");
    if (g.mesh->vertices.size() < 4 || g.mesh->polygons.empty())
      return Problem::degenerate("convex mesh is empty (cook it with cookConvexMesh)");
    if (const Problem p = scaleProblem(g.scale, false)) return p;
    if (pair && !scaledExtentIsSupported(g.mesh->localBounds, g.scale))
      return Problem::invalid("scaled convex mesh exceeds the supported magnitude (1e9 in float, 1e75 in double)");
    return {};
  }
  Problem operator()(const TriangleMeshGeometry<T>& g) const {
    if (!g.mesh) return Problem::invalid("triangle mesh geometry has no cooked mesh");
    if (g.mesh->triangles.empty() || !g.mesh->accel || g.mesh->accel->bvh.rootChild == MeshBvhNode::kEmpty)
      return Problem::degenerate("triangle mesh is empty (cook it with cookTriangleMesh)");
    if (const Problem p = scaleProblem(g.scale, true)) return p;
    if (pair && !scaledExtentIsSupported(g.mesh->localBounds, g.scale))
      return Problem::invalid("scaled triangle mesh exceeds the supported magnitude (1e9 in float, 1e75 in double)");
    return {};
  }
  Problem operator()(const HeightFieldGeometry<T>& g) const {
    if (!g.heightField) return Problem::invalid("heightfield geometry has no cooked heightfield");
    if (!detail::heightFieldIsWellFormed(*g.heightField))
      return Problem::degenerate("heightfield is empty or malformed (cook it with cookHeightField)");
    if (!positive(g.heightScale) || !positive(g.rowScale) || !positive(g.columnScale))
      return Problem::invalid("heightfield scales must be finite and > 0");
    if (pair && !heightFieldExtentIsSupported(g))
      return Problem::invalid("scaled heightfield exceeds the supported magnitude (1e9 in float, 1e75 in double)");
    return {};
  }
  Problem operator()(const CustomGeometry<T>& g) const {
    return g.callbacks ? Problem() : Problem::invalid("custom geometry has no callbacks");
  }
};

}  // namespace

namespace detail {
template <class T> Problem geometryProblem(const Geometry<T>& geom) {
  return std::visit(Validator<T>{false}, geom.variant());
}
template <class T> Problem pairGeometryProblem(const Geometry<T>& geom) {
  return std::visit(Validator<T>{true}, geom.variant());
}
template Problem geometryProblem<float>(const Geometry<float>&);
template Problem geometryProblem<double>(const Geometry<double>&);
template Problem pairGeometryProblem<float>(const Geometry<float>&);
template Problem pairGeometryProblem<double>(const Geometry<double>&);
}  // namespace detail

template <class T> Status validateGeometry(const Geometry<T>& geom) noexcept { return detail::geometryProblem(geom).status(); }

template Status validateGeometry<float>(const Geometry<float>&);
template Status validateGeometry<double>(const Geometry<double>&);

}  // namespace gq
