// The solid-pair table (see solid_pairs.h). Entries are generated per ordered pair of FCL shapes: a pair out of
// core's order (its GeometryType order, a <= b) swaps its inputs; a swapped distance exchanges the witnesses and
// negates the normal, as the façade's `swapped` wrapper does.
#include "solid_pairs.h"

#include <fcl/geometry/shape/box.h>
#include <fcl/geometry/shape/capsule.h>
#include <fcl/geometry/shape/cone.h>
#include <fcl/geometry/shape/cylinder.h>
#include <fcl/geometry/shape/halfspace.h>
#include <fcl/geometry/shape/sphere.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <type_traits>
#include <utility>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif


#include "box_contacts.h"
#include "fallback.h"
#include "geometry_cache.h"
#include "gq/contacts.h"
#include "gq/kernels.h"
#include "pair_kernels.h"
#include "plane_crossing.h"

namespace gq::fcl::internal {
namespace {

namespace k = gq::kernels;
using GT = GeometryType;
using FS = FclShape;

// ---- FCL primitives read in place ----

// Each reader validates what the query depends on, which covers FCL's whole Transform3 (bad input writes nothing):
// the translation is finite; a sphere's rotation is only checked finite (it does not move the sphere); other
// linear parts must be orthonormal, which also rejects a non-finite entry (any NaN or inf makes the test false).

template <class S> bool positive(S v) { return v > S(0) && v <= std::numeric_limits<S>::max(); }

// Sizes are checked before any kernel runs (a few comparisons; the kernels' clamps need ordered bounds). The
// transforms' checks, the costly part, run in the readers or, for collide, only before a hit (validatedHit).
template <class S> S sphereRadius(Solid<S> s) {
  return static_cast<const ::fcl::Sphere<S>*>(s.geometry)->radius;
}
template <class S> Vec3<S> boxHalf(Solid<S> s) {
  return static_cast<const ::fcl::Box<S>*>(s.geometry)->side * S(0.5);
}
template <class S> bool boxSized(const Vec3<S>& half) {
  return positive(half.x()) && positive(half.y()) && positive(half.z());
}
// Four sizes positive and finite at once (sphere-box distance: the radius and the half extents).
template <class S> bool allPositive(S a, S b, S c, S d) { return positive(a) && positive(b) && positive(c) && positive(d); }
#if defined(__SSE2__)
// The same for double in two SSE2 pairs (eight compares and branches took ~6 more instructions; NaN fails).
inline bool allPositive(double a, double b, double c, double d) {
  const __m128d ab = _mm_set_pd(b, a), cd = _mm_set_pd(d, c);
  const __m128d zero = _mm_setzero_pd(), largest = _mm_set1_pd(std::numeric_limits<double>::max());
  const __m128d ok = _mm_and_pd(_mm_and_pd(_mm_cmpgt_pd(ab, zero), _mm_cmple_pd(ab, largest)),
                                _mm_and_pd(_mm_cmpgt_pd(cd, zero), _mm_cmple_pd(cd, largest)));
  return _mm_movemask_pd(ok) == 3;
}
#endif

// FCL's capsule: radius and full length lz along local Z, placed with its centre at `centre`.
template <class S> k::CapsuleAxis<S> capsuleAxisAt(Solid<S> s, const Vec3<S>& centre) {
  const auto* c = static_cast<const ::fcl::Capsule<S>*>(s.geometry);
  return k::CapsuleAxis<S>{centre, s.tf->linear().col(2), c->lz * S(0.5), c->radius};
}
// The same with its centre taken relative to `origin`.
template <class S> k::CapsuleAxis<S> capsuleAxis(Solid<S> s, const Vec3<S>& origin) {
  return capsuleAxisAt(s, Vec3<S>(s.tf->translation() - origin));
}
template <class S> bool capsuleSized(Solid<S> s) {
  const auto* c = static_cast<const ::fcl::Capsule<S>*>(s.geometry);
  return positive(c->radius) && c->lz >= S(0) && c->lz <= std::numeric_limits<S>::max();
}

// A sphere's transform: finite (its rotation does not move it). A box's, capsule's or cylinder's: a finite
// translation and an orthonormal linear part. Two spheres' transforms are checked finite in one reduction (half the
// instructions of two); a sphere and another shape: the sphere's reduced alone, the other's translation and linear
// part as above (the orthonormality test fails on a non-finite entry; reducing both transforms cost sphere-box 3-14
// more instructions); two of the others: both in one pass (bothRigid, a lane each).
template <class S> bool rigidPoses(Solid<S> a, Solid<S> b) { return bothRigid<false>(*a.tf, *b.tf); }
// Out of line: it runs on hits only, and inline its registers cost every call of sphereSphereOverlap.
template <class S> [[gnu::noinline]] bool spherePoses(Solid<S> a, Solid<S> b) { return isFiniteTransforms(*a.tf, *b.tf); }
// Collide's form, out of line, on hits only (the inline form's joint sum below, called from here, took 2-4 % more time
// in collide sphere-box and sphere-cylinder, though 2 instructions fewer).
template <class S> bool sphereRigidPoses(Solid<S> sphere, Solid<S> rigid) {
  return isFiniteTransform(*sphere.tf) && finiteTranslation(*rigid.tf) && isOrthonormal(*rigid.tf);
}
// The same inline, for distance (a call there cost its caller ~25 instructions of spilled values and saved
// registers): the sphere's entries and the other's translation column in one sum, finite only if each is (a
// non-finite sum is a non-finite entry or an overflow of finite ones, which the exact tests tell apart).
// Sphere-cylinder distance runs it after the kernel, on the answer in the caller's scratch result (bad input still
// writes nothing): its loads and sums then overlap the kernel's dependency chain instead of delaying its start
// (~14 % faster and 20 fewer instructions than checking first, in alternating runs). The kernels are arithmetic without
// loops: NaN or infinite poses give some number, never a fault.
template <class S> [[gnu::always_inline]] inline bool sphereRigidPosesInline(Solid<S> sphere, Solid<S> rigid) {
  const bool finite = (sphere.tf->matrix().sum() + rigid.tf->matrix().col(3).sum()) * S(0) == S(0) ||
                      (everyEntryFinite(*sphere.tf) && finiteTranslation(*rigid.tf));
  return finite && isOrthonormal(*rigid.tf);
}

template <class S> bool readBoxes(Solid<S> a, Solid<S> b, Vec3<S>& ha, Vec3<S>& hb) {
  ha = boxHalf(a);
  hb = boxHalf(b);
  return boxSized(ha) && boxSized(hb) && rigidPoses(a, b);
}

// collide writes only on a hit, and bad input must write nothing: a miss writes nothing whatever the transforms
// hold, so collide's closed-form entries run their kernel on them as read and check them only before reporting a
// hit (most calls of a narrow phase miss), or on a miss too when the caller must tell it from bad input (`check`:
// collide returns the result's count on a miss and 0 on bad input). The kernels are arithmetic with fixed loop
// bounds: a NaN or inf transform gives some boolean, never a fault.
template <class Valid> Answer validatedHit(bool check, Valid valid) {
  return !check || valid() ? Answer::Done : Answer::Invalid;
}

// x (world) in the frame of the pose tf: R^T (x - t), the dot products of x - t with R's columns (Eigen's
// transposed product of the 4x4's block cost the sphere-cylinder pairs ~15 more instructions).
template <class S> [[gnu::always_inline]] inline Vec3<S> inFrame(const Isometry<S>& tf, const Vec3<S>& x) {
  const S* m = tf.data();  // column-major 4x4: the columns start at 0, 4, 8, the translation at 12
  const S dx = x.x() - m[12], dy = x.y() - m[13], dz = x.z() - m[14];
  return Vec3<S>(m[0] * dx + m[1] * dy + m[2] * dz, m[4] * dx + m[5] * dy + m[6] * dz,
                 m[8] * dx + m[9] * dy + m[10] * dz);
}

// ---- results back to world ----

// R v and R v + t on the 4x4's entries, inline (Eigen's products of its blocks ran out of line here, ~25 instructions
// each with the call); the same sums, column by column.
template <class S> [[gnu::always_inline]] inline Vec3<S> rotated(const Isometry<S>& tf, const Vec3<S>& v) {
  const S* m = tf.data();  // column-major 4x4: the columns start at 0, 4, 8, the translation at 12
  return Vec3<S>(m[0] * v.x() + m[4] * v.y() + m[8] * v.z(), m[1] * v.x() + m[5] * v.y() + m[9] * v.z(),
                 m[2] * v.x() + m[6] * v.y() + m[10] * v.z());
}
template <class S> [[gnu::always_inline]] inline Vec3<S> placed(const Isometry<S>& tf, const Vec3<S>& v) {
  const S* m = tf.data();
  return rotated(tf, v) + Vec3<S>(m[12], m[13], m[14]);
}

template <class S> void frameToWorld(const Isometry<S>& tf, bool withPoints, const DistanceResult<S>& local,
                                     DistanceResult<S>& out) {
  out.distance = local.distance;
  out.normal = tf.linear() * local.normal;
  if (!withPoints) return;
  out.point0 = tf * local.point0;
  out.point1 = tf * local.point1;
}

// A sphere (world centre c, radius r) against a shape whose frame is tf, the result in that frame: every sphere kernel
// writes point0 = c_local + r n, so the world point0 is c + r (R n), one transform fewer than frameToWorld.
template <class S>
[[gnu::always_inline]] inline void sphereResultToWorld(const Isometry<S>& tf, const Vec3<S>& c, S r, bool withPoints,
                                                       const DistanceResult<S>& local, DistanceResult<S>& out) {
  out.distance = local.distance;
  out.normal = rotated(tf, local.normal);
  if (!withPoints) return;
  out.point0 = c + r * out.normal;
  out.point1 = placed(tf, local.point1);
}

template <class S> void shiftPoints(const Vec3<S>& origin, bool withPoints, DistanceResult<S>& out) {
  if (!withPoints) return;
  out.point0 += origin;
  out.point1 += origin;
}

// FCL's answer for an overlapping pair without enable_signed_distance (GJK pairs, boxes).
template <class S> void writeOverlapping(DistanceResult<S>& out) {
  out.distance = S(-1);
  out.normal = out.point0 = out.point1 = Vec3<S>::Zero();
}

template <class S> void flip(DistanceResult<S>& d) {
  std::swap(d.point0, d.point1);
  d.normal = -d.normal;
}

// GJK's stop tolerance from the request: FCL's GJK stops when an iteration gains less than distance_tolerance; gq's
// stops once its certified error bound is below it. 0 (gq's own) for a non-positive, infinite or NaN one.
template <class S> S stopTolerance(DistanceAsk ask) {
  return ask.tolerance > 0 && ask.tolerance <= double(std::numeric_limits<S>::max()) ? S(ask.tolerance) : S(0);
}
// GJK's bound: the distance to beat (ask.farEnough came from S: exact), worked out only on the pairs that run GJK.
template <class S> S farEnough(DistanceAsk ask) { return distanceToBeat(S(ask.farEnough)); }

// Every number finite, by the x * 0 test on their sum (one comparison instead of ten classifications); a sum that
// overflows (finite numbers near the largest double) fails it, and then each number is tested, out of line and on a
// copy: by reference the caller's result was address-taken and kept in memory (sphere-cylinder distance 447
// instructions, 35.8 ns), and inline the test cost more time than it saved instructions (401, 35.4 ns; by value
// out of line: 415, 29.7 ns).
template <class S> [[gnu::cold, gnu::noinline]] bool everyNumberFinite(DistanceResult<S> r) {
  const auto zeroed = r.point0.array() * S(0) + r.point1.array() * S(0) + r.normal.array() * S(0);
  return r.distance * S(0) + zeroed.sum() == S(0);
}
template <class S> [[gnu::always_inline]] inline bool finiteResult(const DistanceResult<S>& r) {
  if ((r.distance + r.point0.sum() + r.point1.sum() + r.normal.sum()) * S(0) == S(0)) [[likely]] return true;
  return everyNumberFinite(r);
}

// ---- primitive pairs, in core's order ----

template <class S> Answer sphereSphereOverlap(Solid<S> a, Solid<S> b, bool checkMiss, bool& hit) {
  const S ra = sphereRadius(a), rb = sphereRadius(b);
  if (!positive(ra) || !positive(rb)) return Answer::Invalid;
  hit = k::overlapSphereSphere<S>(a.tf->translation(), ra, b.tf->translation(), rb);
  return validatedHit(hit || checkMiss, [&] { return spherePoses(a, b); });
}

template <class S> [[gnu::always_inline]] inline Answer sphereSphereDistance(Solid<S> a, Solid<S> b, DistanceAsk, DistanceResult<S>& out) {
  const S ra = sphereRadius(a), rb = sphereRadius(b);
  if (!positive(ra) || !positive(rb) || !isFiniteTransforms(*a.tf, *b.tf)) return Answer::Invalid;
  k::ballsDistance<S>(a.tf->translation(), ra, b.tf->translation(), rb, out);
  return Answer::Done;
}

template <class S> Answer sphereCapsuleOverlap(Solid<S> a, Solid<S> b, bool checkMiss, bool& hit) {
  const S ra = sphereRadius(a);
  if (!positive(ra) || !capsuleSized(b)) return Answer::Invalid;
  const k::CapsuleAxis<S> cb = capsuleAxis(b, Vec3<S>(a.tf->translation()));
  hit = k::overlapSphereCapsule<S>(Vec3<S>::Zero(), ra, cb.centre, cb.halfHeight * cb.axis, cb.radius);
  return validatedHit(hit || checkMiss, [&] { return sphereRigidPoses(a, b); });
}

template <class S> [[gnu::always_inline]] inline Answer sphereCapsuleDistance(Solid<S> a, Solid<S> b, DistanceAsk ask, DistanceResult<S>& out) {
  if (!sphereRigidPosesInline(a, b)) return Answer::Invalid;
  const S ra = sphereRadius(a);
  if (!positive(ra) || !capsuleSized(b)) return Answer::Invalid;
  const Vec3<S> origin = a.tf->translation();
  const k::CapsuleAxis<S> cb = capsuleAxis(b, origin);
  k::distanceSphereCapsule<S>(Vec3<S>::Zero(), ra, cb, out);
  shiftPoints(origin, ask.points, out);
  return Answer::Done;
}

template <class S> Answer sphereBoxOverlap(Solid<S> a, Solid<S> b, bool checkMiss, bool& hit) {
  const S ra = sphereRadius(a);
  const Vec3<S> hb = boxHalf(b);
  if (!positive(ra) || !boxSized(hb)) return Answer::Invalid;
  hit = k::overlapSphereBox<S>(inFrame(*b.tf, Vec3<S>(a.tf->translation())), ra, hb);
  return validatedHit(hit || checkMiss, [&] { return sphereRigidPoses(a, b); });
}

template <class S> [[gnu::always_inline]] inline Answer sphereBoxDistance(Solid<S> a, Solid<S> b, DistanceAsk ask, DistanceResult<S>& out) {
  // The check first here: after the kernel it took 20.3 -> 19.2 ns but 325 -> 334 instructions (3.06x -> 2.98x FCL's).
  if (!sphereRigidPosesInline(a, b)) return Answer::Invalid;
  const S ra = sphereRadius(a);
  const Vec3<S> hb = boxHalf(b);
  if (!allPositive(hb.x(), hb.y(), hb.z(), ra)) return Answer::Invalid;
  DistanceResult<S> local;
  const Vec3<S> centre = a.tf->translation();
  k::distanceSphereBox<S>(inFrame(*b.tf, centre), ra, hb, local);
  sphereResultToWorld(*b.tf, centre, ra, ask.points, local, out);
  return Answer::Done;
}

template <class S> Answer capsuleCapsuleOverlap(Solid<S> a, Solid<S> b, bool checkMiss, bool& hit) {
  if (!capsuleSized(a) || !capsuleSized(b)) return Answer::Invalid;
  const Vec3<S> origin = a.tf->translation();
  const k::CapsuleAxis<S> ca = capsuleAxis(a, origin), cb = capsuleAxis(b, origin);
  hit = k::overlapCapsuleCapsule<S>(ca.centre, ca.halfHeight * ca.axis, ca.radius, cb.centre, cb.halfHeight * cb.axis,
                                    cb.radius);
  return validatedHit(hit || checkMiss, [&] { return rigidPoses(a, b); });
}

template <class S>
[[gnu::always_inline]] inline Answer capsuleCapsuleDistance(Solid<S> a, Solid<S> b, DistanceAsk ask, DistanceResult<S>& out) {
  // The kernel on the poses as read, their check inline beside it (its arithmetic overlaps the kernel's chain;
  // out is the caller's scratch, so bad input still writes nothing); both capsules centred on a's centre.
  if (!capsuleSized(a) || !capsuleSized(b)) return Answer::Invalid;
  const Vec3<S> origin = a.tf->translation();
  const auto intersecting = [ta = a.tf, tb = b.tf]() __attribute__((always_inline)) {
    return k::intersectingAxesNormal<S>(ta->linear().col(2), tb->linear().col(2), tb->translation() - ta->translation());
  };
  k::distanceCapsuleCapsule<S>(capsuleAxisAt(a, Vec3<S>(Vec3<S>::Zero())), capsuleAxis(b, origin), intersecting, out);
  if (!bothRigidInline<false>(*a.tf, *b.tf)) return Answer::Invalid;
  shiftPoints(origin, ask.points, out);
  return Answer::Done;
}

// The capsule's segment in the box's frame: centre c and half-axis d.
template <class S> void capsuleInBox(Solid<S> capsule, Solid<S> box, k::CapsuleAxis<S>& c, Vec3<S>& d) {
  c = capsuleAxis(capsule, Vec3<S>(box.tf->translation()));
  const auto rt = box.tf->linear().transpose();
  c.centre = rt * c.centre;
  d = rt * (c.halfHeight * c.axis);
}

template <class S> Answer capsuleBoxOverlap(Solid<S> a, Solid<S> b, bool checkMiss, bool& hit) {
  const Vec3<S> h = boxHalf(b);
  if (!capsuleSized(a) || !boxSized(h)) return Answer::Invalid;
  k::CapsuleAxis<S> c;
  Vec3<S> d;
  capsuleInBox(a, b, c, d);
  hit = k::overlapCapsuleBox<S>(c.centre, d, c.radius, h);
  return validatedHit(hit || checkMiss, [&] { return rigidPoses(a, b); });
}

template <class S> [[gnu::always_inline]] inline Answer capsuleBoxDistance(Solid<S> a, Solid<S> b, DistanceAsk ask, DistanceResult<S>& out) {
  const Vec3<S> h = boxHalf(b);
  if (!capsuleSized(a) || !boxSized(h) || !rigidPoses(a, b)) return Answer::Invalid;
  k::CapsuleAxis<S> c;
  Vec3<S> d;
  capsuleInBox(a, b, c, d);
  DistanceResult<S> local;
  k::distanceCapsuleBox<S>(c.centre, d, c.radius, h, local);
  frameToWorld(*b.tf, ask.points, local, out);
  return finiteResult(local) ? Answer::Done : Answer::Unanswered;
}

// Shape b in shape a's frame: axes R_a^T R_b, centre R_a^T (t_b - t_a) (box pairs, hull pairs). Entry (i, j) of the
// axes is column i of R_a dotted with column j of R_b, written out: Eigen's product of the two 4x4 blocks ran out of
// line (~90 instructions with its call).
template <class S> [[gnu::always_inline]] inline void bInFrameOfA(Solid<S> a, Solid<S> b, Mat3<S>& r, Vec3<S>& t) {
  const S *p = a.tf->data(), *q = b.tf->data();  // column-major 4x4: the columns start at 0, 4, 8
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i)
      r(i, j) = p[4 * i] * q[4 * j] + p[4 * i + 1] * q[4 * j + 1] + p[4 * i + 2] * q[4 * j + 2];
  t = inFrame(*a.tf, Vec3<S>(b.tf->translation()));
}

template <class S> Answer boxBoxOverlap(Solid<S> a, Solid<S> b, bool checkMiss, bool& hit) {
  const Vec3<S> ha = boxHalf(a), hb = boxHalf(b);
  if (!boxSized(ha) || !boxSized(hb)) return Answer::Invalid;
  Vec3<S> t;
  Mat3<S> r;
  bInFrameOfA(a, b, r, t);
  hit = k::overlapBoxBox<S>(ha, hb, r, t);
  return validatedHit(hit || checkMiss, [&] { return rigidPoses(a, b); });
}

// In box a's frame, core's closed form (distanceBoxBoxLocal); GJK/EPA in its rare overlapping parallel-face case.
// Without a requested depth, overlapping boxes answer FCL's -1 (FCL 0.7 runs libccd's GJK on boxes): their depth is
// free from the SAT, its witnesses are a search (a third of the calls of bench_fcl_adapter's box pairs overlap).
template <class S> [[gnu::always_inline]] inline Answer boxBoxDistance(Solid<S> a, Solid<S> b, DistanceAsk ask, DistanceResult<S>& out) {
  Vec3<S> ha, hb, t;
  Mat3<S> r;
  if (!readBoxes(a, b, ha, hb)) return Answer::Invalid;
  bInFrameOfA(a, b, r, t);
  DistanceResult<S> local;
  if (!ask.depth) {
    if (!k::separatedBoxBoxLocal<S>(ha, hb, r, t, local)) {
      writeOverlapping(out);
      return Answer::Done;
    }
  } else if (!k::distanceBoxBoxLocal<S>(ha, hb, r, t, local)) {
    const Geometry<S> ga = BoxGeometry<S>(ha), gb = BoxGeometry<S>(hb);
    const Transform<S> pb(t, Quat<S>(r));
    const S tolerance = stopTolerance<S>(ask);
    if (!k::distanceGjk(ga, Transform<S>(), gb, pb, static_cast<GjkCache<S>*>(nullptr), local, tolerance).ok())
      return Answer::Unanswered;
  }
  frameToWorld(*a.tf, ask.points, local, out);
  return finiteResult(local) ? Answer::Done : Answer::Unanswered;
}

// ---- pairs with a converted side: core's kernel for the gq types, chosen at compile time ----

constexpr GT gqType(FS s) {
  switch (s) {
    case FS::Sphere: return GT::Sphere;
    case FS::Box: return GT::Box;
    case FS::Capsule: return GT::Capsule;
    case FS::Convex: return GT::ConvexMesh;
    case FS::Halfspace: return GT::Plane;
    default: return GT::Custom;  // cylinder, cone, ellipsoid, triangle: support-mapped custom shapes
  }
}

template <GT G, class S> const auto& as(const Geometry<S>& g) {
  if constexpr (G == GT::Sphere) return g.template get<SphereGeometry<S>>();
  else if constexpr (G == GT::Plane) return g.template get<PlaneGeometry<S>>();
  else if constexpr (G == GT::Capsule) return g.template get<CapsuleGeometry<S>>();
  else if constexpr (G == GT::Box) return g.template get<BoxGeometry<S>>();
  else if constexpr (G == GT::ConvexMesh) return g.template get<ConvexMeshGeometry<S>>();
  else return g.template get<CustomGeometry<S>>();
}

template <class S> Answer convertBoth(Solid<S> a, Solid<S> b, Converted<S>& ca, Converted<S>& cb) {
  const bool ok = convert(a.geometry, ca) == Conversion::Ok && convert(b.geometry, cb) == Conversion::Ok;
  return ok ? Answer::Done : Answer::Invalid;
}

template <class S> Answer posesOf(Solid<S> a, Solid<S> b, const Converted<S>& ca, const Converted<S>& cb,
                                  Transform<S>& pa, Transform<S>& pb) {
  if (!isFiniteTransforms(*a.tf, *b.tf) || !rotationUsable(ca, *a.tf) || !rotationUsable(cb, *b.tf))
    return Answer::Invalid;
  pa = shapePose(ca, *a.tf);
  pb = shapePose(cb, *b.tf);
  return Answer::Done;
}

// Overlap kernels run with a at the origin (b relative to it), as the façade does for precision far from it.
template <class S, GT A, GT B>
Answer overlapGq(const Geometry<S>& a, const Geometry<S>& b, const Transform<S>& pb, bool& hit) {
  const Transform<S> pa;
  if constexpr (A == GT::Plane && B == GT::Plane) {
    return Answer::Unanswered;
  } else if constexpr (B == GT::Custom) {  // its own overlap callback first (as the façade), else the plane form or GJK
    if (k::customOverlap(a, pa, b, pb, hit)) return Answer::Done;
    if constexpr (A == GT::Plane) hit = k::overlapPlaneCustom(as<A>(a), pa, as<B>(b), pb);
    else hit = k::overlapCustomAny(a, pa, b, pb);
  } else if constexpr (A == GT::Sphere && B == GT::Plane) {
    hit = k::overlapSpherePlane(as<A>(a), pa, as<B>(b), pb);
  } else if constexpr (A == GT::Sphere) {
    hit = k::overlapSphereConvex(as<A>(a), pa, as<B>(b), pb);
  } else if constexpr (A == GT::Plane && B == GT::Capsule) {
    hit = k::overlapPlaneCapsule(as<A>(a), pa, as<B>(b), pb);
  } else if constexpr (A == GT::Plane && B == GT::Box) {
    hit = k::overlapPlaneBox(as<A>(a), pa, as<B>(b), pb);
  } else if constexpr (A == GT::Plane) {
    hit = k::overlapPlaneConvex(as<A>(a), pa, as<B>(b), pb);
  } else if constexpr (A == GT::Capsule) {
    hit = k::overlapCapsuleConvex(as<A>(a), pa, as<B>(b), pb);
  } else if constexpr (A == GT::Box) {
    hit = k::overlapBoxConvex(as<A>(a), pa, as<B>(b), pb);
  } else {
    hit = k::overlapConvexConvex(as<A>(a), pa, as<B>(b), pb);
  }
  return Answer::Done;
}

// FCL's distance without enable_signed_distance on a GJK pair: GJK alone. Separated (or only the margins overlap):
// the exact signed distance. Overlapping cores: FCL's answer, -1 with both nearest points at the origin (its GJK
// path writes those); the depth would need EPA, which the request did not ask for.
// A GJK stop above tolerance still writes its best answer (as core's distanceGjk, which reports it as a warning).
// `start`: GJK's first direction when the caller has the centres (convexConvexDistance's balls), else GJK's own.
// A pair proven farther than the ask's farEnough gets only that lower bound (out.distance).
template <class S>
void distanceWithoutDepth(const k::ConvexShape<S>& a, const k::ConvexShape<S>& b, DistanceAsk ask,
                          DistanceResult<S>& out, const Vec3<S>* start = nullptr) {
  const k::GjkResult<S> g = k::gjkDistance(a, b, static_cast<GjkCache<S>*>(nullptr), stopTolerance<S>(ask), start,
                                           farEnough<S>(ask));
  if (g.beyond) {
    out.distance = g.distance;
    return;
  }
  if (g.coresOverlap) return writeOverlapping(out);
  k::writeSeparated(g, out);
}

template <class S, GT A, GT B>
Answer distanceGq(const Geometry<S>& a, const Transform<S>& pa, const Geometry<S>& b, const Transform<S>& pb,
                  DistanceAsk ask, DistanceResult<S>& out) {
  if constexpr (A == GT::Plane && B == GT::Plane) {
    return Answer::Unanswered;
  } else if constexpr (A == GT::Sphere && B == GT::Plane) {
    k::distanceSpherePlane(as<A>(a), pa, as<B>(b), pb, out);
  } else if constexpr (A == GT::Plane && B == GT::Capsule) {
    k::distancePlaneCapsule(as<A>(a), pa, as<B>(b), pb, out);
  } else if constexpr (A == GT::Plane && B == GT::Box) {
    k::distancePlaneBox(as<A>(a), pa, as<B>(b), pb, out);
  } else if constexpr (A == GT::Plane) {  // convex mesh or custom: through its support mapping
    k::distancePlaneConvex(as<A>(a), pa, b, pb, out);
  } else if (!ask.depth) {
    distanceWithoutDepth(k::makeConvexShape(a, pa), k::makeConvexShape(b, pb), ask, out);
  } else {
    if (!k::distanceGjk(a, pa, b, pb, static_cast<GjkCache<S>*>(nullptr), out, stopTolerance<S>(ask), farEnough<S>(ask))
             .ok())
      return Answer::Unanswered;
  }
  return finiteResult(out) ? Answer::Done : Answer::Unanswered;
}

template <class S, FS A, FS B>
Answer overlapConverted(Solid<S> a, Solid<S> b, const Converted<S>& ca, const Converted<S>& cb,
                        bool& hit) {
  Transform<S> pa, pb;
  const Answer r = posesOf(a, b, ca, cb, pa, pb);
  if (r != Answer::Done) return r;
  return overlapGq<S, gqType(A), gqType(B)>(ca.geometry(), cb.geometry(), pb.relativeTo(pa), hit);
}

template <class S, FS A, FS B> Answer convertedOverlap(Solid<S> a, Solid<S> b, bool& hit) {
  Converted<S> ca, cb;
  const Answer r = convertBoth(a, b, ca, cb);
  return r == Answer::Done ? overlapConverted<S, A, B>(a, b, ca, cb, hit) : r;
}

template <class S, FS A, FS B>
Answer distanceConverted(Solid<S> a, Solid<S> b, const Converted<S>& ca, const Converted<S>& cb,
                         DistanceAsk ask, DistanceResult<S>& out) {
  Transform<S> pa, pb;
  const Answer r = posesOf(a, b, ca, cb, pa, pb);
  if (r != Answer::Done) return r;
  return distanceGq<S, gqType(A), gqType(B)>(ca.geometry(), pa, cb.geometry(), pb, ask, out);
}

template <class S, FS A, FS B>
Answer convertedDistance(Solid<S> a, Solid<S> b, DistanceAsk ask, DistanceResult<S>& out) {
  Converted<S> ca, cb;
  const Answer r = convertBoth(a, b, ca, cb);
  return r == Answer::Done ? distanceConverted<S, A, B>(a, b, ca, cb, ask, out) : r;
}

// Two Convex: core's certificate on the cooked hulls' balls, placed by FCL's matrices (a Convex keeps FCL's frame);
// the converted path (GJK) when it decides nothing. A hull is not symmetric: its linear part must be a rotation.
// Both Convex come straight from the cache (cachedHulls), without Converted objects (their construction and the
// node-type switch cost ~50 instructions a call).

template <class S> [[gnu::always_inline]] inline k::HullBalls<S> hullBalls(Solid<S> s, const Cooked<S>& c) {
  const ConvexMesh<S>& m = *c.support->hull;
  return {s.tf->linear() * m.center + s.tf->translation(), m.innerRadius, m.outerRadius};
}

template <class S>
[[gnu::always_inline]] inline k::OverlapCertificate convexCertificate(Solid<S> a, Solid<S> b, const Cooked<S>& ca,
                                        const Cooked<S>& cb) {
  return k::hullBallsCertificate(hullBalls(a, ca), hullBalls(b, cb));
}

// A hull is not symmetric: its linear part must be a rotation, not a reflection (both hulls' in one pass).
template <class S> bool rotationPoses(Solid<S> a, Solid<S> b) { return bothRigid<true>(*a.tf, *b.tf); }

// A Convex's support mapping (prepared by the cache at cooking) placed at (r, t): a copy, since the cached one is
// shared between threads and GJK writes its climbing hints into the shapes it is given.
template <class S> k::ConvexShape<S> placedHull(const Cooked<S>& c, const Mat3<S>& r, const Vec3<S>& t) {
  k::ConvexShape<S> s = *c.support;
  s.rotation = r;
  s.position = t;
  return s;
}

// Hulls with more faces than this together skip innerPointInside: its plane tests then cost about what the GJK runs
// it saves (convex100 distance 5,201 -> 5,246 with it; two 30-vertex hulls have ~110 faces).
constexpr std::size_t kInnerPointFaces = 160;
template <class S> bool fewFaces(const Cooked<S>& a, const Cooked<S>& b) {
  return a.support->hull->polygons.size() + b.support->hull->polygons.size() <= kInnerPointFaces;
}

// Whether point p (the hull's frame) lies inside the hull of `planes` by a margin: every face plane n.x + d <= -margin,
// the dot product formed as ConvexMesh's planes are, (nx px + ny py) + nz pz, then + d. Two planes a step.
template <class S> bool insideHull(const HullPlanes<S>& planes, const Vec3<S>& p, S margin) {
  const S* q = planes.packed.data();
  for (std::uint32_t k = 0; k < planes.pairs; ++k, q += 8)
    for (int lane = 0; lane < 2; ++lane)
      if (!((q[lane] * p.x() + q[2 + lane] * p.y()) + q[4 + lane] * p.z() + q[6 + lane] <= -margin)) return false;
  return true;
}
#if defined(__SSE2__)
template <> bool insideHull<double>(const HullPlanes<double>& planes, const Vec3<double>& p, double margin) {
  const __m128d px = _mm_set1_pd(p.x()), py = _mm_set1_pd(p.y()), pz = _mm_set1_pd(p.z()), limit = _mm_set1_pd(-margin);
  const double* q = planes.packed.data();
  for (std::uint32_t k = 0; k < planes.pairs; ++k, q += 8) {
    const __m128d s = _mm_add_pd(_mm_add_pd(_mm_add_pd(_mm_mul_pd(_mm_loadu_pd(q), px), _mm_mul_pd(_mm_loadu_pd(q + 2), py)),
                                            _mm_mul_pd(_mm_loadu_pd(q + 4), pz)),
                                 _mm_loadu_pd(q + 6));
    if (_mm_movemask_pd(_mm_cmple_pd(s, limit)) != 3) return false;  // a NaN compares false: not inside
  }
  return true;
}
#endif

// A point of each hull's inner ball towards the other hull's centre, inside the other hull (b's frame is (r, t) in
// a's): a common point, beyond the inner balls' reach (hullBallsCertificate), without GJK. ~150 instructions on
// 30-vertex hulls against GJK's ~3,000 (it saves ~280 instructions of a convex30 collide call). The same line's
// vertex extents as a separating plane (an Apart certificate) were measured to cost more than the GJK runs they save
// (convex100 collide ~1,600 -> ~2,000 instructions): GJK's first support pair already separates most apart pairs.
// The midpoint between the two points, in both hulls, decides elongated hulls that reach past their inner balls along
// the line: the same instructions, ~5 % less time on convex30 collide (alternating runs; fewer GJK runs, whose steps
// wait on each other, for plane tests that do not).
template <class S>
bool innerPointInside(const Cooked<S>& hullA, const Cooked<S>& hullB, const Mat3<S>& r, const Vec3<S>& t) {
  const ConvexMesh<S>&a = *hullA.support->hull, &b = *hullB.support->hull;
  const Vec3<S> cb = r * b.center + t, d = cb - a.center;
  const S len = d.norm();
  if (!(len > S(0))) return false;
  const Vec3<S> u = d / len;
  const S margin = S(64) * std::numeric_limits<S>::epsilon() * (a.outerRadius + b.outerRadius + t.norm());
  // A point farther from a hull's centre than its outer ball is outside it: no plane to test (a false "outside" only
  // leaves the pair to GJK).
  const Vec3<S> pa = a.center + a.innerRadius * u;  // in a, a's frame, len - a.innerRadius from b's centre
  if (len - a.innerRadius <= b.outerRadius && insideHull(*hullB.planes, Vec3<S>(r.transpose() * (pa - t)), margin))
    return true;
  const Vec3<S> pb = cb - b.innerRadius * u;  // in b, a's frame, len - b.innerRadius from a's centre
  if (len - b.innerRadius <= a.outerRadius && insideHull(*hullA.planes, pb, margin)) return true;
  // Between the inner balls (elongated hulls reach past them along the line): the midpoint in both hulls.
  const S alongA = S(0.5) * (len + a.innerRadius - b.innerRadius);  // the midpoint's distance from a's centre
  const Vec3<S> m = S(0.5) * (pa + pb);
  return alongA <= a.outerRadius && len - alongA <= b.outerRadius && insideHull(*hullA.planes, m, margin) &&
         insideHull(*hullB.planes, Vec3<S>(r.transpose() * (m - t)), margin);
}

template <class S>
[[gnu::always_inline]] inline Answer convexConvexOverlap(Solid<S> a, Solid<S> b, bool checkMiss, bool& hit) {
  Cooked<S> ca, cb;
  if (!cachedHulls(a.geometry, b.geometry, ca, cb)) return Answer::Invalid;
  const k::OverlapCertificate certificate = convexCertificate(a, b, ca, cb);
  if (certificate == k::OverlapCertificate::Unknown) {  // core's GJK, then its exact kernels within the band
    if (!rotationPoses(a, b)) return Answer::Invalid;
    // b in a's frame, as the façade runs its kernels (precision far from the origin), placed by FCL's matrices
    // as they are (a quaternion round trip cost ~400 instructions a call).
    Mat3<S> r;
    Vec3<S> t;
    bInFrameOfA(a, b, r, t);
    if (fewFaces(ca, cb) && innerPointInside(ca, cb, r, t)) {
      hit = true;
      return Answer::Done;
    }
    // overlapByGjk takes its own copy of a (GJK writes its climbing hints into the shapes it is given).
    const k::OverlapCertificate gjk = k::overlapByGjk(*ca.support, placedHull(cb, r, t));
    hit = gjk == k::OverlapCertificate::Unknown
              ? k::overlapConvexShapes(*ca.geometry, Transform<S>(), *cb.geometry, Transform<S>(t, Quat<S>(r)))
              : gjk == k::OverlapCertificate::Overlapping;
    return Answer::Done;
  }
  hit = certificate == k::OverlapCertificate::Overlapping;
  return validatedHit(hit || checkMiss, [&] { return rotationPoses(a, b); });
}

// FCL's cylinder: radius and full length lz along local Z, valid as the conversion takes it (both positive).
template <class S> bool cylinderSize(Solid<S> s, S& radius, S& halfHeight) {
  const auto* c = static_cast<const ::fcl::Cylinder<S>*>(s.geometry);
  radius = c->radius;
  halfHeight = c->lz * S(0.5);
  return positive(c->radius) && positive(c->lz);
}

// The cylinder in the box's frame (FCL's cylinder axis is its local Z): centre, unit axis, radius, half height.
template <class S> struct CylinderInBox {
  Vec3<S> centre, axis;
  S radius, halfHeight;
};

// Sizes are checked (false: Invalid), the transforms by the callers.
template <class S> bool cylinderInBox(Solid<S> box, Solid<S> cylinder, Vec3<S>& h, CylinderInBox<S>& c) {
  h = boxHalf(box);
  if (!boxSized(h) || !cylinderSize(cylinder, c.radius, c.halfHeight)) return false;
  const auto rt = box.tf->linear().transpose();
  c.centre = rt * (cylinder.tf->translation() - box.tf->translation());
  c.axis = rt * cylinder.tf->linear().col(2);
  return true;
}

template <class S> k::OverlapCertificate boxCylinderCertificate(const Vec3<S>& h, const CylinderInBox<S>& c) {
  return k::cylinderBoxCertificate<S>(c.centre, c.axis, c.radius, c.halfHeight, h);
}

// Box and cylinder: core's certificates in the box's frame; GJK when they find none.
template <class S> bool boxCylinderCertificate(Solid<S> box, Solid<S> cylinder,
                                               k::OverlapCertificate& certificate) {
  Vec3<S> h;
  CylinderInBox<S> c;
  if (!cylinderInBox(box, cylinder, h, c)) return false;
  certificate = boxCylinderCertificate(h, c);
  return true;
}

template <class S> Answer boxCylinderOverlap(Solid<S> a, Solid<S> b, bool checkMiss, bool& hit) {
  k::OverlapCertificate certificate;
  if (!boxCylinderCertificate(a, b, certificate)) return Answer::Invalid;
  if (certificate == k::OverlapCertificate::Unknown) return convertedOverlap<S, FS::Box, FS::Cylinder>(a, b, hit);
  hit = certificate == k::OverlapCertificate::Overlapping;
  return validatedHit(hit || checkMiss, [&] { return rigidPoses(a, b); });
}

// Sphere and cylinder: core's closed forms in the cylinder's frame, FCL's axis Z taken as core's X: core's
// (X, Y, Z) is FCL's (Z, X, Y).
template <class S> Vec3<S> fclFromAxisX(const Vec3<S>& v) { return Vec3<S>(v.y(), v.z(), v.x()); }

// The sphere's centre in the cylinder's frame, in core's axes.
template <class S> [[gnu::always_inline]] inline Vec3<S> sphereInCylinder(Solid<S> sphere, Solid<S> cylinder) {
  const Vec3<S> c = inFrame(*cylinder.tf, Vec3<S>(sphere.tf->translation()));
  return Vec3<S>(c.z(), c.x(), c.y());
}

template <class S> Answer sphereCylinderOverlap(Solid<S> a, Solid<S> b, bool checkMiss, bool& hit) {
  const S ra = sphereRadius(a);
  S radius, halfHeight;
  if (!positive(ra) || !cylinderSize(b, radius, halfHeight)) return Answer::Invalid;
  hit = k::overlapSphereCylinder<S>(sphereInCylinder(a, b), ra, radius, halfHeight);
  return validatedHit(hit || checkMiss, [&] { return sphereRigidPoses(a, b); });
}

template <class S>
[[gnu::always_inline]] inline Answer sphereCylinderDistance(Solid<S> a, Solid<S> b, DistanceAsk ask, DistanceResult<S>& out) {
  const S ra = sphereRadius(a);
  S radius, halfHeight;
  if (!positive(ra) || !cylinderSize(b, radius, halfHeight)) return Answer::Invalid;
  DistanceResult<S> local;
  k::distanceSphereCylinder<S>(sphereInCylinder(a, b), ra, radius, halfHeight, local);
  local.normal = fclFromAxisX(local.normal);
  local.point1 = fclFromAxisX(local.point1);
  sphereResultToWorld(*b.tf, Vec3<S>(a.tf->translation()), ra, ask.points, local, out);
  if (!sphereRigidPosesInline(a, b)) return Answer::Invalid;
  return finiteResult(local) ? Answer::Done : Answer::Unanswered;
}

// Box and cylinder distance: without a requested depth, proven overlap is FCL's -1 at once; a separated pair is
// core's certified closest pair (distanceBoxCylinderLocal, within GJK's tolerance for the pair, as the overlap
// certificate's); the rest (touching, overlap with a requested depth, nothing proven) is GJK's and EPA's.
template <class S> [[gnu::always_inline]] inline Answer boxCylinderDistance(Solid<S> a, Solid<S> b, DistanceAsk ask, DistanceResult<S>& out) {
  Vec3<S> h;
  CylinderInBox<S> c;
  if (!cylinderInBox(a, b, h, c)) return Answer::Invalid;
  const auto overlapping = [&] {
    if (!rigidPoses(a, b)) return Answer::Invalid;
    writeOverlapping(out);
    return Answer::Done;
  };
  if (!ask.depth && boxCylinderCertificate(h, c) == k::OverlapCertificate::Overlapping) return overlapping();
  DistanceResult<S> local;
  switch (k::distanceBoxCylinderLocal<S>(h, c.centre, c.axis, c.radius, c.halfHeight, local)) {
    case k::BoxCylinderDistance::Separated:
      if (!rigidPoses(a, b)) return Answer::Invalid;
      frameToWorld(*a.tf, ask.points, local, out);
      return finiteResult(local) ? Answer::Done : Answer::Unanswered;
    case k::BoxCylinderDistance::Overlapping:
      if (!ask.depth) return overlapping();
      break;
    case k::BoxCylinderDistance::Unknown: break;
  }
  return convertedDistance<S, FS::Box, FS::Cylinder>(a, b, ask, out);
}

// Without a requested depth, a proven overlap (inner balls, or innerPointInside) is FCL's -1 at once; everything
// else is GJK's.
template <class S>
Answer convexConvexDistance(Solid<S> a, Solid<S> b, DistanceAsk ask, DistanceResult<S>& out) {
  if (ask.depth) return convertedDistance<S, FS::Convex, FS::Convex>(a, b, ask, out);
  Cooked<S> ca, cb;
  if (!cachedHulls(a.geometry, b.geometry, ca, cb)) return Answer::Invalid;
  const k::HullBalls<S> ba = hullBalls(a, ca), bb = hullBalls(b, cb);
  const k::OverlapCertificate balls = k::hullBallsCertificate(ba, bb);
  if (!rotationPoses(a, b)) return Answer::Invalid;
  // Overlapping by the inner balls, or by a point of one inner ball inside the other hull (b in a's frame).
  bool overlapping = balls == k::OverlapCertificate::Overlapping;
  if (balls == k::OverlapCertificate::Unknown && fewFaces(ca, cb)) {
    Mat3<S> r;
    Vec3<S> t;
    bInFrameOfA(a, b, r, t);
    overlapping = innerPointInside(ca, cb, r, t);
  }
  if (overlapping) {
    writeOverlapping(out);
    return Answer::Done;
  }
  // World frame, as the converted path: FCL's nearest points are world points. GJK starts along the balls' centre
  // difference, the hulls' centres it would place again itself.
  const Vec3<S> start = ba.center - bb.center;
  distanceWithoutDepth(placedHull(ca, Mat3<S>(a.tf->linear()), Vec3<S>(a.tf->translation())),
                       placedHull(cb, Mat3<S>(b.tf->linear()), Vec3<S>(b.tf->translation())), ask, out, &start);
  return finiteResult(out) ? Answer::Done : Answer::Unanswered;
}

// ---- the table ----

// Overlap without contact geometry. A miss writes nothing, as bad input must not: the closed-form pairs validate only
// before reporting a hit, or on a miss too when `checkMiss` (the caller tells the two apart).
template <class S, FS A, FS B>
[[gnu::always_inline]] inline Answer overlapEntry(Solid<S> a, Solid<S> b, bool checkMiss, bool& hit) {
  if constexpr (gqType(A) > gqType(B)) return overlapEntry<S, B, A>(b, a, checkMiss, hit);
  else if constexpr (A == FS::Sphere && B == FS::Sphere) return sphereSphereOverlap(a, b, checkMiss, hit);
  else if constexpr (A == FS::Sphere && B == FS::Capsule) return sphereCapsuleOverlap(a, b, checkMiss, hit);
  else if constexpr (A == FS::Sphere && B == FS::Box) return sphereBoxOverlap(a, b, checkMiss, hit);
  else if constexpr (A == FS::Capsule && B == FS::Capsule) return capsuleCapsuleOverlap(a, b, checkMiss, hit);
  else if constexpr (A == FS::Capsule && B == FS::Box) return capsuleBoxOverlap(a, b, checkMiss, hit);
  else if constexpr (A == FS::Box && B == FS::Box) return boxBoxOverlap(a, b, checkMiss, hit);
  else if constexpr (A == FS::Box && B == FS::Cylinder) return boxCylinderOverlap(a, b, checkMiss, hit);
  else if constexpr (A == FS::Sphere && B == FS::Cylinder) return sphereCylinderOverlap(a, b, checkMiss, hit);
  else if constexpr (A == FS::Convex && B == FS::Convex) return convexConvexOverlap(a, b, checkMiss, hit);
  else return convertedOverlap<S, A, B>(a, b, hit);
}

template <class S, FS A, FS B>
[[gnu::always_inline]] inline Answer distanceEntry(Solid<S> a, Solid<S> b, DistanceAsk ask, DistanceResult<S>& out) {
  if constexpr (gqType(A) > gqType(B)) {
    const Answer r = distanceEntry<S, B, A>(b, a, ask, out);
    if (r == Answer::Done) flip(out);
    return r;
  } else if constexpr (A == FS::Sphere && B == FS::Sphere) {
    return sphereSphereDistance(a, b, ask, out);
  } else if constexpr (A == FS::Sphere && B == FS::Capsule) {
    return sphereCapsuleDistance(a, b, ask, out);
  } else if constexpr (A == FS::Sphere && B == FS::Box) {
    return sphereBoxDistance(a, b, ask, out);
  } else if constexpr (A == FS::Capsule && B == FS::Capsule) {
    return capsuleCapsuleDistance(a, b, ask, out);
  } else if constexpr (A == FS::Capsule && B == FS::Box) {
    return capsuleBoxDistance(a, b, ask, out);
  } else if constexpr (A == FS::Box && B == FS::Box) {
    return boxBoxDistance(a, b, ask, out);
  } else if constexpr (A == FS::Box && B == FS::Cylinder) {
    return boxCylinderDistance(a, b, ask, out);
  } else if constexpr (A == FS::Sphere && B == FS::Cylinder) {
    return sphereCylinderDistance(a, b, ask, out);
  } else if constexpr (A == FS::Convex && B == FS::Convex) {
    return convexConvexDistance(a, b, ask, out);
  } else {
    return convertedDistance<S, A, B>(a, b, ask, out);
  }
}

// FCL's DistanceResult::update (the smaller distance wins), on the result's public fields as FCL 0.7 defines them:
// the library's out-of-line copy costs a call on the fast path.
template <class S>
void keepSmaller(S distance, const ::fcl::CollisionGeometry<S>* o1, const ::fcl::CollisionGeometry<S>* o2,
                 const DistanceResult<S>* points, ::fcl::DistanceResult<S>& result) {
  if (!(result.min_distance > distance)) return;
  result.min_distance = distance;
  result.o1 = o1;
  result.o2 = o2;
  result.b1 = result.b2 = kNoPrimitive;
  if (!points) return;
  result.nearest_points[0] = points->point0;
  result.nearest_points[1] = points->point1;
}

// A pair gq leaves unanswered goes to FCL. Out of line: inline, its frame would cost the answered path every call.
template <class S, FS A, FS B>
[[gnu::noinline]] S unansweredDistance(Solid<S> a, Solid<S> b, const ::fcl::DistanceRequest<S>& request,
                                       ::fcl::DistanceResult<S>& result) {
  // FCL 0.7 crashes on these (libccd's GJK calls a null support function for a Halfspace): nothing written.
  if constexpr (A == FS::Halfspace || B == FS::Halfspace) return std::numeric_limits<S>::max();
  else return fclDistance(a.geometry, *a.tf, b.geometry, *b.tf, request, result);
}

template <class S, FS A, FS B>
S fclDistanceEntry(const FclGeometry<S>* ga, const Isometry<S>* ta, const FclGeometry<S>* gb, const Isometry<S>* tb,
                   const ::fcl::DistanceRequest<S>& request, ::fcl::DistanceResult<S>& result) {
  const Solid<S> a{ga, ta}, b{gb, tb};
  DistanceResult<S> d;
  // Nearest points are written whatever enable_nearest_points says, as FCL 0.7's shape traversal always passes its
  // solver's points to DistanceResult::update (a host reading them must not see stale values).
  const DistanceAsk ask{true, request.enable_signed_distance, double(request.distance_tolerance),
                       double(result.min_distance)};
  switch (distanceEntry<S, A, B>(a, b, ask, d)) {
    case Answer::Done: break;
    case Answer::Invalid: return std::numeric_limits<S>::max();  // bad input: nothing written
    case Answer::Unanswered: return unansweredDistance<S, A, B>(a, b, request, result);
  }
  keepSmaller(d.distance, a.geometry, b.geometry, &d, result);
  countGq();  // after the result is written: nothing of the answer stays live across the call
  return result.min_distance;
}

// What collide did with a pair: its answer and, when Done, whether it added the contact (returned by value: through
// a reference the flag lived in memory on every call).
struct Collided {
  Answer answer;
  bool added;
};

// ---- contact positions by FCL's rules ----
// gq's depth and normal are exact; the position is a choice. By default it is midway between the two deepest points;
// the pairs below place it where FCL 0.7's closed forms do, so a host sees FCL's point with the same depth.

// FCL's tolerance for "a face or axis parallel to the half-space" (fcl::detail::halfspaceIntersectTolerance).
template <class S> constexpr S fclParallelTolerance() { return std::is_same_v<S, float> ? S(1e-4) : S(1e-7); }

template <FS A, FS B> constexpr bool fclPositionRule() {
  constexpr auto halfspaceRule = [](FS x) {
    return x == FS::Sphere || x == FS::Box || x == FS::Capsule || x == FS::Cylinder || x == FS::Cone;
  };
  return (A == FS::Sphere && B == FS::Sphere) || (A == FS::Sphere && B == FS::Capsule) ||
         (A == FS::Capsule && B == FS::Sphere) || (B == FS::Halfspace && halfspaceRule(A)) ||
         (A == FS::Halfspace && halfspaceRule(B));
}

// A shape reaching a half-space whose outward world normal is n, `depth` deep: FCL's contact position. FCL picks the
// deepest point (the centre of a deepest face, or of a capsule's or cylinder's deepest side line, when it is parallel
// to the boundary within fclParallelTolerance) and reports it moved half the depth back along n.
template <class S, FS A> Vec3<S> halfspaceContactPosition(Solid<S> shape, const Vec3<S>& n, S depth) {
  const Mat3<S> r = shape.tf->linear();
  const Vec3<S> t = shape.tf->translation();
  const S tol = fclParallelTolerance<S>();
  Vec3<S> deepest = t;
  if constexpr (A == FS::Sphere) {
    deepest = t - n * sphereRadius(shape);
  } else if constexpr (A == FS::Box) {
    const Vec3<S> side = static_cast<const ::fcl::Box<S>*>(shape.geometry)->side;
    const Vec3<S> q = r.transpose() * n;
    const auto towards = [&](int i) { return r.col(i) * (S(0.5) * side[i] * (q[i] * side[i] > S(0) ? S(-1) : S(1))); };
    int face = -1;
    for (int i = 0; i < 3 && face < 0; ++i)
      if (std::abs(q[i] - S(1)) < tol || std::abs(q[i] + S(1)) < tol) face = i;
    if (face >= 0) deepest += towards(face);
    else deepest += towards(0) + towards(1) + towards(2);
  } else if constexpr (A == FS::Capsule) {
    const auto* c = static_cast<const ::fcl::Capsule<S>*>(shape.geometry);
    const Vec3<S> z = r.col(2);
    const S cosa = z.dot(n);
    if (!(std::abs(cosa) < tol)) deepest += z * (c->lz * S(0.5) * (cosa > S(0) ? S(-1) : S(1)));
    deepest -= n * c->radius;
  } else if constexpr (A == FS::Cylinder) {
    const auto* c = static_cast<const ::fcl::Cylinder<S>*>(shape.geometry);
    const Vec3<S> z = r.col(2);
    const S cosa = z.dot(n);
    if (std::abs(cosa) < tol) {
      deepest -= n * c->radius;
    } else {
      // The deepest rim point; the disc's centre when the axis is parallel to n.
      Vec3<S> rim = z * cosa - n;
      const S len = rim.norm();
      rim = std::abs(cosa + S(1)) < tol || std::abs(cosa - S(1)) < tol || !(len > S(0)) ? Vec3<S>::Zero()
                                                                                        : Vec3<S>(rim * (c->radius / len));
      deepest += z * (c->lz * S(0.5) * (cosa > S(0) ? S(-1) : S(1))) + rim;
    }
  } else if constexpr (A == FS::Cone) {
    const auto* c = static_cast<const ::fcl::Cone<S>*>(shape.geometry);
    const Vec3<S> z = r.col(2);
    const S cosa = z.dot(n);
    if (std::abs(cosa) < tol) {
      deepest += -z * (c->lz * S(0.5)) - n * c->radius;
    } else {
      // FCL takes the base rim for every cosa < tol, also when the apex points into the half-space and is deeper
      // (its depth is then wrong too): the deeper of the two here.
      Vec3<S> rim = z * cosa - n;
      const S len = rim.norm();
      rim = std::abs(cosa + S(1)) < tol || std::abs(cosa - S(1)) < tol || !(len > S(0))
                ? Vec3<S>::Zero()
                : Vec3<S>(rim * (c->radius / len));
      const Vec3<S> apex = t + z * (c->lz * S(0.5)), base = t - z * (c->lz * S(0.5)) + rim;
      deepest = apex.dot(n) < base.dot(n) ? apex : base;  // the deeper; the base on a tie, as FCL
    }
  }
  return deepest + n * (S(0.5) * depth);
}

// A sphere against a capsule, `depth` deep, in the capsule's frame as FCL forms it: the centre's nearest point on
// the axis segment (from the +z end towards the -z end) and the offset from it to the centre. FCL's point lies on
// the line from that axis point to the centre, `depth` from the axis (the axis point itself for a centre on the
// axis); its normal is the offset's direction, which a centre on the axis to rounding leaves to the rounding.
template <class S> struct SphereOnCapsuleAxis {
  Vec3<S> axisPoint, offset;  // capsule frame
};
template <class S> SphereOnCapsuleAxis<S> sphereOnCapsuleAxis(Solid<S> sphere, Solid<S> capsule) {
  const S half = static_cast<const ::fcl::Capsule<S>*>(capsule.geometry)->lz * S(0.5);
  const Vec3<S> centre = capsule.tf->inverse(Eigen::Isometry) * sphere.tf->translation();
  const Vec3<S> top(S(0), S(0), half), down(S(0), S(0), S(-2) * half);
  const S along = (centre - top).dot(down), length2 = down.dot(down);
  SphereOnCapsuleAxis<S> r;
  r.axisPoint = along <= S(0) ? top : length2 <= along ? Vec3<S>(-top) : Vec3<S>(top + down * (along / length2));
  r.offset = centre - r.axisPoint;
  return r;
}

template <class S> Vec3<S> sphereCapsulePosition(Solid<S> sphere, Solid<S> capsule, S depth) {
  const SphereOnCapsuleAxis<S> r = sphereOnCapsuleAxis(sphere, capsule);
  const S len = r.offset.norm();
  return *capsule.tf * (len > S(0) ? Vec3<S>(r.axisPoint + r.offset * (depth / len)) : r.axisPoint);
}

// A sphere centred on a capsule's axis (to rounding: every direction perpendicular to the axis is as deep): FCL's
// normal, from o1 to o2, where it is a unit one (a zero offset leaves gq's).
template <class S> void sphereCapsuleTieNormal(Solid<S> sphere, Solid<S> capsule, bool sphereFirst, Vec3<S>& normal) {
  const SphereOnCapsuleAxis<S> r = sphereOnCapsuleAxis(sphere, capsule);
  const S len = r.offset.norm(), scale = std::max(S(1), r.axisPoint.norm());
  if (!(len > S(0)) || len > S(64) * std::numeric_limits<S>::epsilon() * scale) return;
  const Vec3<S> towardsAxis = capsule.tf->linear() * Vec3<S>(-r.offset / len);
  normal = sphereFirst ? towardsAxis : Vec3<S>(-towardsAxis);
}

template <class S> Vec3<S> halfspaceNormal(Solid<S> halfspace) {
  return halfspace.tf->linear() * static_cast<const ::fcl::Halfspace<S>*>(halfspace.geometry)->n;
}

template <class S, FS A, FS B> Vec3<S> fclContactPosition(Solid<S> a, Solid<S> b, S depth, const Vec3<S>& midway) {
  if constexpr (A == FS::Sphere && B == FS::Sphere) {
    // FCL: c1 + (c2 - c1) r1 / (r1 + r2).
    const S ra = sphereRadius(a), rb = sphereRadius(b);
    const Vec3<S> ca = a.tf->translation(), cb = b.tf->translation();
    return ca + (cb - ca) * (ra / (ra + rb));
  } else if constexpr (A == FS::Sphere && B == FS::Capsule) {
    return sphereCapsulePosition(a, b, depth);
  } else if constexpr (A == FS::Capsule && B == FS::Sphere) {
    return sphereCapsulePosition(b, a, depth);
  } else if constexpr (B == FS::Halfspace) {
    return halfspaceContactPosition<S, A>(a, halfspaceNormal(b), depth);
  } else if constexpr (A == FS::Halfspace) {
    return halfspaceContactPosition<S, B>(b, halfspaceNormal(a), depth);
  } else {
    return midway;
  }
}

// ---- a solid crossing FCL's two-sided Plane n.x = d: FCL 0.7 puts the contact on the plane ----
// A sphere or box: its half-space point (above) for the side its centre is not on, projected onto the plane; a
// cylinder: the nearer to the plane of its two extreme rim points along n, projected (the centre's projection when
// the axis is parallel to the plane). A capsule: where its axis crosses the plane; else the projection of its centre
// when both ends are within the radius of the plane, or of the end that is. A cone: the midpoint of the two points
// where the triangle (apex, the two rim points in the plane of the axis and n) crosses the plane; the axis parallel
// to the plane (within FCL's tolerance): the centre's projection moved from the base towards the apex by depth /
// radius of the length.
template <class S> Vec3<S> ontoPlane(const Vec3<S>& p, const Vec3<S>& n, S d) { return p - n * (n.dot(p) - d); }

template <class S> Vec3<S> capsulePlanePosition(Solid<S> shape, const Vec3<S>& n, S d) {
  const auto* c = static_cast<const ::fcl::Capsule<S>*>(shape.geometry);
  const Vec3<S> t = shape.tf->translation(), half = shape.tf->linear().col(2) * (c->lz * S(0.5));
  const Vec3<S> p1 = t + half, p2 = t - half;
  const S d1 = n.dot(p1) - d, d2 = n.dot(p2) - d;
  if (d1 * d2 < -fclParallelTolerance<S>()) return planeCrossing(p1, d1, p2, d2);
  const bool near1 = std::abs(d1) <= c->radius, near2 = std::abs(d2) <= c->radius;
  return ontoPlane(near1 && near2 ? t : near1 ? p1 : p2, n, d);
}

// A cylinder's two rim points FCL compares with the plane (the axis not parallel to it): c[0] on the top disc, c[1]
// on the bottom, the extreme points along n, with their heights h (FCL's arithmetic: a tie is decided as FCL does).
template <class S> struct CylinderRims {
  Vec3<S> c[2];
  S h[2];
  int nearer() const { return std::abs(h[0]) > std::abs(h[1]) ? 1 : 0; }
};
template <class S> CylinderRims<S> cylinderRims(Solid<S> shape, const Vec3<S>& n, S d) {
  const auto* g = static_cast<const ::fcl::Cylinder<S>*>(shape.geometry);
  const Vec3<S> t = shape.tf->translation(), z = shape.tf->linear().col(2);
  const S tol = fclParallelTolerance<S>(), cosa = z.dot(n);
  Vec3<S> rim = z * cosa - n;
  rim = std::abs(cosa + S(1)) < tol || std::abs(cosa - S(1)) < tol ? Vec3<S>::Zero()
                                                                   : Vec3<S>(rim * (g->radius / rim.norm()));
  const Vec3<S> half = z * (g->lz * S(0.5)), turn = cosa > S(0) ? Vec3<S>(-rim) : rim;
  CylinderRims<S> r;
  r.c[0] = t + half + turn;
  r.c[1] = t - half - turn;
  for (int i = 0; i < 2; ++i) r.h[i] = n.dot(r.c[i]) - d;
  return r;
}

template <class S> Vec3<S> cylinderPlanePosition(Solid<S> shape, const Vec3<S>& n, S d) {
  const Vec3<S> t = shape.tf->translation();
  if (std::abs(shape.tf->linear().col(2).dot(n)) < fclParallelTolerance<S>()) return ontoPlane(t, n, d);
  const CylinderRims<S> r = cylinderRims(shape, n, d);
  const int k = r.nearer();
  return r.c[k] - n * r.h[k];
}

// A cone's apex and the two rim points in the plane of its axis and n (the axis not parallel to the plane), with
// their heights (FCL's arithmetic).
template <class S> struct ConeTriangle {
  Vec3<S> p[3];
  S h[3];
};
template <class S> ConeTriangle<S> coneTriangle(Solid<S> shape, const Vec3<S>& n, S d) {
  const auto* c = static_cast<const ::fcl::Cone<S>*>(shape.geometry);
  const Vec3<S> t = shape.tf->translation(), z = shape.tf->linear().col(2);
  const S tol = fclParallelTolerance<S>(), cosa = z.dot(n);
  Vec3<S> rim = z * cosa - n;
  rim = std::abs(cosa + S(1)) < tol || std::abs(cosa - S(1)) < tol ? Vec3<S>::Zero()
                                                                   : Vec3<S>(rim * (c->radius / rim.norm()));
  const Vec3<S> base = t - z * (c->lz * S(0.5));
  ConeTriangle<S> r{{t + z * (c->lz * S(0.5)), base + rim, base - rim}, {}};
  for (int i = 0; i < 3; ++i) r.h[i] = n.dot(r.p[i]) - d;
  return r;
}

template <class S> Vec3<S> conePlanePosition(Solid<S> shape, const Vec3<S>& n, S d) {
  const auto* c = static_cast<const ::fcl::Cone<S>*>(shape.geometry);
  const Vec3<S> t = shape.tf->translation(), z = shape.tf->linear().col(2);
  const S tol = fclParallelTolerance<S>(), cosa = z.dot(n), centre = n.dot(t) - d;
  if (std::abs(cosa) < tol) {
    const S depth = c->radius - std::abs(centre);
    return t - n * centre + z * (c->lz * (depth / c->radius - S(1)) * S(0.5));
  }
  const ConeTriangle<S> tri = coneTriangle(shape, n, d);
  return straddleMidpoint(tri.p, tri.h, true);
}

template <class S, FS A> void extentAlong(Solid<S> shape, const Vec3<S>& n, S& lo, S& hi);

// The normal (from the shape to the plane: +n or -n) FCL's rule gives a shape crossing the plane: the side of the
// centre (sphere, box), of the nearer end or rim point (capsule, cylinder), of the smaller reach (cone).
template <class S, FS A> Vec3<S> planeNormalOf(Solid<S> shape, const Vec3<S>& n, S d) {
  const Vec3<S> t = shape.tf->translation(), z = shape.tf->linear().col(2);
  const S tol = fclParallelTolerance<S>(), centre = n.dot(t) - d, cosa = z.dot(n);
  const auto towards = [&](bool minus) { return minus ? Vec3<S>(-n) : n; };
  if constexpr (A == FS::Capsule) {
    const Vec3<S> half = z * (static_cast<const ::fcl::Capsule<S>*>(shape.geometry)->lz * S(0.5));
    const S d1 = n.dot(t + half) - d, d2 = n.dot(t - half) - d;  // FCL's ends' heights, as FCL rounds them
    if (d1 * d2 < -tol) return std::abs(d1) < std::abs(d2) ? towards(d1 < S(0)) : towards(d2 < S(0));
    return towards(!(d1 < S(0)));
  } else if constexpr (A == FS::Cylinder || A == FS::Cone) {
    if (std::abs(cosa) < tol) return towards(!(centre < S(0)));
    if constexpr (A == FS::Cylinder) {
      const CylinderRims<S> r = cylinderRims(shape, n, d);  // the nearer rim point's side decides
      return towards(r.h[r.nearer()] < S(0));
    } else {
      const ConeTriangle<S> c = coneTriangle(shape, n, d);  // the side reaching farther decides
      S above = 0, below = 0;
      for (S h : c.h) (h >= S(0) ? above : below) = std::max(h >= S(0) ? above : below, std::abs(h));
      return towards(above > below);
    }
  } else {
    return towards(centre > S(0));
  }
}

// The shape's extent [lo, hi] along the unit n (world).
template <class S, FS A> void extentAlong(Solid<S> shape, const Vec3<S>& n, S& lo, S& hi) {
  const Mat3<S> r = shape.tf->linear();
  const S c = n.dot(shape.tf->translation()), cosa = r.col(2).dot(n);
  const S sina = std::sqrt(std::max(S(0), S(1) - cosa * cosa));
  S reach = 0;
  if constexpr (A == FS::Sphere) {
    reach = sphereRadius(shape);
  } else if constexpr (A == FS::Box) {
    reach = (r.transpose() * n).cwiseAbs().dot(boxHalf(shape));
  } else if constexpr (A == FS::Capsule) {
    const auto* g = static_cast<const ::fcl::Capsule<S>*>(shape.geometry);
    reach = std::abs(cosa) * g->lz * S(0.5) + g->radius;
  } else if constexpr (A == FS::Cylinder) {
    const auto* g = static_cast<const ::fcl::Cylinder<S>*>(shape.geometry);
    reach = std::abs(cosa) * g->lz * S(0.5) + g->radius * sina;
  } else if constexpr (A == FS::Cone) {
    const auto* g = static_cast<const ::fcl::Cone<S>*>(shape.geometry);
    const S apex = c + cosa * g->lz * S(0.5), base = c - cosa * g->lz * S(0.5), rim = g->radius * sina;
    lo = std::min(apex, base - rim);
    hi = std::max(apex, base + rim);
    return;
  }
  lo = c - reach;
  hi = c + reach;
}

template <class S, FS A> Vec3<S> planeContactPositionOf(Solid<S> shape, const Vec3<S>& n, S d) {
  if constexpr (A == FS::Capsule) return capsulePlanePosition(shape, n, d);
  else if constexpr (A == FS::Cylinder) return cylinderPlanePosition(shape, n, d);
  else if constexpr (A == FS::Cone) return conePlanePosition(shape, n, d);
  else {
    const Vec3<S> away = n.dot(shape.tf->translation()) - d > S(0) ? n : Vec3<S>(-n);
    return ontoPlane(halfspaceContactPosition<S, A>(shape, away, S(0)), n, d);
  }
}

// Collide's contact from the signed distance (enable_contact). Out of line: inline, its frame cost the boolean
// path of the heavier pairs (box-box collide 56 -> 70 ns).
template <class S, FS A, FS B>
[[gnu::noinline]] Collided collideWithContact(const FclGeometry<S>* ga, const Isometry<S>* ta, const FclGeometry<S>* gb,
                                              const Isometry<S>* tb, ::fcl::CollisionResult<S>& result) {
  DistanceResult<S> d;
  const Answer answer = distanceEntry<S, A, B>(Solid<S>{ga, ta}, Solid<S>{gb, tb}, DistanceAsk{true, true}, d);
  const bool added = answer == Answer::Done && d.distance <= S(0);
  if (added) {
    Vec3<S> position = (d.point0 + d.point1) * S(0.5), normal = d.normal;
    if constexpr (fclPositionRule<A, B>())
      position = fclContactPosition<S, A, B>(Solid<S>{ga, ta}, Solid<S>{gb, tb}, -d.distance, position);
    if constexpr (A == FS::Sphere && B == FS::Capsule) sphereCapsuleTieNormal(Solid<S>{ga, ta}, Solid<S>{gb, tb}, true, normal);
    if constexpr (A == FS::Capsule && B == FS::Sphere) sphereCapsuleTieNormal(Solid<S>{gb, tb}, Solid<S>{ga, ta}, false, normal);
    result.addContact(::fcl::Contact<S>(ga, gb, kNoPrimitive, kNoPrimitive, position, normal, -d.distance));
  }
  return {answer, added};
}

// Two boxes' SAT is called from their collide entry: inline, its registers spilled around the entry's calls into
// FCL (box-box collide 652 -> 719 instructions); every other pair's overlap is inline (out of line, the convex
// pairs' cost 36-42 instructions more).
template <class S, FS A, FS B> [[gnu::noinline]] Answer overlapCall(Solid<S> a, Solid<S> b, bool checkMiss, bool& hit) {
  return overlapEntry<S, A, B>(a, b, checkMiss, hit);
}

// A contact FCL computes (its MPR or box-box routine) under gq's boolean, so that the boolean does not depend on the
// request's flags: a pair gq finds apart writes nothing; a pair gq finds touching or overlapping gets FCL's contact,
// or gq's exact one where FCL misses it (libccd's MPR reports no contact for shapes that touch without overlapping).
template <class S, FS A, FS B>
[[gnu::noinline]] std::size_t collideWithFclContact(Solid<S> a, Solid<S> b, const ::fcl::CollisionRequest<S>& request,
                                                    ::fcl::CollisionResult<S>& result, std::size_t before) {
  bool hit = false;
  switch (overlapCall<S, A, B>(a, b, true, hit)) {
    case Answer::Invalid: return 0;  // bad input: nothing written
    case Answer::Unanswered: return collideOthers(a.geometry, *a.tf, b.geometry, *b.tf, request, result, true);
    case Answer::Done: break;
  }
  if (!hit) {
    countGq();
    return before;
  }
  collideOthers(a.geometry, *a.tf, b.geometry, *b.tf, request, result, true);
  if (result.numContacts() == before) collideWithContact<S, A, B>(a.geometry, a.tf, b.geometry, b.tf, result);
  return result.numContacts();
}

// Two boxes under collide with contacts: FCL's box-box set (box_contacts.h: its points, placement and culling)
// around gq's exact minimum translation (computePenetration's SAT), so that the normal and the deepest depth are the
// exact ones in every mode; the deepest first when num_max_contacts leaves less room (FCL sorts them so). A pair gq
// finds apart writes nothing; a touching pair (no penetration to place the set by) gets the exact contact.
template <class S>
[[gnu::noinline]] std::size_t collideBoxBoxContacts(Solid<S> a, Solid<S> b, const ::fcl::CollisionRequest<S>& request,
                                                    ::fcl::CollisionResult<S>& result, std::size_t before) {
  bool hit = false;
  switch (overlapCall<S, FS::Box, FS::Box>(a, b, true, hit)) {
    case Answer::Invalid: return 0;  // bad input: nothing written
    case Answer::Unanswered: return collideOthers(a.geometry, *a.tf, b.geometry, *b.tf, request, result, true);
    case Answer::Done: break;
  }
  countGq();
  if (!hit) return before;
  const OrientedBox<S> boxA{a.tf->translation(), a.tf->linear(), boxHalf(a)};
  const OrientedBox<S> boxB{b.tf->translation(), b.tf->linear(), boxHalf(b)};
  const Transform<S> pa(boxA.centre, Quat<S>(boxA.axes).normalized());
  const Transform<S> pb(boxB.centre, Quat<S>(boxB.axes).normalized());
  PenetrationResult<S> mtd;
  BoxContact<S> set[4];
  Vec3<S> normal;
  int count = 0;
  if (computePenetration(mtd, Geometry<S>(BoxGeometry<S>(boxA.half)), pa, Geometry<S>(BoxGeometry<S>(boxB.half)), pb)
          .ok() &&
      mtd.penetrating && mtd.depth > S(0))
    count = fclBoxContactSet<S>(boxA, boxB, Vec3<S>(-mtd.direction), mtd.depth, normal, set);
  if (count == 0) {
    collideWithContact<S, FS::Box, FS::Box>(a.geometry, a.tf, b.geometry, b.tf, result);
    return result.numContacts();
  }
  int order[4] = {0, 1, 2, 3};
  const std::size_t room = request.num_max_contacts - std::min(request.num_max_contacts, before);
  if (room < std::size_t(count))
    std::stable_sort(order, order + count, [&](int i, int j) { return set[i].depth > set[j].depth; });
  for (int k = 0; k < count && std::size_t(k) < room; ++k)
    result.addContact(::fcl::Contact<S>(a.geometry, b.geometry, kNoPrimitive, kNoPrimitive, set[order[k]].position,
                                        normal, set[order[k]].depth));
  return result.numContacts();
}

// Two closed solids under collide: at most one contact, no buffer; contact geometry only when asked for.
template <class S, FS A, FS B>
[[gnu::always_inline]] inline Collided collideSolids(Solid<S> a, Solid<S> b, bool withContact, bool resultHeldContacts,
                                                     ::fcl::CollisionResult<S>& result) {
  if (withContact) return collideWithContact<S, A, B>(a.geometry, a.tf, b.geometry, b.tf, result);
  bool hit = false;
  Answer answer;
  if constexpr (A == FS::Box && B == FS::Box) answer = overlapCall<S, A, B>(a, b, resultHeldContacts, hit);
  else answer = overlapEntry<S, A, B>(a, b, resultHeldContacts, hit);
  const bool added = answer == Answer::Done && hit;
  if (added) result.addContact(::fcl::Contact<S>(a.geometry, b.geometry, kNoPrimitive, kNoPrimitive));
  return {answer, added};
}

// The whole of gq::fcl::collide for the pair: one call from the public entry, the kernel inline (a second call and
// its frame through a table of kernels cost sphere-sphere collide 15.8 -> 13.5 ns).
template <class S, FS A, FS B>
std::size_t fclCollideEntry(const FclGeometry<S>* ga, const Isometry<S>* ta, const FclGeometry<S>* gb,
                            const Isometry<S>* tb, const ::fcl::CollisionRequest<S>& request,
                            ::fcl::CollisionResult<S>& result, Options options) {
  const Solid<S> a{ga, ta}, b{gb, tb};
  if (request.num_max_contacts == 0) return 0;  // FCL: "should stop early", nothing computed
  const std::size_t before = result.numContacts();
  if (satisfiedBy(request, before)) return before;
  const bool fclContact = request.enable_contact && contactFromFcl(A, B, options);
  // Two boxes' contacts are FCL's set around the exact minimum translation in every mode: its normal and deepest
  // depth are the exact ones that minimumTranslation and exactContainedBoxDepth ask for.
  if constexpr (A == FS::Box && B == FS::Box)
    if (!request.enable_cost && request.enable_contact) return collideBoxBoxContacts<S>(a, b, request, result, before);
  if (!request.enable_cost && fclContact) return collideWithFclContact<S, A, B>(a, b, request, result, before);
  if (!request.enable_cost && !fclContact) {
    const Collided c = collideSolids<S, A, B>(a, b, request.enable_contact, before > 0, result);
    switch (c.answer) {
      case Answer::Done: countGq(); return before + c.added;
      case Answer::Invalid: return 0;  // bad input: nothing written
      case Answer::Unanswered: break;
    }
  }
  return collideOthers(ga, *ta, gb, *tb, request, result, fclContact);
}

template <class S, std::size_t... I> constexpr std::array<PairEntry<S>, sizeof...(I)> makeTable(std::index_sequence<I...>) {
  return {{PairEntry<S>{&fclCollideEntry<S, FS(I / kSolids), FS(I % kSolids)>,
                        &fclDistanceEntry<S, FS(I / kSolids), FS(I % kSolids)>}...}};
}

}  // namespace

