#pragma once
// Internal name of the public kernels in gq/kernels/vector.h (declared there, defined in core/src).
#include <limits>

#include "gq/kernels/vector.h"

namespace gq::detail {
using namespace kernels;

// tryUnit for a caller that has |d|^2 (len2) and |d| = sqrt(len2) (len) already: the same answer without a second
// norm in the common case.
template <class T> inline bool tryUnitWithNorm(const Vec3<T>& d, T len2, T len, Vec3<T>& unit) {
  if (len2 >= std::numeric_limits<T>::min() && len2 <= std::numeric_limits<T>::max()) [[likely]] {
    unit = d / len;
    return true;
  }
  return tryUnit(d, unit);
}
}  // namespace gq::detail
