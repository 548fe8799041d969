#pragma once
// Scenes: many geometry instances, each with a pose, a 32-bit mask and the caller's 64-bit id, in a dynamic AABB
// tree, with the spec's queries over all of them at once (raycast, sweep, overlap, distance, overlapping pairs).
//
// Every instance is a prepared shape (gq/shape.h): add() validates a Geometry<T> once (validateGeometry's rules and
// Status) or takes a Shape<T> as made. Its tree box is computeGeomBounds at its pose (default inflation) padded by a
// few ulps, so the tree never prunes an instance a query touches. Instances whose box is unbounded (planes) are kept
// beside the tree and tested by every query.
//
// Each scene query answers what the loop over all instances through the single queries of gq/shape.h answers, with
// the same per-instance calls and arguments: the tree only skips instances whose boxes prove they cannot change the
// result. Ties (equal distances) go to the smaller id; lists come sorted (hits by distance then id, ids ascending,
// pairs by (first, second)). An instance pair the single query does not answer (an unsupported pair such as plane
// against mesh, or a solver that did not converge) is left out and the query returns a Warning naming how many
// (Status::index()); everything else is answered.
//
// Filtering (as PhysX's scene queries): an instance takes part in a query when (filter.mask & instance mask) != 0
// and filter.callback, when set, returns true for its id. A pair of instances takes part in overlappingPairs when
// (mask0 & mask1) != 0 and the pair callback, when set, returns true.
//
// Tree upkeep: add() inserts a leaf where it grows the tree's surface area least (surface-area heuristic); setPose()
// refits the leaf's ancestors; when refits have grown the summed area of the tree's inner boxes beyond
// kRebuildAreaFactor times what insertions alone made, the next mutation rebuilds the tree top down. Rays walk a
// second, 8-wide tree (the mesh raycast's tree, one instance a leaf): add() inserts into it, setPose() refits it,
// remove() empties the instance's lane, and each top-down rebuild builds it again; without it (boxes beyond 1e30, or
// after an insertion path deeper than its walk allows, until a rebuild or the add that brings the adds since its last
// build to an eighth of the instances) rays walk the binary tree (the same hits).
//
// Threads: the query functions are const and touch no shared mutable state: any number of threads may query one
// scene at once. Mutation (add, remove, setPose, setMask, rebuild) is single-threaded: no query may run on the
// scene while it is mutated. Callbacks run on the querying thread.
//
// Errors: every function returns a Status and never throws. A rejected mutation (NaN or non-unit pose, unknown or
// duplicate id, invalid geometry, empty shape) changes nothing. A rejected query (NaN input, non-unit direction,
// negative distance, null output) writes no output.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "gq/geometry.h"
#include "gq/hit.h"
#include "gq/math.h"
#include "gq/query.h"
#include "gq/shape.h"
#include "gq/status.h"
#include "gq/transform.h"

