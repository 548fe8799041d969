#pragma once
// sin and cos of a joint angle together, in double, without a libm call (~50 instructions instead of ~110 for
// glibc's sincos: forward kinematics evaluates one per moving revolute joint per check).
// Reduction: x = k pi/2 + r with |r| <= pi/4, pi/2 split into three doubles (Cody-Waite; the first two have 33
// significant bits, so k * part is exact for |k| < 2^20). On |r| <= pi/4 the Taylor series cut after r^17 (sin) and
// r^16 (cos) leave a truncation below 1e-18, so the result is within about one ulp of the true value.
#include <Eigen/Core>
#include <cmath>

namespace gq::urdf::internal {

// Beyond this |x| the three-part reduction loses exactness; such angles go to libm.
constexpr double kFastSinCosLimit = 0x1p19;

inline void sinCos(double x, double& s, double& c) {
  if (!(std::abs(x) <= kFastSinCosLimit)) {
    s = std::sin(x);
    c = std::cos(x);
    return;
  }
  constexpr double twoOverPi = 0x1.45f306dc9c883p-1;
  constexpr double pio2a = 0x1.921fb54400000p+0, pio2b = 0x1.0b4611a600000p-34, pio2c = 0x1.3198a2e037073p-69;
  const double y = x * twoOverPi;
  const long long quadrant = static_cast<long long>(y + (y >= 0 ? 0.5 : -0.5));  // nearest integer (|y| < 2^19)
  const double k = double(quadrant);
  const double r = ((x - k * pio2a) - k * pio2b) - k * pio2c;
  const double w = r * r;
  // sin r = r + r^3 (-1/3! + w (1/5! - w (1/7! ...))), cos r = 1 - w/2 + w^2 (1/4! - w (1/6! ...)): both tails by
  // Horner in one two-lane pass (SSE2: one multiply and one add per step for both). The cos lane starts from a
  // zero leading coefficient, so each lane performs exactly the scalar Horner's operations (same rounding).
  using Lanes = Eigen::Array2d;  // (sin tail, cos tail)
  const Lanes ww = Lanes::Constant(w);
  Lanes tail(1.0 / 355687428096000.0, 0.0);
  tail = tail * ww + Lanes(-1.0 / 1307674368000.0, 1.0 / 20922789888000.0);
  tail = tail * ww + Lanes(1.0 / 6227020800.0, -1.0 / 87178291200.0);
  tail = tail * ww + Lanes(-1.0 / 39916800, 1.0 / 479001600);
  tail = tail * ww + Lanes(1.0 / 362880, -1.0 / 3628800);
  tail = tail * ww + Lanes(-1.0 / 5040, 1.0 / 40320);
  tail = tail * ww + Lanes(1.0 / 120, -1.0 / 720);
  tail = tail * ww + Lanes(-1.0 / 6, 1.0 / 24);
  const double sr = r + r * w * tail[0];
  const double cr = 1.0 - 0.5 * w + w * w * tail[1];
  switch (quadrant & 3) {  // quadrant: rotate (sin, cos) by k quarter turns
    case 0: s = sr; c = cr; break;
    case 1: s = cr; c = -sr; break;
    case 2: s = -sr; c = -cr; break;
    default: s = -cr; c = sr; break;
  }
}

}  // namespace gq::urdf::internal
