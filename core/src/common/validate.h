#pragma once
// Input checks shared by the query façades. Each returns Ok or an InvalidArgument status naming the field.
// Nothing allocates: rules answer a Problem (a code and a static reason, none when valid) and messages are literals
// (FieldText), with a number such as a vector's length as the Status detail. A primitive query spends ~20
// instructions here.
#include <cmath>
#include <exception>
#include <new>
#include <string>
#include <type_traits>

#include "gq/custom.h"
#include "gq/geometry.h"
#include "gq/mesh_query.h"
#include "gq/status.h"
#include "gq/tolerances.h"
#include "gq/transform.h"

#ifdef GQ_SSE42
#include <immintrin.h>
#endif

namespace gq::detail {

// Why an input is rejected; `reason == nullptr` means valid.
struct Problem {
  StatusCode code = StatusCode::Ok;
  const char* reason = nullptr;

  static Problem invalid(const char* r) { return {StatusCode::InvalidArgument, r}; }
  static Problem degenerate(const char* r) { return {StatusCode::DegenerateMesh, r}; }
  explicit operator bool() const { return reason != nullptr; }
  Status status() const { return reason ? Status(code, reason) : Status(); }
};

// The largest size or pose offset a pair query (overlap, penetration, distance, sweep) accepts. Kernels form products of up to four lengths (the squared
// norm of a cross product of two edges), so kMaxMagnitude^4 stays inside T's range: float 1e36 < 3.4e38, double
// 1e300 < 1.8e308. Beyond it a product overflows and an answer would be garbage (fuzz_pair_queries: a double sphere
// of radius 1.8e308 gave a penetration direction of length 2e-33).
template <class T> constexpr T kMaxMagnitude = std::is_same_v<T, float> ? T(1e9) : T(1e75);

// The geometry rules (common/geometry.cpp); validateGeometry() is their Status form. pairGeometryProblem adds the
// size bound kMaxMagnitude of pair queries.
template <class T> Problem geometryProblem(const Geometry<T>& geom);
template <class T> Problem pairGeometryProblem(const Geometry<T>& geom);

// | |v| - 1 | <= tolerance, tested on |v|^2 against the squared bounds (the same set, no square root; NaN fails).
inline bool squaredNormIsUnit(double n2, double tolerance) {
  return n2 >= (1.0 - tolerance) * (1.0 - tolerance) && n2 <= (1.0 + tolerance) * (1.0 + tolerance);
}

template <class T> [[gnu::always_inline]] inline bool isUnitQuaternion(const Quat<T>& q) {
  return squaredNormIsUnit(double(q.squaredNorm()), tol::kUnitQuaternion);
}

// q is exactly the identity rotation (w = 1, x = y = z = +-0): one 4-lane compare where SSE is compiled in. An
// identity pose (a shape placed as cooked) skips both its unit-norm test and the quaternion products.
template <class T> [[gnu::always_inline]] inline bool isIdentityRotation(const Quat<T>& q) {
  const T* c = q.coeffs().data();  // x, y, z, w
#ifdef GQ_SSE42
  if constexpr (std::is_same_v<T, float>) {
    return _mm_movemask_ps(_mm_cmpeq_ps(_mm_loadu_ps(c), _mm_setr_ps(0.0f, 0.0f, 0.0f, 1.0f))) == 0xF;
  } else {
    const __m128d xy = _mm_cmpeq_pd(_mm_loadu_pd(c), _mm_setzero_pd());
    const __m128d zw = _mm_cmpeq_pd(_mm_loadu_pd(c + 2), _mm_setr_pd(0.0, 1.0));
    return _mm_movemask_pd(_mm_and_pd(xy, zw)) == 0x3;
  }
#else
  return c[3] == T(1) && c[0] == T(0) && c[1] == T(0) && c[2] == T(0);
#endif
}

// A NaN or infinite quaternion component fails the norm bounds; x * 0 is exactly 0 only for a finite x.
template <class T> bool poseIsValid(const Transform<T>& pose) {
  return T(0) * pose.p.x() + T(0) * pose.p.y() + T(0) * pose.p.z() == T(0) && isUnitQuaternion(pose.q);
}

// The messages naming one input of a query: pre-composed literals, so a rejection builds no string.
struct FieldText {
  const char* notFinite;
  const char* notUnit;  // a direction: "is not a unit vector"; a pose: "rotation is not a unit quaternion"
};
constexpr FieldText kPointField{"point is not finite", "point is not finite"};
constexpr FieldText kRayOriginField{"ray origin is not finite", "ray origin is not finite"};
constexpr FieldText kRayDirectionField{"ray direction is not finite", "ray direction is not a unit vector"};
constexpr FieldText kSweepDirectionField{"sweep direction is not finite", "sweep direction is not a unit vector"};
constexpr FieldText kPoseField{"pose is not finite", "pose rotation is not a unit quaternion"};
constexpr FieldText kPose0Field{"pose0 is not finite", "pose0 rotation is not a unit quaternion"};
constexpr FieldText kPose1Field{"pose1 is not finite", "pose1 rotation is not a unit quaternion"};
constexpr FieldText kGeometryPoseField{"geometry pose is not finite", "geometry pose rotation is not a unit quaternion"};
constexpr FieldText kMeshPoseField{"meshPose is not finite", "meshPose rotation is not a unit quaternion"};
constexpr FieldText kHeightFieldPoseField{"heightFieldPose is not finite",
                                          "heightFieldPose rotation is not a unit quaternion"};

template <class T> Status checkFinite(const Vec3<T>& v, const FieldText& field) {
  if (!isFinite(v)) return Status::invalid(field.notFinite);
  return {};
}

// A non-unit direction's length goes in the Status detail (formatted by toString()).
template <class T> Status checkUnitDirection(const Vec3<T>& d, const FieldText& field) {
  if (isFinite(d) && squaredNormIsUnit(double(d.squaredNorm()), tol::kUnitDirection)) return {};
  if (!isFinite(d)) return Status::invalid(field.notFinite);
  const double len = std::sqrt(double(d.squaredNorm()));
  if (std::abs(len - 1.0) > tol::kUnitDirection) return Status::invalid(field.notUnit).withLength(float(len));
  return {};
}

template <class T> Status checkPose(const Transform<T>& pose, const FieldText& field) {
  if (poseIsValid(pose)) return {};
  if (!pose.isFinite()) return Status::invalid(field.notFinite);
  const double n = std::sqrt(double(pose.q.squaredNorm()));
  if (std::abs(n - 1.0) > tol::kUnitQuaternion) return Status::invalid(field.notUnit).withNorm(float(n));
  return {};
}

// maxDist, the one non-negative scalar the queries take.
template <class T> Status checkMaxDist(T x) {
  if (!std::isfinite(x) && !(x > 0)) return Status::invalid("maxDist is NaN or -inf");
  if (!(x >= T(0))) return Status::invalid("maxDist is negative");
  return {};
}

// Non-convex custom shapes answer only raycast and bounds (gq/custom.h).
template <class T> bool isNonConvexCustom(const Geometry<T>& g) {
  const auto* c = g.template getIf<CustomGeometry<T>>();
  return c && !c->callbacks->isConvex();
}

// Geometry + pose, the pair every query takes.
template <class T>
Status checkGeometryAndPose(const Geometry<T>& g, const Transform<T>& pose, const FieldText& poseField) {
  if (const Problem p = geometryProblem(g)) return p.status();
  return checkPose(pose, poseField);
}

// Both inputs of a pair query ("pose0", "pose1").
// Pair kernels work in pose0's frame: the offset p1 - p0 must be a length they can square (see kMaxMagnitude).
template <class T>
[[gnu::always_inline]] inline bool pairOffsetIsSupported(const Transform<T>& p0, const Transform<T>& p1) {
  return ((p1.p - p0.p).array().abs() <= kMaxMagnitude<T>).all();
}

// The poses of a pair query whose geometries are valid (a prepared shape's, or checked before): a handful of compares
// on the success path. The offset test also proves both positions finite: an infinite or NaN coordinate on either
// side makes that offset coordinate infinite or NaN (inf - inf is NaN), and both fail `<= kMaxMagnitude`. Always
// inline: out of line (GCC's choice once a caller grows) it cost a call and its spills on every query.
template <class T>
[[gnu::always_inline]] inline bool pairPosesAreValid(const Transform<T>& p0, const Transform<T>& p1) {
  return pairOffsetIsSupported(p0, p1) && isUnitQuaternion(p0.q) && isUnitQuaternion(p1.q);
}

template <class T> Status pairPosesStatus(const Transform<T>& p0, const Transform<T>& p1) {
  if (Status s = checkPose(p0, kPose0Field); !s.ok()) return s;
  if (Status s = checkPose(p1, kPose1Field); !s.ok()) return s;
  return Status::invalid("pose1 is too far from pose0: a pair query takes offsets up to 1e9 in float, 1e75 in double");
}

template <class T>
Status checkPairInputs(const Geometry<T>& g0, const Transform<T>& p0, const Geometry<T>& g1, const Transform<T>& p1) {
  if (!pairGeometryProblem(g0) && !pairGeometryProblem(g1) && poseIsValid(p0) && poseIsValid(p1) &&
      pairOffsetIsSupported(p0, p1))
    return {};
  if (const Problem p = pairGeometryProblem(g0)) return p.status();
  if (Status s = checkPose(p0, kPose0Field); !s.ok()) return s;
  if (const Problem p = pairGeometryProblem(g1)) return p.status();
  return pairPosesStatus(p0, p1);
}

// A raw triangle given with a shape (generateTriangleContacts, sweepTriangles) is the second geometry of a pair
// query: finite vertices within kMaxMagnitude of the shape's pose. nullptr when valid, else the whole message.
template <class T> const char* rawTriangleProblem(const Triangle<T>& tri, const Transform<T>& pose) {
  for (const Vec3<T>& v : tri.verts) {
    if (!isFinite(v)) return "the triangle has a non-finite vertex";
    if (!((v - pose.p).array().abs() <= kMaxMagnitude<T>).all())
      return "the triangle has a vertex too far from the pose (offsets up to 1e9 in float, 1e75 in double)";
  }
  return nullptr;
}

// Runs `body` (returning Status) and turns any escaping exception into InternalError: nothing throws out. Only an
// exception, which has allocated already, makes the one owned message (its what()) of a query. Always inline: the
// handlers are off the hot path, and out of line (GCC's choice once a caller grows) the guard cost a call, a frame
// and the unpacking of the body's captures, ~50 instructions on every query.
template <class F> [[gnu::always_inline]] inline Status guarded(F&& body) noexcept {
  try {
    return body();
  } catch (const std::bad_alloc&) {
    return Status::internal("out of memory");
  } catch (const std::exception& e) {
    return Status::owned(StatusCode::InternalError, e.what());
  } catch (...) {
    return Status::internal("unknown exception");
  }
}

}  // namespace gq::detail
