// Heightfield cooking: validates the sample grid and precomputes the height range of the whole field and of every
// block of HeightField::kBlock x kBlock cells (the raycast walks blocks first and skips those the ray passes above
// or below).
#include <algorithm>
#include <cmath>
#include <string>

#include "common/validate.h"
#include "gq/cooking.h"
#include "gq/tolerances.h"

namespace gq {
namespace {

template <class T> Status validateHeightFieldDesc(const HeightFieldDesc<T>& desc) {
  if (desc.rows < 2 || desc.columns < 2)
    return Status::owned(StatusCode::InvalidArgument, "heightfield needs at least 2 rows and 2 columns of samples (got " +
                           std::to_string(desc.rows) + " x " + std::to_string(desc.columns) + ")");
  const std::uint64_t samples = std::uint64_t(desc.rows) * desc.columns;
  if (samples > tol::kMaxHeightFieldSamples)
    return Status::owned(StatusCode::InvalidArgument, "heightfield has " + std::to_string(samples) + " samples, more than the limit of " +
                           std::to_string(tol::kMaxHeightFieldSamples));
  if (desc.heights.size() != samples)
    return Status::owned(StatusCode::InvalidArgument, "heightfield heights has " + std::to_string(desc.heights.size()) +
                           " entries, expected rows * columns = " + std::to_string(samples));
  for (std::size_t i = 0; i < desc.heights.size(); ++i)
    if (!std::isfinite(desc.heights[i]))
      return Status::owned(StatusCode::InvalidArgument, "heightfield height " + std::to_string(i) + " is not finite");
  const std::uint64_t cells = std::uint64_t(desc.rows - 1) * (desc.columns - 1);
  for (std::uint32_t h : desc.holes)
    if (h >= cells)
      return Status::owned(StatusCode::InvalidArgument, "heightfield hole index " + std::to_string(h) + " is out of range (" +
                             std::to_string(cells) + " cells)");
  return {};
}

// Number of blocks needed to cover `cells` cells.
std::uint32_t blockCount(std::uint32_t cells) { return (cells + HeightField<double>::kBlock - 1) / HeightField<double>::kBlock; }

// Height range of the samples touching each block's cells: block (br, bc) covers sample rows
// [br*B, min(br*B+B, rows-1)] and likewise columns (the far corner samples belong to the last cells).
template <class T> void computeBlockRanges(HeightField<T>& hf) {
  constexpr std::uint32_t kB = HeightField<T>::kBlock;
  hf.blockRows = blockCount(hf.rows - 1);
  hf.blockColumns = blockCount(hf.columns - 1);
  hf.blockMin.assign(std::size_t(hf.blockRows) * hf.blockColumns, T(0));
  hf.blockMax.assign(hf.blockMin.size(), T(0));
  for (std::uint32_t br = 0; br < hf.blockRows; ++br) {
    const std::uint32_t r1 = std::min(br * kB + kB, hf.rows - 1);
    for (std::uint32_t bc = 0; bc < hf.blockColumns; ++bc) {
      const std::uint32_t c1 = std::min(bc * kB + kB, hf.columns - 1);
      T lo = hf.height(br * kB, bc * kB), hi = lo;
      for (std::uint32_t r = br * kB; r <= r1; ++r)
        for (std::uint32_t c = bc * kB; c <= c1; ++c) {
          lo = std::min(lo, hf.height(r, c));
          hi = std::max(hi, hf.height(r, c));
        }
      hf.blockMin[std::size_t(br) * hf.blockColumns + bc] = lo;
      hf.blockMax[std::size_t(br) * hf.blockColumns + bc] = hi;
    }
  }
}

}  // namespace

template <class T>
Status cookHeightField(const HeightFieldDesc<T>& desc, std::shared_ptr<const HeightField<T>>& out) {
  return detail::guarded([&]() -> Status {
    if (Status s = validateHeightFieldDesc(desc); !s.ok()) return s;
    auto hf = std::make_shared<HeightField<T>>();
    hf->rows = desc.rows;
    hf->columns = desc.columns;
    hf->heights = desc.heights;
    hf->hole.assign(std::size_t(desc.rows - 1) * (desc.columns - 1), 0);
    for (std::uint32_t h : desc.holes) hf->hole[h] = 1;
    const auto range = std::minmax_element(hf->heights.begin(), hf->heights.end());
    hf->minHeight = *range.first;
    hf->maxHeight = *range.second;
    computeBlockRanges(*hf);
    out = std::move(hf);
    return Status();
  });
}

template Status cookHeightField<float>(const HeightFieldDesc<float>&, std::shared_ptr<const HeightField<float>>&);
template Status cookHeightField<double>(const HeightFieldDesc<double>&, std::shared_ptr<const HeightField<double>>&);

}  // namespace gq
