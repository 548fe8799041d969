#pragma once
// The MTD of two support-mapped shapes by GJK, then EPA when they overlap, in the kernels' convention: EPA's normal
// points from a to b, so a separates along -normal.
#include <algorithm>

#include "gjk/gjk.h"

namespace gq::detail {

// The MTD of overlapping shapes by EPA. Returns EPA's status: out of iterations (NotConverged) it still reports its
// best face, an upper bound that separates; the caller decides whether that answers.
template <class T> Status mtdByEpa(const ConvexShape<T>& a, const ConvexShape<T>& b, Vec3<T>& direction, T& depth) {
  const EpaResult<T> epa = epaPenetration(a, b);
  direction = -epa.normal;
  depth = std::max(epa.depth, T(0));
  return epa.status;
}

// EPA out of iterations answers with its best upper bound (a translation that separates) under a Warning, as
// distance does on the same pair: the caller gets a usable push-out, flagged as not certified to tolerance.
template <class T>
Status penetrationGjkEpa(const ConvexShape<T>& a, const ConvexShape<T>& b, bool& penetrating, Vec3<T>& direction,
                         T& depth) {
  penetrating = gjkOverlap(a, b);
  if (!penetrating) return Status();
  const Status epa = mtdByEpa(a, b, direction, depth);
  return epa.ok() ? Status() : epa.withCode(StatusCode::Warning);
}

}  // namespace gq::detail
