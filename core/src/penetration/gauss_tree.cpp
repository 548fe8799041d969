// Building and caching Gauss-map trees (see gauss_tree.h).
#include "penetration/gauss_tree.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <mutex>
#include <numeric>
#include <shared_mutex>
#include <unordered_map>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

#include "overlap/polytope.h"

namespace gq::detail {
namespace {

using Vec3d = Eigen::Matrix<double, 3, 1>;

// Cooking works in double whatever T is; what it stores is widened by these for T's rounding.
template <class T> double capSlack() { return 64.0 * double(std::numeric_limits<T>::epsilon()); }

// A cap wider than this (about 84 degrees) bounds nothing useful and would not hold its arcs near a hemisphere.
constexpr double kMaxCapCos = 0.1;

struct BuildFace {
  Vec3d normal;
  double offset;  // n.x + offset = 0 through the first vertex
  Vec3d point;    // the first vertex
  std::uint32_t source;  // the cooked polygon
};

struct BuildEdge {
  std::uint32_t v0, v1, f1, f2;  // f1, f2 as indices into the build faces
};

template <class T> class TreeBuilder {
 public:
  TreeBuilder(const std::vector<Vec3d>& vertices, const Vec3d& interior, std::vector<BuildFace> faces,
              const std::vector<BuildEdge>& edges)
      : vertices_(vertices), interior_(interior), faces_(std::move(faces)), edgesIn_(edges) {}

  void build(GaussTree<T>& out) {
    const std::uint32_t n = std::uint32_t(faces_.size());
    leafFaces_ = n < kGaussSmallHullFaces ? kGaussSmallLeafFaces : kGaussLeafFaces;
    order_.resize(n);
    std::iota(order_.begin(), order_.end(), 0u);
    out.nodes.clear();
    out.nodes.push_back({});
    split(out, 0, 0, n);
    // Faces in tree order.
    std::vector<std::uint32_t> rank(n);
    for (std::uint32_t i = 0; i < n; ++i) rank[order_[i]] = i;
    out.faceNormal.resize(n);
    out.faceOffset.resize(n);
    out.facePolygon.resize(n);
    for (std::uint32_t i = 0; i < n; ++i) {
      out.facePolygon[i] = faces_[order_[i]].source;
      out.faceNormal[i] = faces_[order_[i]].normal.template cast<T>();
      out.faceOffset[i] = T(faces_[order_[i]].offset);
    }
    // Edges grouped by the leaf of their first face, leaves in tree order (a subtree's edges are contiguous).
    std::vector<std::uint32_t> edgeOrder(edgesIn_.size());
    std::iota(edgeOrder.begin(), edgeOrder.end(), 0u);
    std::stable_sort(edgeOrder.begin(), edgeOrder.end(), [&](std::uint32_t a, std::uint32_t b) {
      return rank[edgesIn_[a].f1] < rank[edgesIn_[b].f1];
    });
    out.edges.clear();
    for (const std::uint32_t e : edgeOrder) {
      const BuildEdge& be = edgesIn_[e];
      const double c = faces_[be.f1].normal.dot(faces_[be.f2].normal);
      out.edges.push_back(
          {be.v0, be.v1, rank[be.f1], rank[be.f2], T(std::sqrt(std::max((1.0 + c) / 2.0, 0.0))), false});
    }
    // Edge ranges per node: a leaf's are the edges whose first face it holds.
    for (typename GaussTree<T>::Node& node : out.nodes) {
      const auto firstAt = [&](std::uint32_t face) {
        return std::uint32_t(std::lower_bound(out.edges.begin(), out.edges.end(), face,
                                              [](const typename GaussTree<T>::Edge& e, std::uint32_t f) {
                                                return e.face1 < f;
                                              }) -
                             out.edges.begin());
      };
      node.edgeBegin = firstAt(node.faceBegin);
      node.edgeEnd = firstAt(node.faceEnd);
    }
    for (typename GaussTree<T>::Node& node : out.nodes) bound(out, node);
    leafRings(out);
    cutTopLevels(out, kGaussStartNodes, out.startCut);
    cutTopLevels(out, kGaussPairStartNodes, out.pairStartCut);
    out.usable = true;
  }

 private:
  // Each leaf's ring (the faces outside it beside its edges) and which of its edges have both faces inside.
  static void leafRings(GaussTree<T>& out) {
    out.ringFaces.clear();
    for (typename GaussTree<T>::Node& node : out.nodes) {
      node.ringBegin = node.ringEnd = std::uint32_t(out.ringFaces.size());
      if (!node.leaf()) continue;
      for (std::uint32_t e = node.edgeBegin; e < node.edgeEnd; ++e) {
        typename GaussTree<T>::Edge& edge = out.edges[e];
        edge.face2InLeaf = edge.face2 >= node.faceBegin && edge.face2 < node.faceEnd;
        if (edge.face2InLeaf) continue;
        const auto ring = out.ringFaces.begin() + node.ringBegin;
        if (std::find(ring, out.ringFaces.end(), edge.face2) == out.ringFaces.end()) out.ringFaces.push_back(edge.face2);
      }
      node.ringEnd = std::uint32_t(out.ringFaces.size());
    }
  }

  // The top levels of the tree, a level at a time, while the cut stays within `limit` nodes.
  static void cutTopLevels(const GaussTree<T>& out, std::size_t limit, std::vector<std::uint32_t>& cut) {
    cut.assign(1, 0);
    for (;;) {
      std::size_t inner = 0;
      for (const std::uint32_t i : cut) inner += !out.nodes[i].leaf();
      if (inner == 0 || cut.size() + inner > limit) break;
      const std::size_t n = cut.size();
      for (std::size_t j = 0; j < n; ++j) {
        const typename GaussTree<T>::Node& node = out.nodes[cut[j]];
        if (node.leaf()) continue;
        cut[j] = node.child[0];
        cut.push_back(node.child[1]);
      }
    }
  }

  // Splits order_[begin, end) into the subtree of node `index`.
  void split(GaussTree<T>& out, std::uint32_t index, std::uint32_t begin, std::uint32_t end) {
    out.nodes[index].faceBegin = begin;
    out.nodes[index].faceEnd = end;
    out.nodes[index].child[0] = out.nodes[index].child[1] = 0;
    if (end - begin <= leafFaces_) return;
    // The widest spread of the normals (the covariance's principal axis), split at its median.
    Vec3d mean = Vec3d::Zero();
    for (std::uint32_t i = begin; i < end; ++i) mean += faces_[order_[i]].normal;
    mean /= double(end - begin);
    Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
    for (std::uint32_t i = begin; i < end; ++i) {
      const Vec3d d = faces_[order_[i]].normal - mean;
      cov += d * d.transpose();
    }
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
    const Vec3d axis = eig.eigenvectors().col(2);
    const std::uint32_t mid = begin + (end - begin) / 2;
    std::nth_element(order_.begin() + begin, order_.begin() + mid, order_.begin() + end,
                     [&](std::uint32_t a, std::uint32_t b) {
                       return faces_[a].normal.dot(axis) < faces_[b].normal.dot(axis);
                     });
    const std::uint32_t left = std::uint32_t(out.nodes.size());
    out.nodes.push_back({});
    out.nodes.push_back({});
    out.nodes[index].child[0] = left;
    out.nodes[index].child[1] = left + 1;
    split(out, left, begin, mid);
    split(out, left + 1, mid, end);
  }

  // The cap and ball of a node from its faces and edges (tree order in `out`).
  void bound(const GaussTree<T>& out, typename GaussTree<T>::Node& node) const {
    // Points of the cap: the faces' normals and the far ends of the edges' arcs.
    std::vector<Vec3d> points;
    for (std::uint32_t f = node.faceBegin; f < node.faceEnd; ++f) points.push_back(normal(out, f));
    for (std::uint32_t e = node.edgeBegin; e < node.edgeEnd; ++e) points.push_back(normal(out, out.edges[e].face2));
    Vec3d sum = Vec3d::Zero();
    for (const Vec3d& p : points) sum += p;
    node.bounded = false;
    node.axis = Vec3<T>::UnitX();
    node.cosAngle = T(-1);
    node.sinAngle = T(0);
    node.centre = interior_.template cast<T>();
    node.radius = T(0);
    node.radiusMax = std::numeric_limits<T>::max();
    if (!(sum.norm() > 1e-6 * double(points.size()))) return;
    const Vec3d axis = sum.normalized();
    double minCos = 1.0;
    for (const Vec3d& p : points) minCos = std::min(minCos, axis.dot(p));
    const double angle = std::acos(std::clamp(minCos, -1.0, 1.0)) + capSlack<T>();
    if (!(std::cos(angle) > kMaxCapCos)) return;
    // The ball: the candidate centre whose bound is tightest on test points at the node's surface.
    std::vector<Vec3d> candidates = {interior_};
    for (const double weight : {1e-3, 1e-1}) {
      Vec3d c;
      if (fitSphere(out, node, weight, c)) candidates.push_back(c);
    }
    double bestSlack = std::numeric_limits<double>::infinity();
    for (const Vec3d& c : candidates) {
      double radius = std::numeric_limits<double>::infinity();
      forEachSupport(out, node, [&](const Vec3d& n, const Vec3d& v) { radius = std::min(radius, n.dot(v - c)); });
      if (!(radius >= 0.0)) continue;
      const double slack = worstSlack(out, node, axis, std::cos(angle), std::sin(angle), c, radius);
      if (slack < bestSlack) {
        bestSlack = slack;
        node.centre = c.template cast<T>();
        // Less a few ulps: the stored centre is rounded to T.
        node.radius = T(std::max(radius - capSlack<T>() * (c.norm() + radius), 0.0));
        double farthest = 0.0;
        for (std::uint32_t i = node.faceBegin; i < node.faceEnd; ++i)
          farthest = std::max(farthest, -offset(i) - normal(out, i).dot(c));
        node.radiusMax = T(farthest + capSlack<T>() * (c.norm() + farthest));
      }
    }
    if (!(bestSlack < std::numeric_limits<double>::infinity())) return;
    node.bounded = true;
    node.axis = axis.template cast<T>();
    node.cosAngle = T(std::cos(angle));
    node.sinAngle = T(std::sin(angle));
  }

  Vec3d normal(const GaussTree<T>&, std::uint32_t treeFace) const { return faces_[order_[treeFace]].normal; }
  double offset(std::uint32_t treeFace) const { return faces_[order_[treeFace]].offset; }

  // Calls f(n, v) with h(n) = n.v at every face normal (v: a point of its plane) and at both ends of every arc
  // (v: the edge's vertex0) of the node.
  template <class F> void forEachSupport(const GaussTree<T>& out, const typename GaussTree<T>::Node& node, F f) const {
    for (std::uint32_t i = node.faceBegin; i < node.faceEnd; ++i) {
      const Vec3d n = normal(out, i);
      f(n, Vec3d(-offset(i) * n));
    }
    for (std::uint32_t e = node.edgeBegin; e < node.edgeEnd; ++e) {
      const Vec3d& v = vertices_[out.edges[e].vertex0];
      f(normal(out, out.edges[e].face1), v);
      f(normal(out, out.edges[e].face2), v);
    }
  }

  // Least-squares sphere touching the node's face planes (n.c + r = -offset), held towards the interior point with
  // `weight` per face.
  bool fitSphere(const GaussTree<T>& out, const typename GaussTree<T>::Node& node, double weight, Vec3d& centre) const {
    Eigen::Matrix4d a = Eigen::Matrix4d::Zero();
    Eigen::Vector4d b = Eigen::Vector4d::Zero();
    const double count = double(node.faceEnd - node.faceBegin);
    for (std::uint32_t i = node.faceBegin; i < node.faceEnd; ++i) {
      const Vec3d n = normal(out, i);
      const Eigen::Vector4d row(n.x(), n.y(), n.z(), 1.0);
      a += row * row.transpose();
      b += row * -offset(i);
    }
    for (int k = 0; k < 3; ++k) {
      a(k, k) += weight * count;
      b(k) += weight * count * interior_(k);
    }
    const Eigen::Vector4d x = a.ldlt().solve(b);
    if (!x.allFinite()) return false;
    centre = x.head<3>();
    return true;
  }

  // The largest gap between a node's true minimum of h(n) - n.w over its face normals and its bound, over test
  // points w on and just below its faces.
  double worstSlack(const GaussTree<T>& out, const typename GaussTree<T>::Node& node, const Vec3d& axis, double cosA,
                    double sinA, const Vec3d& centre, double radius) const {
    double worst = 0.0;
    for (std::uint32_t i = node.faceBegin; i < node.faceEnd; ++i) {
      const Vec3d& onFace = faces_[order_[i]].point;
      for (const double depth : {0.0, 0.05, 0.2}) {
        const Vec3d w = onFace + (interior_ - onFace) * depth;
        double truth = std::numeric_limits<double>::infinity();
        for (std::uint32_t j = node.faceBegin; j < node.faceEnd; ++j)
          truth = std::min(truth, -offset(j) - normal(out, j).dot(w));
        const Vec3d z = w - centre;
        const double zc = axis.dot(z), z2 = z.squaredNorm(), zp = std::sqrt(std::max(z2 - zc * zc, 0.0));
        const double reach = (zc > 0.0 && zp * cosA <= zc * sinA) ? std::sqrt(z2) : zc * cosA + zp * sinA;
        worst = std::max(worst, truth - (radius - reach));
      }
    }
    return worst;
  }

  const std::vector<Vec3d>& vertices_;
  Vec3d interior_;
  std::vector<BuildFace> faces_;
  const std::vector<BuildEdge>& edgesIn_;
  std::vector<std::uint32_t> order_;
  std::uint32_t leafFaces_ = kGaussLeafFaces;
};

template <class T> std::shared_ptr<const GaussTree<T>> makeHullGaussTree(const std::shared_ptr<const ConvexMesh<T>>& mesh) {
  auto tree = std::make_shared<GaussTree<T>>();
  const std::shared_ptr<const PolytopeTopology> topology = hullTopology(mesh);
  const PolytopeTopology& topo = *topology;
  const ConvexMesh<T>& m = *mesh;
  if (!topo.edgeFacesKnown || topo.facePolygon.empty() || topo.edges.empty() || !(m.innerRadius > T(0))) return tree;
  std::vector<Vec3d> vertices;
  for (const Vec3<T>& v : m.vertices) vertices.push_back(v.template cast<double>());
  std::vector<BuildFace> faces;
  for (std::size_t f = 0; f < topo.facePolygon.size(); ++f) {
    const Vec3<T>& n = m.polygons[topo.facePolygon[f]].normal;
    // The offset as the posed polytope computes it (through the face's first vertex), in T.
    const T offset = -n.dot(m.vertices[topo.faceVertices[topo.faceBegin[f]]]);
    faces.push_back({n.template cast<double>(), double(offset),
                     m.vertices[topo.faceVertices[topo.faceBegin[f]]].template cast<double>(), topo.facePolygon[f]});
  }
  std::vector<BuildEdge> edges;
  for (std::size_t e = 0; e < topo.edges.size(); ++e)
    edges.push_back({topo.edges[e][0], topo.edges[e][1], topo.edgeFaces[e][0], topo.edgeFaces[e][1]});
  TreeBuilder<T>(vertices, m.center.template cast<double>(), std::move(faces), edges).build(*tree);
  return tree;
}

template <class T> struct GaussTreeCache {
  struct Entry {
    std::weak_ptr<const ConvexMesh<T>> mesh;
    std::shared_ptr<const GaussTree<T>> tree;
  };
  std::shared_mutex mutex;
  std::unordered_map<const ConvexMesh<T>*, Entry> entries;
  std::size_t pruneAt = 64;  // drop entries of destroyed meshes when the map grows past this

  static GaussTreeCache& instance() {
    static GaussTreeCache cache;
    return cache;
  }

  std::shared_ptr<const GaussTree<T>> find(const std::shared_ptr<const ConvexMesh<T>>& mesh) {
    {
      std::shared_lock<std::shared_mutex> lock(mutex);
      const auto it = entries.find(mesh.get());
      if (it != entries.end() && !it->second.mesh.expired()) return it->second.tree;
    }
    std::shared_ptr<const GaussTree<T>> tree = makeHullGaussTree(mesh);
    std::unique_lock<std::shared_mutex> lock(mutex);
    const auto it = entries.find(mesh.get());
    if (it != entries.end() && !it->second.mesh.expired()) return it->second.tree;  // built meanwhile
    if (entries.size() >= pruneAt) {
      for (auto e = entries.begin(); e != entries.end();) e = e->second.mesh.expired() ? entries.erase(e) : std::next(e);
      pruneAt = std::max<std::size_t>(64, 2 * entries.size());
    }
    entries[mesh.get()] = {mesh, tree};
    return tree;
  }
};

// A thread's last lookups (the registry's entries live as long as their mesh, so the raw pointer stays valid while
// the weak reference is alive).
template <class T> struct GaussTreeFront {
  static constexpr std::size_t kSlots = 4;
  struct Slot {
    const ConvexMesh<T>* key = nullptr;
    std::weak_ptr<const ConvexMesh<T>> mesh;
    std::shared_ptr<const GaussTree<T>> tree;
  };
  Slot slots[kSlots];
  std::size_t next = 0;
};

}  // namespace

template <class T> const GaussTree<T>* hullGaussTree(const std::shared_ptr<const ConvexMesh<T>>& mesh) {
  if (!mesh) return nullptr;
  thread_local GaussTreeFront<T> front;
  for (auto& slot : front.slots)
    if (slot.key == mesh.get() && !slot.mesh.expired()) return slot.tree.get();
  auto& slot = front.slots[front.next];
  front.next = (front.next + 1) % GaussTreeFront<T>::kSlots;
  slot.tree = GaussTreeCache<T>::instance().find(mesh);
  slot.key = mesh.get();
  slot.mesh = mesh;
  return slot.tree.get();
}

template <class T> void boxGaussTree(const Vec3<T>& h, GaussTree<T>& out) {
  // Faces +X, -X, +Y, -Y, +Z, -Z; vertex i has coordinate k at +h[k] when bit k of i is set (as the box polytope).
  out.faceNormal.resize(6);
  out.faceOffset.resize(6);
  out.facePolygon.assign(6, 0);
  for (int axis = 0; axis < 3; ++axis) {
    out.faceNormal[2 * axis] = Vec3<T>::Unit(axis);
    out.faceNormal[2 * axis + 1] = -Vec3<T>::Unit(axis);
    out.faceOffset[2 * axis] = out.faceOffset[2 * axis + 1] = -h[axis];
  }
  out.edges.clear();
  const auto faceOf = [](std::uint32_t i, std::uint32_t j) { return 2 * j + ((i & (1u << j)) ? 0u : 1u); };
  const T halfCos = std::sqrt(T(0.5));
  for (std::uint32_t i = 0; i < 8; ++i)
    for (std::uint32_t k = 0; k < 3; ++k)
      if (!(i & (1u << k)))
        out.edges.push_back({i, i | (1u << k), faceOf(i, (k + 1) % 3), faceOf(i, (k + 2) % 3), halfCos, true});
  out.ringFaces.clear();
  out.startCut.assign(1, 0);
  out.pairStartCut.assign(1, 0);
  out.nodes.resize(1);
  typename GaussTree<T>::Node& root = out.nodes[0];
  root.axis = Vec3<T>::UnitX();
  root.cosAngle = T(-1);
  root.sinAngle = T(0);
  root.centre = Vec3<T>::Zero();
  root.radius = h.minCoeff();
  root.radiusMax = h.maxCoeff();
  root.faceBegin = 0;
  root.faceEnd = 6;
  root.edgeBegin = 0;
  root.edgeEnd = 12;
  root.child[0] = root.child[1] = 0;
  root.ringBegin = root.ringEnd = 0;
  root.bounded = false;
  out.usable = true;
}

template const GaussTree<float>* hullGaussTree<float>(const std::shared_ptr<const ConvexMesh<float>>&);
template const GaussTree<double>* hullGaussTree<double>(const std::shared_ptr<const ConvexMesh<double>>&);
template void boxGaussTree<float>(const Vec3<float>&, GaussTree<float>&);
template void boxGaussTree<double>(const Vec3<double>&, GaussTree<double>&);

}  // namespace gq::detail
