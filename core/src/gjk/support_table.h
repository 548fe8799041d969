#pragma once
// Support start tables: for a cooked convex hull, the extreme vertex along the centre direction of every cell of a
// cube map over the sphere of directions. A hill climb started from the cell's vertex is one step or none from the
// answer (it stays exact: the climb itself decides), where a climb warm-started from the previous GJK direction
// walks several steps (successive GJK directions often point to opposite sides of a shape).
//
// Cube map: a direction d falls on the face of its largest |component| (6 faces: +X, -X, +Y, -Y, +Z, -Z); the other
// two components divided by that one lie in [-1, 1] and are cut into k x k cells.
//
// Tables live in a process-wide registry keyed by the mesh's address (ConvexMesh is public and has no room for
// them): built once per mesh under a lock, immutable afterwards, and an entry is never replaced while its mesh is
// alive (a weak reference tells a live mesh from a dead one at a reused address). A small per-thread table in front
// of the registry makes the usual lookup lock-free. Like every cooked-data cache in core, it assumes a mesh is not
// modified after its first query.
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <vector>

#if defined(__SSE4_1__)
#include <smmintrin.h>
#elif defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "gq/cooking.h"
#include "gq/kernels/gjk.h"

namespace gq::kernels {

// Hulls with at most this many vertices get no table (they are scanned, or climbed from a few samples).
inline constexpr std::uint32_t kStartTableMinVertices = 8;

// Neighbour runs of the packed climbing graph are padded to a multiple of this many slots (one SSE register of T).
template <class T> inline constexpr std::uint32_t kClimbLanes = std::uint32_t(16 / sizeof(T));

template <class T> class SupportStartTable {
 public:
  // Builds the table of `hull` (which needs vertex adjacency or is scanned exhaustively per cell).
  explicit SupportStartTable(const ConvexMesh<T>& hull);

  // A cell's entry is its start vertex, with kSettled set when that vertex is the support along every direction of
  // the cell by a margin above the climb's rounding (settleCells): the climb from it would not move, so the support
  // is the entry itself, without a neighbour scan.
  static constexpr std::uint32_t kSettled = 1u << 31;
  static bool settled(std::uint32_t entry) { return (entry & kSettled) != 0; }
  static std::uint32_t vertexOf(std::uint32_t entry) { return entry & ~kSettled; }

  // Start vertex for direction d (need not be unit); 0 for a zero or non-finite direction.
  std::uint32_t lookup(const Vec3<T>& d) const { return vertexOf(lookupEntry(d)); }
  // The same with the cell's kSettled flag.
  std::uint32_t lookupEntry(const Vec3<T>& d) const {
    const T ax = std::abs(d.x()), ay = std::abs(d.y()), az = std::abs(d.z());
    const T sum = ax + ay + az;  // NaN or inf when any component is
    if (!(sum > T(0)) || !(sum < std::numeric_limits<T>::infinity())) return 0;
    // Face f = 2 * axis + (component < 0); (u, v) = the two other components.
    std::uint32_t face;
    T major, u, v;
    if (ax >= ay && ax >= az) {
      face = d.x() < T(0) ? 1u : 0u; major = ax; u = d.y(); v = d.z();
    } else if (ay >= az) {
      face = d.y() < T(0) ? 3u : 2u; major = ay; u = d.x(); v = d.z();
    } else {
      face = d.z() < T(0) ? 5u : 4u; major = az; u = d.x(); v = d.y();
    }
    const T scale = halfCells_ / major;  // maps u / major in [-1, 1] to [0, k]
    return start_[(face * cells_ + cellIndex(u * scale)) * cells_ + cellIndex(v * scale)];
  }

  // Steepest-ascent hill climb from `start` to the vertex of `hull` (the mesh the table was built from) extreme along
  // d; exact like climbVertex. The table keeps the hull's edge graph with every vertex's neighbour coordinates
  // stored contiguously (x, y, z arrays in CSR order), each run padded to kClimbLanes<T> slots by repeating its last
  // neighbour (a repeated candidate cannot change a maximum), so a step is a few packed multiply-adds with no index
  // indirection. Dot products are formed as in dot3, so values (and ties) match the scalar climb.
  std::uint32_t climb(const ConvexMesh<T>& hull, const Vec3<T>& d, std::uint32_t current) const {
    T currentDot = dot(hull.vertices[current], d);
    for (;;) {
      T bestDot;
      const std::uint32_t slot = bestNeighbourSlot(current, d, bestDot);
      if (!(bestDot > currentDot)) return current;
      current = neighbour_[slot];
      currentDot = bestDot;
    }
  }
  bool hasClimbGraph() const { return !neighbour_.empty(); }

  std::uint32_t cellsPerSide() const { return cells_; }
  // Unit centre direction of cell (face, i, j) (what the stored vertex is extreme along).
  Vec3<T> cellDirection(std::uint32_t face, std::uint32_t i, std::uint32_t j) const;
  std::uint32_t startOfCell(std::uint32_t face, std::uint32_t i, std::uint32_t j) const {
    return vertexOf(start_[(face * cells_ + i) * cells_ + j]);
  }
  bool cellSettled(std::uint32_t face, std::uint32_t i, std::uint32_t j) const {
    return settled(start_[(face * cells_ + i) * cells_ + j]);
  }

 private:
  // Cell of a scaled coordinate c in [-k/2, k/2] (k/2 itself, from a component equal to the major one, is the last
  // cell). Clamped before the conversion: c is NaN or infinite when the major component underflows the scale.
  std::uint32_t cellIndex(T c) const {
    const T x = c + halfCells_;
    if (!(x > T(0))) return 0;
    if (!(x < cellsT_)) return cells_ - 1;
    return static_cast<std::uint32_t>(x);
  }

  static T dot(const Vec3<T>& v, const Vec3<T>& d) { return v.x() * d.x() + v.y() * d.y() + v.z() * d.z(); }

  // Slot of the neighbour of `vertex` with the largest d.v (its value in `best`; -inf for a vertex without any).
  std::uint32_t bestNeighbourSlot(std::uint32_t vertex, const Vec3<T>& d, T& best) const;

  void buildClimbGraph(const ConvexMesh<T>& hull);
  void settleCells(const ConvexMesh<T>& hull);
  // Direction (major, u, v) of a face's cube-map coordinates (u, v in [-1, 1]), unnormalised.
  Vec3<T> faceDirection(std::uint32_t face, T u, T v) const;

  std::uint32_t cells_;
  T cellsT_;  // cells_ as T (the lookup compares with it)
  T halfCells_;
  std::vector<std::uint32_t> start_;
  std::vector<std::uint32_t> offsets_;    // padded CSR offsets, one run per vertex
  std::vector<T> x_, y_, z_;              // neighbour coordinates per slot
  std::vector<std::uint32_t> neighbour_;  // neighbour vertex per slot
};

#if defined(__SSE2__)
// Lanes of `a` where `mask` is set, else of `b`: one blend with SSE4.1 (core's baseline, GQ_SSE42), else three
// logic operations (a third of the scan's instructions). Both give the same lanes bit for bit, so a translation unit
// outside core that includes this header without SSE4.1 computes what core computes.
inline __m128d laneSelect(__m128d mask, __m128d a, __m128d b) {
#if defined(__SSE4_1__)
  return _mm_blendv_pd(b, a, mask);
#else
  return _mm_or_pd(_mm_and_pd(mask, a), _mm_andnot_pd(mask, b));
#endif
}
inline __m128 laneSelect(__m128 mask, __m128 a, __m128 b) {
#if defined(__SSE4_1__)
  return _mm_blendv_ps(b, a, mask);
#else
  return _mm_or_ps(_mm_and_ps(mask, a), _mm_andnot_ps(mask, b));
#endif
}

// Packed scans: the running maximum and the slot it came from are kept per lane (slots as floating-point values,
// exact below 2^24 slots, which buildClimbGraph guarantees), then reduced across lanes (first slot on ties).
template <> inline std::uint32_t SupportStartTable<double>::bestNeighbourSlot(std::uint32_t vertex, const Vec3<double>& d,
                                                                              double& best) const {
  const __m128d dx = _mm_set1_pd(d.x()), dy = _mm_set1_pd(d.y()), dz = _mm_set1_pd(d.z());
  __m128d bestValue = _mm_set1_pd(-std::numeric_limits<double>::infinity()), bestSlot = _mm_setzero_pd();
  const std::uint32_t begin = offsets_[vertex], end = offsets_[vertex + 1];
  __m128d slot = _mm_set_pd(double(begin + 1), double(begin));
  const __m128d step = _mm_set1_pd(2.0);
  for (std::uint32_t k = begin; k < end; k += 2) {
    const __m128d s = _mm_add_pd(_mm_add_pd(_mm_mul_pd(_mm_loadu_pd(&x_[k]), dx), _mm_mul_pd(_mm_loadu_pd(&y_[k]), dy)),
                                 _mm_mul_pd(_mm_loadu_pd(&z_[k]), dz));
    const __m128d better = _mm_cmpgt_pd(s, bestValue);
    bestValue = laneSelect(better, s, bestValue);
    bestSlot = laneSelect(better, slot, bestSlot);
    slot = _mm_add_pd(slot, step);
  }
  const double v0 = _mm_cvtsd_f64(bestValue), v1 = _mm_cvtsd_f64(_mm_unpackhi_pd(bestValue, bestValue));
  const double s0 = _mm_cvtsd_f64(bestSlot), s1 = _mm_cvtsd_f64(_mm_unpackhi_pd(bestSlot, bestSlot));
  const bool second = v1 > v0 || (v1 == v0 && s1 < s0);
  best = second ? v1 : v0;
  return static_cast<std::uint32_t>(second ? s1 : s0);
}

template <> inline std::uint32_t SupportStartTable<float>::bestNeighbourSlot(std::uint32_t vertex, const Vec3<float>& d,
                                                                             float& best) const {
  const __m128 dx = _mm_set1_ps(d.x()), dy = _mm_set1_ps(d.y()), dz = _mm_set1_ps(d.z());
  __m128 bestValue = _mm_set1_ps(-std::numeric_limits<float>::infinity()), bestSlot = _mm_setzero_ps();
  const std::uint32_t begin = offsets_[vertex], end = offsets_[vertex + 1];
  const float b = float(begin);
  __m128 slot = _mm_set_ps(b + 3, b + 2, b + 1, b);
  const __m128 step = _mm_set1_ps(4.0f);
  for (std::uint32_t k = begin; k < end; k += 4) {
    const __m128 s = _mm_add_ps(_mm_add_ps(_mm_mul_ps(_mm_loadu_ps(&x_[k]), dx), _mm_mul_ps(_mm_loadu_ps(&y_[k]), dy)),
                                _mm_mul_ps(_mm_loadu_ps(&z_[k]), dz));
    const __m128 better = _mm_cmpgt_ps(s, bestValue);
    bestValue = laneSelect(better, s, bestValue);
    bestSlot = laneSelect(better, slot, bestSlot);
    slot = _mm_add_ps(slot, step);
  }
  alignas(16) float values[4], slots[4];
  _mm_store_ps(values, bestValue);
  _mm_store_ps(slots, bestSlot);
  std::uint32_t lane = 0;
  for (std::uint32_t l = 1; l < 4; ++l)
    if (values[l] > values[lane] || (values[l] == values[lane] && slots[l] < slots[lane])) lane = l;
  best = values[lane];
  return static_cast<std::uint32_t>(slots[lane]);
}
#else
template <class T>
inline std::uint32_t SupportStartTable<T>::bestNeighbourSlot(std::uint32_t vertex, const Vec3<T>& d, T& best) const {
  best = -std::numeric_limits<T>::infinity();
  std::uint32_t slot = offsets_[vertex];
  for (std::uint32_t k = offsets_[vertex], end = offsets_[vertex + 1]; k < end; ++k) {
    const T s = x_[k] * d.x() + y_[k] * d.y() + z_[k] * d.z();
    if (s > best) { best = s; slot = k; }
  }
  return slot;
}
#endif

// Cells per side of a cube face, the same for every hull with a table (24 KB a hull, ~0.3-1 ms to build on first use):
// the count sets how many cells settle (settleCells), 84 % / 71 % of the cells of 30 / 100-vertex hulls at 32
// (43-48 % at 8 / 16).
inline constexpr std::uint32_t kStartTableCells = 32;

// The shared table of `mesh`, built on first use; nullptr for hulls of <= kStartTableMinVertices vertices.
// The pointer stays valid as long as the mesh is alive.
template <class T> const SupportStartTable<T>* supportStartTable(const std::shared_ptr<const ConvexMesh<T>>& mesh);

}  // namespace gq::kernels

namespace gq::detail {
using namespace kernels;
}  // namespace gq::detail
