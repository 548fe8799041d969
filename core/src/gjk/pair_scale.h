#pragma once
// GJK and EPA square cross products of simplex edges: |e1 x e2|^2 grows as |e|^4, which overflows float past
// |e| ~ 1.4e9 (and double past 1e77) and underflows below 1e-9.5 (1e-77). A pair whose length scale leaves
// [kPairScaleLow, kPairScaleHigh] runs in a frame scaled by an even power of two that brings that scale near 1:
// multiplying by a power of two is exact, and every test in gjk.cpp, simplex.cpp and epa.cpp compares quantities of
// the same dimension, so the scaled run rounds as the unscaled one would have without overflow (an even power keeps
// square roots exact too). The answers are scaled back the same way.
#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>

#include "gjk/gjk.h"

namespace gq::detail {

// The length scales run as given: within them |e|^4 stays between 2^-80 and 2^80 in float (normal range 2^-126 to
// 2^128) and between 2^-400 and 2^400 in double, with room for the products the tests form from it.
template <class T> constexpr T kPairScaleHigh = std::is_same_v<T, float> ? T(1 << 20) : T(1e30);
template <class T> constexpr T kPairScaleLow = T(1) / kPairScaleHigh<T>;

// Whether a pair of this length scale (gjkPairLength) runs rescaled: outside the range, finite and not zero.
template <class T> bool needsRescale(T length) {
  if (length > kPairScaleHigh<T>) return length <= std::numeric_limits<T>::max();
  return length < kPairScaleLow<T> && length > T(0);
}
// The factor that brings it near 1: 2^-2k with 2^2k within a factor 4 of the length.
template <class T> T rescaleFactor(T length) { return std::ldexp(T(1), -2 * (std::ilogb(length) / 2)); }

// The shape with every length multiplied by `factor`: its place, its core (through localScale) and its margin.
template <class T> ConvexShape<T> scaledShape(const ConvexShape<T>& s, T factor) {
  ConvexShape<T> out = s;
  out.position *= factor;
  out.localScale *= factor;
  out.margin *= factor;
  out.size *= factor;
  return out;
}

// The rescaled copies' hill-climbing hints back to the caller's shapes.
template <class T> void keepHints(const ConvexShape<T>& from, const ConvexShape<T>& to) {
  to.climbStart = from.climbStart;
}

// Support points (and their parts) multiplied by `factor`; search directions keep theirs.
template <class T> void scaleSimplex(GjkSimplex<T>& s, T factor) {
  for (std::uint32_t k = 0; k < s.size; ++k) {
    s.points[k].w *= factor;
    s.points[k].a *= factor;
    s.points[k].b *= factor;
  }
}

}  // namespace gq::detail
