// gq::Scene (gq/scene.h): instances in a dynamic AABB tree (scene/aabb_tree.h) and the scene queries. Each query
// walks the tree to find the instances whose boxes allow a hit, then asks each through the single query of
// gq/shape.h with the arguments the loop over all instances would pass, so both give the same answer.
#include "gq/scene.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <limits>
#include <new>
#include <unordered_map>
#include <utility>

#include "common/validate.h"
#include "scene/aabb_tree.h"
#include "scene/ray_tree.h"

namespace gq {

namespace {

using detail::AabbTree;

// A stack with inline room for 64 entries (a tree that deep holds far more instances than memory); deeper trees
// spill to the heap, which may throw std::bad_alloc (the queries catch it).
template <class E> class SmallStack {
 public:
  void push(const E& v) {
    if (size_ < kInline) {
      inline_[size_] = v;
    } else {
      heap_.push_back(v);
    }
    ++size_;
  }
  E pop() {
    --size_;
    if (size_ < kInline) return inline_[size_];
    const E v = heap_.back();
    heap_.pop_back();
    return v;
  }
  bool empty() const { return size_ == 0; }

 private:
  static constexpr std::size_t kInline = 64;
  E inline_[kInline];
  std::size_t size_ = 0;
  std::vector<E> heap_;
};

// A ray prepared for slab tests: its origin and the reciprocals of its direction (infinite for a zero component).
template <class T> struct RaySlabs {
  Vec3<T> origin;
  Vec3<T> inverse;
  RaySlabs(const Vec3<T>& o, const Vec3<T>& d) : origin(o), inverse(d.cwiseInverse()) {}
};

// Entry parameter of the ray into the box [lo, hi] within [0, tMax]; false when it misses. A zero direction
// component gives infinite slab parameters (the origin outside that slab misses, inside it passes) or NaN for an
// origin exactly on a slab plane, which the comparisons ignore (the origin is inside that slab).
template <class T>
inline bool rayEntersBox(const RaySlabs<T>& r, const Vec3<T>& lo, const Vec3<T>& hi, T tMax, T& tEnter) {
  T t0 = T(0), t1 = tMax;
  for (int a = 0; a < 3; ++a) {
    const T ta = (lo[a] - r.origin[a]) * r.inverse[a];
    const T tb = (hi[a] - r.origin[a]) * r.inverse[a];
    const T tn = ta < tb ? ta : tb;
    const T tf = ta < tb ? tb : ta;
    if (tn > t0) t0 = tn;
    if (tf < t1) t1 = tf;
  }
  tEnter = t0;
  return t0 <= t1;
}

// A leaf's box: computeGeomBounds' box padded by a few ulps of its coordinates, so that the rounding of a slab test
// never loses a touch (a flat mesh has a box of zero thickness, which the bounds' inflation does not widen).
template <class T> Bounds3<T> paddedBox(const Bounds3<T>& b) {
  const T scale = std::max(b.min.cwiseAbs().maxCoeff(), b.max.cwiseAbs().maxCoeff());
  const T pad = scale * T(8) * std::numeric_limits<T>::epsilon() + std::numeric_limits<T>::min();
  return Bounds3<T>{b.min.array() - pad, b.max.array() + pad};
}

template <class T> T boxDistance(const Bounds3<T>& a, const Bounds3<T>& b) {
  const Vec3<T> gap = (a.min - b.max).cwiseMax(b.min - a.max).cwiseMax(Vec3<T>::Zero());
  return gap.norm();
}

bool passes(const SceneFilter& f, std::uint32_t mask, InstanceId id) {
  if ((f.mask & mask) == 0) return false;
  return f.callback == nullptr || f.callback(f.userData, id);
}

// A per-instance call that did not answer: bad query input fails the scene query; anything else (an unsupported
// pair, a solver that did not converge) leaves the instance out.
bool isInputError(const Status& s) { return s.code == StatusCode::InvalidArgument; }

Status skippedWarning(std::uint32_t skipped) {
  if (skipped == 0) return {};
  return Status::warning(
             "some instances were left out: their single query does not answer this pair (unsupported "
             "or not converged); index = how many")
      .withIndex(skipped);
}

Status outOfMemory() { return Status::internal("out of memory"); }

}  // namespace

template <class T> struct Scene<T>::Impl {
  struct Instance {
    InstanceId id = 0;
    Shape<T> shape;
    Transform<T> pose;
    Bounds3<T> box;
    std::uint32_t mask = 0;
    std::int32_t leaf = AabbTree<T>::kNull;  // kNull: unbounded, in `unbounded`
  };

  std::vector<Instance> instances;
  std::unordered_map<InstanceId, std::uint32_t> indexOf;
  std::vector<std::uint32_t> unbounded;  // instances whose box has no finite area (planes)
  AabbTree<T> tree;
  // The bounded instances in an 8-wide tree for rays: instances inserted as they are added, the whole built again
  // with each top-down rebuild (scene/ray_tree.h).
  detail::SceneRayTree<T> rayTree;
  // Adds since the ray tree was last built: when the tree has been left (an insertion deeper than its walk allows,
  // as instances added in sorted order make) and these reach an eighth of the instances (at least 64), the add builds
  // it again, as it does when removed instances' positions outnumber the live ones (adds and removes at a steady
  // size): an amortized O(log n) an add.
  std::size_t addsSinceRayTree = 0;
  std::uint64_t rebuilds = 0;

  static bool isBounded(const Bounds3<T>& b) { return std::isfinite(detail::boxArea(b)); }

  const Instance* find(InstanceId id) const {
    const auto it = indexOf.find(id);
    return it == indexOf.end() ? nullptr : &instances[it->second];
  }

  void removeUnbounded(std::uint32_t index) { unbounded.erase(std::find(unbounded.begin(), unbounded.end(), index)); }

  // The walkers below return false when memory ran out (a tree deeper than the inline stack, or a visitor's own
  // allocation): the caller reports it and writes nothing.
  template <class BoxTest, class Visit> bool forBoxes(const BoxTest& boxTest, const Visit& visit) const noexcept {
    try {
      walkBoxes(boxTest, visit);
    } catch (const std::bad_alloc&) {
      return false;
    }
    return true;
  }
  template <class Visit>
  bool forRay(const Vec3<T>& o, const Vec3<T>& d, T tMax, const Vec3<T>& grow, const Visit& visit) const noexcept {
    try {
      walkRay(o, d, tMax, grow, visit);
    } catch (const std::bad_alloc&) {
      return false;
    }
    return true;
  }

  template <class BoxTest, class Visit> void walkBoxes(const BoxTest& boxTest, const Visit& visit) const {
    for (std::uint32_t u : unbounded) visit(u);
    if (tree.root() == AabbTree<T>::kNull) return;
    SmallStack<std::int32_t> stack;
    stack.push(tree.root());
    while (!stack.empty()) {
      const auto& n = tree.node(stack.pop());
      if (!boxTest(n.box)) continue;
      if (n.isLeaf()) {
        visit(std::uint32_t(n.item));
      } else {
        stack.push(n.right);
        stack.push(n.left);
      }
    }
  }

  // Builds the ray tree over the bounded instances (after the binary tree's rebuild); without memory it stays
  // cleared and rays walk the binary tree.
  void buildRayTree() noexcept {
    addsSinceRayTree = 0;
    try {
      std::vector<std::uint32_t> bounded;
      std::vector<Bounds3<T>> boxes;
      bounded.reserve(instances.size());
      boxes.reserve(instances.size());
      for (std::uint32_t i = 0; i < instances.size(); ++i) {
        if (instances[i].leaf == AabbTree<T>::kNull) continue;
        bounded.push_back(i);
        boxes.push_back(instances[i].box);
      }
      (void)rayTree.build(bounded, boxes);
    } catch (const std::bad_alloc&) {
      rayTree.clear();
    }
  }

  // The ray tree's visit of an instance in a leaf the ray enters.
  template <class Visit> struct RayTreeVisit {
    const Visit& visit;
    T limit;
    static T call(void* context, std::uint32_t index) {
      auto& c = *static_cast<RayTreeVisit*>(context);
      c.limit = std::min(c.limit, c.visit(index));
      return c.limit;
    }
  };

  // Front-to-back ray walk: visit(index) returns the parameter beyond which nothing matters any more (tMax to go
  // on, a smaller value to prune, negative to stop). `grow` widens each box (a swept shape's extents). Rays (no
  // growth) walk the ray tree when it is current, else the binary tree: both visit every instance whose box the
  // ray enters before the limit.
  template <class Visit>
  void walkRay(const Vec3<T>& o, const Vec3<T>& d, T tMax, const Vec3<T>& grow, const Visit& visit) const {
    T limit = tMax;
    for (std::uint32_t u : unbounded) {
      limit = std::min(limit, visit(u));
      if (limit < T(0)) return;
    }
    if (tree.root() == AabbTree<T>::kNull) return;
    if (rayTree.ready() && grow == Vec3<T>::Zero()) {
      RayTreeVisit<Visit> context{visit, limit};
      if (rayTree.walkRay(o, d, limit, &RayTreeVisit<Visit>::call, &context)) return;
    }
    struct Entry {
      std::int32_t node;
      T t;
    };
    SmallStack<Entry> stack;
    T t0;
    const RaySlabs<T> ray(o, d);
    auto enters = [&](std::int32_t node, T& t) {
      const Bounds3<T>& b = tree.node(node).box;
      return rayEntersBox(ray, Vec3<T>(b.min - grow), Vec3<T>(b.max + grow), limit, t);
    };
    if (!enters(tree.root(), t0)) return;
    stack.push({tree.root(), t0});
    while (!stack.empty()) {
      const Entry e = stack.pop();
      if (e.t > limit) continue;
      const auto& n = tree.node(e.node);
      if (n.isLeaf()) {
        limit = std::min(limit, visit(std::uint32_t(n.item)));
        if (limit < T(0)) return;
        continue;
      }
      T tl, tr;
      const bool hl = enters(n.left, tl);
      const bool hr = enters(n.right, tr);
      if (hl && hr) {  // the nearer one on top
        if (tl <= tr) {
          stack.push({n.right, tr});
          stack.push({n.left, tl});
        } else {
          stack.push({n.left, tl});
          stack.push({n.right, tr});
        }
      } else if (hl) {
        stack.push({n.left, tl});
      } else if (hr) {
        stack.push({n.right, tr});
      }
    }
  }

  void maybeRebuild() {
    if (tree.degraded(kRebuildAreaFactor)) {
      tree.rebuild();
      ++rebuilds;
      buildRayTree();
    }
  }
};

template <class T> Scene<T>::Scene() : impl_(new Impl()) {}
template <class T> Scene<T>::~Scene() = default;
template <class T> Scene<T>::Scene(Scene&&) noexcept = default;
template <class T> Scene<T>& Scene<T>::operator=(Scene&&) noexcept = default;

// ---- mutation ---------------------------------------------------------------------------------------------------

template <class T>
Status Scene<T>::add(InstanceId id, const Geometry<T>& geometry, const Transform<T>& pose,
                     std::uint32_t mask) noexcept {
  Shape<T> shape;
  if (Status s = Shape<T>::make(geometry, shape); !s.ok()) return s;
  return add(id, shape, pose, mask);
}

template <class T>
Status Scene<T>::add(InstanceId id, const Shape<T>& shape, const Transform<T>& pose, std::uint32_t mask) noexcept {
  if (!impl_) impl_.reset(new (std::nothrow) Impl());
  if (!impl_) return outOfMemory();
  if (shape.empty()) return Status::invalid("the shape is empty (not made by Shape::make)");
  if (Status s = detail::checkPose(pose, detail::kPoseField); !s.ok()) return s;
  if (impl_->indexOf.count(id)) return Status::invalid("an instance with this id is already in the scene");
  Bounds3<T> box;
  if (Status s = computeGeomBounds(box, shape, pose); !s.ok()) return s;
  box = paddedBox(box);
  Impl& m = *impl_;
  try {
    // Everything that allocates happens before the scene changes.
    m.instances.reserve(m.instances.size() + 1 > m.instances.capacity() ? 2 * m.instances.size() + 1 : 0);
    m.unbounded.reserve(m.unbounded.size() + 1);
    m.tree.reserve(m.instances.size() + 1);
    m.indexOf.reserve(m.instances.size() + 1);
    typename Impl::Instance inst;
    inst.id = id;
    inst.shape = shape;
    inst.pose = pose;
    inst.box = box;
    inst.mask = mask;
    const std::uint32_t index = std::uint32_t(m.instances.size());
    m.indexOf.emplace(id, index);
    if (Impl::isBounded(box)) {
      inst.leaf = m.tree.insert(box, std::int32_t(index));
    } else {
      m.unbounded.push_back(index);
    }
    m.instances.push_back(std::move(inst));
  } catch (const std::bad_alloc&) {
    return outOfMemory();
  }
  if (m.instances.back().leaf != AabbTree<T>::kNull) (void)m.rayTree.insert(std::uint32_t(m.instances.size() - 1), box);
  ++m.addsSinceRayTree;
  const std::size_t n = m.instances.size();
  if (m.rayTree.ready() ? m.rayTree.positions() > 2 * n + 64 : m.addsSinceRayTree >= std::max<std::size_t>(64, n / 8)) {
    m.buildRayTree();
  }
  return {};
}

template <class T> Status Scene<T>::remove(InstanceId id) noexcept {
  if (!impl_) return Status::invalid("no instance with this id in the scene");
  Impl& m = *impl_;
  const auto it = m.indexOf.find(id);
  if (it == m.indexOf.end()) return Status::invalid("no instance with this id in the scene");
  const std::uint32_t index = it->second;
  const std::uint32_t last = std::uint32_t(m.instances.size() - 1);
  if (m.instances[index].leaf != AabbTree<T>::kNull) {
    m.tree.remove(m.instances[index].leaf);
  } else {
    m.removeUnbounded(index);
  }
  m.indexOf.erase(it);
  if (index != last) {  // the last instance fills the hole
    m.instances[index] = std::move(m.instances[last]);
    auto& moved = m.instances[index];
    m.indexOf[moved.id] = index;  // the key exists: no allocation
    if (moved.leaf != AabbTree<T>::kNull) {
      m.tree.setItem(moved.leaf, std::int32_t(index));
    } else {
      *std::find(m.unbounded.begin(), m.unbounded.end(), last) = index;
    }
  }
  m.instances.pop_back();
  m.rayTree.remove(index, last);
  return {};
}

template <class T> Status Scene<T>::setPose(InstanceId id, const Transform<T>& pose) noexcept {
  if (!impl_) return Status::invalid("no instance with this id in the scene");
  Impl& m = *impl_;
  const auto it = m.indexOf.find(id);
  if (it == m.indexOf.end()) return Status::invalid("no instance with this id in the scene");
  if (Status s = detail::checkPose(pose, detail::kPoseField); !s.ok()) return s;
  auto& inst = m.instances[it->second];
  Bounds3<T> box;
  if (Status s = computeGeomBounds(box, inst.shape, pose); !s.ok()) return s;
  box = paddedBox(box);
  // A shape's boundedness does not depend on its pose (planes are unbounded everywhere); a box that overflows
  // at a far pose stays where it is and the move is refused.
  if (Impl::isBounded(box) != (inst.leaf != AabbTree<T>::kNull)) {
    return Status::invalid("pose is too far from the origin: the instance's bounds overflow");
  }
  inst.pose = pose;
  inst.box = box;
  if (inst.leaf != AabbTree<T>::kNull) {
    m.tree.refit(inst.leaf, box);
    (void)m.rayTree.refit(it->second, box);
    try {
      m.maybeRebuild();
    } catch (const std::bad_alloc&) {
      // The refit tree stays valid; it is rebuilt on a later move.
    }
  }
  return {};
}

template <class T> Status Scene<T>::setMask(InstanceId id, std::uint32_t mask) noexcept {
  if (!impl_) return Status::invalid("no instance with this id in the scene");
  const auto it = impl_->indexOf.find(id);
  if (it == impl_->indexOf.end()) return Status::invalid("no instance with this id in the scene");
  impl_->instances[it->second].mask = mask;
  return {};
}

template <class T> void Scene<T>::rebuild() noexcept {
  if (!impl_) return;
  try {
    impl_->tree.rebuild();
    ++impl_->rebuilds;
  } catch (const std::bad_alloc&) {
    // rebuild allocates before it changes the tree: the tree stays as it was.
  }
  impl_->buildRayTree();
}

template <class T> void Scene<T>::clear() noexcept {
  if (!impl_) return;
  impl_->instances.clear();
  impl_->indexOf.clear();
  impl_->unbounded.clear();
  impl_->tree.clear();
  impl_->rayTree.reset();
}

// ---- inspection -------------------------------------------------------------------------------------------------

template <class T> std::size_t Scene<T>::size() const noexcept { return impl_ ? impl_->instances.size() : 0; }
template <class T> bool Scene<T>::contains(InstanceId id) const noexcept { return impl_ && impl_->find(id); }

template <class T> Status Scene<T>::pose(InstanceId id, Transform<T>& out) const noexcept {
  const auto* inst = impl_ ? impl_->find(id) : nullptr;
  if (!inst) return Status::invalid("no instance with this id in the scene");
  out = inst->pose;
  return {};
}

template <class T> Status Scene<T>::bounds(InstanceId id, Bounds3<T>& out) const noexcept {
  const auto* inst = impl_ ? impl_->find(id) : nullptr;
  if (!inst) return Status::invalid("no instance with this id in the scene");
  out = inst->box;
  return {};
}

template <class T> Status Scene<T>::ids(std::vector<InstanceId>& out) const noexcept {
  try {
    std::vector<InstanceId> v;
    if (impl_) {
      v.reserve(impl_->instances.size());
      for (const auto& inst : impl_->instances) v.push_back(inst.id);
    }
    std::sort(v.begin(), v.end());
    out.swap(v);
  } catch (const std::bad_alloc&) {
    return outOfMemory();
  }
  return {};
}

template <class T> std::uint32_t Scene<T>::treeDepth() const noexcept { return impl_ ? impl_->tree.depth() : 0; }
template <class T> bool Scene<T>::rayTreeCurrent() const noexcept { return impl_ && impl_->rayTree.ready(); }
template <class T> std::uint64_t Scene<T>::rebuildCount() const noexcept { return impl_ ? impl_->rebuilds : 0; }

// ---- raycasts ---------------------------------------------------------------------------------------------------

namespace {
template <class T> Status checkRay(const Vec3<T>& origin, const Vec3<T>& unitDir, T maxDist) {
  if (Status s = detail::checkFinite(origin, detail::kRayOriginField); !s.ok()) return s;
  if (Status s = detail::checkUnitDirection(unitDir, detail::kRayDirectionField); !s.ok()) return s;
  return detail::checkMaxDist(maxDist);
}

// The length of an instance's raycast once the hits kept end at distance d: a few units beyond d (within maxDist), so
// that a hit at exactly d (a tie the smaller id may win) is found by tests that compare t scaled by a determinant
// (heightfield triangles), and a ray starting on a surface (d = 0) still has a length.
template <class T> T reachOf(T d, T maxDist) {
  return std::min(d * (T(1) + T(16) * std::numeric_limits<T>::epsilon()) + std::numeric_limits<T>::min(), maxDist);
}

// (distance, id) order; ties in both keep the earlier.
template <class T> bool hitBefore(T d0, InstanceId id0, T d1, InstanceId id1) {
  return d0 < d1 || (d0 == d1 && id0 < id1);
}

// One ray through the scene's instances: the filter, then each instance's own raycast. An input error stops the walk
// and is returned; an instance that cannot answer (unsupported) is counted and left out.
template <class T> struct SceneRayWalk {
  SceneRayWalk(const Vec3<T>& o, const Vec3<T>& d, T m, HitFlags f, const SceneFilter& fl)
      : origin(o), unitDir(d), maxDist(m), hitFlags(f), filter(fl),
        fullLength(f.has(HitFlag::AnyHit) || f.has(HitFlag::MeshMultiple)) {}
  const Vec3<T>& origin;
  const Vec3<T>& unitDir;
  T maxDist;
  HitFlags hitFlags;
  const SceneFilter& filter;
  bool fullLength;  // every instance's raycast runs to maxDist (see cast)
  Status failure;
  std::uint32_t skipped = 0;

  // The hits written to `hits` (at most maxHits; 0 when filtered out or left out), or -1 when the walk must stop.
  // `reach`: the distance beyond which the caller keeps no hit (the early-out fed to the instance's raycast), at
  // most maxDist. A kernel's closest hit does not depend on the ray's length once the length reaches it, so the hits
  // kept are the ones a raycast to maxDist returns. Not so for a custom shape's callback, for an any-hit raycast (the
  // first hit found within the length) or for several hits a mesh (ties at its maxHits-th hit kept by the order
  // found): those get maxDist, as in the loop over all instances.
  template <class Instance>
  int cast(const Instance& inst, std::uint32_t maxHits, RaycastHit<T>* hits, T reach) {
    if (!passes(filter, inst.mask, inst.id)) return 0;
    std::uint32_t n = 0;
    const T length = fullLength || inst.shape.geometry().type() == GeometryType::Custom ? maxDist : reach;
    const Status s = raycast(origin, unitDir, inst.shape, inst.pose, length, hitFlags, maxHits, hits, n);
    if (s.ok()) return int(n);
    if (isInputError(s)) {
      failure = s;
      return -1;
    }
    ++skipped;
    return 0;
  }
};
}  // namespace

template <class T>
Status Scene<T>::raycastClosest(const Vec3<T>& origin, const Vec3<T>& unitDir, T maxDist, SceneRaycastHit<T>& hit,
                                bool& hasHit, HitFlags hitFlags, const SceneFilter& filter) const noexcept {
  if (Status s = checkRay(origin, unitDir, maxDist); !s.ok()) return s;
  SceneRayWalk<T> walk(origin, unitDir, maxDist, hitFlags, filter);
  SceneRaycastHit<T> best;
  bool found = false;
  if (impl_) {
    const Impl& m = *impl_;
    if (!m.forRay(origin, unitDir, maxDist, Vec3<T>::Zero(), [&](std::uint32_t i) -> T {
          const auto& inst = m.instances[i];
          RaycastHit<T> h;
          const int n = walk.cast(inst, 1u, &h, found ? reachOf(best.hit.distance, maxDist) : maxDist);
          if (n < 0) return T(-1);
          if (n > 0 && (!found || hitBefore(h.distance, inst.id, best.hit.distance, best.id))) {
            best.id = inst.id;
            best.hit = h;
            found = true;
          }
          return found ? best.hit.distance : maxDist;
        })) {
      return outOfMemory();
    }
  }
  if (!walk.failure.ok()) return walk.failure;
  hasHit = found;
  if (found) hit = best;
  return skippedWarning(walk.skipped);
}

template <class T>
Status Scene<T>::raycastAny(const Vec3<T>& origin, const Vec3<T>& unitDir, T maxDist, SceneRaycastHit<T>& hit,
                            bool& hasHit, HitFlags hitFlags, const SceneFilter& filter) const noexcept {
  if (Status s = checkRay(origin, unitDir, maxDist); !s.ok()) return s;
  SceneRayWalk<T> walk(origin, unitDir, maxDist, hitFlags, filter);
  SceneRaycastHit<T> any;
  bool found = false;
  if (impl_) {
    const Impl& m = *impl_;
    if (!m.forRay(origin, unitDir, maxDist, Vec3<T>::Zero(), [&](std::uint32_t i) -> T {
          const auto& inst = m.instances[i];
          RaycastHit<T> h;
          const int n = walk.cast(inst, 1u, &h, maxDist);
          if (n < 0) return T(-1);
          if (n == 0) return maxDist;
          any.id = inst.id;
          any.hit = h;
          found = true;
          return T(-1);
        })) {
      return outOfMemory();
    }
  }
  if (!walk.failure.ok()) return walk.failure;
  hasHit = found;
  if (found) {
    hit = any;
    return {};  // instances left out before the hit do not change that there is one
  }
  return skippedWarning(walk.skipped);
}

template <class T>
Status Scene<T>::raycastAll(const Vec3<T>& origin, const Vec3<T>& unitDir, T maxDist, HitFlags hitFlags,
                            std::uint32_t maxHits, SceneRaycastHit<T>* hits, std::uint32_t& hitCount,
                            const SceneFilter& filter) const noexcept {
  if (Status s = checkRay(origin, unitDir, maxDist); !s.ok()) return s;
  if (maxHits == 0) return Status::invalid("maxHits is 0");
  if (hits == nullptr) return Status::invalid("hits is null");
  SceneRayWalk<T> walk(origin, unitDir, maxDist, hitFlags, filter);
  std::vector<SceneRaycastHit<T>> best;  // sorted by (distance, id), at most maxHits
  try {
    std::vector<RaycastHit<T>> local(maxHits);
    best.reserve(std::min<std::uint32_t>(maxHits, 1024u));
    if (impl_) {
      const Impl& m = *impl_;
      if (!m.forRay(origin, unitDir, maxDist, Vec3<T>::Zero(), [&](std::uint32_t i) -> T {
            const auto& inst = m.instances[i];
            const T reach = best.size() == maxHits ? reachOf(best.back().hit.distance, maxDist) : maxDist;
            const int n = walk.cast(inst, maxHits, local.data(), reach);
            if (n < 0) return T(-1);
            for (int k = 0; k < n; ++k) {
              const SceneRaycastHit<T> h{inst.id, local[k]};
              const auto pos = std::upper_bound(best.begin(), best.end(), h, [](const auto& a, const auto& b) {
                return hitBefore(a.hit.distance, a.id, b.hit.distance, b.id);
              });
              if (best.size() == maxHits) {
                if (pos == best.end()) continue;
                best.pop_back();
              }
              best.insert(pos, h);
            }
            return best.size() == maxHits ? best.back().hit.distance : maxDist;
          })) {
        return outOfMemory();
      }
    }
  } catch (const std::bad_alloc&) {
    return outOfMemory();
  }
  if (!walk.failure.ok()) return walk.failure;
  std::copy(best.begin(), best.end(), hits);
  hitCount = std::uint32_t(best.size());
  return skippedWarning(walk.skipped);
}

// ---- sweep, overlap, nearest ------------------------------------------------------------------------------------

template <class T>
Status Scene<T>::sweepClosest(const Vec3<T>& unitDir, T maxDist, const Shape<T>& shape, const Transform<T>& pose,
                              SceneSweepHit<T>& hit, bool& hasHit, HitFlags hitFlags, T inflation,
                              const SceneFilter& filter) const noexcept {
  if (shape.empty()) return Status::invalid("the shape is empty (not made by Shape::make)");
  if (Status s = detail::checkPose(pose, detail::kPoseField); !s.ok()) return s;
  if (Status s = detail::checkUnitDirection(unitDir, detail::kSweepDirectionField); !s.ok()) return s;
  if (Status s = detail::checkMaxDist(maxDist); !s.ok()) return s;
  if (!std::isfinite(inflation) || inflation < T(0)) return Status::invalid("inflation is negative or not finite");
  Bounds3<T> qb;
  if (Status s = computeGeomBounds(qb, shape, pose, inflation); !s.ok()) return s;
  qb = paddedBox(qb);
  SceneSweepHit<T> best;
  bool found = false;
  Status failure;
  std::uint32_t skipped = 0;
  if (impl_ && std::isfinite(detail::boxArea(qb))) {
    const Impl& m = *impl_;
    const T travel = std::min(maxDist, T(tol::kMaxSweepDistance));
    if (!m.forRay(qb.center(), unitDir, travel, qb.extents(), [&](std::uint32_t i) -> T {
          const auto& inst = m.instances[i];
          if (!passes(filter, inst.mask, inst.id)) return travel;
          SweepHit<T> h;
          bool has = false;
          const Status s = sweep(unitDir, maxDist, shape, pose, inst.shape, inst.pose, h, has, hitFlags, inflation);
          if (!s.ok()) {
            if (isInputError(s)) {
              failure = s;
              return T(-1);
            }
            ++skipped;
            return travel;
          }
          if (has && (!found || hitBefore(h.distance, inst.id, best.hit.distance, best.id))) {
            best.id = inst.id;
            best.hit = h;
            found = true;
          }
          // A hit with initial overlap (distance 0 or -depth) ends the search only at its own distance.
          return found ? std::max(best.hit.distance, T(0)) : travel;
        })) {
      return outOfMemory();
    }
  } else if (impl_ && !impl_->instances.empty()) {
    return Status::unsupported("sweep of an unbounded shape (plane) through a scene");
  }
  if (!failure.ok()) return failure;
  hasHit = found;
  if (found) hit = best;
  return skippedWarning(skipped);
}

template <class T>
Status Scene<T>::overlapAll(const Shape<T>& shape, const Transform<T>& pose, std::vector<InstanceId>& ids,
                            const SceneFilter& filter) const noexcept {
  if (shape.empty()) return Status::invalid("the shape is empty (not made by Shape::make)");
  if (Status s = detail::checkPose(pose, detail::kPoseField); !s.ok()) return s;
  Bounds3<T> qb;
  if (Status s = computeGeomBounds(qb, shape, pose); !s.ok()) return s;
  qb = paddedBox(qb);
  Status failure;
  std::uint32_t skipped = 0;
  std::vector<InstanceId> out;
  try {
    if (impl_) {
      const Impl& m = *impl_;
      if (!m.forBoxes([&](const Bounds3<T>& b) { return failure.ok() && b.overlaps(qb); },
                      [&](std::uint32_t i) {
                        if (!failure.ok()) return;
                        const auto& inst = m.instances[i];
                        if (!passes(filter, inst.mask, inst.id)) return;
                        bool hitting = false;
                        const Status s = overlap(shape, pose, inst.shape, inst.pose, hitting);
                        if (!s.ok()) {
                          if (isInputError(s))
                            failure = s;
                          else
                            ++skipped;
                          return;
                        }
                        if (hitting) out.push_back(inst.id);
                      })) {
        return outOfMemory();
      }
    }
    std::sort(out.begin(), out.end());
  } catch (const std::bad_alloc&) {
    return outOfMemory();
  }
  if (!failure.ok()) return failure;
  ids.swap(out);
  return skippedWarning(skipped);
}

template <class T>
Status Scene<T>::nearest(const Shape<T>& shape, const Transform<T>& pose, T maxDistance, SceneDistanceResult<T>& result,
                         bool& found, const SceneFilter& filter) const noexcept {
  if (shape.empty()) return Status::invalid("the shape is empty (not made by Shape::make)");
  if (Status s = detail::checkPose(pose, detail::kPoseField); !s.ok()) return s;
  if (std::isnan(maxDistance)) return Status::invalid("maxDistance is NaN");
  Bounds3<T> qb;
  if (Status s = computeGeomBounds(qb, shape, pose); !s.ok()) return s;
  qb = paddedBox(qb);
  SceneDistanceResult<T> best;
  bool any = false;
  T bound = maxDistance;  // the best distance so far, or the caller's bound
  Status failure;
  std::uint32_t skipped = 0;
  if (impl_) {
    const Impl& m = *impl_;
    // Boxes farther than the bound cannot hold a nearer instance; while the bound is <= 0 (penetration), every box
    // touching the query's may hold a deeper one.
    if (!m.forBoxes([&](const Bounds3<T>& b) { return failure.ok() && !(boxDistance(b, qb) > std::max(bound, T(0))); },
                    [&](std::uint32_t i) {
                      if (!failure.ok()) return;
                      const auto& inst = m.instances[i];
                      if (!passes(filter, inst.mask, inst.id)) return;
                      DistanceResult<T> r;
                      bool beyond = false;
                      // distanceWithin proves most far pairs beyond the best so far cheaply; one step above it keeps a
                      // pair at exactly that distance (a tie the smaller id may win).
                      const T within =
                          std::isfinite(bound) ? std::nextafter(bound, std::numeric_limits<T>::infinity()) : bound;
                      const Status s = distanceWithin(r, beyond, within, shape, pose, inst.shape, inst.pose);
                      if (!s.ok()) {
                        if (isInputError(s))
                          failure = s;
                        else
                          ++skipped;
                        return;
                      }
                      if (beyond || r.distance > bound) return;
                      // A candidate: its answer is distance()'s (distanceWithin's may differ in the last bits where its
                      // search stopped early), so the nearest is the same whichever instances were asked before it.
                      if (Status e = distance(r, shape, pose, inst.shape, inst.pose); !e.ok()) {
                        ++skipped;
                        return;
                      }
                      if (r.distance > bound) return;
                      if (!any || hitBefore(r.distance, inst.id, best.result.distance, best.id)) {
                        best.id = inst.id;
                        best.result = r;
                        any = true;
                        bound = r.distance;
                      }
                    })) {
      return outOfMemory();
    }
  }
  if (!failure.ok()) return failure;
  found = any;
  if (any) result = best;
  return skippedWarning(skipped);
}

template <class T>
Status Scene<T>::sweepClosest(const Vec3<T>& unitDir, T maxDist, const Geometry<T>& geometry, const Transform<T>& pose,
                              SceneSweepHit<T>& hit, bool& hasHit, HitFlags hitFlags, T inflation,
                              const SceneFilter& filter) const noexcept {
  Shape<T> shape;
  if (Status s = Shape<T>::make(geometry, shape); !s.ok()) return s;
  return sweepClosest(unitDir, maxDist, shape, pose, hit, hasHit, hitFlags, inflation, filter);
}

template <class T>
Status Scene<T>::overlapAll(const Geometry<T>& geometry, const Transform<T>& pose, std::vector<InstanceId>& ids,
                            const SceneFilter& filter) const noexcept {
  Shape<T> shape;
  if (Status s = Shape<T>::make(geometry, shape); !s.ok()) return s;
  return overlapAll(shape, pose, ids, filter);
}

template <class T>
Status Scene<T>::nearest(const Geometry<T>& geometry, const Transform<T>& pose, T maxDistance,
                         SceneDistanceResult<T>& result, bool& found, const SceneFilter& filter) const noexcept {
  Shape<T> shape;
  if (Status s = Shape<T>::make(geometry, shape); !s.ok()) return s;
  return nearest(shape, pose, maxDistance, result, found, filter);
}

// ---- overlapping pairs ------------------------------------------------------------------------------------------

namespace {

// Candidate pairs (instance index in a, instance index in b) whose boxes overlap; `self` skips (i, i) and lists
// each unordered pair once.
template <class T, class Inst>
void candidatePairs(const AabbTree<T>& ta, const std::vector<std::uint32_t>& ua, const std::vector<Inst>& ia,
                    const AabbTree<T>& tb, const std::vector<std::uint32_t>& ub, const std::vector<Inst>& ib, bool self,
                    std::vector<std::pair<std::uint32_t, std::uint32_t>>& out) {
  using Tree = AabbTree<T>;
  // Unbounded instances against everything.
  for (std::uint32_t u : ua) {
    for (std::uint32_t j = 0; j < ib.size(); ++j) {
      if (self && (j == u || (ib[j].leaf == Tree::kNull && j < u))) continue;
      out.emplace_back(u, j);
    }
  }
  for (std::uint32_t u : ub) {
    if (self) break;  // listed above
    for (std::uint32_t i = 0; i < ia.size(); ++i) {
      if (ia[i].leaf == Tree::kNull) continue;  // listed above
      out.emplace_back(i, u);
    }
  }
  if (ta.root() == Tree::kNull || tb.root() == Tree::kNull) return;
  // Pairs of nodes (a, b) whose boxes overlap; in a self walk a == b means "pairs inside a". A pair is tested
  // before it is pushed, so every popped pair is descended.
  SmallStack<std::pair<std::int32_t, std::int32_t>> stack;
  const auto pushIfOverlapping = [&](std::int32_t a, std::int32_t b) {
    if (ta.node(a).box.overlaps(tb.node(b).box)) stack.push({a, b});
  };
  if (self)
    stack.push({ta.root(), tb.root()});
  else
    pushIfOverlapping(ta.root(), tb.root());
  while (!stack.empty()) {
    const auto [a, b] = stack.pop();
    const auto& na = ta.node(a);
    const auto& nb = tb.node(b);
    if (self && a == b) {
      if (na.isLeaf()) continue;
      stack.push({na.left, na.left});
      stack.push({na.right, na.right});
      pushIfOverlapping(na.left, na.right);
      continue;
    }
    if (na.isLeaf() && nb.isLeaf()) {
      out.emplace_back(std::uint32_t(na.item), std::uint32_t(nb.item));
    } else if (nb.isLeaf() || (!na.isLeaf() && detail::boxArea(na.box) >= detail::boxArea(nb.box))) {
      pushIfOverlapping(na.left, b);
      pushIfOverlapping(na.right, b);
    } else {
      pushIfOverlapping(a, nb.left);
      pushIfOverlapping(a, nb.right);
    }
  }
}

}  // namespace

template <class T>
Status Scene<T>::overlappingPairs(std::vector<ScenePair>& pairs, const ScenePairFilter& filter) const noexcept {
  std::vector<ScenePair> out;
  std::uint32_t skipped = 0;
  try {
    if (impl_) {
      const Impl& m = *impl_;
      std::vector<std::pair<std::uint32_t, std::uint32_t>> cand;
      candidatePairs(m.tree, m.unbounded, m.instances, m.tree, m.unbounded, m.instances, true, cand);
      for (auto [i, j] : cand) {
        const auto* a = &m.instances[i];
        const auto* b = &m.instances[j];
        if (b->id < a->id) std::swap(a, b);
        if ((a->mask & b->mask) == 0) continue;
        if (filter.callback && !filter.callback(filter.userData, a->id, b->id)) continue;
        bool hitting = false;
        const Status s = overlap(a->shape, a->pose, b->shape, b->pose, hitting);
        if (!s.ok()) {  // e.g. an unsupported pair, or an offset too large for a pair query
          ++skipped;
          continue;
        }
        if (hitting) out.push_back({a->id, b->id});
      }
    }
    std::sort(out.begin(), out.end(), [](const ScenePair& x, const ScenePair& y) {
      return x.id0 < y.id0 || (x.id0 == y.id0 && x.id1 < y.id1);
    });
  } catch (const std::bad_alloc&) {
    return outOfMemory();
  }
  pairs.swap(out);
  return skippedWarning(skipped);
}

template <class T>
Status Scene<T>::overlappingPairs(const Scene& other, std::vector<ScenePair>& pairs,
                                  const ScenePairFilter& filter) const noexcept {
  std::vector<ScenePair> out;
  std::uint32_t skipped = 0;
  try {
    if (impl_ && other.impl_) {
      const Impl& ma = *impl_;
      const Impl& mb = *other.impl_;
      std::vector<std::pair<std::uint32_t, std::uint32_t>> cand;
      candidatePairs(ma.tree, ma.unbounded, ma.instances, mb.tree, mb.unbounded, mb.instances, false, cand);
      for (auto [i, j] : cand) {
        const auto& a = ma.instances[i];
        const auto& b = mb.instances[j];
        if ((a.mask & b.mask) == 0) continue;
        if (filter.callback && !filter.callback(filter.userData, a.id, b.id)) continue;
        bool hitting = false;
        const Status s = overlap(a.shape, a.pose, b.shape, b.pose, hitting);
        if (!s.ok()) {
          ++skipped;
          continue;
        }
        if (hitting) out.push_back({a.id, b.id});
      }
    }
    std::sort(out.begin(), out.end(), [](const ScenePair& x, const ScenePair& y) {
      return x.id0 < y.id0 || (x.id0 == y.id0 && x.id1 < y.id1);
    });
  } catch (const std::bad_alloc&) {
    return outOfMemory();
  }
  pairs.swap(out);
  return skippedWarning(skipped);
}

template class Scene<float>;
template class Scene<double>;

}  // namespace gq
