#pragma once
// The FCL 0.7 backend: overlap through fcl::collide (no contacts: the boolean), penetration through fcl::collide
// with contacts (deepest contact), distance through fcl::distance with signed distance and nearest points. The GJK
// solver is GST_LIBCCD (backend "fcl") or GST_INDEP ("fcl-indep"). Shapes: sphere, capsule, box, plane (Halfspace),
// convex (fcl::Convex from gq's hull polygons), mesh (BVHModel<OBBRSS>), cylinder, cone. Runs in the case's precision.
#include <memory>

#include "backend.h"

namespace gq::cases {

enum class FclSolver { Libccd, Indep };

class FclBackend final : public Backend {
 public:
  explicit FclBackend(FclSolver solver);
  ~FclBackend() override;
  const char* name() const override;
  Result run(const Case& c, int repeat) override;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace gq::cases
