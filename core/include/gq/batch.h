#pragma once
// Batches: one query over many inputs, in parallel, answering exactly what the loop of single queries answers.
//
// Inputs are strided arrays (StridedArray: a pointer, a count and a byte stride), so a numpy array or a field of a
// std::vector of structs passes without a copy. Outputs are plain arrays of `count` entries, one per item, plus an
// optional per-item Status array: an item with bad input (a NaN origin, a non-unit direction) gets its Status and
// leaves its output entry untouched; every other item is answered. A variable-length output (all hits of each ray)
// is asked twice: once for the count of each item, then, with the offsets the caller derives from the counts, to
// fill one array.
//
// Determinism: item i's output is bitwise the single query's answer for item i, whatever the thread count or grain:
// items are independent, each is computed by one thread with the single query's code, and nothing is reduced across
// items except the number of failed items.
//
// Threads: items run on oneTBB's thread pool (parallel_for in a task_arena of BatchSettings::threads). threads == 1
// runs the plain loop on the calling thread and creates no thread; 0 uses every hardware thread. The geometry,
// shapes and scene are shared read-only by the workers (their cooked data is immutable); nothing global is mutable.
//
// Return value: a batch-level Status. InvalidArgument for bad arrays (null data with a non-zero count, a stride
// smaller than the element or misaligned for it, counts that differ, a null output) or bad shared input (an empty
// shape, an invalid geometry): nothing is written. Otherwise Ok when every item succeeded, or a Warning whose
// index() is the number of items that failed (their Status says why).
#include <cstddef>
#include <cstdint>

#include "gq/geometry.h"
#include "gq/hit.h"
#include "gq/math.h"
#include "gq/query.h"
#include "gq/scene.h"
#include "gq/shape.h"
#include "gq/status.h"
#include "gq/transform.h"

namespace gq {

// A read-only strided array of E: element i starts `stride` bytes after element i - 1. The bytes must hold E's
// layout: Vec3<T> is 3 consecutive T (x, y, z); Transform<T> is the quaternion (x, y, z, w) then the position.
template <class E> struct StridedArray {
  const void* data = nullptr;
  std::size_t count = 0;
  std::size_t stride = sizeof(E);  // bytes

  StridedArray() = default;
  StridedArray(const E* first, std::size_t n, std::size_t strideBytes = sizeof(E))
      : data(first), count(n), stride(strideBytes) {}
  // From raw memory (a numpy buffer): `first` points at element 0.
  static StridedArray fromBytes(const void* first, std::size_t n, std::size_t strideBytes) {
    StridedArray a;
    a.data = first;
    a.count = n;
    a.stride = strideBytes;
    return a;
  }
  const E& operator[](std::size_t i) const {
    return *reinterpret_cast<const E*>(static_cast<const unsigned char*>(data) + i * stride);
  }
};

struct BatchSettings {
  std::uint32_t threads = 0;  // 0: every hardware thread; 1: the calling thread only (no thread is created)
  std::size_t grain = 64;     // items per task (at least 1)
};

// ---- rays ---------------------------------------------------------------------------------------------------------

// Closest hit of each ray (origins[i], unitDirs[i]) against one shape: raycast(..., maxHits 1). hasHit[i] says whether
// hits[i] was written.
template <class T>
Status raycastBatch(StridedArray<Vec3<T>> origins, StridedArray<Vec3<T>> unitDirs, T maxDist, const Shape<T>& shape,
                    const Transform<T>& pose, HitFlags hitFlags, RaycastHit<T>* hits, std::uint8_t* hasHit,
                    Status* statuses = nullptr, const BatchSettings& settings = {}) noexcept;
template <class T>
Status raycastBatch(StridedArray<Vec3<T>> origins, StridedArray<Vec3<T>> unitDirs, T maxDist,
                    const Geometry<T>& geometry, const Transform<T>& pose, HitFlags hitFlags, RaycastHit<T>* hits,
                    std::uint8_t* hasHit, Status* statuses = nullptr, const BatchSettings& settings = {}) noexcept;

// Closest hit of each ray in a scene: Scene::raycastClosest per ray (a Warning of one ray is its Status).
template <class T>
Status raycastBatch(StridedArray<Vec3<T>> origins, StridedArray<Vec3<T>> unitDirs, T maxDist, const Scene<T>& scene,
                    HitFlags hitFlags, SceneRaycastHit<T>* hits, std::uint8_t* hasHit, Status* statuses = nullptr,
                    const BatchSettings& settings = {}, const SceneFilter& filter = {}) noexcept;

// Up to maxHitsPerRay hits of each ray in a scene (Scene::raycastAll), in two calls:
//  - offsets == nullptr: counts[i] receives ray i's hit count; hits is not read;
//  - offsets != nullptr: ray i's hits are written at hits[offsets[i]] ... hits[offsets[i] + its count - 1]; the
//    caller sizes `hits` (e.g. offsets = exclusive prefix sums of the first call's counts), and counts[i] receives
//    the count again.
template <class T>
Status raycastAllBatch(StridedArray<Vec3<T>> origins, StridedArray<Vec3<T>> unitDirs, T maxDist,
                       const Scene<T>& scene, HitFlags hitFlags, std::uint32_t maxHitsPerRay, std::uint32_t* counts,
                       const std::uint64_t* offsets, SceneRaycastHit<T>* hits, Status* statuses = nullptr,
                       const BatchSettings& settings = {}, const SceneFilter& filter = {}) noexcept;

// ---- pose pairs -------------------------------------------------------------------------------------------------

// shape0 at poses0[i] against shape1 at poses1[i]: overlap(), distance(), computePenetration() per item.
template <class T>
Status overlapBatch(const Shape<T>& shape0, StridedArray<Transform<T>> poses0, const Shape<T>& shape1,
                    StridedArray<Transform<T>> poses1, std::uint8_t* overlapping, Status* statuses = nullptr,
                    const BatchSettings& settings = {}) noexcept;
template <class T>
Status distanceBatch(const Shape<T>& shape0, StridedArray<Transform<T>> poses0, const Shape<T>& shape1,
                     StridedArray<Transform<T>> poses1, DistanceResult<T>* results, Status* statuses = nullptr,
                     const BatchSettings& settings = {}) noexcept;
template <class T>
Status penetrationBatch(const Shape<T>& shape0, StridedArray<Transform<T>> poses0, const Shape<T>& shape1,
                        StridedArray<Transform<T>> poses1, PenetrationResult<T>* results,
                        Status* statuses = nullptr, const BatchSettings& settings = {}) noexcept;

// ---- points -----------------------------------------------------------------------------------------------------

// pointDistance(points[i], shape, pose) per item.
template <class T>
Status pointDistanceBatch(StridedArray<Vec3<T>> points, const Shape<T>& shape, const Transform<T>& pose,
                          PointDistanceResult<T>* results, Status* statuses = nullptr,
                          const BatchSettings& settings = {}) noexcept;

}  // namespace gq
