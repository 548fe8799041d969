#pragma once
// Runs every query family of gq/query.h on one set of inputs, starting each output from a sentinel, and checks the
// contract: a rejected call (any status that is not ok) leaves its output bitwise untouched; an accepted one writes
// only finite numbers.
#include <limits>
#include <string>
#include <vector>

#include "hardening_fixtures.h"

namespace gq::hardening {

template <class T> struct FamilyInputs {
  Geometry<T> geom0 = SphereGeometry<T>(T(0.5));  // swept shape, first of a pair
  Transform<T> pose0;
  Geometry<T> geom1 = SphereGeometry<T>(T(0.5));  // ray target, second of a pair, point-distance / bounds target
  Transform<T> pose1 = Transform<T>(Vec3<T>(T(0.25), T(0), T(0)));
  Vec3<T> origin = Vec3<T>(T(-5), T(0.1), T(0.05));
  Vec3<T> dir = Vec3<T>::UnitX();
  T maxDist = T(100);
  Vec3<T> point = Vec3<T>(T(3), T(0.2), T(0.1));
  T inflation = T(0);
  T boundsOffset = T(0);
  T boundsInflation = T(1.01);
  T maxDistance = std::numeric_limits<T>::infinity();  // distanceWithin's bound
};

struct FamilyOutcome {
  std::string family;
  Status status;
};

template <class T> bool finite(const Vec3<T>& v) { return isFinite(v); }

// Each family once; ADD_FAILUREs when the untouched/finite rule is broken, returns every status for the caller.
template <class T> std::vector<FamilyOutcome> runEveryFamily(const FamilyInputs<T>& in) {
  std::vector<FamilyOutcome> out;
  auto record = [&](const char* family, const Status& s, bool untouched, bool finiteOutput) {
    if (!s.ok() && !untouched) ADD_FAILURE() << family << " wrote its output although it returned " << s.toString();
    if (s.ok() && !finiteOutput) ADD_FAILURE() << family << " returned " << s.toString() << " with a non-finite output";
    out.push_back({family, s});
  };
  {
    RaycastHit<T> hits[4] = {sentinelRaycastHit<T>(), sentinelRaycastHit<T>(), sentinelRaycastHit<T>(),
                             sentinelRaycastHit<T>()};
    std::uint32_t count = 4242;
    const Status s = raycast(in.origin, in.dir, in.geom1, in.pose1, in.maxDist, kDefaultHitFlags | HitFlag::UV, 4u,
                             hits, count);
    bool untouched = count == 4242, fin = true;
    for (const auto& h : hits) untouched = untouched && sameBits(h, sentinelRaycastHit<T>());
    for (std::uint32_t i = 0; s.ok() && i < count && i < 4; ++i)
      fin = fin && finite(hits[i].position) && finite(hits[i].normal) && std::isfinite(hits[i].distance) &&
            std::isfinite(hits[i].u) && std::isfinite(hits[i].v);
    record("raycast", s, untouched, fin);
  }
  {
    SweepHit<T> hit = sentinelSweepHit<T>();
    bool hasHit = true;
    const Status s = sweep(in.dir, in.maxDist, in.geom0, in.pose0, in.geom1, in.pose1, hit, hasHit,
                           kDefaultHitFlags | HitFlag::Mtd, in.inflation);
    const bool fin = !hasHit || (finite(hit.position) && finite(hit.normal) && std::isfinite(hit.distance));
    record("sweep", s, hasHit && sameBits(hit, sentinelSweepHit<T>()), fin);
  }
  {
    bool overlapping = true;
    const Status s = overlap(in.geom0, in.pose0, in.geom1, in.pose1, overlapping);
    record("overlap", s, overlapping, true);
  }
  {
    PenetrationResult<T> r = sentinelPenetration<T>();
    const Status s = computePenetration(r, in.geom0, in.pose0, in.geom1, in.pose1);
    record("penetration", s, sameBits(r, sentinelPenetration<T>()), finite(r.direction) && std::isfinite(r.depth));
  }
  {
    DistanceResult<T> r = sentinelDistance<T>();
    const Status s = distance(r, in.geom0, in.pose0, in.geom1, in.pose1);
    record("distance", s, sameBits(r, sentinelDistance<T>()),
           std::isfinite(r.distance) && finite(r.point0) && finite(r.point1) && finite(r.normal));
  }
  {
    PointDistanceResult<T> r = sentinelPointDistance<T>();
    const Status s = pointDistance(in.point, in.geom1, in.pose1, r);
    record("pointDistance", s, sameBits(r, sentinelPointDistance<T>()),
           std::isfinite(r.distance) && finite(r.closestPoint));
  }
  {
    Bounds3<T> b = sentinelBounds<T>();
    const Status s = computeGeomBounds(b, in.geom1, in.pose1, in.boundsOffset, in.boundsInflation);
    record("bounds", s, sameBits(b, sentinelBounds<T>()), finite(b.min) && finite(b.max));
  }
  {  // last, so that the other families keep their indices
    DistanceResult<T> r = sentinelDistance<T>();
    bool beyond = true;
    const Status s = distanceWithin(r, beyond, in.maxDistance, in.geom0, in.pose0, in.geom1, in.pose1);
    record("distanceWithin", s, beyond && sameBits(r, sentinelDistance<T>()),
           !std::isnan(r.distance) && finite(r.point0) && finite(r.point1) && finite(r.normal));
  }
  return out;
}

// Every family returned `code` (families listed in `except` are not checked).
template <class T>
void expectEveryFamilyReturns(const FamilyInputs<T>& in, StatusCode code, const std::vector<std::string>& except = {}) {
  for (const FamilyOutcome& o : runEveryFamily(in)) {
    if (std::find(except.begin(), except.end(), o.family) != except.end()) continue;
    EXPECT_EQ(o.status.code, code) << o.family << ": " << o.status.toString();
    EXPECT_STRNE(o.status.message(), "") << o.family << " gave no message";
  }
}

}  // namespace gq::hardening
