// Raycast against a heightfield: the spec treats it as a triangle mesh whose normals face +Y in shape space.
// The ray is taken to shape space (the pose is rigid, so distances are unchanged), clipped to the field's box, and
// its XZ projection is walked over the grid front to back: first over blocks of kBlock x kBlock cells, skipping
// blocks whose cooked height range the ray passes above or below, then over the cells of each remaining block,
// skipping cells by the height range of their four samples. Only the two triangles of a visited cell are tested
// (watertight test of mesh/triangle.h), so the cost grows with the cells crossed, not with the field size.
//
// The walk is conservative: each row strip and each cell is widened by a small pad, so rounding in the walk can
// only add cells, never drop one; a ray through a grid vertex or along a cell diagonal still reaches every cell
// whose triangles the watertight test would report.
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "cook/height_field_layout.h"
#include "gq/cooking.h"
#include "gq/tolerances.h"
#include "mesh/triangle.h"
#include "raycast/raycast.h"

namespace gq::detail {
namespace {

template <class T> struct Span {
  T t0, t1;
  bool empty() const { return !(t0 <= t1); }
};

// Part of `s` in which o + t*d lies in [lo, hi].
template <class T> Span<T> clipToSlab(T o, T d, T lo, T hi, Span<T> s) {
  if (d == T(0)) {
    if (o < lo || o > hi) return {T(1), T(0)};
    return s;
  }
  T a = (lo - o) / d, b = (hi - o) / d;
  if (a > b) std::swap(a, b);
  return {std::max(s.t0, a), std::min(s.t1, b)};
}

// A ray's XZ projection in grid units (cells or blocks): row coordinate ox + t*dx, column coordinate oz + t*dz.
template <class T> struct GridLine {
  T ox, dx, oz, dz;
};

template <class T> GridLine<T> gridLine(const Vec3<T>& o, const Vec3<T>& d, T rowSize, T columnSize) {
  return {o.x() / rowSize, d.x() / rowSize, o.z() / columnSize, d.z() / columnSize};
}

// Inclusive integer range [first, last] of unit intervals touched by [min(a,b) - pad, max(a,b) + pad], clamped to
// [lo, hi]; empty when first > last.
template <class T> void touchedRange(T a, T b, T pad, std::int64_t lo, std::int64_t hi, std::int64_t& first,
                                     std::int64_t& last) {
  const T f = std::max(T(lo), std::floor(std::min(a, b) - pad));
  const T l = std::min(T(hi), std::floor(std::max(a, b) + pad));
  // An empty (or NaN) range converts nothing: f can be ~1e161 for far rays, beyond int64 (UB; found by fuzz_raycast).
  if (!(f <= l)) {
    first = lo;
    last = lo - 1;
    return;
  }
  first = std::int64_t(f);
  last = std::int64_t(l);
}

// Calls step(k, slabSpan) for the unit slabs k in [lo, hi] (widened by `pad`) that the line o + t d crosses during
// `span`, in the order it crosses them. Returns true when a step does (stop the query); a slab entered after
// limit() ends the walk (slabs are entered in increasing t).
template <class T, class Limit, class Step>
bool walkSlabs(T o, T d, Span<T> span, std::int64_t lo, std::int64_t hi, T pad, Limit& limit, Step&& step) {
  std::int64_t first, last;
  touchedRange(o + span.t0 * d, o + span.t1 * d, pad, lo, hi, first, last);
  const bool up = d >= T(0);
  for (std::int64_t i = first; i <= last; ++i) {
    const std::int64_t k = up ? i : first + last - i;
    const Span<T> slab = clipToSlab(o, d, T(k) - pad, T(k + 1) + pad, span);
    if (slab.empty()) continue;
    if (slab.t0 > limit()) return false;
    if (step(k, slab)) return true;
  }
  return false;
}

// Visits the grid cells (r, c) with r in [rowLo, rowHi], c in [colLo, colHi] that the line crosses during `span`,
// front to back: row strips in the order the ray crosses them, and cells along each strip likewise. Each strip and
// cell is widened by `pad` (grid units). Cells entered after limit() are skipped. visit(r, c, cellSpan) returns
// true to stop the whole query; walkGrid then returns true.
template <class T, class Limit, class Visit>
bool walkGrid(const GridLine<T>& line, Span<T> span, std::int64_t rowLo, std::int64_t rowHi, std::int64_t colLo,
              std::int64_t colHi, T pad, Limit&& limit, Visit&& visit) {
  return walkSlabs(line.ox, line.dx, span, rowLo, rowHi, pad, limit, [&](std::int64_t r, const Span<T>& strip) {
    return walkSlabs(line.oz, line.dz, strip, colLo, colHi, pad, limit,
                     [&](std::int64_t c, const Span<T>& cell) { return visit(r, c, cell); });
  });
}

template <class T> struct Candidate {
  T t, u, v;
  std::uint32_t triangle;
  bool front;
};

// Keeps the closest hit, any hit (stops at the first), or the `cap` closest hits (MeshMultiple). limit() is the
// early-out distance the walk and the triangle tests read.
template <class T> class HitCollector {
 public:
  HitCollector(T maxDist, std::uint32_t cap, bool anyHit)
      : maxDist_(maxDist), cap_(cap), anyHit_(anyHit), hits_(threadScratch()) {}

  T limit() const { return limit_; }
  bool done() const { return anyHit_ && !hits_.empty(); }

  void add(const Candidate<T>& c) {
    if (hits_.size() < cap_) {
      hits_.push_back(c);
      if (hits_.size() == cap_) updateLimit();
      return;
    }
    auto farthest = std::max_element(hits_.begin(), hits_.end(), byDistance);
    if (c.t < farthest->t) {
      *farthest = c;
      updateLimit();
    }
  }

  std::vector<Candidate<T>>& sortedHits() {
    std::sort(hits_.begin(), hits_.end(), byDistance);
    return hits_;
  }

 private:
  static bool byDistance(const Candidate<T>& a, const Candidate<T>& b) { return a.t < b.t; }
  // The hits of the thread's current raycast: kept per thread, so a raycast allocates only while the buffer grows to
  // the most hits a call has kept (one collector per thread at a time: a heightfield raycast runs no user code).
  static std::vector<Candidate<T>>& threadScratch() {
    thread_local std::vector<Candidate<T>> hits;
    hits.clear();
    return hits;
  }
  // Once the buffer is full only closer hits matter.
  void updateLimit() { limit_ = std::max_element(hits_.begin(), hits_.end(), byDistance)->t; }

  T maxDist_;
  std::uint32_t cap_;
  bool anyHit_;
  T limit_ = maxDist_;
  std::vector<Candidate<T>>& hits_;
};

template <class T> class HeightFieldRaycaster {
 public:
  HeightFieldRaycaster(const HeightFieldGeometry<T>& g, const Transform<T>& pose, const RayQuery<T>& ray)
      : g_(g),
        hf_(*g.heightField),
        pose_(pose),
        ray_(ray),
        o_(pose.transformInv(ray.origin)),
        d_(pose.rotateInv(ray.dir)),
        wray_(makeWatertightRay(o_, d_)),
        cullBackFaces_(!g.doubleSided() && !ray.flags.has(HitFlag::MeshBothSides)),
        collector_(ray.maxDist, ray.maxHits, ray.flags.has(HitFlag::AnyHit) && ray.maxHits == 1) {}

  std::uint32_t run(RaycastHit<T>* hits) {
    Span<T> span{T(0), ray_.maxDist};
    if (!clipToField(span)) return 0;
    // Pads: in grid units for the walk, in length for the height culling; a few hundred ulps of the largest
    // coordinate involved, so rounding in the walk cannot drop a cell.
    const T rel = tol::Rel<T>::kEpsilon;
    const T reach = o_.cwiseAbs().maxCoeff() + span.t1;
    padY_ = rel * (reach + sizeY());
    const GridLine<T> cells = gridLine(o_, d_, g_.rowScale, g_.columnScale);
    cellPad_ = rel * (T(1) + std::max(reach / g_.rowScale, reach / g_.columnScale));
    cells_ = cells;
    const T b = T(HeightField<T>::kBlock);
    const GridLine<T> blocks{cells.ox / b, cells.dx / b, cells.oz / b, cells.dz / b};
    auto limit = [this] { return collector_.limit(); };
    walkGrid(blocks, span, 0, std::int64_t(hf_.blockRows) - 1, 0, std::int64_t(hf_.blockColumns) - 1, cellPad_ / b,
             limit, [this, &limit](std::int64_t br, std::int64_t bc, const Span<T>& s) { return visitBlock(br, bc, s, limit); });
    return writeHits(hits);
  }

 private:
  T sizeY() const { return std::max(std::abs(hf_.minHeight), std::abs(hf_.maxHeight)) * g_.heightScale; }

  // Clips `span` to the field's shape-space box (padded); false if the ray misses it.
  bool clipToField(Span<T>& span) const {
    const T rel = tol::Rel<T>::kEpsilon;
    const Vec3<T> hi(T(hf_.rows - 1) * g_.rowScale, hf_.maxHeight * g_.heightScale, T(hf_.columns - 1) * g_.columnScale);
    const Vec3<T> lo(T(0), hf_.minHeight * g_.heightScale, T(0));
    const T pad = rel * (hi.cwiseAbs().maxCoeff() + lo.cwiseAbs().maxCoeff() + o_.cwiseAbs().maxCoeff());
    for (int k = 0; k < 3; ++k) span = clipToSlab(o_[k], d_[k], lo[k] - pad, hi[k] + pad, span);
    return !span.empty();
  }

  // Whether the ray's height over `s` can meet heights in [lo, hi] (shape space, before padding).
  bool heightOverlaps(const Span<T>& s, T lo, T hi) const {
    const T y0 = o_.y() + s.t0 * d_.y(), y1 = o_.y() + s.t1 * d_.y();
    return std::max(y0, y1) >= lo - padY_ && std::min(y0, y1) <= hi + padY_;
  }

  template <class Limit>
  bool visitBlock(std::int64_t br, std::int64_t bc, const Span<T>& s, Limit& limit) {
    const std::size_t block = std::size_t(br) * hf_.blockColumns + std::size_t(bc);
    if (!heightOverlaps(s, hf_.blockMin[block] * g_.heightScale, hf_.blockMax[block] * g_.heightScale)) return false;
    constexpr std::int64_t kB = HeightField<T>::kBlock;
    const std::int64_t rowHi = std::min<std::int64_t>(br * kB + kB, hf_.rows - 1) - 1;
    const std::int64_t colHi = std::min<std::int64_t>(bc * kB + kB, hf_.columns - 1) - 1;
    return walkGrid(cells_, s, br * kB, rowHi, bc * kB, colHi, cellPad_, limit,
                    [this](std::int64_t r, std::int64_t c, const Span<T>& cs) { return visitCell(r, c, cs); });
  }

  bool visitCell(std::int64_t r, std::int64_t c, const Span<T>& s) {
    const std::uint32_t cell = heightFieldCellIndex(hf_, std::uint32_t(r), std::uint32_t(c));
    if (hf_.hole[cell]) return false;
    const std::uint32_t s00 = std::uint32_t(r) * hf_.columns + std::uint32_t(c);
    const Vec3<T> v00 = heightFieldVertex(g_, s00), v01 = heightFieldVertex(g_, s00 + 1);
    const Vec3<T> v10 = heightFieldVertex(g_, s00 + hf_.columns), v11 = heightFieldVertex(g_, s00 + hf_.columns + 1);
    const T lo = std::min(std::min(v00.y(), v01.y()), std::min(v10.y(), v11.y()));
    const T hi = std::max(std::max(v00.y(), v01.y()), std::max(v10.y(), v11.y()));
    if (!heightOverlaps(s, lo, hi)) return false;
    testTriangle(2 * cell, v00, v01, v10);
    if (collector_.done()) return true;
    testTriangle(2 * cell + 1, v01, v11, v10);
    return collector_.done();
  }

  void testTriangle(std::uint32_t tri, const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& c) {
    TriangleRayHit<T> h;
    // As for meshes: overflowing products give a NaN t that passes t <= limit (float ray from y = 1e6, fuzz_raycast).
    if (intersectRayTriangle(wray_, a, b, c, collector_.limit(), cullBackFaces_, h) && std::isfinite(h.t) &&
        std::isfinite(h.u) && std::isfinite(h.v))
      collector_.add({h.t, h.u, h.v, tri, h.frontFace});
  }

  // World normal of triangle `tri` facing +Y in shape space; a back-face hit on a double-sided field reports the
  // reversed normal (the spec). Each edge is divided by its largest coordinate before the cross product: with row and
  // column scales near 1e20 in float (1e160 in double) the plain product overflows and normalizes to NaN (found by
  // fuzz_raycast). An edge that itself overflows leaves no direction: the normal then faces the ray, as for meshes.
  Vec3<T> worldNormal(const Candidate<T>& c) const {
    const std::array<std::uint32_t, 3> s = heightFieldTriangleSamples(hf_, c.triangle);
    const Vec3<T> a = heightFieldVertex(g_, s[0]);
    auto unitMax = [](const Vec3<T>& e) -> Vec3<T> { return e / e.cwiseAbs().maxCoeff(); };
    Vec3<T> n = unitMax(heightFieldVertex(g_, s[1]) - a).cross(unitMax(heightFieldVertex(g_, s[2]) - a));
    n = n.stableNormalized();
    if (!n.allFinite() || n.squaredNorm() == T(0)) return -ray_.dir;
    if (!c.front && g_.doubleSided()) n = -n;
    return pose_.rotate(n);
  }

  std::uint32_t writeHits(RaycastHit<T>* hits) {
    const std::vector<Candidate<T>>& found = collector_.sortedHits();
    for (std::size_t i = 0; i < found.size(); ++i) {
      const Candidate<T>& c = found[i];
      RaycastHit<T>& hit = hits[i];
      hit.distance = c.t;
      hit.faceIndex = c.triangle;
      HitFlags written;
      if (ray_.flags.has(HitFlag::Position)) {
        hit.position = ray_.origin + c.t * ray_.dir;
        written |= HitFlag::Position;
      }
      if (ray_.flags.has(HitFlag::Normal)) {
        hit.normal = worldNormal(c);
        written |= HitFlag::Normal;
      }
      if (ray_.flags.has(HitFlag::UV)) {
        hit.u = c.u;
        hit.v = c.v;
        written |= HitFlag::UV;
      }
      if (ray_.flags.has(HitFlag::FaceIndex)) written |= HitFlag::FaceIndex;
      hit.flags = written;
    }
    return std::uint32_t(found.size());
  }

  const HeightFieldGeometry<T>& g_;
  const HeightField<T>& hf_;
  const Transform<T>& pose_;
  const RayQuery<T>& ray_;
  const Vec3<T> o_, d_;  // ray in shape space
  const WatertightRay<T> wray_;
  const bool cullBackFaces_;
  HitCollector<T> collector_;
  GridLine<T> cells_{};
  T padY_ = T(0), cellPad_ = T(0);
};

}  // namespace

template <class T>
std::uint32_t raycastHeightField(const HeightFieldGeometry<T>& g, const Transform<T>& pose, const RayQuery<T>& ray,
                                 RaycastHit<T>* hits) {
  if (!(ray.maxDist > T(0))) return 0;  // a zero-length ray hits nothing
  if (!heightFieldIsWellFormed(*g.heightField)) return 0;  // not cooked: nothing to hit, never out of bounds
  return HeightFieldRaycaster<T>(g, pose, ray).run(hits);
}

template std::uint32_t raycastHeightField<float>(const HeightFieldGeometry<float>&, const Transform<float>&,
                                                 const RayQuery<float>&, RaycastHit<float>*);
template std::uint32_t raycastHeightField<double>(const HeightFieldGeometry<double>&, const Transform<double>&,
                                                  const RayQuery<double>&, RaycastHit<double>*);

}  // namespace gq::detail
