// gq/batch.h: each batch checks its arrays once, then runs the single query per item on oneTBB's pool (or the plain
// loop for one thread). Items write only their own output entries, so any schedule gives the same bytes.
#include "gq/batch.h"

#include "batch/ray_order.h"
#include "raycast/raycast.h"

#include <tbb/blocked_range.h>
#include <tbb/info.h>
#include <tbb/parallel_for.h>
#include <tbb/partitioner.h>
#include <tbb/task_arena.h>

#if defined(__linux__)
#include <sys/mman.h>
#endif

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <exception>
#include <limits>
#include <memory>
#include <new>
#include <type_traits>
#include <vector>

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

// The arena's concurrency for these settings: oneTBB runs at most the hardware's threads (more would only wait for
// a core, and it warns on stderr).
int arenaThreads(const BatchSettings& settings) {
  const int hardware = tbb::info::default_concurrency();
  return settings.threads == 0 || settings.threads > std::uint32_t(hardware) ? hardware : int(settings.threads);
}

std::atomic<int> gFailingPoolRun{-1};  // detail::failBatchPoolRun: the pool run that fails, or -1
std::atomic<int> gPoolRuns{0};         // pool runs since failBatchPoolRun

// Runs range(begin, end, slot) over [0, n) in ranges of `grain` (the last may be shorter) on the pool, slot <
// arenaThreads(settings) the worker's index in the arena; range returns how many of its items failed, added to
// `failed`. False when the pool failed to run them all (out of memory or threads): some ranges may have run.
template <class Range>
bool tryRunRanges(std::size_t n, std::size_t grain, const BatchSettings& settings, const Range& range,
                  std::size_t& failed) {
  if (grain == 0) grain = 1;
  if (settings.threads == 1 || n <= grain) {
    failed += range(std::size_t(0), n, 0u);
    return true;
  }
  std::atomic<std::size_t> rangesFailed{0};
  const bool failsMidway = gFailingPoolRun.load() >= 0 && gPoolRuns.fetch_add(1) == gFailingPoolRun.load();
  try {
    tbb::task_arena arena(arenaThreads(settings));
    arena.execute([&] {
      tbb::parallel_for(
          tbb::blocked_range<std::size_t>(0, n, grain),
          [&](const tbb::blocked_range<std::size_t>& r) {
            if (failsMidway && r.begin() >= n / 2) throw std::bad_alloc();
            const int index = tbb::this_task_arena::current_thread_index();
            const std::size_t f = range(r.begin(), r.end(), index < 0 ? 0u : std::uint32_t(index));
            if (f) rangesFailed.fetch_add(f, std::memory_order_relaxed);
          },
          tbb::simple_partitioner());
    });
  } catch (...) {
    return false;
  }
  failed += rangesFailed.load();
  return true;
}

// tryRunRanges, and when the pool fails the loop on this thread, which gives the same answers: items are pure
// functions of their input, so recomputing those already done rewrites the same bytes. Returns the number of failed
// items.
template <class Range>
std::size_t runRanges(std::size_t n, std::size_t grain, const BatchSettings& settings, const Range& range) {
  std::size_t failed = 0;
  if (tryRunRanges(n, grain, settings, range, failed)) return failed;
  return range(std::size_t(0), n, 0u);
}

// Runs item(i, slot) for i in [0, n) in ranges of settings.grain; item returns true when item i succeeded. Returns
// the number of failed items.
template <class Item> std::size_t runSlottedItems(std::size_t n, const BatchSettings& settings, const Item& item) {
  return runRanges(n, settings.grain, settings, [&](std::size_t begin, std::size_t end, std::uint32_t slot) {
    std::size_t failed = 0;
    for (std::size_t i = begin; i < end; ++i) failed += item(i, slot) ? 0 : 1;
    return failed;
  });
}

