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
#include <functional>
#include <memory>

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

namespace detail {
class BatchScratchAccess;
}

// Scratch memory kept between batch calls by their caller: a mesh ray batch cast in coherent order (below) that is
// given one reuses the arrays an earlier call grew instead of allocating fresh ones and faulting them in (72-88
// bytes a ray of a block in double, 40-56 in float, and up to 16 more for each further worker: see
// BatchSettings::coherentRayOrder). A caller casting batch after batch keeps one; one batch call at a time may use
// it. The memory is held until release() or destruction.
class BatchScratch {
 public:
  BatchScratch() noexcept;
  ~BatchScratch();
  BatchScratch(const BatchScratch&) = delete;
  BatchScratch& operator=(const BatchScratch&) = delete;
  std::size_t bytes() const noexcept;  // held now
  void release() noexcept;

 private:
  friend class detail::BatchScratchAccess;
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

struct BatchSettings {
  // 0: every hardware thread; 1: the calling thread only (no thread is created); more than the hardware's threads
  // runs the hardware's count.
  std::uint32_t threads = 0;
  std::size_t grain = 64;     // items per task (at least 1)
  // Ray batches against a triangle mesh of at least 32,768 rays cast their rays in a coherent order: in blocks of up
  // to 1,048,576 input rays, each sorted by where its rays pass the mesh's bounds and by their direction, so
  // neighbouring rays walk the same nodes while they are in cache; the workers share each block (grain does not
  // apply to them). Each ray's answer and Status are the same in either order; false keeps the input order (rays that
  // are already coherent). Memory: 72 bytes (double; 40 in float) a ray of the largest block and, for each worker,
  // 16 bytes a ray of that block's largest bucket, each array in whole 2 MB pages: for 1M rays on one worker about
  // 76 MB (double) when they spread over the buckets, at most 88 MB (56 MB in float) when they all fall in one (16 MB
  // more for each further worker); freed on return unless `scratch` keeps it.
  bool coherentRayOrder = true;
  BatchScratch* scratch = nullptr;  // memory kept between calls (BatchScratch); nullptr: each call allocates its own
};

// ---- rays ---------------------------------------------------------------------------------------------------------

// Ray i starts at origins[i] along unitDirs[i]; every ray shares maxDist and hitFlags.
template <class T> struct RayBatch {
  StridedArray<Vec3<T>> origins;
  StridedArray<Vec3<T>> unitDirs;
  T maxDist = T(0);
  HitFlags hitFlags = kDefaultHitFlags;
  // true: unitDirs[i] may have any length; ray i runs along unitDirs[i] / sqrt(x*x + y*y + z*z) (summed in that
  // order, divided per coordinate: numpy's `d / np.linalg.norm(d, axis=1)[:, None]`, bit for bit). A zero-length
  // direction fails its item with InvalidArgument; a NaN or infinite one fails as the single raycast does. The sum
  // of squares is taken in T: a length whose square overflows or underflows T (float: above ~1.8e19 or below
  // ~1e-19) does not give a unit direction, and the item fails as a non-unit direction.
  bool normalizeDirections = false;
};

// Each ray's closest hit written field by field into caller arrays (numpy-style columns, entry i for ray i); a null
// pointer skips its field. A miss writes hit 0, distance +inf, position and normal 0, faceIndex -1. A failed ray
// leaves its entries untouched.
template <class T> struct RayHitColumns {
  std::uint8_t* hit = nullptr;         // 1: hit, 0: miss
  T* distance = nullptr;
  T* position = nullptr;               // 3 T per ray (x, y, z)
  T* normal = nullptr;                 // 3 T per ray
  std::int64_t* faceIndex = nullptr;   // -1: a miss, or a hit on a shape without faces
};

// Closest hit of each ray against one shape: raycast(..., maxHits 1). hasHit[i] says whether hits[i] was written.
template <class T>
Status raycastBatch(const RayBatch<T>& rays, const Shape<T>& shape, const Transform<T>& pose, RaycastHit<T>* hits,
                    std::uint8_t* hasHit, Status* statuses = nullptr, const BatchSettings& settings = {}) noexcept;
template <class T>
Status raycastBatch(const RayBatch<T>& rays, const Geometry<T>& geometry, const Transform<T>& pose, RaycastHit<T>* hits,
                    std::uint8_t* hasHit, Status* statuses = nullptr, const BatchSettings& settings = {}) noexcept;

// The same closest hits written into columns (RayHitColumns): no RaycastHit array in between.
template <class T>
Status raycastBatch(const RayBatch<T>& rays, const Shape<T>& shape, const Transform<T>& pose,
                    const RayHitColumns<T>& out, Status* statuses = nullptr,
                    const BatchSettings& settings = {}) noexcept;

// Closest hit of each ray in a scene: Scene::raycastClosest per ray (a Warning of one ray is its Status).
template <class T>
Status raycastBatch(const RayBatch<T>& rays, const Scene<T>& scene, SceneRaycastHit<T>* hits, std::uint8_t* hasHit,
                    Status* statuses = nullptr, const BatchSettings& settings = {},
                    const SceneFilter& filter = {}) noexcept;

// Where raycastAllBatch writes: counts[i] receives ray i's hit count. With offsets == nullptr only the counts are
// written (hits is not read); with offsets, ray i's hits go to hits[offsets[i]] ... hits[offsets[i] + count - 1]
// (offsets = exclusive prefix sums of the counts of a first call, `hits` sized to their sum).
template <class T> struct SceneHitsOutput {
  std::uint32_t* counts = nullptr;
  const std::uint64_t* offsets = nullptr;
  SceneRaycastHit<T>* hits = nullptr;
};

// Up to maxHitsPerRay hits of each ray in a scene (Scene::raycastAll), sorted per ray: count, then fill.
template <class T>
Status raycastAllBatch(const RayBatch<T>& rays, const Scene<T>& scene, std::uint32_t maxHitsPerRay,
                       const SceneHitsOutput<T>& out, Status* statuses = nullptr, const BatchSettings& settings = {},
                       const SceneFilter& filter = {}) noexcept;

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
                        StridedArray<Transform<T>> poses1, PenetrationResult<T>* results, Status* statuses = nullptr,
                        const BatchSettings& settings = {}) noexcept;

// ---- points -----------------------------------------------------------------------------------------------------

// pointDistance(points[i], shape, pose) per item.
template <class T>
Status pointDistanceBatch(StridedArray<Vec3<T>> points, const Shape<T>& shape, const Transform<T>& pose,
                          PointDistanceResult<T>* results, Status* statuses = nullptr,
                          const BatchSettings& settings = {}) noexcept;

// ---- any per-item work ------------------------------------------------------------------------------------------

// How many workers a batch with these settings runs at most: the `slot` numbers forEachBatchItem hands out are below
// it (size per-worker scratch by it).
std::uint32_t batchSlots(const BatchSettings& settings) noexcept;

// Runs item(i, slot) for every i in [0, count) on the batches' pool, as the batches above do: `slot` (below
// batchSlots(settings)) names the worker, and no two items run at once in one slot, so per-worker state needs no
// lock. item returns false when item i failed (an exception counts as a failure). Ok, or a Warning whose index is
// how many items failed. With items that write only their own outputs, any thread count gives the same bytes.
Status forEachBatchItem(std::size_t count, const BatchSettings& settings,
                        const std::function<bool(std::size_t item, std::uint32_t slot)>& item) noexcept;

}  // namespace gq
