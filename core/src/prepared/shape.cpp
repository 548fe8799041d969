// Shape<T>::make: the geometry's validation and the data queries derive from it, once.
#include <limits>
#include <mutex>

#include "gjk/support_table.h"
#include "gq/cooking.h"
#include "gq/custom.h"
#include "gq/shape.h"
#include "prepared/shape_ref.h"

namespace gq {

template <class T> Status Shape<T>::make(const Geometry<T>& geometry, Shape& out) noexcept {
  return detail::guarded([&]() -> Status {
    if (const detail::Problem p = detail::geometryProblem(geometry)) return p.status();
    Shape s;
    s.geometry_ = geometry;
    s.featureRadius_ = detail::featureRadius(geometry);
    if (Status b = computeGeomBounds(s.localBounds_, geometry, Transform<T>(), T(0), T(1)); !b.ok()) return b;
    const detail::Problem pair = detail::pairGeometryProblem(geometry);
    s.pairCode_ = pair.code;
    s.pairProblem_ = pair.reason;
    s.nonConvexCustom_ = detail::isNonConvexCustom(geometry);
    if (geometry.type() == GeometryType::ConvexMesh) s.derived_ = std::make_shared<detail::ShapeDerived<T>>();
    if (geometry.type() == GeometryType::TriangleMesh) {
      s.rayMesh_ = true;
      s.rayMeshUnscaled_ = geometry.template get<TriangleMeshGeometry<T>>().scale.isIdentity();
    }
    s.made_ = true;
    s.pairReady_ = !s.pairProblem_ && !s.nonConvexCustom_;
    out = std::move(s);
    return Status();
  });
}

template <class T> ShapeBalls<T> Shape<T>::hullBalls() const noexcept {
  if (!derived_) return {Vec3<T>::Zero(), T(0), std::numeric_limits<T>::infinity()};
  detail::ShapeDerived<T>& d = *derived_;
  // std::call_once publishes the build to every thread that returns from it: later calls read without a lock.
  std::call_once(d.once, [&] {
    const auto& g = geometry_.template get<ConvexMeshGeometry<T>>();
    const ConvexMesh<T>& m = *g.mesh;
    if (g.scale.isIdentity()) {
      d.balls = {m.center, m.innerRadius, m.outerRadius};
    } else {
      const Vec3<T> s = g.scale.scale.cwiseAbs();
      d.balls = {Vec3<T>(g.scale.toMatrix() * m.center), s.minCoeff() * m.innerRadius, s.maxCoeff() * m.outerRadius};
    }
    try {
      d.supportStartTable = detail::supportStartTable(g.mesh);
    } catch (...) {  // out of memory: GJK builds or skips the table itself on its next query
      d.supportStartTable = nullptr;
    }
    ++d.builds;
  });
  return d.balls;
}

template class Shape<float>;
template class Shape<double>;

}  // namespace gq