// runSlottedItems for items that keep no per-worker state: item(i).
template <class Item> std::size_t runItems(std::size_t n, const BatchSettings& settings, const Item& item) {
  return runSlottedItems(n, settings, [&](std::size_t i, std::uint32_t) { return item(i); });
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

// Ray i's direction: unitDirs[i], or, when the batch normalizes, unitDirs[i] over its length (numpy's norm and
// division, bit for bit) stored in `scratch`. Null for a zero length.
template <class T> const Vec3<T>* directionOf(const RayBatch<T>& rays, const Vec3<T>& d, Vec3<T>& scratch) {
  if (!rays.normalizeDirections) return &d;
  const T length = std::sqrt(d.x() * d.x() + d.y() * d.y() + d.z() * d.z());
  if (length == T(0)) return nullptr;
  scratch = Vec3<T>(d.x() / length, d.y() / length, d.z() / length);
  return &scratch;
}
template <class T> const Vec3<T>* rayDirection(const RayBatch<T>& rays, std::size_t i, Vec3<T>& scratch) {
  return directionOf(rays, rays.unitDirs[i], scratch);
}

Status zeroLengthDirection() { return Status::invalid("zero-length ray direction (it cannot be normalized)"); }

// A cache-line prefetch (a no-op where the compiler has no builtin).
inline void prefetchRead(const void* p) {
#if defined(__GNUC__)
  __builtin_prefetch(p, 0, 3);
#else
  (void)p;
#endif
}

// Where a batch puts ray i's closest hit: slot(i, local) is where the kernel writes a hit (Local: the storage the
// output needs per ray), store() finishes the entry from the hit written there or elsewhere.
// The caller's RaycastHit array: the kernel writes into it directly.
template <class T> struct HitArrayOut {
  struct Local {};
  RaycastHit<T>* hits;
  std::uint8_t* hasHit;
  RaycastHit<T>* slot(std::size_t i, Local&) const { return hits + i; }
  void store(std::size_t i, std::uint32_t count, const RaycastHit<T>& h) const {
    if (count > 0 && &h != hits + i) hits[i] = h;
    hasHit[i] = count > 0 ? 1 : 0;
  }
  // A mesh hit kept without its position (flags 0: none), and the position: the single raycast's hit field by field.
  void store(std::size_t i, const detail::MeshRayHit<T>& c, const Vec3<T>& position) const {
    const bool hit = c.flags.bits() != 0;
    if (hit) {
      RaycastHit<T>& h = hits[i];
      h.position = position;
      h.normal = c.normal;
      h.distance = c.distance;
      h.flags = c.flags;
      h.faceIndex = c.faceIndex;
      h.u = c.u;
      h.v = c.v;
    }
    hasHit[i] = hit ? 1 : 0;
  }
};

// Columns (RayHitColumns): the kernel writes into a local hit, copied field by field.
template <class T> struct HitColumnsOut {
  using Local = RaycastHit<T>;
  const RayHitColumns<T>& columns;
  RaycastHit<T>* slot(std::size_t, Local& local) const { return &local; }
  void store(std::size_t i, std::uint32_t count, const RaycastHit<T>& h) const {
    write(i, count > 0, h.distance, h.position, h.normal, h.faceIndex);
  }
  void store(std::size_t i, const detail::MeshRayHit<T>& c, const Vec3<T>& position) const {
    const bool hit = c.flags.bits() != 0;  // a miss wrote its flags alone
    write(i, hit, hit ? c.distance : T(0), position, hit ? c.normal : Vec3<T>::Zero(), hit ? c.faceIndex : 0u);
  }
  void write(std::size_t i, bool hit, T distance, const Vec3<T>& position, const Vec3<T>& normal,
             std::uint32_t faceIndex) const {
    if (columns.hit) columns.hit[i] = hit ? 1 : 0;
    if (columns.distance) columns.distance[i] = hit ? distance : std::numeric_limits<T>::infinity();
    for (int k = 0; k < 3; ++k) {
      if (columns.position) columns.position[3 * i + std::size_t(k)] = hit ? position[k] : T(0);
      if (columns.normal) columns.normal[3 * i + std::size_t(k)] = hit ? normal[k] : T(0);
    }
    if (columns.faceIndex)
      columns.faceIndex[i] = hit && faceIndex != kInvalidFaceIndex ? std::int64_t(faceIndex) : std::int64_t(-1);
  }
};

// The rays of a batch against a mesh shape whose pose, maxDist and flags passed the façade's checks: the mesh frame
// and the node test are found once (detail::TriangleMeshRays), each ray takes the façade's own checks and then the
// kernel of the single raycast, so its hit and Status are the single query's bit for bit. A ray failing its checks
// takes the single query, whose Status names the problem. operator()(i) casts ray i; true when it succeeded.
template <class T, class Out> struct MeshRayItems {
  const RayBatch<T>& rays;
  const Shape<T>& shape;
  const Transform<T>& pose;
  const Out& out;
  Status* statuses;
  detail::TriangleMeshRays<T> mesh;

  MeshRayItems(const RayBatch<T>& r, const Shape<T>& s, const Transform<T>& p, const Out& o, Status* st)
      : rays(r), shape(s), pose(p), out(o), statuses(st),
        mesh(s.geometry().template get<TriangleMeshGeometry<T>>(), p) {}

  bool operator()(std::size_t i) const {
    Vec3<T> scratch;
    const Vec3<T>* dir = rayDirection(rays, i, scratch);
    if (dir == nullptr) return record(statuses, i, zeroLengthDirection());
    const Vec3<T>& origin = rays.origins[i];
    std::uint32_t count = 0;
    if (detail::rayIsValid(origin, *dir, pose.p)) {
      typename Out::Local local;
      RaycastHit<T>* slot = out.slot(i, local);
      count = mesh.cast(detail::rayQuery(origin, *dir, rays.maxDist, rays.hitFlags, 1u), slot);  // written on a hit
      out.store(i, count, *slot);
    } else {
      RaycastHit<T> h;
      Status s = raycast(origin, *dir, shape, pose, rays.maxDist, rays.hitFlags, 1u, &h, count);
      if (!s.ok()) return record(statuses, i, std::move(s));
      out.store(i, count, h);
    }
    return record(statuses, i, Status());
  }
};

// A batch's scratch: an array of default-initialized E (for plain data and Eigen vectors no code runs; every entry is
// written before it is read). On Linux its memory is asked to be in huge pages (2 MB): first touched, the scratch of
// a million rays then costs a few dozen page faults instead of ~18,000, and its scattered reads few TLB misses. Each
// array takes whole 2 MB pages.
template <class E> class ScratchArray {
  static_assert(std::is_trivially_destructible_v<E>, "freed without destructors");

 public:
  ScratchArray() = default;
  ScratchArray(const ScratchArray&) = delete;
  ScratchArray& operator=(const ScratchArray&) = delete;
  ~ScratchArray() { std::free(data); }
  // At least n entries (the contents are not kept); false when out of memory.
  bool reserve(std::size_t n) {
    if (n <= size) return true;
    std::free(data);
    data = nullptr;
    size = 0;
    constexpr std::size_t kHugePage = std::size_t(2) << 20;
    if (n > (std::numeric_limits<std::size_t>::max() - kHugePage) / sizeof(E)) return false;
    const std::size_t bytes = (n * sizeof(E) + kHugePage - 1) / kHugePage * kHugePage;
    void* p = std::aligned_alloc(kHugePage, bytes);
    if (p == nullptr) return false;
#if defined(__linux__)
    (void)madvise(p, bytes, MADV_HUGEPAGE);  // advice only: without huge pages the array works the same
#endif
    size = bytes / sizeof(E);
    data = static_cast<E*>(p);
    std::uninitialized_default_construct_n(data, size);  // begins the entries' lifetimes
    return true;
  }
  E* data = nullptr;
  std::size_t size = 0;
};

// The arrays of castBlockInKeyOrder, kept from block to block (their first use costs page faults). The block's, in
// the first worker slot's scratch: per ray of a block its key, then its slot (4 bytes), its place in key order (4
// bytes), and a slot holding its copy, then its hit (one 64-byte cache line in double, 32 bytes in float): 72 bytes a
// ray in double, 40 in float; each worker's: 16 bytes a ray of the block's largest bucket for its sorts.
template <class T> struct KeyOrderScratch {
  struct Ray {  // a ray of the block, copied in coarse key order
    Vec3<T> origin, dir;
    std::uint32_t key;
  };
  // The single raycast's output but its position, which the copy-out computes from the input ray as the raycast does
  // (origin + dir * distance): so a slot fits a cache line (flags 0: no hit; a hit has at least FaceIndex; or
  // kByIndex).
  using Hit = detail::MeshRayHit<T>;
  // A ray's copy until it is cast, then its hit.
  union alignas(sizeof(T) == 8 ? 64 : 32) Slot {
    Slot() {}  // no member alive: each is begun by placement new
    Ray ray;
    Hit hit;
  };
  static constexpr HitFlags kByIndex = HitFlags(std::uint16_t(0xffff));  // a ray that takes the per-index path
  static constexpr std::uint32_t kAnswered = 0xffffffffu;  // a ray answered by the key pass (rank)
  ScratchArray<std::uint64_t> items;  // a bucket's fine keys << 32 | ray in the bucket, and their sort's scratch
  ScratchArray<Slot> slots;
  ScratchArray<std::uint32_t> rank;   // by ray within the block: its key, then its slot, or kAnswered
  ScratchArray<std::uint32_t> order;  // the slots in key order
  std::vector<std::uint32_t> starts;  // where each coarse bucket begins in slots
  // By part of the block (in input order) and bucket: the part's ray count, then where its next ray is copied.
  std::vector<std::uint32_t> next;

  std::size_t bytes() const noexcept {
    return items.size * sizeof(std::uint64_t) + slots.size * sizeof(Slot) +
           (rank.size + order.size) * sizeof(std::uint32_t) +
           (starts.capacity() + next.capacity()) * sizeof(std::uint32_t);
  }
  bool reserve(std::size_t m, std::size_t buckets, std::size_t parts) {
    try {
      if (!slots.reserve(m) || !rank.reserve(m) || !order.reserve(m)) return false;
      starts.resize(buckets + 1);
      next.resize(buckets * parts);
      return true;
    } catch (const std::bad_alloc&) {
      return false;
    }
  }
};

// One KeyOrderScratch per worker slot.
template <class T> using WorkerScratch = std::vector<std::unique_ptr<KeyOrderScratch<T>>>;

}  // namespace

