// gq/batch.h: each batch checks its arrays once, then runs the single query per item on oneTBB's pool (or the plain
// loop for one thread). Items write only their own output entries, so any schedule gives the same bytes.
#include "gq/batch.h"

#include <atomic>
#include <cstdint>
#include <exception>
#include <new>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/partitioner.h>
#include <tbb/task_arena.h>

namespace gq {

namespace {

template <class E> Status checkArray(const StridedArray<E>& a) {
  if (a.count == 0) return {};
  if (a.data == nullptr) return Status::invalid("a batch input array is null but its count is not 0");
  if (a.stride < sizeof(E)) return Status::invalid("a batch input stride is smaller than the element size");
  if (reinterpret_cast<std::uintptr_t>(a.data) % alignof(E) != 0 || a.stride % alignof(E) != 0) {
    return Status::invalid("a batch input array or stride is not aligned for its element type");
  }
  return {};
}

template <class E0, class E1> Status checkArrays(const StridedArray<E0>& a, const StridedArray<E1>& b) {
  if (Status s = checkArray(a); !s.ok()) return s;
  if (Status s = checkArray(b); !s.ok()) return s;
  if (a.count != b.count) return Status::invalid("batch input arrays have different counts");
  return {};
}

// Runs item(i) for i in [0, n); item returns true when item i succeeded. Returns the number of failed items.
template <class Item> std::size_t runItems(std::size_t n, const BatchSettings& settings, const Item& item) {
  const std::size_t grain = settings.grain == 0 ? 1 : settings.grain;
  auto serial = [&](std::size_t begin, std::size_t end) {
    std::size_t failed = 0;
    for (std::size_t i = begin; i < end; ++i) failed += item(i) ? 0 : 1;
    return failed;
  };
  if (settings.threads == 1 || n <= grain) return serial(0, n);
  std::atomic<std::size_t> failed{0};
  try {
    tbb::task_arena arena(settings.threads == 0 ? int(tbb::task_arena::automatic) : int(settings.threads));
    arena.execute([&] {
      tbb::parallel_for(
          tbb::blocked_range<std::size_t>(0, n, grain),
          [&](const tbb::blocked_range<std::size_t>& r) {
            const std::size_t f = serial(r.begin(), r.end());
            if (f) failed.fetch_add(f, std::memory_order_relaxed);
          },
          tbb::simple_partitioner());
    });
  } catch (...) {
    // The pool could not start (out of memory or threads): the loop on this thread gives the same answers. Items
    // are pure functions of their input, so recomputing those already done rewrites the same bytes.
    return serial(0, n);
  }
  return failed.load();
}

Status batchResult(std::size_t failed) {
  if (failed == 0) return {};
  return Status::warning("some batch items failed: their per-item Status says why; index = how many")
      .withIndex(failed > 0xffffffffu ? 0xffffffffu : std::uint32_t(failed));
}

Status emptyShape() { return Status::invalid("the shape is empty (not made by Shape::make)"); }
Status nullOutput() { return Status::invalid("a batch output array is null"); }

// Stores the item's Status when asked to; true when it succeeded.
inline bool record(Status* statuses, std::size_t i, Status&& s) {
  const bool ok = s.ok();
  if (statuses) statuses[i] = std::move(s);
  return ok;
}

}  // namespace

template <class T>
Status raycastBatch(StridedArray<Vec3<T>> origins, StridedArray<Vec3<T>> unitDirs, T maxDist, const Shape<T>& shape,
                    const Transform<T>& pose, HitFlags hitFlags, RaycastHit<T>* hits, std::uint8_t* hasHit,
                    Status* statuses, const BatchSettings& settings) noexcept {
  if (Status s = checkArrays(origins, unitDirs); !s.ok()) return s;
  if (shape.empty()) return emptyShape();
  const std::size_t n = origins.count;
  if (n > 0 && (hits == nullptr || hasHit == nullptr)) return nullOutput();
  return batchResult(runItems(n, settings, [&](std::size_t i) {
    RaycastHit<T> h;
    std::uint32_t count = 0;
    Status s = raycast(origins[i], unitDirs[i], shape, pose, maxDist, hitFlags, 1u, &h, count);
    if (s.ok()) {
      hasHit[i] = count > 0 ? 1 : 0;
      if (count > 0) hits[i] = h;
    }
    return record(statuses, i, std::move(s));
  }));
}

template <class T>
Status raycastBatch(StridedArray<Vec3<T>> origins, StridedArray<Vec3<T>> unitDirs, T maxDist,
                    const Geometry<T>& geometry, const Transform<T>& pose, HitFlags hitFlags, RaycastHit<T>* hits,
                    std::uint8_t* hasHit, Status* statuses, const BatchSettings& settings) noexcept {
  Shape<T> shape;
  if (Status s = Shape<T>::make(geometry, shape); !s.ok()) return s;
  return raycastBatch(origins, unitDirs, maxDist, shape, pose, hitFlags, hits, hasHit, statuses, settings);
}

template <class T>
Status raycastBatch(StridedArray<Vec3<T>> origins, StridedArray<Vec3<T>> unitDirs, T maxDist, const Scene<T>& scene,
                    HitFlags hitFlags, SceneRaycastHit<T>* hits, std::uint8_t* hasHit, Status* statuses,
                    const BatchSettings& settings, const SceneFilter& filter) noexcept {
  if (Status s = checkArrays(origins, unitDirs); !s.ok()) return s;
  const std::size_t n = origins.count;
  if (n > 0 && (hits == nullptr || hasHit == nullptr)) return nullOutput();
  return batchResult(runItems(n, settings, [&](std::size_t i) {
    SceneRaycastHit<T> h;
    bool has = false;
    Status s = scene.raycastClosest(origins[i], unitDirs[i], maxDist, h, has, hitFlags, filter);
    if (s.ok()) {
      hasHit[i] = has ? 1 : 0;
      if (has) hits[i] = h;
    }
    return record(statuses, i, std::move(s));
  }));
}

template <class T>
Status raycastAllBatch(StridedArray<Vec3<T>> origins, StridedArray<Vec3<T>> unitDirs, T maxDist,
                       const Scene<T>& scene, HitFlags hitFlags, std::uint32_t maxHitsPerRay, std::uint32_t* counts,
                       const std::uint64_t* offsets, SceneRaycastHit<T>* hits, Status* statuses,
                       const BatchSettings& settings, const SceneFilter& filter) noexcept {
  if (Status s = checkArrays(origins, unitDirs); !s.ok()) return s;
  if (maxHitsPerRay == 0) return Status::invalid("maxHitsPerRay is 0");
  const std::size_t n = origins.count;
  if (n > 0 && counts == nullptr) return nullOutput();
  if (n > 0 && offsets != nullptr && hits == nullptr) return nullOutput();
  return batchResult(runItems(n, settings, [&](std::size_t i) {
    // The hits go straight to the caller's array in the fill pass; the count pass uses a small local buffer.
    SceneRaycastHit<T> local[8];
    SceneRaycastHit<T>* out = offsets ? hits + offsets[i] : local;
    std::uint32_t count = 0;
    Status s;
    if (offsets == nullptr && maxHitsPerRay > 8) {
      try {
        std::vector<SceneRaycastHit<T>> buffer(maxHitsPerRay);
        s = scene.raycastAll(origins[i], unitDirs[i], maxDist, hitFlags, maxHitsPerRay, buffer.data(), count, filter);
      } catch (const std::bad_alloc&) {
        s = Status::internal("out of memory");
      }
    } else {
      s = scene.raycastAll(origins[i], unitDirs[i], maxDist, hitFlags, maxHitsPerRay, out, count, filter);
    }
    if (s.ok()) counts[i] = count;
    return record(statuses, i, std::move(s));
  }));
}

template <class T>
Status overlapBatch(const Shape<T>& shape0, StridedArray<Transform<T>> poses0, const Shape<T>& shape1,
                    StridedArray<Transform<T>> poses1, std::uint8_t* overlapping, Status* statuses,
                    const BatchSettings& settings) noexcept {
  if (Status s = checkArrays(poses0, poses1); !s.ok()) return s;
  if (shape0.empty() || shape1.empty()) return emptyShape();
  const std::size_t n = poses0.count;
  if (n > 0 && overlapping == nullptr) return nullOutput();
  return batchResult(runItems(n, settings, [&](std::size_t i) {
    bool hit = false;
    Status s = overlap(shape0, poses0[i], shape1, poses1[i], hit);
    if (s.ok()) overlapping[i] = hit ? 1 : 0;
    return record(statuses, i, std::move(s));
  }));
}

template <class T>
Status distanceBatch(const Shape<T>& shape0, StridedArray<Transform<T>> poses0, const Shape<T>& shape1,
                     StridedArray<Transform<T>> poses1, DistanceResult<T>* results, Status* statuses,
                     const BatchSettings& settings) noexcept {
  if (Status s = checkArrays(poses0, poses1); !s.ok()) return s;
  if (shape0.empty() || shape1.empty()) return emptyShape();
  const std::size_t n = poses0.count;
  if (n > 0 && results == nullptr) return nullOutput();
  return batchResult(runItems(n, settings, [&](std::size_t i) {
    return record(statuses, i, distance(results[i], shape0, poses0[i], shape1, poses1[i]));
  }));
}

template <class T>
Status penetrationBatch(const Shape<T>& shape0, StridedArray<Transform<T>> poses0, const Shape<T>& shape1,
                        StridedArray<Transform<T>> poses1, PenetrationResult<T>* results, Status* statuses,
                        const BatchSettings& settings) noexcept {
  if (Status s = checkArrays(poses0, poses1); !s.ok()) return s;
  if (shape0.empty() || shape1.empty()) return emptyShape();
  const std::size_t n = poses0.count;
  if (n > 0 && results == nullptr) return nullOutput();
  return batchResult(runItems(n, settings, [&](std::size_t i) {
    return record(statuses, i, computePenetration(results[i], shape0, poses0[i], shape1, poses1[i]));
  }));
}

template <class T>
Status pointDistanceBatch(StridedArray<Vec3<T>> points, const Shape<T>& shape, const Transform<T>& pose,
                          PointDistanceResult<T>* results, Status* statuses, const BatchSettings& settings) noexcept {
  if (Status s = checkArray(points); !s.ok()) return s;
  if (shape.empty()) return emptyShape();
  const std::size_t n = points.count;
  if (n > 0 && results == nullptr) return nullOutput();
  return batchResult(runItems(n, settings, [&](std::size_t i) {
    return record(statuses, i, pointDistance(points[i], shape, pose, results[i]));
  }));
}

#define GQ_INSTANTIATE_BATCH(T)                                                                                      \
  template Status raycastBatch<T>(StridedArray<Vec3<T>>, StridedArray<Vec3<T>>, T, const Shape<T>&,                  \
                                  const Transform<T>&, HitFlags, RaycastHit<T>*, std::uint8_t*, Status*,             \
                                  const BatchSettings&) noexcept;                                                    \
  template Status raycastBatch<T>(StridedArray<Vec3<T>>, StridedArray<Vec3<T>>, T, const Geometry<T>&,               \
                                  const Transform<T>&, HitFlags, RaycastHit<T>*, std::uint8_t*, Status*,             \
                                  const BatchSettings&) noexcept;                                                    \
  template Status raycastBatch<T>(StridedArray<Vec3<T>>, StridedArray<Vec3<T>>, T, const Scene<T>&, HitFlags,        \
                                  SceneRaycastHit<T>*, std::uint8_t*, Status*, const BatchSettings&,                 \
                                  const SceneFilter&) noexcept;                                                      \
  template Status raycastAllBatch<T>(StridedArray<Vec3<T>>, StridedArray<Vec3<T>>, T, const Scene<T>&, HitFlags,     \
                                     std::uint32_t, std::uint32_t*, const std::uint64_t*, SceneRaycastHit<T>*,       \
                                     Status*, const BatchSettings&, const SceneFilter&) noexcept;                    \
  template Status overlapBatch<T>(const Shape<T>&, StridedArray<Transform<T>>, const Shape<T>&,                      \
                                  StridedArray<Transform<T>>, std::uint8_t*, Status*, const BatchSettings&) noexcept; \
  template Status distanceBatch<T>(const Shape<T>&, StridedArray<Transform<T>>, const Shape<T>&,                     \
                                   StridedArray<Transform<T>>, DistanceResult<T>*, Status*,                          \
                                   const BatchSettings&) noexcept;                                                   \
  template Status penetrationBatch<T>(const Shape<T>&, StridedArray<Transform<T>>, const Shape<T>&,                  \
                                      StridedArray<Transform<T>>, PenetrationResult<T>*, Status*,                    \
                                      const BatchSettings&) noexcept;                                                \
  template Status pointDistanceBatch<T>(StridedArray<Vec3<T>>, const Shape<T>&, const Transform<T>&,                 \
                                        PointDistanceResult<T>*, Status*, const BatchSettings&) noexcept;

GQ_INSTANTIATE_BATCH(float)
GQ_INSTANTIATE_BATCH(double)

}  // namespace gq
