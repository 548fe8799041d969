#pragma once
// The gq-fcl backend: the same ::fcl objects and queries as the native "fcl" backend, answered through the gq::fcl
// adapter (gq::fcl::collide / distance) with both corrections on (true minimum translation, exact box-box depths),
// so the rows show gq's answers plus the adapter's conversion overhead. Runs in the case's precision.
#include <memory>

#include "backend.h"

namespace gq::cases {

class GqFclBackend final : public Backend {
 public:
  GqFclBackend();
  ~GqFclBackend() override;
  const char* name() const override { return "gq-fcl"; }
  Result run(const Case& c, int repeat) override;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace gq::cases