namespace detail {
void failBatchPoolRun(int run) {
  gPoolRuns.store(0);
  gFailingPoolRun.store(run);
}
}  // namespace detail

struct BatchScratch::Impl {
  WorkerScratch<float> f;
  WorkerScratch<double> d;
};

namespace detail {
class BatchScratchAccess {
 public:
  // The workers' scratch of precision T kept by `s` (created on first use; may throw std::bad_alloc).
  template <class T> static WorkerScratch<T>& workers(BatchScratch& s) {
    if (!s.impl_) s.impl_ = std::make_unique<BatchScratch::Impl>();
    if constexpr (std::is_same_v<T, float>) {
      return s.impl_->f;
    } else {
      return s.impl_->d;
    }
  }
};
}  // namespace detail

BatchScratch::BatchScratch() noexcept = default;
BatchScratch::~BatchScratch() = default;

std::size_t BatchScratch::bytes() const noexcept {
  std::size_t total = 0;
  if (impl_) {
    for (const auto& w : impl_->f) total += w->bytes();
    for (const auto& w : impl_->d) total += w->bytes();
  }
  return total;
}

void BatchScratch::release() noexcept { impl_.reset(); }

namespace {

// Rays [begin, end) of a batch cast in key order (batch/ray_order.h) by the workers together; returns how many
// failed. Rays that miss the mesh's bounds are cast at once in input order. The others are copied, in one sequential
// pass over each part of the caller's arrays (a part a worker), into buckets of the key's top bits
// (RayOrderSettings::coarseBits), each ray's slot noted at its index (rank); the buckets are then sorted by the
// remaining bits, as the workers come free, into one list of slots in key order, and the rays cast from their copies
// by runs of that list, each hit written over the copy it was cast from. A last pass in input order copies each
// ray's hit from its slot (read a few rays ahead) to the caller's arrays, written sequentially. So every write of the
// casts goes to the slot just read: a scattered write there (the hits, or rank, at input indices) waits for its cache
// line and holds up the cast's own stores behind it (a 4-byte rank write per cast cost about 60 ms a million rays).
// A ray failing the quick checks takes the per-index path (the single query's Status). Without memory for the
// scratch the block keeps input order; when the pool fails during a pass (the passes cannot be run twice: a cast
// overwrites its ray) the whole block is cast again in input order, which writes the same bytes.
template <class T, class Out>
std::size_t castBlockInKeyOrder(const MeshRayItems<T, Out>& items, const detail::RayOrderKey<T>& key,
                                const detail::RayOrderSettings& order, const WorkerScratch<T>& workers,
                                std::size_t workerCount, const BatchSettings& settings, std::size_t begin,
                                std::size_t end) {
  using Scratch = KeyOrderScratch<T>;
  using Ray = typename Scratch::Ray;
  constexpr std::size_t kPrefetchAhead = 16;  // rays
  constexpr std::size_t kComparisonSortRays = 256;
  constexpr std::size_t kHitAhead = 24;       // rays (one cache line each)
  constexpr std::size_t kCopyOutGrain = 8192;  // rays
  constexpr std::size_t kCastGrain = 1024;     // rays
  const RayBatch<T>& rays = items.rays;
  // A key's bits: coarseBits (its bucket), fineBits (its place in the bucket), unsortedBits.
  const int fineBits = order.sortedBits - order.coarseBits, unsortedBits = 30 - order.sortedBits;
  const int bucketShift = fineBits + unsortedBits;
  const std::size_t buckets = std::size_t(1) << order.coarseBits;
  const std::size_t size = end - begin, parts = workerCount;
  const std::size_t partRays = (size + parts - 1) / parts;
  Scratch& scratch = *workers[0];
  // Input order for the rays [first, last) of the block whose rank passes `cast` (all when the keys are not made).
  auto inputOrder = [&](auto&& cast) {
    return runRanges(size, settings.grain, settings, [&](std::size_t first, std::size_t last, std::uint32_t) {
      std::size_t failed = 0;
      for (std::size_t j = first; j < last; ++j) failed += cast(j) && !items(begin + j) ? 1 : 0;
      return failed;
    });
  };
  // The whole block in input order: every ray's answer written again, the same bytes.
  auto wholeBlockInInputOrder = [&] { return inputOrder([](std::size_t) { return true; }); };
  if (!scratch.reserve(size, buckets, parts)) return wholeBlockInInputOrder();
  bool pooled = true;  // every pass so far ran whole
  auto pass = [&](std::size_t n, std::size_t grain, const auto& range) {
    std::size_t passFailed = 0;
    pooled = pooled && tryRunRanges(n, grain, settings, range, passFailed);
    return passFailed;
  };
  std::uint32_t* rank = scratch.rank.data;
  std::uint32_t* starts = scratch.starts.data();
  std::uint32_t* next = scratch.next.data();
  // Each part's keys (in rank until the rays are copied) and its count of rays in each bucket.
  // (Each pass copies the values its loop reads into locals: read through the closure, they were loaded again after
  // every store through a pointer that might alias them.)
  std::size_t failed = pass(parts, 1, [&](std::size_t first, std::size_t last, std::uint32_t) {
    const int shift = bucketShift;
    std::uint32_t* const keys = rank;
    std::size_t partFailed = 0;
    for (std::size_t p = first; p < last; ++p) {
      const std::size_t j0 = std::min(size, p * partRays), j1 = std::min(size, j0 + partRays);
      std::uint32_t* counts = next + p * buckets;
      std::fill(counts, counts + buckets, 0u);
      if (j0 == j1) continue;
      key.keyRays(StridedArray<Vec3<T>>(&rays.origins[begin + j0], j1 - j0, rays.origins.stride),
                  StridedArray<Vec3<T>>(&rays.unitDirs[begin + j0], j1 - j0, rays.unitDirs.stride), rays.maxDist,
                  rank + j0);
      for (std::size_t j = j0; j < j1; ++j) {
        const std::uint32_t k = keys[j];
        if (k == detail::RayOrderKey<T>::kMisses) {
          partFailed += items(begin + j) ? 0 : 1;
          keys[j] = Scratch::kAnswered;
        } else {
          ++counts[k >> shift];
        }
      }
    }
    return partFailed;
  });
  if (!pooled) return wholeBlockInInputOrder();
  // Where each bucket begins, and within it each part's rays in part order (so the slots hold each bucket's rays in
  // input order, whatever the number of parts).
  std::uint32_t largest = 0, placed = 0;  // the largest bucket; the rays placed so far
  for (std::size_t b = 0; b < buckets; ++b) {
    starts[b] = placed;
    for (std::size_t p = 0; p < parts; ++p) {
      const std::uint32_t count = next[p * buckets + b];
      next[p * buckets + b] = placed;
      placed += count;
    }
    largest = std::max(largest, placed - starts[b]);
  }
  starts[buckets] = placed;
  for (std::size_t w = 0; w < workerCount; ++w) {
    if (!workers[w]->items.reserve(2 * std::size_t(largest))) {  // no memory to sort the buckets: input order
      return failed + inputOrder([&](std::size_t j) { return rank[j] != Scratch::kAnswered; });
    }
  }
  // The rays copied into their buckets, part by part.
  pass(parts, 1, [&](std::size_t first, std::size_t last, std::uint32_t) {
    const int shift = bucketShift;
    std::uint32_t* const ranks = rank;
    typename Scratch::Slot* const to = scratch.slots.data;
    const StridedArray<Vec3<T>> origins = rays.origins, dirs = rays.unitDirs;
    for (std::size_t p = first; p < last; ++p) {
      const std::size_t j0 = std::min(size, p * partRays), j1 = std::min(size, j0 + partRays);
      std::uint32_t* partNext = next + p * buckets;
      for (std::size_t j = j0; j < j1; ++j) {
        const std::uint32_t k = ranks[j];
        if (k == Scratch::kAnswered) continue;
        const std::size_t i = begin + j;
        const std::uint32_t slot = partNext[k >> shift]++;
        new (&to[slot].ray) Ray{origins[i], dirs[i], k};
        ranks[j] = slot;
      }
    }
    return std::size_t(0);
  });
  if (!pooled) return wholeBlockInInputOrder();
  // Each bucket sorted by the worker that takes it: keyOrder lists the slots in key order.
  const std::uint32_t fineMask = (1u << fineBits) - 1u;
  typename Scratch::Slot* slots = scratch.slots.data;
  std::uint32_t* keyOrder = scratch.order.data;
  pass(buckets, 1, [&](std::size_t firstBucket, std::size_t lastBucket, std::uint32_t worker) {
    const int unsorted = unsortedBits;
    const std::uint32_t mask = fineMask;
    for (std::size_t b = firstBucket; b < lastBucket; ++b) {
      const std::size_t first = starts[b], count = starts[b + 1] - first;
      if (count == 0) continue;
      const typename Scratch::Slot* bucket = slots + first;
      std::uint64_t* fine = workers[worker]->items.data;
      for (std::size_t j = 0; j < count; ++j) {
        fine[j] = std::uint64_t((bucket[j].ray.key >> unsorted) & mask) << 32 | std::uint64_t(j);
      }
      // Small buckets by comparisons (the payloads differ, so this is the same order as the stable radix sort's):
      // the radix pass clears and sums a histogram of 2^fineBits counts whatever the bucket's size.
      const std::uint64_t* sorted = fine;
      if (count <= kComparisonSortRays) {
        std::sort(fine, fine + count);
      } else {
        sorted = detail::sortByKey(fine, fine + count, count, fineBits);
      }
      for (std::size_t j = 0; j < count; ++j) keyOrder[first + j] = std::uint32_t(first + (sorted[j] & 0xffffffffu));
    }
    return std::size_t(0);
  });
  // The rays cast in that order, in runs of kCastGrain (a bucket holding most rays, as from one sensor inside the
  // bounds, is shared by the workers), each hit written over the ray it was cast from.
  if (!pooled) return wholeBlockInInputOrder();
  pass(placed, kCastGrain, [&](std::size_t first, std::size_t last, std::uint32_t) {
    const std::uint32_t* const sortedSlots = keyOrder;
    typename Scratch::Slot* const all = slots;
    for (std::size_t p = first; p < last; ++p) {
      if (p + kPrefetchAhead < last) prefetchRead(&all[sortedSlots[p + kPrefetchAhead]]);
      typename Scratch::Slot& slot = all[sortedSlots[p]];
      const Ray& r = slot.ray;  // copied into the query before the slot takes the hit
      Vec3<T> normalized;
      const Vec3<T>* dir = directionOf(rays, r.dir, normalized);
      if (dir != nullptr && detail::rayIsValid(r.origin, *dir, items.pose.p)) {
        const detail::RayQuery<T> query = detail::rayQuery(r.origin, *dir, rays.maxDist, rays.hitFlags, 1u);
        items.mesh.castOne(query, *new (&slot.hit) typename Scratch::Hit);
      } else {
        new (&slot.hit) typename Scratch::Hit;
        slot.hit.flags = Scratch::kByIndex;
      }
    }
    return std::size_t(0);
  });
  // The outputs in input order, each hit read kHitAhead rays ahead.
  if (!pooled) return wholeBlockInInputOrder();
  failed += pass(size, kCopyOutGrain, [&](std::size_t first, std::size_t last, std::uint32_t) {
    const std::uint32_t* const ranks = rank;
    const typename Scratch::Slot* const from = slots;
    const std::size_t offset = begin;
    std::size_t rangeFailed = 0;
    for (std::size_t j = first; j < last; ++j) {
      if (j + kHitAhead < last && ranks[j + kHitAhead] != Scratch::kAnswered) {
        prefetchRead(&from[ranks[j + kHitAhead]]);
      }
      const std::uint32_t place = ranks[j];
      if (place == Scratch::kAnswered) continue;
      const typename Scratch::Hit& c = from[place].hit;
      const std::size_t i = offset + j;
      if (c.flags == Scratch::kByIndex) {
        rangeFailed += items(i) ? 0 : 1;
        continue;
      }
      // The mesh raycast's position: ray.origin + ray.dir * t.
      Vec3<T> position = Vec3<T>::Zero();
      if (c.flags.has(HitFlag::Position)) {
        Vec3<T> normalized;
        position = rays.origins[i] + *directionOf(rays, rays.unitDirs[i], normalized) * c.distance;
      }
      items.out.store(i, c, position);
      rangeFailed += record(items.statuses, i, Status()) ? 0 : 1;
    }
    return rangeFailed;
  });
  return pooled ? failed : wholeBlockInInputOrder();
}

// Whether a batch casts in key order: asked for, and at least minRays rays.
inline bool castsInKeyOrder(const BatchSettings& settings, std::size_t n, const detail::RayOrderSettings& order) {
  return settings.coherentRayOrder && n >= order.minRays;
}

// Casts the mesh rays of a batch: in key order by blocks (RayOrderSettings), all workers on one block at a time,
// when castsInKeyOrder; else in input order.
template <class T, class Out>
std::size_t raycastMeshItems(const RayBatch<T>& rays, const Shape<T>& shape, const Transform<T>& pose, const Out& out,
                             Status* statuses, const BatchSettings& settings) {
  const MeshRayItems<T, Out> items(rays, shape, pose, out, statuses);
  const std::size_t n = rays.origins.count;
  const detail::RayOrderSettings order;
  Bounds3<T> box;
  if (!castsInKeyOrder(settings, n, order) || !computeGeomBounds(box, shape, pose).ok()) {
    return runItems(n, settings, items);
  }
  const detail::RayOrderKey<T> key(box);
  const std::size_t blocks = (n + order.blockRays - 1) / order.blockRays;
  const std::size_t blockRays = (n + blocks - 1) / blocks;
  const std::size_t slots = batchSlots(settings);
  WorkerScratch<T> local;
  WorkerScratch<T>* scratch = &local;
  try {
    if (settings.scratch != nullptr) scratch = &detail::BatchScratchAccess::workers<T>(*settings.scratch);
    while (scratch->size() < slots) scratch->push_back(std::make_unique<KeyOrderScratch<T>>());
  } catch (const std::bad_alloc&) {
    return runItems(n, settings, items);
  }
  std::size_t failed = 0;
  for (std::size_t b = 0; b < blocks; ++b) {
    const std::size_t begin = std::min(n, b * blockRays), end = std::min(n, begin + blockRays);
    if (begin < end) failed += castBlockInKeyOrder(items, key, order, *scratch, slots, settings, begin, end);
  }
  return failed;
}

// Closest hits of a batch against one shape: the mesh items above, else the single raycast per ray.
template <class T, class Out>
Status raycastShapeBatch(const RayBatch<T>& rays, const Shape<T>& shape, const Transform<T>& pose, const Out& out,
                         Status* statuses, const BatchSettings& settings) {
  RaycastHit<T> probe;
  if (shape.type() == GeometryType::TriangleMesh &&
      detail::raySettingsAreValid(pose, rays.maxDist, rays.hitFlags, 1u, &probe)) {
    return batchResult(raycastMeshItems(rays, shape, pose, out, statuses, settings));
  }
  return batchResult(runItems(rays.origins.count, settings, [&](std::size_t i) {
    Vec3<T> scratch;
    const Vec3<T>* dir = rayDirection(rays, i, scratch);
    if (dir == nullptr) return record(statuses, i, zeroLengthDirection());
    RaycastHit<T> h;
    std::uint32_t count = 0;
    Status s = raycast(rays.origins[i], *dir, shape, pose, rays.maxDist, rays.hitFlags, 1u, &h, count);
    if (s.ok()) out.store(i, count, h);
    return record(statuses, i, std::move(s));
  }));
}

}  // namespace

