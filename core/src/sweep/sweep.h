#pragma once
// Sweep kernels (sweep/<swept>_<target>.cpp; "convex" stands for any support-mapped swept shape: sphere, capsule,
// box, convex mesh). Inputs are validated by the façade (dispatch/sweep.cpp), which also moves the origin to the
// swept shape's start position (poses keep their rotations), so kernels work near the origin and the façade adds
// pose0.p back to reported positions.
//
// Conventions of a kernel's SweepOutcome:
//  - hit at distance t: the swept shape translated by t * dir touches the target; normal is unit, points out of
//    the target towards the swept shape (dot(normal, dir) < 0), position is the touching point;
//  - initial overlap (t = 0 and the shapes intersect or touch): the façade fills the hit from `mtd*` fields.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include "gjk/gjk.h"
#include "gq/custom.h"
#include "gq/geometry.h"
#include "gq/hit.h"
#include "gq/mesh_query.h"
#include "gq/status.h"
#include "gq/transform.h"

namespace gq::detail {

// Conservative advancement stops once the shapes are this close (times gjkTolerance of the pair): the step lands
// at half of it, so GJK still sees separated cores and returns a well-defined contact normal.
inline constexpr double kSweepTouchFactor = 8.0;
// Newton steps of conservative advancement (quadratic convergence on curved contacts, exact on flat ones).
inline constexpr std::uint32_t kSweepMaxIterations = 64;
// Two mesh hits whose distances differ by less than this (times the TOI tolerance) are equally close; the one whose
// triangle faces the sweep most (smallest dot(faceNormal, dir)) wins.
inline constexpr double kSweepTieFactor = 4.0;

template <class T> struct SweepQuery {
  Vec3<T> dir;            // unit, world
  T maxDist;              // clamped to tol::kMaxSweepDistance
  HitFlags flags;         // already cleaned of incompatible flags by the façade
  T inflation;            // >= 0, added to the swept shape as a rounded shell
  bool testInitialOverlap;  // false with assumeNoInitialOverlap
  bool mtd;               // compute depth and depenetration direction of an initial overlap
  bool cullBackFaces;     // meshes/heightfields: not doubleSided and no meshBothSides
  bool anyHit;            // meshes: stop at the first hit found
};

template <class T> struct SweepOutcome {
  Status status;  // not ok: a custom callback answered wrongly; the façade returns it
  bool hit = false;
  bool initialOverlap = false;
  T distance = T(0);
  Vec3<T> normal = Vec3<T>::Zero();
  Vec3<T> position = Vec3<T>::Zero();
  std::uint32_t faceIndex = kInvalidFaceIndex;
  // Initial overlap with mtd: depth >= 0, depenetration direction of the swept shape and a point on it.
  bool mtdValid = false;
  T mtdDepth = T(0);
  Vec3<T> mtdNormal = Vec3<T>::Zero();
  Vec3<T> mtdPosition = Vec3<T>::Zero();
};

// Time of impact of two support-mapped shapes, a moving along dir (a's margin already includes the inflation).
template <class T> struct ToiResult {
  enum class Kind : std::uint8_t { Miss, Hit, InitialOverlap } kind = Kind::Miss;
  T distance = T(0);
  Vec3<T> normal = Vec3<T>::Zero();    // out of b, towards a
  Vec3<T> position = Vec3<T>::Zero();  // on b
};
template <class T>
ToiResult<T> sweepConvexShapes(const ConvexShape<T>& a, const ConvexShape<T>& b, const Vec3<T>& dir, T maxDist,
                               bool testInitialOverlap);
// Depth and depenetration direction of overlapping shapes (EPA), written into out.mtd*.
template <class T> void convexMtd(const ConvexShape<T>& a, const ConvexShape<T>& b, SweepOutcome<T>& out);

// A triangle as a convex support mapping (a custom shape at the identity pose).
template <class T> class TriangleSupport final : public CustomGeometryCallbacks<T> {
 public:
  explicit TriangleSupport(const Triangle<T>& t) : tri_(t) {}
  const char* name() const override { return "triangle"; }
  Bounds3<T> localBounds() const override;
  Vec3<T> support(const Vec3<T>& dir) const override;
  bool raycast(const Vec3<T>&, const Vec3<T>&, T, HitFlags, RaycastHit<T>&) const override { return false; }
  ConvexShape<T> shape() const;  // refers to *this: keep it alive while the shape is used

 private:
  Triangle<T> tri_;
};

// The swept shape at its start pose, with the inflation added to its margin.
template <class T> ConvexShape<T> makeSweptShape(const Geometry<T>& g, const Transform<T>& pose, T inflation);

// One triangle (world vertices, outward winding) against the swept shape: culling by the query, then TOI.
// Returns false when culled; otherwise `toi` holds the answer and `facing` = dot(faceNormal, dir).
template <class T>
bool sweepOneTriangle(const ConvexShape<T>& a, const Triangle<T>& tri, const SweepQuery<T>& q, bool doubleSided,
                      ToiResult<T>& toi, T& facing);

// Keeps the best triangle hit across a mesh/heightfield/triangle array (closest; ties to the most facing; initial
// overlaps win, the smallest triangle index among them).
template <class T> struct TriangleHitPicker {
  T tieTolerance;
  bool found = false;
  bool overlap = false;
  ToiResult<T> best;
  T bestFacing = T(0);
  std::uint32_t bestIndex = kInvalidFaceIndex;
  // Returns true when the query may stop (anyHit).
  bool offer(const ToiResult<T>& toi, T facing, std::uint32_t index, bool anyHit);
  T earlyOut(T maxDist) const { return found && !overlap ? std::min(maxDist, best.distance + tieTolerance) : maxDist; }
};

// Deepest overlapping triangle for the mtd of an initial overlap against triangles: triangles whose plane has the
// swept shape's centre behind it are skipped unless double-sided.
template <class T> struct TriangleMtdPicker {
  bool found = false;
  T depth = T(0);
  Vec3<T> normal = Vec3<T>::Zero();
  Vec3<T> position = Vec3<T>::Zero();
  std::uint32_t index = kInvalidFaceIndex;
  void offer(const ConvexShape<T>& a, const Triangle<T>& tri, std::uint32_t triIndex, bool doubleSided);
  void writeTo(SweepOutcome<T>& out, const Vec3<T>& dir) const;
};

// The swept shape's start box (centre `origin`, half extents `half`) moving along `dir` (a "fat ray"), in world space
// or in a mesh's space: that is an affine image of world space, so the parameter t along dir stays the world sweep
// distance. Triangles and BVH nodes are visited in order of entry() and skipped beyond the current closest hit.
template <class T> struct FatRay {
  Vec3<T> origin, dir, half;

  // First t in [0, tMax] at which the moving box meets [lo, hi] (their Minkowski sum contains origin + t dir);
  // +inf when never. The bounds grow by kFatRayPad of their magnitude: node boxes are float roundings.
  T entry(const Vec3<T>& lo, const Vec3<T>& hi, T tMax) const {
    T t0 = T(0), t1 = tMax;
    for (int i = 0; i < 3; ++i) {
      const T pad = T(kFatRayPad) * (std::abs(lo[i]) + std::abs(hi[i]) + half[i]);
      const T a = lo[i] - half[i] - pad, b = hi[i] + half[i] + pad;
      if (dir[i] == T(0)) {
        if (origin[i] < a || origin[i] > b) return std::numeric_limits<T>::infinity();
        continue;
      }
      T ta = (a - origin[i]) / dir[i], tb = (b - origin[i]) / dir[i];
      if (ta > tb) std::swap(ta, tb);
      t0 = std::max(t0, ta);
      t1 = std::min(t1, tb);
      if (t0 > t1) return std::numeric_limits<T>::infinity();
    }
    return t0;
  }
  static constexpr double kFatRayPad = 1e-6;
};

// AABB, in the frame `frame` (shape space of a mesh or heightfield), of the swept shape over [0, reach] along dir.
template <class T>
Bounds3<T> sweptBoundsInFrame(const ConvexShape<T>& a, const Transform<T>& frame, const Vec3<T>& dir, T reach);

// Tolerance under which two triangle hits count as equally close: the advancement's stopping distance for shapes
// spanning `box` (the swept volume), times kSweepTieFactor.
template <class T> T triangleTieTolerance(const ConvexShape<T>& a, const Bounds3<T>& box);

template <class T> void outcomeFromToi(const ToiResult<T>& toi, SweepOutcome<T>& out);

// Kernels (the façade's table).
template <class T>
void sweepConvexConvex(const Geometry<T>& g0, const Transform<T>& p0, const Geometry<T>& g1, const Transform<T>& p1,
                       const SweepQuery<T>& q, SweepOutcome<T>& out);
// Against custom geometry: its sweep callback when it answers (gq/custom.h), else sweepConvexConvex.
template <class T>
void sweepConvexCustom(const Geometry<T>& g0, const Transform<T>& p0, const Geometry<T>& g1, const Transform<T>& p1,
                       const SweepQuery<T>& q, SweepOutcome<T>& out);
template <class T>
void sweepSphereSphere(const Geometry<T>& g0, const Transform<T>& p0, const Geometry<T>& g1, const Transform<T>& p1,
                       const SweepQuery<T>& q, SweepOutcome<T>& out);
template <class T>
void sweepConvexPlane(const Geometry<T>& g0, const Transform<T>& p0, const Geometry<T>& g1, const Transform<T>& p1,
                      const SweepQuery<T>& q, SweepOutcome<T>& out);
template <class T>
void sweepConvexTriangleMesh(const Geometry<T>& g0, const Transform<T>& p0, const Geometry<T>& g1,
                             const Transform<T>& p1, const SweepQuery<T>& q, SweepOutcome<T>& out);
template <class T>
void sweepConvexHeightField(const Geometry<T>& g0, const Transform<T>& p0, const Geometry<T>& g1,
                            const Transform<T>& p1, const SweepQuery<T>& q, SweepOutcome<T>& out);
// Polygon of a convex mesh touched at `point` with outward normal `normal` (world): the polygon through the point
// whose normal agrees best with it.
template <class T>
std::uint32_t convexPolygonAt(const ConvexMeshGeometry<T>& g, const Transform<T>& pose, const Vec3<T>& point,
                              const Vec3<T>& normal);

}  // namespace gq::detail
