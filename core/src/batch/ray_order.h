#pragma once
// A coherent order for the rays of a batch against one mesh: rays that enter the mesh's box near each other in
// nearly the same direction walk the same nodes and triangles, so cast one after another they find them in cache.
// The order changes only when each ray is cast, never its answer.
#include <cstddef>
#include <cstdint>

#include "gq/batch.h"
#include "gq/math.h"

namespace gq::detail {

// Settings of the reordering (counts of rays).
struct RayOrderSettings {
  // Batches smaller than this keep the input order: their rays are too sparse for neighbours in key order to share
  // nodes, and the keys, sorts and copies would be lost.
  std::size_t minRays = 32768;
  // Rays are ordered in consecutive blocks of at most this many (the block's scratch, shared by the workers: 72 bytes
  // a ray in double, 40 in float; each array at least one 2 MB page). The whole block is cast in key order: the larger
  // the block, the nearer neighbours in key order are (docs/performance.md: one 1M block against 128k blocks).
  std::size_t blockRays = std::size_t(1) << 20;
  // A block's rays are first copied into buckets of this many top bits of the key (a histogram and 1,024 write
  // streams stay in L1 and L2), then each bucket is sorted by the next sortedBits - coarseBits bits and cast from its
  // copies.
  int coarseBits = 10;
  // The key's top bits the order sorts by; rays differing only in the others keep their input order. Sorting the
  // 9 lowest bits too changed no cache miss of the casts (callgrind, 1M bunny rays) and cost a second radix pass of
  // each bucket (20 instructions a ray).
  int sortedBits = 21;
};

// A 30-bit key of a ray against a target box: the Morton interleave of the point where the ray enters the box
// (its origin when inside), 6 bits per axis of the box, and of the ray's direction in octahedral coordinates, 6 bits
// per coordinate. The direction need not be unit. Any input is keyed without fault (a NaN coordinate counts as the
// box's low side).
template <class T> class RayOrderKey {
 public:
  explicit RayOrderKey(const Bounds3<T>& target);
  // Writes the key and returns true when the ray enters the box within maxDist (measured along the unit direction);
  // else writes 0 and returns false: such rays stop at the root and gain nothing from the order.
  bool operator()(const Vec3<T>& origin, const Vec3<T>& dir, T maxDist, std::uint32_t& key) const;
  // The key for any maxDist (0 for a ray that misses the box).
  std::uint32_t operator()(const Vec3<T>& origin, const Vec3<T>& dir) const;
  // Keys the rays of two strided arrays of the same count: keys[i] = ray i's key, or kMisses for a ray not entering
  // the box within maxDist. With AVX2 (x86-64 builds with GQ_SSE42, on CPUs that have it) 8 rays at a time in float:
  // those keys and entry decisions may differ from operator()'s near cell and box borders (they only choose an
  // order), and any input is keyed without fault.
  void keyRays(const StridedArray<Vec3<T>>& origins, const StridedArray<Vec3<T>>& dirs, T maxDist,
               std::uint32_t* keys) const;
  static constexpr std::uint32_t kMisses = 1u << 31;

 private:
  // keyRays for rays [first, count) by operator().
  void keyRaysScalar(const StridedArray<Vec3<T>>& origins, const StridedArray<Vec3<T>>& dirs, std::size_t first,
                     T maxDist, std::uint32_t* keys) const;
  Vec3<T> lo_, hi_, invExtent_;
};

// keyRays uses the scalar operator() on any CPU when true (so tests can compare both key paths on one machine). Not
// for use while a batch runs.
void setRayOrderKeysScalarOnly(bool scalarOnly);
// Whether keyRays keys 8 rays at a time on this build and CPU (when not set scalar-only).
bool rayOrderKeysHaveWidePath();

// For tests of the batches' recovery: the pool run numbered `run` from now on (counting the runs that use the pool,
// from 0) fails with std::bad_alloc in its ranges past the middle, as a pool running out of memory midway would; -1
// (the default) fails none. Not for use while a batch runs.
void failBatchPoolRun(int run);

// Sorts items of the form (key << 32 | payload), key below 2^keyBits (keyBits at most 32), by key: LSD radix sort
// in as few passes of at most 11 bits as the key needs (a pass whose digit is the same for every item is skipped);
// equal keys keep their order. n is below 2^32; scratch holds n items. Returns where the sorted items are (items or
// scratch).
std::uint64_t* sortByKey(std::uint64_t* items, std::uint64_t* scratch, std::size_t n, int keyBits = 30);

}  // namespace gq::detail
