#pragma once
// `gq-query --backend bullet` (and `gq-bullet`, gq through the Bullet adapter): Bullet's float and float64
// libraries cannot share a program, so gq-query runs the case file through gq-query-bullet (float cases) and
// gq-query-bullet64 (double cases), found beside gq-query, and prints for each line the answer of the build whose
// precision matches the case.
#include <iosfwd>
#include <string>

#include "backend.h"

namespace gq::cases {

// Runs both helpers from `toolDir` with `--backend backend` ("bullet" or "gq-bullet") over `casesPath` and writes
// the merged result lines. False with `error` when a helper cannot be run or their outputs disagree in length.
bool runBulletForwarded(const std::string& toolDir, const std::string& backend, const std::string& casesPath,
                        int repeat, std::ostream& out, std::string& error);

// The in-process "bullet" registry entry: it cannot hold both Bullet builds, so every case says where to go.
class BulletForwardingBackend final : public Backend {
 public:
  const char* name() const override { return "bullet"; }
  Result run(const Case&, int) override {
    return Result::failure("unsupported: in-process; run gq-query --backend bullet (it forwards to gq-query-bullet "
                           "and gq-query-bullet64)");
  }
};

}  // namespace gq::cases
