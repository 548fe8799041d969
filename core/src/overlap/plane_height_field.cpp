// Plane vs heightfield (distance/plane_surface.h): the samples of the cells that are not holes, block by block. The
// cooked per-block height ranges (HeightField::blockMin/blockMax, blocks of kBlock x kBlock cells) bound the height
// over the plane of every sample of a block from below; a block is skipped when that bound cannot reach the answer
// (above 0 for overlap, not below the best so far for distance), else its cells are visited.
#include <algorithm>

#include "distance/plane_surface.h"
#include "gq/cooking.h"

namespace gq::detail {
namespace {

// height(r, h, c) = ((k + m.x (r rowScale)) + m.y (h heightScale)) + m.z (c columnScale): the same expression for a
// sample and, with each term at its smaller end, for a block's lower bound.
template <class T> struct HeightFieldHeights {
  Vec3<T> m;
  T k, rowScale, heightScale, columnScale;
  T rowTerm(std::uint32_t r) const { return m.x() * (T(r) * rowScale); }
  T heightTerm(T h) const { return m.y() * (h * heightScale); }
  T columnTerm(std::uint32_t c) const { return m.z() * (T(c) * columnScale); }
  T at(std::uint32_t r, T h, std::uint32_t c) const { return ((k + rowTerm(r)) + heightTerm(h)) + columnTerm(c); }
  T lowerBound(std::uint32_t r0, std::uint32_t r1, T h0, T h1, std::uint32_t c0, std::uint32_t c1) const {
    return ((k + std::min(rowTerm(r0), rowTerm(r1))) + std::min(heightTerm(h0), heightTerm(h1))) +
           std::min(columnTerm(c0), columnTerm(c1));
  }
};

}  // namespace

template <class T>
LowestVertex<T> lowestVertexHeightField(const HeightFieldGeometry<T>& g, const Transform<T>& hfPose,
                                        const Transform<T>& planePose, T stopAtOrBelow) {
  const HeightField<T>& hf = *g.heightField;
  constexpr std::uint32_t kB = HeightField<T>::kBlock;
  const Vec3<T> n = planePose.rotate(Vec3<T>::UnitX());
  const HeightFieldHeights<T> f{hfPose.rotateInv(n), n.dot(hfPose.p - planePose.p), g.rowScale, g.heightScale,
                                g.columnScale};
  LowestVertex<T> lowest;
  std::uint32_t bestRow = 0, bestColumn = 0;
  for (std::uint32_t br = 0; br < hf.blockRows; ++br) {
    const std::uint32_t r0 = br * kB, r1 = std::min(r0 + kB, hf.rows - 1);  // samples; cells [r0, r1)
    for (std::uint32_t bc = 0; bc < hf.blockColumns; ++bc) {
      const std::uint32_t c0 = bc * kB, c1 = std::min(c0 + kB, hf.columns - 1);
      const std::size_t block = std::size_t(br) * hf.blockColumns + bc;
      if (!(f.lowerBound(r0, r1, hf.blockMin[block], hf.blockMax[block], c0, c1) < lowest.height)) continue;
      for (std::uint32_t r = r0; r < r1; ++r)
        for (std::uint32_t c = c0; c < c1; ++c) {
          if (hf.isHole(r, c)) continue;
          for (std::uint32_t corner = 0; corner < 4; ++corner) {
            const std::uint32_t sr = r + (corner >> 1), sc = c + (corner & 1);
            const T h = f.at(sr, hf.height(sr, sc), sc);
            if (h < lowest.height) {
              lowest.height = h;
              bestRow = sr;
              bestColumn = sc;
            }
          }
          if (lowest.height <= stopAtOrBelow) goto found;
        }
    }
  }
found:
  if (lowest.height < std::numeric_limits<T>::infinity())
    lowest.point = hfPose.transform(Vec3<T>(T(bestRow) * g.rowScale, hf.height(bestRow, bestColumn) * g.heightScale,
                                            T(bestColumn) * g.columnScale));
  return lowest;
}

template <class T>
Status overlapPlaneHeightField(const Geometry<T>&, const Transform<T>& p0, const Geometry<T>& g1,
                               const Transform<T>& p1, bool& overlapping) {
  overlapping = lowestVertexHeightField(g1.template get<HeightFieldGeometry<T>>(), p1, p0, T(0)).height <= T(0);
  return Status();
}

template LowestVertex<float> lowestVertexHeightField<float>(const HeightFieldGeometry<float>&,
                                                            const Transform<float>&, const Transform<float>&, float);
template LowestVertex<double> lowestVertexHeightField<double>(const HeightFieldGeometry<double>&,
                                                              const Transform<double>&, const Transform<double>&,
                                                              double);
template Status overlapPlaneHeightField<float>(const Geometry<float>&, const Transform<float>&,
                                               const Geometry<float>&, const Transform<float>&, bool&);
template Status overlapPlaneHeightField<double>(const Geometry<double>&, const Transform<double>&,
                                                const Geometry<double>&, const Transform<double>&, bool&);

}  // namespace gq::detail
