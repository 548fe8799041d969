// Branch and bound over two Gauss-map trees for the exact MTD of two polytopes (see hull_pair_mtd.h).
#include "penetration/hull_pair_mtd.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "gjk/support_map.h"
#include "gjk/support_table.h"
#include "gq/tolerances.h"
#include "penetration/gauss_tree.h"
#include "penetration/polytope_mtd.h"

namespace gq::detail {
namespace {

// A tree's face planes through plain pointers, which the loops over faces keep in registers across their stores.
template <class T> struct Planes {
  const Vec3<T>* normal;
  const T* offset;
  T scale;
  // How far face f must move the other shape's point w (own frame) to put it outside: -offset - n.w.
  T pushOut(std::uint32_t f, const Vec3<T>& w) const { return -offset[f] * scale - normal[f].dot(w); }
};

// One shape in its own frame: its tree, vertices (times a uniform scale) and support map, and the map from its frame
// to the other shape's.
template <class T> struct Side {
  const GaussTree<T>* tree = nullptr;
  const ConvexMesh<T>* mesh = nullptr;  // null for a box
  const SupportStartTable<T>* table = nullptr;
  bool climb = false;
  std::uint32_t hint = 0;
  bool cold = true;
  Vec3<T> halfExtents = Vec3<T>::Zero();
  T scale = T(1);
  Vec3<T> innerCentre = Vec3<T>::Zero();  // a ball inside the shape (own frame)
  T innerRadius = T(0);
  Mat3<T> rot;    // own frame -> other frame: x_other = rot * x_own + trans
  Vec3<T> trans;
  bool first = true;  // geom0 (its frame is the search's)

  Vec3<T> vertex(std::uint32_t i) const {
    if (mesh) return mesh->vertices[i] * scale;
    return Vec3<T>((i & 1) ? halfExtents.x() : -halfExtents.x(), (i & 2) ? halfExtents.y() : -halfExtents.y(),
                   (i & 4) ? halfExtents.z() : -halfExtents.z());
  }
  // The point of the shape extreme along d (own frame).
  Vec3<T> support(const Vec3<T>& d) {
    if (!mesh) return supportBox(halfExtents, d);
    return mesh->vertices[hullVertex(*mesh, table, climb, d, hint, cold)] * scale;
  }
  // A vertex of the shape near the extreme along d (own frame): the support start table's vertex for d, without the
  // climb (a point of the shape is all a lower bound needs).
  Vec3<T> nearSupport(const Vec3<T>& d) {
    if (!mesh) return supportBox(halfExtents, d);
    if (!climb || !table || !table->hasClimbGraph()) return support(d);
    return mesh->vertices[table->lookup(d)] * scale;
  }
  Planes<T> planes() const { return {tree->faceNormal.data(), tree->faceOffset.data(), scale}; }
  // An own-frame vector in geom0's frame.
  Vec3<T> vectorToFirst(const Vec3<T>& v) const { return first ? v : Vec3<T>(rot * v); }
  Vec3<T> pointToFirst(const Vec3<T>& p) const { return first ? p : Vec3<T>(rot * p + trans); }
};

// The point of `other` extreme along the own-frame direction d, in own's frame.
template <class T> Vec3<T> otherSupport(const Side<T>& own, Side<T>& other, const Vec3<T>& d) {
  const Vec3<T> w = other.support(Vec3<T>(own.rot * d));
  return own.rot.transpose() * (w - own.trans);
}

// A point of `other` near its extreme along the own-frame direction d, in own's frame.
template <class T> Vec3<T> otherNearSupport(const Side<T>& own, Side<T>& other, const Vec3<T>& d) {
  const Vec3<T> w = other.nearSupport(Vec3<T>(own.rot * d));
  return own.rot.transpose() * (w - own.trans);
}

// h(d) of a side, d in geom0's frame.
template <class T> T supportValue(Side<T>& side, const Vec3<T>& d) {
  if (side.first) return d.dot(side.support(d));
  const Vec3<T> local = side.rot.transpose() * d;
  return local.dot(side.support(local)) + d.dot(side.trans);
}

// A lower bound of u.z over the arc from n1 to n2, from e1 = n1.z, e2 = n2.z (polytope_mtd.h); -max for nearly
// opposite normals.
template <class T> T arcMinimum(T e1, T e2, T halfCos) {
  const T low = std::min(e1, e2);
  if (low > T(0)) return low;
  return halfCos > T(1e-3) ? low / halfCos : -std::numeric_limits<T>::max();
}

// A node waiting in the search: its bound, and where the other side's support point it was computed from is kept
// (PairScratch::support, own frame). 16 bytes in float too: the heap's moves and index arithmetic on 12-byte entries
// were measured to cost 3% more instructions per 300-point hull query.
template <class T> struct alignas(16) HeapEntry {
  T bound;
  std::uint32_t side : 1, lazy : 1, node : 30;  // lazy: `bound` is the inner-ball bound (no support point yet)
  std::uint32_t support;
  bool operator>(const HeapEntry& o) const { return bound > o.bound; }
};

// An edge arc in geom0's frame (negated for the second shape, so that arcs cross at facet normals of A - B).
template <class T> struct Arc {
  Vec3<T> n1, n2, plane, mid;  // plane = n2 x n1; mid = normalised n1 + n2
  Vec3<T> vertex, direction;   // a vertex of the edge; the edge's unit direction
  T halfCos, halfSin;          // cos and sin of half the angle between n1 and n2 (the arc's cap about mid)
  bool flat;
};

// The search's queue: two binary min-heaps on the bound. The start cut, queued lazily under its inner-ball bounds, is
// heaped once and apart from the nodes queued during the search: a query takes about a third of the cut's nodes, and
// the rest, left in one heap, would add levels to every sift.
template <class T> struct NodeQueue {
  std::vector<HeapEntry<T>> start, live;

  void clear() { start.clear(), live.clear(); }
  void seal() { std::make_heap(start.begin(), start.end(), std::greater<HeapEntry<T>>()); }
  void push(const HeapEntry<T>& e) {
    live.push_back(e);
    std::push_heap(live.begin(), live.end(), std::greater<HeapEntry<T>>());
  }
  bool empty() const { return start.empty() && live.empty(); }
  // The smallest bound queued (not empty).
  T front() const {
    if (start.empty()) return live.front().bound;
    return live.empty() ? start.front().bound : std::min(start.front().bound, live.front().bound);
  }
  // Removes and returns an entry of the smallest bound (not empty).
  HeapEntry<T> pop() {
    const bool fromStart = live.empty() || (!start.empty() && start.front().bound < live.front().bound);
    std::vector<HeapEntry<T>>& h = fromStart ? start : live;
    std::pop_heap(h.begin(), h.end(), std::greater<HeapEntry<T>>());
    const HeapEntry<T> e = h.back();
    h.pop_back();
    return e;
  }
};

template <class T> struct PairScratch {
  NodeQueue<T> queue;
  std::vector<Vec3<T>> support;         // the queued nodes' support points
  std::vector<Vec3<T>> faceSupport[2];  // per tree face: the other side's support point against it (own frame)
  std::vector<T> faceLow[2];  // per face of an evaluated bounded leaf: its push-out bound from the leaf's support point
  struct Leaf {
    std::uint32_t side, node;
    bool supported;   // false: no support point (the box's leaf)
    Vec3<T> support;  // the other side's support point against the leaf's cap axis (own frame)
  };
  std::vector<Leaf> leaves;
  std::vector<Arc<T>> arcs[2];
  GaussTree<T> box;
};
template <class T> PairScratch<T>& pairScratch() {
  thread_local PairScratch<T> s;
  return s;
}

template <class T> bool isFlat(const Vec3<T>& plane) {
  const T flatSine = std::sqrt(T(tol::Rel<T>::kEpsilon));
  return !(plane.squaredNorm() > flatSine * flatSine);
}

template <class T> struct Best {
  T depth = std::numeric_limits<T>::max();
  Vec3<T> direction = Vec3<T>::UnitX();  // geom0's frame
  void consider(T push, const Vec3<T>& d) {
    if (push < depth) depth = push, direction = d;
  }
};

template <class T> class PairSearch {
 public:
  PairSearch(Side<T>& a, Side<T>& b, T margin) : sides_{&a, &b}, margin_(margin), s_(pairScratch<T>()) {
    for (int k = 0; k < 2; ++k)
      innerCentre_[k] = sides_[k]->rot.transpose() * (sides_[1 - k]->innerCentre - sides_[k]->trans);
  }

  // The minimum push-out; `best.depth` < 0 when a separating axis was found (the search then stops).
  Best<T> run() {
    s_.queue.clear();
    s_.support.clear();
    s_.leaves.clear();
    for (int k = 0; k < 2; ++k) {
      s_.faceSupport[k].resize(sides_[k]->tree->faceNormal.size());
      s_.faceLow[k].resize(sides_[k]->tree->faceNormal.size());
    }
    seedFromCentres();
    for (std::uint32_t k = 0; k < 2; ++k) start(k);
    s_.queue.seal();
    while (!s_.queue.empty() && best_.depth >= T(0)) {
      HeapEntry<T> e = s_.queue.pop();
      if (!(e.bound - margin_ < best_.depth)) break;
      const typename GaussTree<T>::Node& node = sides_[e.side]->tree->nodes[e.node];
      if (e.lazy) {
        // Its support bound; refined at once while that is still the smallest bound left.
        Vec3<T> w;
        e.bound = std::max(e.bound, supportBound(e.side, node, w));
        if (!(e.bound - margin_ < best_.depth)) continue;
        if (!s_.queue.empty() && s_.queue.front() < e.bound) {
          push(e.side, e.node, e.bound, &w);
          continue;
        }
        e.support = std::uint32_t(s_.support.size());
        s_.support.push_back(w);
      }
      if (node.leaf()) {
        evaluateLeaf(e.side, e.node, s_.support[e.support]);
      } else {
        enqueue(e.side, node.child[0], e.bound);
        enqueue(e.side, node.child[1], e.bound);
      }
    }
    if (best_.depth >= T(0)) edgePairs();
    return best_;
  }

 private:
  // The node's bound from a point w of the other side (own frame), less `inner` when the other side's support
  // function over the cap is at least inner above w's (a ball of that radius about w inside the other side).
  T nodeBound(std::uint32_t k, const typename GaussTree<T>::Node& node, const Vec3<T>& w, T inner) const {
    const Side<T>& own = *sides_[k];
    const Vec3<T> z = w - node.centre * own.scale;
    const T zc = node.axis.dot(z), z2 = z.squaredNorm();
    const T zp = std::sqrt(std::max(z2 - zc * zc, T(0)));
    const T reach = (zc > T(0) && zp * node.cosAngle <= zc * node.sinAngle) ? std::sqrt(z2)
                                                                            : zc * node.cosAngle + zp * node.sinAngle;
    return node.radius * own.scale + inner - reach;
  }

  // The node's bound from the other side's inner ball: no support call.
  T innerBound(std::uint32_t k, const typename GaussTree<T>::Node& node) const {
    return nodeBound(k, node, innerCentre_[k], sides_[1 - k]->innerRadius);
  }

  // The node's bound against the other side's support point along -axis (written to w, own frame).
  T supportBound(std::uint32_t k, const typename GaussTree<T>::Node& node, Vec3<T>& w) {
    w = otherNearSupport(*sides_[k], *sides_[1 - k], Vec3<T>(-node.axis));
    return nodeBound(k, node, w, T(0));
  }

  // An unbounded leaf of a hull (its cap too wide for a ball bound) bounded over its faces and edges from one point
  // w of the other shape (written, own frame), near the extreme along minus the faces' mean normal: the faces'
  // -offset - n.w, and each edge's arc minimum of n.(v - w) from its faces' values (v lies on both planes).
  T leafBound(std::uint32_t k, const typename GaussTree<T>::Node& node, Vec3<T>& w) {
    Side<T>& own = *sides_[k];
    const GaussTree<T>& tree = *own.tree;
    Vec3<T> mean = Vec3<T>::Zero();
    for (std::uint32_t f = node.faceBegin; f < node.faceEnd; ++f) mean += tree.faceNormal[f];
    if (!(mean.squaredNorm() > T(1e-6))) mean = tree.faceNormal[node.faceBegin];
    w = otherNearSupport(own, *sides_[1 - k], Vec3<T>(-mean));
    const Planes<T> planes = own.planes();
    T* low = s_.faceLow[k].data();
    T bound = std::numeric_limits<T>::max();
    for (std::uint32_t f = node.faceBegin; f < node.faceEnd; ++f) {
      low[f] = planes.pushOut(f, w);
      bound = std::min(bound, low[f]);
    }
    for (std::uint32_t e = node.edgeBegin; e < node.edgeEnd; ++e) {
      const typename GaussTree<T>::Edge& edge = tree.edges[e];
      const T low2 = edge.face2InLeaf ? low[edge.face2] : planes.pushOut(edge.face2, w);
      bound = std::min(bound, arcMinimum(low[edge.face1], low2, edge.halfCos));
    }
    return bound;
  }

  // The search starts from the tree's cut of its top levels (the caps there are too wide to prune: bounding them
  // costs support calls and saves none).
  void start(std::uint32_t k) {
    const GaussTree<T>& tree = *sides_[k]->tree;
    const bool pair = sides_[0]->mesh && sides_[1]->mesh;  // two hulls (gauss_tree.h: kGaussPairStartNodes)
    for (const std::uint32_t i : pair ? tree.pairStartCut : tree.startCut) {
      const typename GaussTree<T>::Node& node = tree.nodes[i];
      if (node.bounded) push(k, i, innerBound(k, node), nullptr);
      else enqueue(k, i, -std::numeric_limits<T>::max());
    }
  }

  // Queues a node under `bound` with the support point w its bound came from, or lazily (w null: `bound` from the
  // inner ball, the support point taken when the node is first popped), unless the bound is not below the best.
  void push(std::uint32_t k, std::uint32_t index, T bound, const Vec3<T>* w) {
    if (!(bound - margin_ < best_.depth)) return;
    const HeapEntry<T> e{bound, k, w == nullptr, index, std::uint32_t(s_.support.size())};
    if (!w) return s_.queue.start.push_back(e);  // heaped once the cut is queued (NodeQueue::seal)
    s_.support.push_back(*w);
    s_.queue.push(e);
  }

  // A node queued under its own bound (at least `floor`, its parent's, which bounds every facet of the parent),
  // unless that bound is not below the best push-out: first from the other side's inner ball, then from one support
  // call.
  void enqueue(std::uint32_t k, std::uint32_t index, T floor) {
    const typename GaussTree<T>::Node& node = sides_[k]->tree->nodes[index];
    Vec3<T> w = Vec3<T>::Zero();
    T bound = floor;
    if (node.bounded) {
      bound = std::max(floor, innerBound(k, node));
      if (!(bound - margin_ < best_.depth)) return;
      bound = std::max(bound, supportBound(k, node, w));
    } else if (node.leaf() && sides_[k]->mesh) {
      bound = std::max(floor, leafBound(k, node, w));
    }
    push(k, index, bound, &w);
  }

  // Faces exactly; the leaf kept for its edges.
  void evaluateLeaf(std::uint32_t k, std::uint32_t index, const Vec3<T>& leafSupport) {
    Side<T>& own = *sides_[k];
    Side<T>& other = *sides_[1 - k];
    const GaussTree<T>& tree = *own.tree;
    const typename GaussTree<T>::Node& node = tree.nodes[index];
    const bool supported = node.bounded || own.mesh;  // a hull's leaf was queued with a point of the other shape
    bool closed = supported;  // every face bounded out from the leaf's point
    const Planes<T> planes = own.planes();
    T* low = s_.faceLow[k].data();
    Vec3<T>* faceSupport = s_.faceSupport[k].data();
    for (std::uint32_t f = node.faceBegin; f < node.faceEnd; ++f) {
      const Vec3<T>& n = planes.normal[f];
      // The leaf's support point bounds the face's push-out from below: no support call when that is enough.
      if (supported) {
        low[f] = planes.pushOut(f, leafSupport);
        if (!(low[f] - margin_ < best_.depth)) {
          faceSupport[f] = leafSupport;
          continue;
        }
      }
      closed = false;
      const Vec3<T> w = otherSupport(own, other, Vec3<T>(-n));
      faceSupport[f] = w;
      const T push = planes.pushOut(f, w);
      if (push < best_.depth) best_.consider(push, own.first ? Vec3<T>(-n) : own.vectorToFirst(n));
    }
    // Its edges are paired only when the leaf's point leaves one of their arc ends below the best push-out: with
    // every face and every ring face bounded out from it, none is (the best push-out only decreases).
    if (closed && ringBoundedOut(own, node, leafSupport)) return;
    s_.leaves.push_back({k, index, supported, leafSupport});
  }

  // Whether every face of a leaf's ring is bounded out by its push-out bound from the point w (own frame).
  bool ringBoundedOut(const Side<T>& own, const typename GaussTree<T>::Node& node, const Vec3<T>& w) const {
    const std::uint32_t* ring = own.tree->ringFaces.data();
    const Planes<T> planes = own.planes();
    for (std::uint32_t r = node.ringBegin; r < node.ringEnd; ++r) {
      if (planes.pushOut(ring[r], w) - margin_ < best_.depth) return false;
    }
    return true;
  }

  // Edges of evaluated leaves whose bound is below the best push-out, as arcs in geom0's frame.
  void collectArcs() {
    for (int k = 0; k < 2; ++k) s_.arcs[k].clear();
    // Positive (edges are paired only while the best push-out is not negative): an arc whose push-out bound
    // (arcMinimum) is at least this has both end values at least this.
    const T cut = best_.depth + margin_;
    for (const auto& leaf : s_.leaves) {
      Side<T>& own = *sides_[leaf.side];
      const GaussTree<T>& tree = *own.tree;
      const typename GaussTree<T>::Node& node = tree.nodes[leaf.node];
      const T sign = own.first ? T(1) : T(-1);
      const T* low = s_.faceLow[leaf.side].data();
      const Vec3<T>* faceSupport = s_.faceSupport[leaf.side].data();
      const typename GaussTree<T>::Edge* edges = tree.edges.data();
      const Planes<T> planes = own.planes();
      std::vector<Arc<T>>& arcs = s_.arcs[leaf.side];
      for (std::uint32_t e = node.edgeBegin; e < node.edgeEnd; ++e) {
        const typename GaussTree<T>::Edge& edge = edges[e];
        const bool face2Here = edge.face2InLeaf;
        const Vec3<T>& n2 = planes.normal[edge.face2];
        // First from the leaf's support point w alone, with the faces' bounds from it: the edge's vertex lies on
        // both faces' planes (within the cooking's plane tolerance, inside the margin), so n.(v - w) at either end is
        // that face's bound.
        if (leaf.supported && low[edge.face1] >= cut &&
            (face2Here ? low[edge.face2] : planes.pushOut(edge.face2, leaf.support)) >= cut)
          continue;
        const Vec3<T>& n1 = planes.normal[edge.face1];
        const Vec3<T> v = own.vertex(edge.vertex0);
        const Vec3<T> z1 = v - faceSupport[edge.face1];
        T bound = arcMinimum(n1.dot(z1), n2.dot(z1), edge.halfCos);
        if (face2Here && !(bound - margin_ >= best_.depth)) {
          const Vec3<T> z = v - faceSupport[edge.face2];
          bound = std::max(bound, arcMinimum(n1.dot(z), n2.dot(z), edge.halfCos));
        }
        if (!(bound - margin_ < best_.depth)) continue;
        Arc<T> arc;
        arc.n1 = own.vectorToFirst(n1) * sign;
        arc.n2 = own.vectorToFirst(n2) * sign;
        arc.plane = arc.n2.cross(arc.n1);
        arc.mid = (arc.n1 + arc.n2).stableNormalized();
        arc.vertex = own.pointToFirst(v);
        arc.halfCos = edge.halfCos;
        arc.halfSin = std::sqrt(std::max(T(1) - edge.halfCos * edge.halfCos, T(0)));
        arc.flat = isFlat(arc.plane);
        arc.direction = arc.flat ? Vec3<T>(own.vectorToFirst(Vec3<T>(own.vertex(edge.vertex1) - v)).stableNormalized())
                                 : Vec3<T>::Zero();
        arcs.push_back(arc);
      }
    }
  }

  // A first best push-out, before the start cut is queued, so that the cut's nodes it bounds out are never queued:
  // the push-out along the line from the second shape's inner centre to the first's (two support calls). The push-out
  // along any direction is at least the minimum over the facets, so the search's answer stays that minimum (this
  // axis is kept only when no facet is below it; negative: a separating axis, and the search ends). On the 64
  // overlapping pairs of 300-point hulls it removes about 7% of a query's instructions (most of the cut is never
  // queued, and the heaps stay shallow).
  void seedFromCentres() {
    const Vec3<T> d = sides_[0]->innerCentre - innerCentre_[0];
    const T len2 = d.squaredNorm();
    if (!(len2 > T(0))) return;
    const Vec3<T> axis = d / std::sqrt(len2);
    best_.consider(supportValue(*sides_[1], axis) + supportValue(*sides_[0], Vec3<T>(-axis)), axis);
  }

  // Push-outs along both signs of a unit axis (geom0's frame), from support calls.
  void axisBothSigns(const Vec3<T>& axis) {
    Side<T>& a = *sides_[0];
    Side<T>& b = *sides_[1];
    const T positive = supportValue(b, axis) + supportValue(a, Vec3<T>(-axis));
    const T negative = supportValue(a, axis) + supportValue(b, Vec3<T>(-axis));
    best_.consider(positive, axis);
    best_.consider(negative, Vec3<T>(-axis));
  }

  // The facets of the collected arcs' crossing pairs, as the full SAT's testArcPairs decides them.
  void edgePairs() {
    collectArcs();
    const T eps = T(tol::Rel<T>::kEpsilon);
    // Arcs whose caps (about mid, half-angle acos(halfCos)) are apart by more than this cannot cross.
    const T capSlack = T(64) * std::numeric_limits<T>::epsilon();
    for (const Arc<T>& ea : s_.arcs[0]) {
      for (const Arc<T>& eb : s_.arcs[1]) {
        // A flat arc's facets lie in its cap too: pairs of caps apart are skipped whether or not an arc is flat.
        if (ea.mid.dot(eb.mid) < ea.halfCos * eb.halfCos - ea.halfSin * eb.halfSin - capSlack) continue;
        if (ea.flat || eb.flat) {
          const Vec3<T> da = ea.flat ? ea.direction : Vec3<T>(ea.plane.normalized());
          const Vec3<T> db = eb.flat ? eb.direction : Vec3<T>(eb.plane.normalized());
          const Vec3<T> c = da.cross(db);
          const T len2 = c.squaredNorm();
          if (len2 > eps * eps) axisBothSigns(Vec3<T>(c / std::sqrt(len2)));
          continue;
        }
        const T cba = eb.n1.dot(ea.plane), dba = eb.n2.dot(ea.plane);
        const T adc = ea.n1.dot(eb.plane), bdc = ea.n2.dot(eb.plane);
        const bool undecided =
            std::abs(cba) <= eps || std::abs(dba) <= eps || std::abs(adc) <= eps || std::abs(bdc) <= eps;
        if (!undecided && !(cba * dba < T(0) && adc * bdc < T(0) && cba * bdc > T(0))) continue;
        const Vec3<T> c = ea.plane.cross(eb.plane);
        const T len2 = c.squaredNorm();
        if (len2 <= eps * eps) continue;  // parallel edges: no facet of their own
        Vec3<T> p = c / std::sqrt(len2);
        if (undecided) {
          axisBothSigns(p);
        } else {
          if (p.dot(ea.n1 + ea.n2) < T(0)) p = -p;
          best_.consider(p.dot(ea.vertex - eb.vertex), Vec3<T>(-p));
        }
      }
    }
  }

  Side<T>* sides_[2];
  Vec3<T> innerCentre_[2];  // the other side's inner ball centre in each side's frame
  T margin_;
  PairScratch<T>& s_;
  Best<T> best_;
};

// A uniform positive scale factor of a hull's MeshScale, or 0.
template <class T> T uniformScale(const MeshScale<T>& s) {
  if (s.isIdentity()) return T(1);
  const T f = s.scale.x();
  return (f > T(0) && s.scale.y() == f && s.scale.z() == f && std::isfinite(f)) ? f : T(0);
}

template <class T> bool setHull(Side<T>& side, const ConvexMeshGeometry<T>& g) {
  if (!g.mesh) return false;
  side.scale = uniformScale(g.scale);
  if (!(side.scale > T(0))) return false;
  side.tree = hullGaussTree(g.mesh);
  if (!side.tree || !side.tree->usable) return false;
  side.mesh = g.mesh.get();
  side.innerCentre = side.mesh->center * side.scale;
  side.innerRadius = side.mesh->innerRadius * side.scale;
  side.table = supportStartTable(g.mesh);
  side.climb = side.mesh->vertices.size() > kHillClimbMinVertices && hasAdjacency(*side.mesh);
  return true;
}

template <class T> T extent(const Side<T>& side) {
  if (!side.mesh) return side.halfExtents.cwiseAbs().maxCoeff();
  const Bounds3<T>& b = side.mesh->localBounds;
  return std::max(b.min.cwiseAbs().maxCoeff(), b.max.cwiseAbs().maxCoeff()) * side.scale;
}

// Both sides set up: the relative pose, the search, the answer in world space.
template <class T>
bool searchPair(Side<T>& a, const Transform<T>& p0, Side<T>& b, const Transform<T>& p1, bool& penetrating,
                Vec3<T>& direction, T& depth) {
  const Mat3<T> r0 = p0.q.toRotationMatrix();
  const Mat3<T> r = r0.transpose() * p1.q.toRotationMatrix();  // b's frame -> a's frame
  const Vec3<T> t = r0.transpose() * (p1.p - p0.p);
  if (!r.allFinite() || !t.allFinite()) return false;
  a.first = true;
  a.rot = r.transpose();
  a.trans = -(a.rot * t);
  b.first = false;
  b.rot = r;
  b.trans = t;
  PolytopeMtdCounts& counts = polytopeMtdCounts();
  ++counts.searches;
  ++counts.inFrame;
  // Rounding of the bounds and push-outs: a few ulps of the pair's coordinates, and the cooking's plane tolerance
  // (a merged polygon's vertices lie within it of the plane through its first vertex).
  const T magnitude = extent(a) + extent(b) + t.cwiseAbs().maxCoeff();
  const T margin = magnitude * (T(128) * std::numeric_limits<T>::epsilon() + T(4e-9));
  const Best<T> best = PairSearch<T>(a, b, margin).run();
  penetrating = best.depth >= T(0);
  if (penetrating) {
    direction = r0 * best.direction;
    depth = best.depth;
  }
  return true;
}

}  // namespace

template <class T>
bool penetrationHullPairInFrame(const ConvexMeshGeometry<T>& g0, const Transform<T>& p0, const ConvexMeshGeometry<T>& g1,
                                const Transform<T>& p1, bool& penetrating, Vec3<T>& direction, T& depth) {
  Side<T> a, b;
  if (!setHull(a, g0) || !setHull(b, g1)) return false;
  return searchPair(a, p0, b, p1, penetrating, direction, depth);
}

template <class T>
bool penetrationBoxHullInFrame(const BoxGeometry<T>& g0, const Transform<T>& p0, const ConvexMeshGeometry<T>& g1,
                               const Transform<T>& p1, bool& penetrating, Vec3<T>& direction, T& depth) {
  Side<T> a, b;
  if (!setHull(b, g1)) return false;
  GaussTree<T>& box = pairScratch<T>().box;
  boxGaussTree(g0.halfExtents, box);
  a.tree = &box;
  a.halfExtents = g0.halfExtents;
  a.innerRadius = g0.halfExtents.cwiseAbs().minCoeff();
  return searchPair(a, p0, b, p1, penetrating, direction, depth);
}

template bool penetrationHullPairInFrame<float>(const ConvexMeshGeometry<float>&, const Transform<float>&,
                                                const ConvexMeshGeometry<float>&, const Transform<float>&, bool&,
                                                Vec3<float>&, float&);
template bool penetrationHullPairInFrame<double>(const ConvexMeshGeometry<double>&, const Transform<double>&,
                                                 const ConvexMeshGeometry<double>&, const Transform<double>&, bool&,
                                                 Vec3<double>&, double&);
template bool penetrationBoxHullInFrame<float>(const BoxGeometry<float>&, const Transform<float>&,
                                               const ConvexMeshGeometry<float>&, const Transform<float>&, bool&,
                                               Vec3<float>&, float&);
template bool penetrationBoxHullInFrame<double>(const BoxGeometry<double>&, const Transform<double>&,
                                                const ConvexMeshGeometry<double>&, const Transform<double>&, bool&,
                                                Vec3<double>&, double&);

}  // namespace gq::detail
