#pragma once
// FCL's DistanceResult as a gq-query answer, for both FCL backends (native ::fcl and gq::fcl).
#include <fcl/narrowphase/distance_result.h>

#include "native_shapes.h"
#include "result.h"

namespace gq::cases {

// Nearest points are world-frame in FCL 0.7; the normal runs from geom0 to geom1: along p1 - p0 when separated,
// against it when penetrating.
template <class S> DistanceOut distanceOutOf(const ::fcl::DistanceResult<S>& result) {
  DistanceOut out;
  out.distance = double(result.min_distance);
  out.point0 = result.nearest_points[0].template cast<double>();
  out.point1 = result.nearest_points[1].template cast<double>();
  const double sign = out.distance < 0 ? -1.0 : 1.0;
  out.normal = sign * native::unitOrZero(out.point1 - out.point0);
  return out;
}

}  // namespace gq::cases
