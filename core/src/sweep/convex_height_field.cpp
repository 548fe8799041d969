// Sweep of a support-mapped shape against a heightfield: the cells under the swept volume's box (in heightfield
// shape space) are gathered, hole cells skipped, and their triangles are visited in order of the parameter at which
// the swept shape's box, moving along the sweep, can first touch them (FatRay), stopping beyond the closest hit; each
// is culled and swept like a mesh triangle (normals face +Y; double-sided with the doubleSided flag or
// meshBothSides). faceIndex = 2*cell (+1).
#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "cook/height_field_layout.h"
#include "sweep/sweep.h"

namespace gq::detail {
namespace {

struct CellRange {
  std::uint32_t r0 = 1, r1 = 0, c0 = 1, c1 = 0;  // inclusive; empty when r0 > r1 or c0 > c1
};

// Cells whose [lo, hi] interval along one axis (sample spacing `spacing`, count cells) meets [a, b].
void cellSpan(double a, double b, double spacing, std::uint32_t cells, std::uint32_t& first, std::uint32_t& last) {
  double lo = a / spacing, hi = b / spacing;
  if (lo > hi) std::swap(lo, hi);
  const double f = std::max(0.0, std::floor(lo)), l = std::min(double(cells) - 1.0, std::floor(hi));
  if (!(f <= l)) { first = 1; last = 0; return; }
  first = std::uint32_t(f);
  last = std::uint32_t(l);
}

template <class T> CellRange cellsUnder(const HeightFieldGeometry<T>& g, const Bounds3<T>& box) {
  const HeightField<T>& hf = *g.heightField;
  CellRange range;
  const double h0 = double(hf.minHeight) * g.heightScale, h1 = double(hf.maxHeight) * g.heightScale;
  if (double(box.max.y()) < std::min(h0, h1) || double(box.min.y()) > std::max(h0, h1)) return range;
  cellSpan(box.min.x(), box.max.x(), g.rowScale, hf.rows - 1, range.r0, range.r1);
  cellSpan(box.min.z(), box.max.z(), g.columnScale, hf.columns - 1, range.c0, range.c1);
  return range;
}

template <class T> Triangle<T> heightFieldTriangle(const HeightFieldGeometry<T>& g, const Transform<T>& pose, std::uint32_t tri) {
  const std::array<std::uint32_t, 3> s = heightFieldTriangleSamples(*g.heightField, tri);
  Triangle<T> t;
  for (int k = 0; k < 3; ++k) t.verts[k] = pose.transform(heightFieldVertex(g, s[k]));
  return t;
}

}  // namespace

template <class T>
void sweepConvexHeightField(const Geometry<T>& g0, const Transform<T>& p0, const Geometry<T>& g1,
                            const Transform<T>& p1, const SweepQuery<T>& q, SweepOutcome<T>& out) {
  const auto& hfGeom = g1.template get<HeightFieldGeometry<T>>();
  const HeightField<T>& hf = *hfGeom.heightField;
  const ConvexShape<T> a = makeSweptShape(g0, p0, q.inflation);
  const Bounds3<T> shapeBox = sweptBoundsInFrame(a, p1, q.dir, q.maxDist);
  const CellRange range = cellsUnder(hfGeom, shapeBox);
  // Scratch kept per thread (the swept shape is a primitive or hull: no user code runs here), so a sweep allocates
  // only while they grow to the most candidates a call has had.
  thread_local std::vector<std::uint32_t> candidates;
  thread_local std::vector<std::pair<T, std::uint32_t>> order;
  candidates.clear();
  order.clear();
  for (std::uint32_t r = range.r0; r <= range.r1 && range.c0 <= range.c1; ++r)
    for (std::uint32_t c = range.c0; c <= range.c1; ++c) {
      if (hf.isHole(r, c)) continue;
      const std::uint32_t cell = heightFieldCellIndex(hf, r, c);
      candidates.push_back(2 * cell);
      candidates.push_back(2 * cell + 1);
    }

  // Candidates ordered by the first parameter at which the start box, moving along dir, meets their boxes (world).
  const Bounds3<T> startBox = sweptBoundsInFrame(a, Transform<T>(), q.dir, T(0));
  const FatRay<T> ray{startBox.center(), q.dir, startBox.extents()};
  for (const std::uint32_t tri : candidates) {
    const Triangle<T> t = heightFieldTriangle(hfGeom, p1, tri);
    Bounds3<T> box;
    for (const Vec3<T>& v : t.verts) box.include(v);
    const T entry = ray.entry(box.min, box.max, q.maxDist);
    if (entry <= q.maxDist) order.emplace_back(entry, tri);
  }
  std::sort(order.begin(), order.end());

  const bool doubleSided = hfGeom.doubleSided();
  SweepQuery<T> local = q;
  local.cullBackFaces = q.cullBackFaces && !doubleSided;
  TriangleHitPicker<T> picker;
  picker.tieTolerance = triangleTieTolerance(a, shapeBox);
  for (const auto& [entry, tri] : order) {
    // Initial overlaps win (the smallest index among them): once one is found only boxes met at t = 0 matter.
    if (entry > (picker.found && picker.overlap ? T(0) : picker.earlyOut(q.maxDist))) break;
    local.maxDist = picker.earlyOut(q.maxDist);
    ToiResult<T> toi;
    T facing;
    if (!sweepOneTriangle(a, heightFieldTriangle(hfGeom, p1, tri), local, doubleSided, toi, facing)) continue;
    // meshAny has no effect on heightfields (the spec): always the closest hit.
    picker.offer(toi, facing, tri, false);
  }
  if (!picker.found) return;
  outcomeFromToi(picker.best, out);
  out.faceIndex = picker.bestIndex;
  if (!(out.initialOverlap && q.mtd)) return;
  TriangleMtdPicker<T> mtd;
  SweepQuery<T> overlapOnly = local;
  overlapOnly.maxDist = T(0);
  for (const std::uint32_t tri : candidates) {
    const Triangle<T> t = heightFieldTriangle(hfGeom, p1, tri);
    ToiResult<T> toi;
    T facing;
    if (!sweepOneTriangle(a, t, overlapOnly, doubleSided, toi, facing)) continue;
    if (toi.kind == ToiResult<T>::Kind::InitialOverlap) mtd.offer(a, t, tri, doubleSided || !q.cullBackFaces);
  }
  mtd.writeTo(out, q.dir);
}

template void sweepConvexHeightField<float>(const Geometry<float>&, const Transform<float>&, const Geometry<float>&,
                                            const Transform<float>&, const SweepQuery<float>&, SweepOutcome<float>&);
template void sweepConvexHeightField<double>(const Geometry<double>&, const Transform<double>&,
                                             const Geometry<double>&, const Transform<double>&,
                                             const SweepQuery<double>&, SweepOutcome<double>&);

}  // namespace gq::detail
