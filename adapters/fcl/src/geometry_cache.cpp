// The per-CollisionGeometry* cache of cooked Convex hulls and BVHModel meshes (rules in geometry_cache.h).
#include "geometry_cache.h"

#include <fcl/geometry/bvh/BVH_model.h>
#include <fcl/geometry/shape/convex.h>
#include <fcl/math/bv/AABB.h>
#include <fcl/math/bv/OBB.h>
#include <fcl/math/bv/OBBRSS.h>
#include <fcl/math/bv/RSS.h>
#include <fcl/math/bv/kDOP.h>
#include <fcl/math/bv/kIOS.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cstring>
#include <memory>
#include <mutex>
#include <optional>
#include <shared_mutex>
#include <unordered_map>
#include <vector>

#include "gq/cooking.h"
#include "gq/kernels/gjk.h"
#include "pair_kernels.h"

namespace gq::fcl::internal {
namespace k = gq::kernels;
namespace {

constexpr int kFingerprintSamples = 16;
// The cook's estimate in tree work units (fcl_tree.h) a triangle. Measured by callgrind on a 192-triangle sphere
// mesh (FclNewMesh.RepeatedQueriesKeepTheirAnswersAcrossTheCook): cookTriangleMesh 1.85M instructions (9.6k a
// triangle), tree distance queries ~74 instructions a work unit, so a cook is ~130 units a triangle.
constexpr std::uint64_t kCookWorkPerTriangle = 130;
constexpr std::size_t kThreadSlots = 16;  // per-thread table in front of the shared map (a power of two)

// FNV-1a over 64-bit words: equal inputs give equal fingerprints; a change is caught unless it collides.
struct Fingerprint {
  std::uint64_t h = 1469598103934665603ull;
  void mix(std::uint64_t word) { h = (h ^ word) * 1099511628211ull; }
  template <class V> void addWord(V v) {
    static_assert(sizeof(V) <= 8, "one word");
    std::uint64_t word = 0;
    std::memcpy(&word, &v, sizeof(V));
    mix(word);
  }
  template <class T> void add(const ::fcl::Vector3<T>& v) { addWord(v[0]), addWord(v[1]), addWord(v[2]); }
  void add(const ::fcl::Triangle& t) { addWord(t[0]), addWord(t[1]), addWord(t[2]); }
};

template <class V> void sampleArray(Fingerprint& f, const V* data, int count) {
  if (count <= 0 || !data) return;
  const int step = std::max(1, count / kFingerprintSamples);
  for (int i = 0; i < count; i += step) f.add(data[i]);
  f.add(data[count - 1]);
}

// The vertex and triangle arrays of a BVHModel of any BV type.
template <class T> struct MeshView {
  const ::fcl::Vector3<T>* vertices = nullptr;
  const ::fcl::Triangle* triangles = nullptr;
  int vertexCount = 0, triangleCount = 0;
  bool triangleModel = false, built = false;
};
template <class BV> MeshView<typename BV::S> viewOf(const ::fcl::CollisionGeometry<typename BV::S>* g) {
  const auto* m = static_cast<const ::fcl::BVHModel<BV>*>(g);
  MeshView<typename BV::S> v;
  v.vertices = m->vertices;
  v.triangles = m->tri_indices;
  v.vertexCount = m->num_vertices;
  v.triangleCount = m->num_tris;
  v.triangleModel = m->getModelType() == ::fcl::BVH_MODEL_TRIANGLES;
  v.built = m->build_state == ::fcl::BVH_BUILD_STATE_PROCESSED || m->build_state == ::fcl::BVH_BUILD_STATE_UPDATED;
  return v;
}
template <class T> bool meshView(const ::fcl::CollisionGeometry<T>* g, ::fcl::NODE_TYPE type, MeshView<T>& v) {
  switch (type) {
    case ::fcl::BV_AABB: v = viewOf<::fcl::AABB<T>>(g); return true;
    case ::fcl::BV_OBB: v = viewOf<::fcl::OBB<T>>(g); return true;
    case ::fcl::BV_RSS: v = viewOf<::fcl::RSS<T>>(g); return true;
    case ::fcl::BV_kIOS: v = viewOf<::fcl::kIOS<T>>(g); return true;
    case ::fcl::BV_OBBRSS: v = viewOf<::fcl::OBBRSS<T>>(g); return true;
    case ::fcl::BV_KDOP16: v = viewOf<::fcl::KDOP<T, 16>>(g); return true;
    case ::fcl::BV_KDOP18: v = viewOf<::fcl::KDOP<T, 18>>(g); return true;
    case ::fcl::BV_KDOP24: v = viewOf<::fcl::KDOP<T, 24>>(g); return true;
    default: return false;
  }
}

// Whether a BVHModel is a finished triangle model gq can cook. FCL 0.7 itself crashes (SIGSEGV) on empty and
// unfinished models, so those are invalid input; point clouds are FCL's to answer.
template <class T> Conversion classifyMesh(const MeshView<T>& v) {
  if (!v.built || v.vertexCount <= 0 || !v.vertices) return Conversion::Invalid;
  if (!v.triangleModel) return Conversion::NotModelled;
  return v.triangleCount > 0 && v.triangles ? Conversion::Ok : Conversion::Invalid;
}

template <class T> std::uint64_t meshFingerprint(const MeshView<T>& v) {
  Fingerprint f;
  f.addWord(v.vertexCount), f.addWord(v.triangleCount), f.addWord(v.vertices), f.addWord(v.triangles);
  sampleArray(f, v.vertices, v.vertexCount);
  sampleArray(f, v.triangles, v.triangleCount);
  return f.h;
}

// A 128-bit hash of a model's whole vertex and triangle arrays (two independent 64-bit mixes of every word), the key
// of the cooked meshes shared between identical models.
struct ContentHash {
  std::uint64_t a = 1469598103934665603ull, b = 0x9E3779B97F4A7C15ull;
  void mix(std::uint64_t word) {
    a = (a ^ word) * 1099511628211ull;
    b = (b + word) * 0xC2B2AE3D27D4EB4Full;
    b ^= b >> 29;
  }
  void bytes(const void* data, std::size_t size) {
    const unsigned char* p = static_cast<const unsigned char*>(data);
    std::size_t i = 0;
    for (; i + 8 <= size; i += 8) {
      std::uint64_t word;
      std::memcpy(&word, p + i, 8);
      mix(word);
    }
    std::uint64_t tail = 0;
    std::memcpy(&tail, p + i, size - i);
    mix(tail ^ (std::uint64_t(size) << 56));
  }
  bool operator==(const ContentHash& o) const { return a == o.a && b == o.b; }
};
struct ContentHashOf {
  std::size_t operator()(const ContentHash& h) const { return std::size_t(h.a ^ (h.b << 1)); }
};

template <class T> ContentHash contentHash(const MeshView<T>& v) {
  ContentHash h;
  h.mix(std::uint64_t(v.vertexCount)), h.mix(std::uint64_t(v.triangleCount));
  for (int i = 0; i < v.vertexCount; ++i) h.bytes(v.vertices[i].data(), 3 * sizeof(T));
  h.bytes(v.triangles, std::size_t(v.triangleCount) * sizeof(::fcl::Triangle));
  return h;
}

template <class T> struct Entry {
  FclShape shape = FclShape::Unsupported;
  Conversion conversion = Conversion::Invalid;
  Geometry<T> geometry;
  std::optional<CandidateVolume<T>> candidate;  // Convex
  std::optional<k::ConvexShape<T>> support;     // Convex: at the identity pose
  HullPlanes<T> planes;                         // Convex: its face planes, packed
  const void* vertexArray = nullptr;            // Convex: its vertex vector (identity)
  std::optional<::fcl::Convex<T>> convexAlive;  // Convex: a copy sharing that vector keeps it alive
  std::uint64_t fingerprint = 0;                // BVHModel
  // A BVHModel not cooked yet: answered on FCL's tree while `spent` (work units) is below `budget` (the cook's
  // estimate); `superseded` once its cooked entry replaced it in the shared map.
  std::optional<MeshTree<T>> tree;
  MeshView<T> view;
  std::uint64_t budget = 0;
  mutable std::atomic<std::uint64_t> spent{0};
  mutable std::atomic<bool> cooking{false}, superseded{false};
};

// The lookup key of one geometry for one call: its identity data.
template <class T> struct Key {
  const ::fcl::CollisionGeometry<T>* geometry;
  bool convex;
  const void* vertexArray;   // Convex
  MeshView<T> mesh;          // BVHModel
  std::uint64_t fingerprint;  // BVHModel
  MeshUse use;                // BVHModel
  ::fcl::NODE_TYPE type;      // BVHModel: its BV type
  bool matches(const Entry<T>& e) const {
    if (convex) return e.vertexArray == vertexArray;
    return e.vertexArray == nullptr && e.fingerprint == fingerprint &&
           (!e.tree || (use == MeshUse::TreeAllowed && !e.superseded.load(std::memory_order_relaxed)));
  }
};

template <class T> HullPlanes<T> packedPlanes(const ConvexMesh<T>& hull) {
  HullPlanes<T> out;
  const std::size_t n = hull.polygons.size();
  out.pairs = std::uint32_t((n + 1) / 2);
  out.packed.resize(8 * std::size_t(out.pairs));
  for (std::size_t i = 0; i < 2 * std::size_t(out.pairs); ++i) {
    const HullPolygon<T>& f = hull.polygons[std::min(i, n - 1)];
    T* pair = &out.packed[8 * (i / 2)];
    const std::size_t lane = i % 2;
    pair[lane] = f.normal.x();
    pair[2 + lane] = f.normal.y();
    pair[4 + lane] = f.normal.z();
    pair[6 + lane] = f.d;
  }
  return out;
}

template <class T> std::shared_ptr<const Entry<T>> cookConvex(const ::fcl::Convex<T>& convex) {
  auto e = std::make_shared<Entry<T>>();
  const auto& vertices = convex.getVertices();
  e->vertexArray = &vertices;
  e->convexAlive.emplace(convex);
  std::shared_ptr<const ConvexMesh<T>> hull;
  if (cookConvexMesh(std::vector<Vec3<T>>(vertices.begin(), vertices.end()), hull).ok()) {
    e->shape = FclShape::Convex;
    e->conversion = Conversion::Ok;
    e->geometry = ConvexMeshGeometry<T>(hull);
    CandidateVolume<T> candidate;
    if (candidateVolume(e->geometry, candidate).ok()) e->candidate = candidate;
    e->support = k::makeConvexShape(e->geometry, Transform<T>());
    e->planes = packedPlanes(*hull);
  }
  return e;
}

template <class T> std::shared_ptr<const TriangleMesh<T>> cookMeshData(const MeshView<T>& v) {
  std::vector<Vec3<T>> vertices(v.vertices, v.vertices + v.vertexCount);
  std::vector<TriangleIndices> triangles(std::size_t(v.triangleCount));
  for (int i = 0; i < v.triangleCount; ++i)
    triangles[std::size_t(i)] = {std::uint32_t(v.triangles[i][0]), std::uint32_t(v.triangles[i][1]),
                                 std::uint32_t(v.triangles[i][2])};
  std::shared_ptr<const TriangleMesh<T>> mesh;
  if (!cookTriangleMesh(vertices, triangles, mesh).ok()) return nullptr;
  return mesh;
}

// Every vertex coordinate finite: the plain sum of all of them is finite only if each is (inf - inf is NaN); a
// non-finite sum is a non-finite coordinate or an overflow of finite ones, told apart exactly (x * 0 is 0 only for
// a finite x). A model with a non-finite vertex is cooked at once: the cook rejects it, and the call writes nothing.
template <class T> bool finiteVertices(const MeshView<T>& v) {
  static_assert(sizeof(::fcl::Vector3<T>) == 3 * sizeof(T), "FCL's vertices are contiguous coordinates");
  const Eigen::Map<const Eigen::Array<T, Eigen::Dynamic, 1>> all(v.vertices[0].data(), 3 * Eigen::Index(v.vertexCount));
  return all.sum() * T(0) == T(0) || (all * T(0)).sum() == T(0);
}

// A model's first entry: its FCL tree, with the cook's estimate as the budget of its tree queries.
template <class T>
std::shared_ptr<const Entry<T>> treeEntry(const ::fcl::CollisionGeometry<T>* g, ::fcl::NODE_TYPE type,
                                          const MeshView<T>& v, std::uint64_t fingerprint) {
  auto e = std::make_shared<Entry<T>>();
  e->fingerprint = fingerprint;
  e->shape = FclShape::Mesh;
  e->conversion = Conversion::Ok;
  e->tree = MeshTree<T>{g, int(type), e.get()};
  e->view = v;
  e->budget = kCookWorkPerTriangle * std::uint64_t(v.triangleCount);
  return e;
}

template <class T> struct SharedCache {
  std::shared_mutex mutex;
  std::unordered_map<const void*, std::shared_ptr<const Entry<T>>> entries;
  // Cooked meshes by content: an identical model (same arrays) shares one cook while any entry holds it.
  std::mutex contentMutex;
  std::unordered_map<ContentHash, std::weak_ptr<const TriangleMesh<T>>, ContentHashOf> byContent;
};
// Bumped by forget and clear: every per-thread slot older than it is stale. At namespace scope (constant
// initialisation, no guard to check on the hit path).
template <class T> std::atomic<std::uint64_t> gGeneration{1};
template <class T> SharedCache<T>& shared() {
  static SharedCache<T> c;
  return c;
}

// The cooked entry of a triangle model: an identical model's cooked mesh when one is alive, else a new cook.
template <class T> std::shared_ptr<const Entry<T>> cookMesh(const MeshView<T>& v, std::uint64_t fingerprint) {
  SharedCache<T>& c = shared<T>();
  const ContentHash hash = contentHash(v);
  std::shared_ptr<const TriangleMesh<T>> mesh;
  {
    std::lock_guard<std::mutex> lock(c.contentMutex);
    auto it = c.byContent.find(hash);
    if (it != c.byContent.end()) mesh = it->second.lock();
  }
  if (!mesh) {
    mesh = cookMeshData(v);
    if (mesh) {
      std::lock_guard<std::mutex> lock(c.contentMutex);
      if (c.byContent.size() > 64 + 2 * c.entries.size())  // drop the expired ones now and then
        for (auto it = c.byContent.begin(); it != c.byContent.end();) it = it->second.expired() ? c.byContent.erase(it) : ++it;
      c.byContent[hash] = mesh;
    }
  }
  auto e = std::make_shared<Entry<T>>();
  e->fingerprint = fingerprint;
  if (mesh) {
    e->shape = FclShape::Mesh;
    e->conversion = Conversion::Ok;
    e->geometry = TriangleMeshGeometry<T>(mesh);
  }
  return e;
}

// The shared entry for `key`, cooked (outside the lock: cooking may take milliseconds) when absent or stale; a
// triangle model looked up with MeshUse::TreeAllowed gets a tree entry instead of a cook.
template <class T> std::shared_ptr<const Entry<T>> sharedLookup(const Key<T>& key) {
  SharedCache<T>& c = shared<T>();
  {
    std::shared_lock<std::shared_mutex> lock(c.mutex);
    auto it = c.entries.find(key.geometry);
    if (it != c.entries.end() && key.matches(*it->second)) return it->second;
  }
  std::shared_ptr<const Entry<T>> fresh;
  if (key.convex) fresh = cookConvex(*static_cast<const ::fcl::Convex<T>*>(key.geometry));
  else if (key.use == MeshUse::TreeAllowed && finiteVertices(key.mesh))
    fresh = treeEntry(key.geometry, key.type, key.mesh, key.fingerprint);
  else fresh = cookMesh(key.mesh, key.fingerprint);
  std::unique_lock<std::shared_mutex> lock(c.mutex);
  std::shared_ptr<const Entry<T>>& slot = c.entries[key.geometry];
  if (slot && slot->tree) slot->superseded.store(true, std::memory_order_relaxed);
  slot = fresh;
  return fresh;
}

template <class T> struct Slot {
  const void* geometry = nullptr;
  std::uint64_t generation = 0;
  std::shared_ptr<const Entry<T>> entry;
};
// Evicted entries are parked in a two-place ring, so that an entry returned earlier in the same call (a call looks
// up two geometries) stays alive when the second lookup takes its slot.
template <class T> struct ThreadSlots {
  std::array<Slot<T>, kThreadSlots> slots;
  std::array<std::shared_ptr<const Entry<T>>, 2> evicted;
  unsigned nextEvicted = 0;
};
template <class T> ThreadSlots<T>& threadSlots() {
  thread_local ThreadSlots<T> t;
  return t;
}

// What a Convex hit compares, per thread slot, mirrored from ThreadSlots (which owns the entries): trivially
// destructible, so reading it needs no thread_local initialisation wrapper (ThreadSlots' shared_ptrs make it one),
// and the hit path does not build a Key. ~75 instructions a lookup -> ~25.
template <class T> struct ConvexHit {
  const void* geometry = nullptr;
  const void* vertexArray = nullptr;
  std::uint64_t generation = 0;
  const Entry<T>* entry = nullptr;
};
template <class T> thread_local std::array<ConvexHit<T>, kThreadSlots> tConvexHits{};

// The slots form sets of two ways (a call looks up two geometries: direct-mapped, two hot geometries whose slots
// collided evicted each other on every call, each lookup then taking the shared map's lock). A set's recent way is
// kept; a miss replaces the other one. Fibonacci hashing of the address spreads sequential allocations.
constexpr std::size_t kThreadSets = kThreadSlots / 2;
template <class T> thread_local std::array<std::uint8_t, kThreadSets> tRecentWay{};

inline std::size_t setOf(const void* geometry) {
  const std::uint64_t h = (std::uint64_t(reinterpret_cast<std::uintptr_t>(geometry)) >> 4) * 0x9E3779B97F4A7C15ull;
  return std::size_t(h >> 61);  // kThreadSets = 8: the top three bits
}
static_assert(kThreadSets == 8, "setOf takes three bits");

template <class T> const Entry<T>* lookup(const Key<T>& key) {
  ThreadSlots<T>& t = threadSlots<T>();
  const std::uint64_t generation = gGeneration<T>.load(std::memory_order_acquire);
  const std::size_t set = setOf(key.geometry);
  for (std::size_t way = 0; way < 2; ++way) {
    const Slot<T>& slot = t.slots[2 * set + way];
    if (slot.geometry == key.geometry && slot.generation == generation && key.matches(*slot.entry)) {
      tRecentWay<T>[set] = std::uint8_t(way);
      return slot.entry.get();
    }
  }
  const std::size_t way = 1u - tRecentWay<T>[set], index = 2 * set + way;
  tRecentWay<T>[set] = std::uint8_t(way);
  Slot<T>& slot = t.slots[index];
  std::shared_ptr<const Entry<T>> entry = sharedLookup(key);
  t.evicted[t.nextEvicted++ & 1u] = std::move(slot.entry);
  slot.geometry = key.geometry;
  slot.generation = generation;
  slot.entry = std::move(entry);
  tConvexHits<T>[index] = key.convex ? ConvexHit<T>{key.geometry, key.vertexArray, generation, slot.entry.get()}
                                     : ConvexHit<T>{};
  return slot.entry.get();
}

template <class T> void fill(const Entry<T>& e, Cooked<T>& out) {
  out.shape = e.shape;
  out.geometry = &e.geometry;
  out.candidate = e.candidate ? &*e.candidate : nullptr;
  out.support = e.support ? &*e.support : nullptr;
  out.planes = &e.planes;
  out.tree = e.tree ? &*e.tree : nullptr;
}

template <class T> void clearShared() {
  SharedCache<T>& c = shared<T>();
  std::unique_lock<std::shared_mutex> lock(c.mutex);
  c.entries.clear();
  gGeneration<T>.fetch_add(1, std::memory_order_acq_rel);
}

// The lookup through the per-thread table and the shared map (out of line: its frame would cost every Convex hit).
template <class T>
[[gnu::noinline]] Conversion slowLookup(const ::fcl::CollisionGeometry<T>* g, ::fcl::NODE_TYPE type, Cooked<T>& out,
                                       MeshUse use = MeshUse::Cooked) {
  Key<T> key{g, type == ::fcl::GEOM_CONVEX, nullptr, {}, 0, use, type};
  if (key.convex) {
    key.vertexArray = &static_cast<const ::fcl::Convex<T>*>(g)->getVertices();
  } else {
    if (!meshView(g, type, key.mesh)) return Conversion::NotModelled;
    const Conversion conversion = classifyMesh(key.mesh);
    if (conversion != Conversion::Ok) return conversion;
    key.fingerprint = meshFingerprint(key.mesh);
  }
  const Entry<T>* e = lookup(key);
  if (e->conversion != Conversion::Ok) return e->conversion;
  fill(*e, out);
  return Conversion::Ok;
}

// A cooked Convex from this thread's mirror of its slots (false: not there, or stale).
template <class T>
[[gnu::always_inline]] inline bool convexHit(const ::fcl::CollisionGeometry<T>* g, std::uint64_t generation,
                                             Cooked<T>& out) {
  const std::size_t set = setOf(g);
  const void* vertices = &static_cast<const ::fcl::Convex<T>*>(g)->getVertices();
  for (std::size_t way = 0; way < 2; ++way) {
    const ConvexHit<T>& hit = tConvexHits<T>[2 * set + way];
    if (hit.geometry == g && hit.vertexArray == vertices && hit.generation == generation &&
        hit.entry->conversion == Conversion::Ok) {
      tRecentWay<T>[set] = std::uint8_t(way);
      fill(*hit.entry, out);
      return true;
    }
  }
  return false;
}

}  // namespace

template <class T>
Conversion cachedGeometry(const ::fcl::CollisionGeometry<T>* g, ::fcl::NODE_TYPE type, Cooked<T>& out, MeshUse use) {
  if (type == ::fcl::GEOM_CONVEX && convexHit(g, gGeneration<T>.load(std::memory_order_acquire), out))
    return Conversion::Ok;
  return slowLookup(g, type, out, use);
}

template <class T> void chargeTree(const MeshTree<T>& tree, std::uint64_t work) {
  const Entry<T>& e = *static_cast<const Entry<T>*>(tree.entry);
  const std::uint64_t spent = e.spent.fetch_add(work, std::memory_order_relaxed) + work;
  if (spent < e.budget || e.cooking.exchange(true, std::memory_order_acq_rel)) return;
  // This query's work reached the cook's estimate: cook now (once), replacing the tree entry if it is still current.
  std::shared_ptr<const Entry<T>> cooked = cookMesh(e.view, e.fingerprint);
  SharedCache<T>& c = shared<T>();
  std::unique_lock<std::shared_mutex> lock(c.mutex);
  auto it = c.entries.find(tree.model);
  if (it == c.entries.end() || it->second.get() != &e) return;
  it->second = std::move(cooked);
  e.superseded.store(true, std::memory_order_relaxed);
}

template <class T>
bool cachedHulls(const ::fcl::CollisionGeometry<T>* a, const ::fcl::CollisionGeometry<T>* b, Cooked<T>& ca,
                 Cooked<T>& cb) {
  const std::uint64_t generation = gGeneration<T>.load(std::memory_order_acquire);
  return (convexHit(a, generation, ca) || slowLookup(a, ::fcl::GEOM_CONVEX, ca) == Conversion::Ok) &&
         (convexHit(b, generation, cb) || slowLookup(b, ::fcl::GEOM_CONVEX, cb) == Conversion::Ok);
}

template <class T> void forgetCached(const ::fcl::CollisionGeometry<T>* g) {
  SharedCache<T>& c = shared<T>();
  std::unique_lock<std::shared_mutex> lock(c.mutex);
  c.entries.erase(g);
  gGeneration<T>.fetch_add(1, std::memory_order_acq_rel);
}

void clearCached() {
  clearShared<float>();
  clearShared<double>();
}

template bool cachedHulls<float>(const ::fcl::CollisionGeometry<float>*, const ::fcl::CollisionGeometry<float>*,
                                 Cooked<float>&, Cooked<float>&);
template bool cachedHulls<double>(const ::fcl::CollisionGeometry<double>*, const ::fcl::CollisionGeometry<double>*,
                                  Cooked<double>&, Cooked<double>&);
template Conversion cachedGeometry<float>(const ::fcl::CollisionGeometry<float>*, ::fcl::NODE_TYPE, Cooked<float>&,
                                          MeshUse);
template Conversion cachedGeometry<double>(const ::fcl::CollisionGeometry<double>*, ::fcl::NODE_TYPE,
                                           Cooked<double>&, MeshUse);
template void chargeTree<float>(const MeshTree<float>&, std::uint64_t);
template void chargeTree<double>(const MeshTree<double>&, std::uint64_t);
template void forgetCached<float>(const ::fcl::CollisionGeometry<float>*);
template void forgetCached<double>(const ::fcl::CollisionGeometry<double>*);

}  // namespace gq::fcl::internal
