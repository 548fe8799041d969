#pragma once
// The libccd backend, called directly: ccdGJKIntersect for overlap; ccdGJKPenetration (backend "libccd") or
// ccdMPRPenetration ("libccd-mpr") for penetration, through support functions written here for sphere, capsule,
// box, convex (scaled hull points), cylinder and cone. libccd is built with CCD_DOUBLE, so float cases run in
// double too. No distance, raycast or sweep: those give "unsupported".
#include "backend.h"

namespace gq::cases {

enum class CcdPenetration { Gjk, Mpr };

class LibccdBackend final : public Backend {
 public:
  explicit LibccdBackend(CcdPenetration method) : method_(method) {}
  const char* name() const override { return method_ == CcdPenetration::Mpr ? "libccd-mpr" : "libccd"; }
  Result run(const Case& c, int repeat) override;

 private:
  CcdPenetration method_;
};

}  // namespace gq::cases
