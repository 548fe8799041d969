#pragma once
// "gq-bullet": gq answering through the Bullet adapter. Like "bullet", it runs in the helper programs
// gq-query-bullet (float) and gq-query-bullet64 (double) with `--backend gq-bullet`, because Bullet's two builds
// cannot share a process: gq-query forwards the whole case file to them (bullet_forward.h). This registry entry
// only names the backend in process.
#include "backend.h"

namespace gq::cases {

class GqBulletForwardingBackend final : public Backend {
 public:
  const char* name() const override { return "gq-bullet"; }
  Result run(const Case&, int) override {
    return Result::failure("unsupported: in-process; run gq-query --backend gq-bullet (it forwards to "
                           "gq-query-bullet and gq-query-bullet64)");
  }
};

}  // namespace gq::cases
