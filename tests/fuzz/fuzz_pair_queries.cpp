// libFuzzer target: overlap, computePenetration, distance and sweep on one decoded pair; bytes = precision, two
// geometries and poses, sweep direction, maxDist, flags, inflation. Contract: ok -> finite outputs (unit normals
// where promised); error -> outputs untouched; and, for two solids, the three families tell one story (below).
#include "fuzz_decode.h"

namespace {

template <class T> bool unitOrZero(const gq::Vec3<T>& n) {
  const T len = n.norm();
  return len == T(0) || std::abs(len - T(1)) < T(1e-2);
}

// Radius about the origin of the shape's local bounds; 0 where unbounded (a plane).
template <class T> long double localRadius(const gq::Geometry<T>& g) {
  gq::Bounds3<T> b;
  if (!gq::computeGeomBounds(b, g, gq::Transform<T>()).ok()) return 0;
  const long double r = b.min.cwiseAbs().cwiseMax(b.max.cwiseAbs()).template cast<long double>().norm();
  return std::isfinite(r) ? r : 0;
}

// A custom shape whose bounds span more than 1e6 (float) or 1e12 (double) times their smallest extent: GJK/EPA on
// it is open (open_findings/: a float sphere centred inside a cylinder 1.4e19 long and 7.9 wide, a double box inside
// one 6.7e153 long, are "not overlapping" by GJK, while the closed-form overlap and the box certificate say
// overlapping). GJK and EPA recompute long thin simplices and faces in a wider type (gjk/wide.h): the double box
// inside a cylinder of aspect 7e10 is answered (regression test GjkLongShapes), hence 1e12 for double; float's
// wider type is double, whose reach the float findings above exceed.
template <class T> bool longCustom(const gq::Geometry<T>& g) {
  const auto* c = g.template getIf<gq::CustomGeometry<T>>();
  if (!c) return false;
  const gq::Vec3<T> e = c->callbacks->localBounds().extents().cwiseAbs();
  return !(e.maxCoeff() <= T(sizeof(T) == 4 ? 1e6 : 1e12) * e.minCoeff());
}

bool isSolid(gq::GeometryType t) {
  return t != gq::GeometryType::TriangleMesh && t != gq::GeometryType::HeightField;
}

// Two solids (meshes and heightfields are surfaces, with other distance semantics): overlap, penetration and signed
// distance must agree up to rounding of the pair's scale (sizes plus offset), relative 1e-3 in float, 1e-6 in
// double; penetration and signed distance are the same MTD, compared within 10x that. Catches gross answers from
// one family (found by this harness: "penetrating 1e30 deep" for shapes 4e29 apart) that each family's own checks pass.
template <class T>
void requireOneStory(const gq::Geometry<T>& g0, const gq::Transform<T>& p0, const gq::Geometry<T>& g1,
                     const gq::Transform<T>& p1, bool overlapping, const gq::PenetrationResult<T>* pen,
                     const gq::DistanceResult<T>* dist) {
  if (!isSolid(g0.type()) || !isSolid(g1.type())) return;
  if (longCustom(g0) || longCustom(g1)) return;  // open findings (above)
  const long double offset = (p1.p - p0.p).template cast<long double>().norm();
  const long double scale = localRadius(g0) + localRadius(g1) + offset;
  const long double tol = (sizeof(T) == 4 ? 1e-3L : 1e-6L) * scale;
  // Float pairs of scale 1e9+ are checked too: they run in a frame rescaled by a power of two (gjk/pair_scale.h),
  // without which GJK's and EPA's squared edge cross products, ~|e|^4, overflow float (a point inside a custom cone
  // 3e10 wide came out 1.7e8 "apart").
  // Hulls scaled to an aspect over 1e6 (sheets and needles) are checked too: sphere and capsule run GJK/EPA on such
  // hulls (penetration/degenerate_hull.h), since their SAT pushed a sphere centred on a sheet out through its rim and
  // called a float sphere 4.5 beside a needle "penetrating 2.0"; the polytope pairs' SAT is right on them.
  if (pen) gq::fuzz::require(pen->penetrating == overlapping || (dist && std::abs((long double)dist->distance) <= tol));
  if (dist) gq::fuzz::require(overlapping ? dist->distance <= tol : dist->distance >= -tol);
  // Float custom shapes are checked too: float EPA on a custom cylinder 1e6 long answered -994,729 where penetration
  // answered 205 and the exact MTD is 3.4, until both ran long faces in the wider type (gjk/wide.h); both answer 3.04.
  if (pen && dist && pen->penetrating && dist->distance < 0)
    gq::fuzz::require(std::abs((long double)pen->depth + dist->distance) <= 10 * tol);
}

template <class T> void run(gq::fuzz::Bytes& in) {
  using namespace gq;
  const Geometry<T> g0 = fuzz::geometry<T>(in);
  const Transform<T> p0 = in.pose<T>();
  const Geometry<T> g1 = fuzz::geometry<T>(in);
  const Transform<T> p1 = in.pose<T>();
  bool overlapping = false;
  const Status overlapStatus = overlap(g0, p0, g1, p1, overlapping);
  fuzz::require(overlapStatus.ok() || !overlapping);
  PenetrationResult<T> pen;
  pen.depth = T(-7);
  const Status penStatus = computePenetration(pen, g0, p0, g1, p1);
  if (!penStatus.ok()) fuzz::require(pen.depth == T(-7) && !pen.penetrating);
  else fuzz::require(isFinite(pen.direction) && std::isfinite(pen.depth) && pen.depth >= T(0) &&
                     (!pen.penetrating || unitOrZero(pen.direction)));
  DistanceResult<T> dist;
  dist.distance = T(-7777);
  GjkCache<T> cache;
  const Status distStatus = distance(dist, g0, p0, g1, p1, in.flag() ? &cache : nullptr);
  if (!distStatus.ok()) fuzz::require(dist.distance == T(-7777));
  else fuzz::require(std::isfinite(dist.distance) && isFinite(dist.point0) && isFinite(dist.point1) &&
                     isFinite(dist.normal));
  if (overlapStatus.ok())
    requireOneStory(g0, p0, g1, p1, overlapping, penStatus.ok() ? &pen : nullptr, distStatus.ok() ? &dist : nullptr);
  {
    const Vec3<T> dir = in.direction<T>();
    const T maxDist = in.scalar<T>();
    const HitFlags flags = fuzz::hitFlags(in);
    const T inflation = in.flag() ? in.scalar<T>() : T(0);
    SweepHit<T> hit;
    hit.distance = T(-7777);
    bool hasHit = true;
    const Status s = sweep(dir, maxDist, g0, p0, g1, p1, hit, hasHit, flags, inflation);
    if (!s.ok()) fuzz::require(hasHit && hit.distance == T(-7777));
    else if (hasHit)
      fuzz::require(isFinite(hit.position) && isFinite(hit.normal) && std::isfinite(hit.distance));
  }
  {  // distanceWithin at any bound: bad input writes nothing; a stop is above the bound with zero witnesses
    const T bound = in.scalar<T>();
    DistanceResult<T> within;
    within.distance = T(-7777);
    bool beyond = false;
    const Status s = distanceWithin(within, beyond, bound, g0, p0, g1, p1, in.flag() ? &cache : nullptr);
    if (!s.ok()) fuzz::require(within.distance == T(-7777));
    else if (beyond)
      fuzz::require(within.distance > bound && within.point0 == Vec3<T>::Zero() && within.normal == Vec3<T>::Zero());
    else
      fuzz::require(std::isfinite(within.distance) && isFinite(within.point0) && isFinite(within.point1) &&
                    isFinite(within.normal) && !(within.distance > bound));
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  gq::fuzz::Bytes in(data, size);
  if (in.flag()) run<float>(in);
  else run<double>(in);
  return 0;
}
