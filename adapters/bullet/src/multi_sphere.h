#pragma once
// btMultiSphereShape as a gq custom convex shape: the convex hull of its spheres (Bullet's margin is part of the
// radii, so the hull is exact). Support: argmax_i (c_i . u + r_i) gives c_i + r_i u for unit u. Raycast: the ray
// against the hull equals a sphere of the smallest radius swept against the hull of the spheres shrunk by it.
#include <memory>
#include <vector>

#include "bt_convert.h"
#include "gq/custom.h"

namespace gq::bullet {

class MultiSphereShape final : public CustomGeometryCallbacks<Real> {
 public:
  // Radii must be > 0 (makeMultiSphere checks).
  MultiSphereShape(std::vector<V3> centres, std::vector<Real> radii, bool withRayCore = true);
  const char* name() const override { return "bullet-multi-sphere"; }
  Bounds3<Real> localBounds() const override;
  V3 support(const V3& dir) const override;
  bool raycast(const V3& origin, const V3& unitDir, Real maxDist, HitFlags flags, RaycastHit<Real>& hit) const override;

 private:
  std::vector<V3> centres_;
  std::vector<Real> radii_;
  Real smallest_ = 0;
  std::shared_ptr<const MultiSphereShape> rayCore_;  // the spheres shrunk by smallest_
};

}  // namespace gq::bullet