template <class T>
Status raycastBatch(const RayBatch<T>& rays, const Shape<T>& shape, const Transform<T>& pose, RaycastHit<T>* hits,
                    std::uint8_t* hasHit, Status* statuses, const BatchSettings& settings) noexcept {
  if (Status s = checkArrays(rays.origins, rays.unitDirs); !s.ok()) return s;
  if (shape.empty()) return emptyShape();
  if (rays.origins.count > 0 && (hits == nullptr || hasHit == nullptr)) return nullOutput();
  return raycastShapeBatch(rays, shape, pose, HitArrayOut<T>{hits, hasHit}, statuses, settings);
}

template <class T>
Status raycastBatch(const RayBatch<T>& rays, const Shape<T>& shape, const Transform<T>& pose,
                    const RayHitColumns<T>& out, Status* statuses, const BatchSettings& settings) noexcept {
  if (Status s = checkArrays(rays.origins, rays.unitDirs); !s.ok()) return s;
  if (shape.empty()) return emptyShape();
  return raycastShapeBatch(rays, shape, pose, HitColumnsOut<T>{out}, statuses, settings);
}

template <class T>
Status raycastBatch(const RayBatch<T>& rays, const Geometry<T>& geometry, const Transform<T>& pose, RaycastHit<T>* hits,
                    std::uint8_t* hasHit, Status* statuses, const BatchSettings& settings) noexcept {
  Shape<T> shape;
  if (Status s = Shape<T>::make(geometry, shape); !s.ok()) return s;
  return raycastBatch(rays, shape, pose, hits, hasHit, statuses, settings);
}

