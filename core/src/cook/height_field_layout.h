#pragma once
// The heightfield triangle layout of gq/cooking.h in one place, for every kernel that reads heightfield triangles
// (raycast, getTriangle, overlaps): cell (r, c) = r * (columns - 1) + c has triangles 2*cell = (v00, v01, v10) and
// 2*cell+1 = (v01, v11, v10), where vRC is the sample (r + R, c + C). Sample (r, c) sits at the shape-space point
// (r * rowScale, height * heightScale, c * columnScale). Every kernel computes a vertex through localVertex(), so a
// sample shared by several triangles has bit-identical coordinates in all of them (needed for watertight tests).
#include <array>
#include <cstdint>

#include "gq/cooking.h"

namespace gq::detail {

// Whether `hf` has the shape cookHeightField gives it (at least 2 x 2 samples, one height per sample, one hole flag
// per cell, block ranges present); a hand-built or default HeightField may not, and kernels must not index it.
template <class T> inline bool heightFieldIsWellFormed(const HeightField<T>& hf) {
  if (hf.rows < 2 || hf.columns < 2) return false;
  const std::uint64_t samples = std::uint64_t(hf.rows) * hf.columns;
  const std::uint64_t cells = std::uint64_t(hf.rows - 1) * (hf.columns - 1);
  const std::uint64_t blocks = std::uint64_t(hf.blockRows) * hf.blockColumns;
  constexpr std::uint32_t kB = HeightField<T>::kBlock;
  return hf.heights.size() == samples && hf.hole.size() == cells && hf.blockRows == (hf.rows - 2) / kB + 1 &&
         hf.blockColumns == (hf.columns - 2) / kB + 1 && hf.blockMin.size() == blocks && hf.blockMax.size() == blocks;
}

template <class T> inline std::uint32_t heightFieldCellCount(const HeightField<T>& hf) {
  return (hf.rows - 1) * (hf.columns - 1);
}

template <class T> inline std::uint32_t heightFieldTriangleCount(const HeightField<T>& hf) {
  return 2 * heightFieldCellCount(hf);
}

template <class T> inline std::uint32_t heightFieldCellIndex(const HeightField<T>& hf, std::uint32_t r, std::uint32_t c) {
  return r * (hf.columns - 1) + c;
}

// Sample indices (row * columns + column) of triangle `tri`'s vertices, in winding order (normal towards +Y).
template <class T>
inline std::array<std::uint32_t, 3> heightFieldTriangleSamples(const HeightField<T>& hf, std::uint32_t tri) {
  const std::uint32_t cell = tri / 2;
  const std::uint32_t r = cell / (hf.columns - 1), c = cell % (hf.columns - 1);
  const std::uint32_t s00 = r * hf.columns + c, s01 = s00 + 1, s10 = s00 + hf.columns, s11 = s10 + 1;
  if (tri % 2 == 0) return {s00, s01, s10};
  return {s01, s11, s10};
}

// Shape-space position of sample index s.
template <class T> inline Vec3<T> heightFieldVertex(const HeightFieldGeometry<T>& g, std::uint32_t s) {
  const HeightField<T>& hf = *g.heightField;
  const std::uint32_t r = s / hf.columns, c = s % hf.columns;
  return Vec3<T>(T(r) * g.rowScale, hf.heights[s] * g.heightScale, T(c) * g.columnScale);
}

}  // namespace gq::detail
