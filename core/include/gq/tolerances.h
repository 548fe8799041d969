#pragma once
// Every tolerance of the library, named once. Relative tolerances are multiplied by a length scale of the
// shapes involved (see scaleOf in the kernels); absolute values appear only where the quantity is unitless.
#include <cstdint>

namespace gq::tol {

// A direction passes as unit when | |d| - 1 | <= kUnitDirection (unitless).
inline constexpr double kUnitDirection = 1e-4;
// A pose quaternion passes when | |q| - 1 | <= kUnitQuaternion (unitless), as PxTransform::isValid().
inline constexpr double kUnitQuaternion = 1e-3;
// Largest accepted sweep distance (the spec's PX_MAX_SWEEP_DISTANCE).
inline constexpr double kMaxSweepDistance = 1e8;
// Default computeGeomBounds inflation (the spec's default).
inline constexpr double kDefaultBoundsInflation = 1.01;
// A triangle whose doubled area is below kDegenerateTriangleArea * (longest edge)^2 is degenerate (unitless).
inline constexpr double kDegenerateTriangleArea = 1e-12;
// Heightfields larger than this many samples are rejected as absurd.
inline constexpr std::uint64_t kMaxHeightFieldSamples = std::uint64_t(1) << 28;

// generateTriangleContacts: contact points closer than kContactMergeFactor * toleranceLength are one point, and
// points within it of the triangle's boundary count as inside (unitless factor).
inline constexpr double kContactMergeFactor = 1e-3;

// Relative tolerances scaled by shape size, per scalar type.
template <class T> struct Rel;
template <> struct Rel<float> {
  static constexpr float kEpsilon = 1e-5f;       // geometric coincidence
  static constexpr float kGjkTolerance = 1e-6f;  // GJK/EPA convergence
};
template <> struct Rel<double> {
  static constexpr double kEpsilon = 1e-12;
  static constexpr double kGjkTolerance = 1e-12;
};

}  // namespace gq::tol
