#include "multi_sphere.h"

#include <algorithm>

#include "gq/query.h"

namespace gq::bullet {

MultiSphereShape::MultiSphereShape(std::vector<V3> centres, std::vector<Real> radii, bool withRayCore)
    : centres_(std::move(centres)), radii_(std::move(radii)) {
  smallest_ = radii_.empty() ? Real(0) : *std::min_element(radii_.begin(), radii_.end());
  if (withRayCore) {
    std::vector<Real> shrunk = radii_;
    for (Real& r : shrunk) r -= smallest_;
    rayCore_ = std::make_shared<MultiSphereShape>(centres_, std::move(shrunk), false);
  }
}

Bounds3<Real> MultiSphereShape::localBounds() const {
  Bounds3<Real> b;
  for (std::size_t i = 0; i < centres_.size(); ++i) b.include(Bounds3<Real>::fromCenterExtents(centres_[i], V3::Constant(radii_[i])));
  return b;
}

V3 MultiSphereShape::support(const V3& dir) const {
  const Real n = dir.norm();
  const V3 u = n > Real(0) ? V3(dir / n) : V3(V3::UnitX());
  std::size_t best = 0;
  Real bestValue = -std::numeric_limits<Real>::max();
  for (std::size_t i = 0; i < centres_.size(); ++i) {
    const Real value = centres_[i].dot(u) + radii_[i];
    if (value > bestValue) bestValue = value, best = i;
  }
  return centres_[best] + radii_[best] * u;
}

bool MultiSphereShape::raycast(const V3& origin, const V3& unitDir, Real maxDist, HitFlags flags,
                               RaycastHit<Real>& hit) const {
  if (!rayCore_ || !(smallest_ > Real(0))) return false;
  SweepHit<Real> h;
  bool has = false;
  const Geometry<Real> core = CustomGeometry<Real>(rayCore_);
  if (!gq::sweep(unitDir, maxDist, Geometry<Real>(SphereGeometry<Real>(smallest_)), Pose(origin), core, Pose(), h, has,
             HitFlag::Position | HitFlag::Normal)
           .ok() ||
      !has)
    return false;
  hit.distance = h.distance;
  hit.position = origin + unitDir * h.distance;
  hit.normal = h.normal;
  hit.flags = flags & (HitFlag::Position | HitFlag::Normal);
  return true;
}

}  // namespace gq::bullet