template <class T>
Status raycastBatch(const RayBatch<T>& rays, const Scene<T>& scene, SceneRaycastHit<T>* hits, std::uint8_t* hasHit,
                    Status* statuses, const BatchSettings& settings, const SceneFilter& filter) noexcept {
  if (Status s = checkArrays(rays.origins, rays.unitDirs); !s.ok()) return s;
  const std::size_t n = rays.origins.count;
  if (n > 0 && (hits == nullptr || hasHit == nullptr)) return nullOutput();
  return batchResult(runItems(n, settings, [&](std::size_t i) {
    Vec3<T> scratch;
    const Vec3<T>* dir = rayDirection(rays, i, scratch);
    if (dir == nullptr) return record(statuses, i, zeroLengthDirection());
    SceneRaycastHit<T> h;
    bool has = false;
    Status s = scene.raycastClosest(rays.origins[i], *dir, rays.maxDist, h, has, rays.hitFlags, filter);
    if (s.ok()) {
      hasHit[i] = has ? 1 : 0;
      if (has) hits[i] = h;
    }
    return record(statuses, i, std::move(s));
  }));
}

template <class T>
Status raycastAllBatch(const RayBatch<T>& rays, const Scene<T>& scene, std::uint32_t maxHitsPerRay,
                       const SceneHitsOutput<T>& out, Status* statuses, const BatchSettings& settings,
                       const SceneFilter& filter) noexcept {
  if (Status s = checkArrays(rays.origins, rays.unitDirs); !s.ok()) return s;
  if (maxHitsPerRay == 0) return Status::invalid("maxHitsPerRay is 0");
  const std::size_t n = rays.origins.count;
  if (n > 0 && out.counts == nullptr) return nullOutput();
  if (n > 0 && out.offsets != nullptr && out.hits == nullptr) return nullOutput();
  constexpr std::uint32_t kLocal = 8;
  return batchResult(runItems(n, settings, [&](std::size_t i) {
    // The fill pass writes straight into the caller's array; the count pass into a local buffer.
    Vec3<T> scratch;
    const Vec3<T>* dir = rayDirection(rays, i, scratch);
    if (dir == nullptr) return record(statuses, i, zeroLengthDirection());
    std::uint32_t count = 0;
    Status s;
    auto cast = [&](SceneRaycastHit<T>* dst) {
      return scene.raycastAll(rays.origins[i], *dir, rays.maxDist, rays.hitFlags, maxHitsPerRay, dst, count, filter);
    };
    if (out.offsets != nullptr) {
      s = cast(out.hits + out.offsets[i]);
    } else if (maxHitsPerRay <= kLocal) {
      SceneRaycastHit<T> local[kLocal];
      s = cast(local);
    } else {
      try {
        std::vector<SceneRaycastHit<T>> buffer(maxHitsPerRay);
        s = cast(buffer.data());
      } catch (const std::bad_alloc&) {
        s = Status::internal("out of memory");
      }
    }
    if (s.ok()) out.counts[i] = count;
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

template Status raycastBatch(const RayBatch<float>&, const Shape<float>&, const Transform<float>&, RaycastHit<float>*,
                             std::uint8_t*, Status*, const BatchSettings&) noexcept;
template Status raycastBatch(const RayBatch<float>&, const Shape<float>&, const Transform<float>&,
                             const RayHitColumns<float>&, Status*, const BatchSettings&) noexcept;
template Status raycastBatch(const RayBatch<float>&, const Geometry<float>&, const Transform<float>&,
                             RaycastHit<float>*, std::uint8_t*, Status*, const BatchSettings&) noexcept;
template Status raycastBatch(const RayBatch<float>&, const Scene<float>&, SceneRaycastHit<float>*, std::uint8_t*,
                             Status*, const BatchSettings&, const SceneFilter&) noexcept;
template Status raycastAllBatch(const RayBatch<float>&, const Scene<float>&, std::uint32_t,
                                const SceneHitsOutput<float>&, Status*, const BatchSettings&,
                                const SceneFilter&) noexcept;
template Status overlapBatch(const Shape<float>&, StridedArray<Transform<float>>, const Shape<float>&,
                             StridedArray<Transform<float>>, std::uint8_t*, Status*, const BatchSettings&) noexcept;
template Status distanceBatch(const Shape<float>&, StridedArray<Transform<float>>, const Shape<float>&,
                              StridedArray<Transform<float>>, DistanceResult<float>*, Status*,
                              const BatchSettings&) noexcept;
template Status penetrationBatch(const Shape<float>&, StridedArray<Transform<float>>, const Shape<float>&,
                                 StridedArray<Transform<float>>, PenetrationResult<float>*, Status*,
                                 const BatchSettings&) noexcept;
template Status pointDistanceBatch(StridedArray<Vec3<float>>, const Shape<float>&, const Transform<float>&,
                                   PointDistanceResult<float>*, Status*, const BatchSettings&) noexcept;
template Status raycastBatch(const RayBatch<double>&, const Shape<double>&, const Transform<double>&,
                             RaycastHit<double>*, std::uint8_t*, Status*, const BatchSettings&) noexcept;
template Status raycastBatch(const RayBatch<double>&, const Shape<double>&, const Transform<double>&,
                             const RayHitColumns<double>&, Status*, const BatchSettings&) noexcept;
template Status raycastBatch(const RayBatch<double>&, const Geometry<double>&, const Transform<double>&,
                             RaycastHit<double>*, std::uint8_t*, Status*, const BatchSettings&) noexcept;
template Status raycastBatch(const RayBatch<double>&, const Scene<double>&, SceneRaycastHit<double>*, std::uint8_t*,
                             Status*, const BatchSettings&, const SceneFilter&) noexcept;
template Status raycastAllBatch(const RayBatch<double>&, const Scene<double>&, std::uint32_t,
                                const SceneHitsOutput<double>&, Status*, const BatchSettings&,
                                const SceneFilter&) noexcept;
template Status overlapBatch(const Shape<double>&, StridedArray<Transform<double>>, const Shape<double>&,
                             StridedArray<Transform<double>>, std::uint8_t*, Status*, const BatchSettings&) noexcept;
template Status distanceBatch(const Shape<double>&, StridedArray<Transform<double>>, const Shape<double>&,
                              StridedArray<Transform<double>>, DistanceResult<double>*, Status*,
                              const BatchSettings&) noexcept;
template Status penetrationBatch(const Shape<double>&, StridedArray<Transform<double>>, const Shape<double>&,
                                 StridedArray<Transform<double>>, PenetrationResult<double>*, Status*,
                                 const BatchSettings&) noexcept;
template Status pointDistanceBatch(StridedArray<Vec3<double>>, const Shape<double>&, const Transform<double>&,
                                   PointDistanceResult<double>*, Status*, const BatchSettings&) noexcept;

std::uint32_t batchSlots(const BatchSettings& settings) noexcept {
  try {
    return settings.threads == 1 ? 1u : std::uint32_t(arenaThreads(settings));
  } catch (...) {
    return 1u;
  }
}

Status forEachBatchItem(std::size_t count, const BatchSettings& settings,
                        const std::function<bool(std::size_t, std::uint32_t)>& item) noexcept {
  if (!item) return Status::invalid("forEachBatchItem: the item function is empty");
  try {
    return batchResult(runSlottedItems(count, settings, [&](std::size_t i, std::uint32_t slot) {
      try {
        return item(i, slot);
      } catch (...) {
        return false;
      }
    }));
  } catch (...) {
    return Status::invalid("forEachBatchItem: the batch could not run");
  }
}

}  // namespace gq
