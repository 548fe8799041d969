#pragma once
// The Embree 3 backend: raycast against triangle meshes only. Closest hit through rtcIntersect1, anyHit through
// rtcOccluded1; single-sided meshes cull back faces (dot(n, dir) > 0 with n = (v1-v0)x(v2-v0)) in a filter
// function, as gq does unless the mesh is double-sided or meshBothSides is set. Embree stores vertices in float,
// so double cases are answered in float too. meshMultiple is unsupported.
#include <memory>

#include "backend.h"

namespace gq::cases {

class EmbreeBackend final : public Backend {
 public:
  EmbreeBackend();
  ~EmbreeBackend() override;
  const char* name() const override { return "embree"; }
  Result run(const Case& c, int repeat) override;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace gq::cases
