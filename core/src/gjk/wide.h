#pragma once
// A wider arithmetic for long thin simplices and polytope faces, which arise from support points of shapes 1e8+ times
// longer than wide (a custom cylinder 1e11 long, a hull scaled to a sheet): the normal n = e1 x e2 of a face with long
// edges e is accurate to about eps |e|^2 / |n| in direction, so a plane offset n.p0 taken far from the origin (|p0|
// about the length) is off by that times |p0|, which can exceed the distance it measures. The points themselves are
// exact inputs: recomputing from them in a wider type (double for float, quadruple precision for double) divides
// that error by eps_T / eps_W. Only such faces pay for it (a test of a few flops decides, planeNeedsWider).
#include <cmath>
#include <cstdint>
#include <limits>
#include <type_traits>

#include "gq/geometry.h"

namespace gq::detail {

template <class T> struct Wider { using type = double; };
#if defined(__SIZEOF_FLOAT128__)
template <> struct Wider<double> { using type = __float128; };  // GCC and Clang on x86-64 (software arithmetic)
#else
template <> struct Wider<double> { using type = long double; };
#endif

template <class W> constexpr W wideEpsilon() {
#if defined(__SIZEOF_FLOAT128__)
  if constexpr (std::is_same_v<W, __float128>)
    return W(1) / (W(std::uint64_t(1) << 56) * W(std::uint64_t(1) << 56));  // 2^-112
  else
#endif
    return std::numeric_limits<W>::epsilon();
}

// Square root in W without libquadmath: Newton steps from the double root (53 -> 106 -> 212 correct bits), with x
// first brought into double's range by even powers of two (exact; quadruple precision reaches 1e4932).
template <class W> W wideSqrt(W x) {
  if (!(x > W(0)) || !(x - x == W(0))) return W(0);  // zero, negative, NaN or infinite
  const W up = W(std::uint64_t(1) << 63) * W(std::uint64_t(1) << 63), down = W(1) / up;  // 2^126 and 2^-126
  W factor = W(1);
  while (x > W(1e300)) x *= down * down, factor *= up;
  while (x < W(1e-300)) x *= up * up, factor *= down;
  W r = W(std::sqrt(double(x)));
  for (int k = 0; k < 2; ++k) r = (r + x / r) / W(2);
  return r * factor;
}

template <class W> using WideVec = Eigen::Matrix<W, 3, 1>;

// Whether rounding can move the offset of a plane through p0 with normal n (|n|^2 = nn, from edges of squared length
// up to edgeSq) by more than `relative` times |p0| and more than the value it measures (squared: valueSq). The
// first test needs no |p0| (it is the thinness edgeSq / |n| against relative / eps) and fails for every face that is
// not 1e3+ times (double) longer than wide, so the usual face pays two products.
template <class T, class FarSq, class ValueSq>
bool planeNeedsWider(T nn, T edgeSq, T relative, FarSq farSq, ValueSq valueSq) {
  constexpr T eps = std::numeric_limits<T>::epsilon();
  if (!(eps * eps * edgeSq * edgeSq > relative * relative * nn)) return false;
  return eps * eps * edgeSq * (edgeSq / nn) * farSq() > valueSq();
}

}  // namespace gq::detail