namespace {
// The contact on the plane by FCL's rule; at a tie (FCL's side as deep as gq's, to rounding) FCL's normal.
template <class S, FS A>
void planeContactOf(Solid<S> solid, const Vec3<S>& n, S d, S depth, Vec3<S>& position, Vec3<S>& normal) {
  position = planeContactPositionOf<S, A>(solid, n, d);
  const Vec3<S> fcl = planeNormalOf<S, A>(solid, n, d);
  if (fcl.dot(normal) > S(0)) return;
  S lo, hi;
  extentAlong<S, A>(solid, n, lo, hi);
  const S fclDepth = fcl.dot(n) > S(0) ? hi - d : d - lo;  // pushed along -normal, clear of the plane
  const S scale = std::max({S(1), std::abs(lo), std::abs(hi), std::abs(d)});
  if (std::abs(fclDepth - depth) <= S(64) * std::numeric_limits<S>::epsilon() * scale) normal = fcl;
}
}  // namespace

template <class S>
bool fclPlaneContact(FclShape shape, Solid<S> solid, const Vec3<S>& n, S d, S depth, Vec3<S>& position,
                     Vec3<S>& normal) {
  switch (shape) {
    case FS::Sphere: planeContactOf<S, FS::Sphere>(solid, n, d, depth, position, normal); return true;
    case FS::Box: planeContactOf<S, FS::Box>(solid, n, d, depth, position, normal); return true;
    case FS::Capsule: planeContactOf<S, FS::Capsule>(solid, n, d, depth, position, normal); return true;
    case FS::Cylinder: planeContactOf<S, FS::Cylinder>(solid, n, d, depth, position, normal); return true;
    case FS::Cone: planeContactOf<S, FS::Cone>(solid, n, d, depth, position, normal); return true;
    default: return false;
  }
}
template bool fclPlaneContact<float>(FclShape, Solid<float>, const Vec3<float>&, float, float, Vec3<float>&,
                                     Vec3<float>&);
template bool fclPlaneContact<double>(FclShape, Solid<double>, const Vec3<double>&, double, double, Vec3<double>&,
                                      Vec3<double>&);

template <class S>
const std::array<PairEntry<S>, kSolids * kSolids> SolidPairs<S>::table =
    makeTable<S>(std::make_index_sequence<kSolids * kSolids>());

template struct SolidPairs<float>;
template struct SolidPairs<double>;

}  // namespace gq::fcl::internal