namespace gq {

using InstanceId = std::uint64_t;

// Which instances a query sees (see the header comment).
struct SceneFilter {
  std::uint32_t mask = 0xffffffffu;
  // Optional: return false to skip the instance. A captureless lambda converts; state goes through userData.
  bool (*callback)(void* userData, InstanceId id) = nullptr;
  void* userData = nullptr;
};

// Which instance pairs overlappingPairs tests, beyond (mask0 & mask1) != 0.
struct ScenePairFilter {
  bool (*callback)(void* userData, InstanceId id0, InstanceId id1) = nullptr;
  void* userData = nullptr;
};

template <class T> struct SceneRaycastHit {
  InstanceId id = 0;
  RaycastHit<T> hit;
};

template <class T> struct SceneSweepHit {
  InstanceId id = 0;
  SweepHit<T> hit;
};

template <class T> struct SceneDistanceResult {
  InstanceId id = 0;
  DistanceResult<T> result;  // the query shape is geom0, the instance geom1
};

// An overlapping pair: in a self query id0 < id1; between two scenes id0 is in the first scene, id1 in the second.
struct ScenePair {
  InstanceId id0 = 0;
  InstanceId id1 = 0;
  bool operator==(const ScenePair& o) const { return id0 == o.id0 && id1 == o.id1; }
};

template <class T> class Scene {
 public:
  // Refits that grow the inner boxes' summed area beyond this factor (over insertions alone) trigger a rebuild.
  static constexpr double kRebuildAreaFactor = 1.5;

  Scene();
  ~Scene();
  Scene(Scene&&) noexcept;
  Scene& operator=(Scene&&) noexcept;
  Scene(const Scene&) = delete;
  Scene& operator=(const Scene&) = delete;

  // ---- mutation (single-threaded) ----
  Status add(InstanceId id, const Geometry<T>& geometry, const Transform<T>& pose,
             std::uint32_t mask = 0xffffffffu) noexcept;
  Status add(InstanceId id, const Shape<T>& shape, const Transform<T>& pose, std::uint32_t mask = 0xffffffffu) noexcept;
  Status remove(InstanceId id) noexcept;
  Status setPose(InstanceId id, const Transform<T>& pose) noexcept;
  Status setMask(InstanceId id, std::uint32_t mask) noexcept;
  // Rebuilds the tree top down now, and the 8-wide tree rays walk (setPose does both when refits have degraded the
  // tree). Call it after adding or removing many instances: trees built top down answer every query in fewer
  // instructions than trees grown by insertions (and keep no lanes emptied by removals).
  void rebuild() noexcept;
  void clear() noexcept;

  // ---- inspection ----
  std::size_t size() const noexcept;
  bool contains(InstanceId id) const noexcept;
  Status pose(InstanceId id, Transform<T>& out) const noexcept;
  // The instance's tree box (see above).
  Status bounds(InstanceId id, Bounds3<T>& out) const noexcept;
  // Every id, ascending.
  Status ids(std::vector<InstanceId>& out) const noexcept;
  // Depth of the tree (0 when empty; a lone leaf is 1), for diagnostics.
  std::uint32_t treeDepth() const noexcept;
  // Number of tree rebuilds so far (explicit and triggered), for diagnostics.
  std::uint64_t rebuildCount() const noexcept;
  // Whether rays walk the 8-wide ray tree (see Tree upkeep above), for diagnostics.
  bool rayTreeCurrent() const noexcept;

  // ---- queries (const, thread-safe) ----
  // The nearest hit within maxDist; hasHit says whether `hit` was written. Each instance is cast with maxHits 1.
  Status raycastClosest(const Vec3<T>& origin, const Vec3<T>& unitDir, T maxDist, SceneRaycastHit<T>& hit, bool& hasHit,
                        HitFlags hitFlags = kDefaultHitFlags, const SceneFilter& filter = {}) const noexcept;
  // Some hit within maxDist (the first the traversal finds), or none: hasHit is the same as raycastClosest's.
  Status raycastAny(const Vec3<T>& origin, const Vec3<T>& unitDir, T maxDist, SceneRaycastHit<T>& hit, bool& hasHit,
                    HitFlags hitFlags = kDefaultHitFlags, const SceneFilter& filter = {}) const noexcept;
  // The maxHits nearest hits, sorted by distance then id. Each instance is cast with maxHits (a mesh reports several
  // hits with HitFlag::MeshMultiple in hitFlags). `hits` holds maxHits entries; hitCount receives how many were
  // written.
  Status raycastAll(const Vec3<T>& origin, const Vec3<T>& unitDir, T maxDist, HitFlags hitFlags, std::uint32_t maxHits,
                    SceneRaycastHit<T>* hits, std::uint32_t& hitCount, const SceneFilter& filter = {}) const noexcept;
  // The first instance `shape` at `pose` touches when moved along unitDir up to maxDist (sweep() per instance).
  Status sweepClosest(const Vec3<T>& unitDir, T maxDist, const Shape<T>& shape, const Transform<T>& pose,
                      SceneSweepHit<T>& hit, bool& hasHit, HitFlags hitFlags = kDefaultHitFlags, T inflation = T(0),
                      const SceneFilter& filter = {}) const noexcept;
  // The ids of every instance overlapping `shape` at `pose` (touching counts), ascending. `ids` is replaced.
  Status overlapAll(const Shape<T>& shape, const Transform<T>& pose, std::vector<InstanceId>& ids,
                    const SceneFilter& filter = {}) const noexcept;
  // The instance nearest to `shape` at `pose` with signed distance <= maxDistance (+inf: no bound). Instances are
  // asked through distanceWithin() with the best distance so far, so far ones stop early; an instance that may be
  // nearer is asked again through distance(), whose answer `result` holds. `found` says whether
  // `result` was written.
  Status nearest(const Shape<T>& shape, const Transform<T>& pose, T maxDistance, SceneDistanceResult<T>& result,
                 bool& found, const SceneFilter& filter = {}) const noexcept;
  // Every overlapping pair of instances of this scene, sorted. `pairs` is replaced.
  Status overlappingPairs(std::vector<ScenePair>& pairs, const ScenePairFilter& filter = {}) const noexcept;
  // Every overlapping pair (instance of this scene, instance of `other`), sorted. `other` may be this scene.
  Status overlappingPairs(const Scene& other, std::vector<ScenePair>& pairs,
                          const ScenePairFilter& filter = {}) const noexcept;

  // Geometry<T> forms of the shape queries: the query geometry is validated (validateGeometry) on every call.
  Status sweepClosest(const Vec3<T>& unitDir, T maxDist, const Geometry<T>& geometry, const Transform<T>& pose,
                      SceneSweepHit<T>& hit, bool& hasHit, HitFlags hitFlags = kDefaultHitFlags, T inflation = T(0),
                      const SceneFilter& filter = {}) const noexcept;
  Status overlapAll(const Geometry<T>& geometry, const Transform<T>& pose, std::vector<InstanceId>& ids,
                    const SceneFilter& filter = {}) const noexcept;
  Status nearest(const Geometry<T>& geometry, const Transform<T>& pose, T maxDistance, SceneDistanceResult<T>& result,
                 bool& found, const SceneFilter& filter = {}) const noexcept;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace gq
