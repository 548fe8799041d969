#pragma once
// Support mappings prepared for the GJK/EPA inner loops. A ConvexShape stores a rotation and, for hulls, a MeshScale
// matrix; rotating every search direction through both costs more than the support itself on small shapes.
// SupportMap folds them once per query into two 3x3 matrices:
//   hull:   s(d) = R S v* + t  with  v* = argmax_v (S R^T d) . v   (S symmetric, so d.(R S v) = (S R^T d).v)
//   others: s(d) = R s_local(R^T d) + t
// (times the shape's localScale on the local point, folded into the first matrix: a rescaled pair, pair_scale.h)
// and dispatches on the shape kind with a switch (custom shapes call their callbacks). Hull supports hill-climb from
// the previous answer, so consecutive GJK/EPA directions (which are close) cost a step or two each.
//
// Header-inline on purpose: the kernels are a few instructions and must inline into gjk.cpp and epa.cpp.
#include <cstdint>
#include <limits>

#include "gjk/gjk.h"
#include "gjk/support_table.h"

namespace gq::detail {

// Box: the corner whose signs match the direction (ties resolve to +).
template <class T> inline Vec3<T> supportBox(const Vec3<T>& halfExtents, const Vec3<T>& d) {
  return Vec3<T>(d.x() < T(0) ? -halfExtents.x() : halfExtents.x(), d.y() < T(0) ? -halfExtents.y() : halfExtents.y(),
                 d.z() < T(0) ? -halfExtents.z() : halfExtents.z());
}

// Segment along X from -h to +h.
template <class T> inline Vec3<T> supportSegment(T halfHeight, const Vec3<T>& d) {
  return Vec3<T>(d.x() < T(0) ? -halfHeight : halfHeight, T(0), T(0));
}

template <class T> inline T dot3(const Vec3<T>& v, const Vec3<T>& d) { return v.x() * d.x() + v.y() * d.y() + v.z() * d.z(); }

// Vertex with the largest d.v (first one on ties).
template <class T> inline std::uint32_t bruteForceVertex(const ConvexMesh<T>& hull, const Vec3<T>& d) {
  const Vec3<T>* v = hull.vertices.data();
  const std::uint32_t n = static_cast<std::uint32_t>(hull.vertices.size());
  std::uint32_t best = 0;
  T bestDot = dot3(v[0], d);
  for (std::uint32_t i = 1; i < n; ++i) {
    const T s = dot3(v[i], d);
    if (s > bestDot) { bestDot = s; best = i; }
  }
  return best;
}

// Steepest-ascent hill climbing over the hull's edge graph. On a convex polytope a vertex with no strictly better
// neighbour maximises the linear function d.v globally, so the climb is exact; it strictly increases d.v, so it ends.
template <class T> inline std::uint32_t climbVertex(const ConvexMesh<T>& hull, const Vec3<T>& d, std::uint32_t start) {
  const Vec3<T>* v = hull.vertices.data();
  const std::uint32_t* offsets = hull.adjacencyOffsets.data();
  const std::uint32_t* adjacency = hull.adjacency.data();
  std::uint32_t current = start < hull.vertices.size() ? start : 0;
  T currentDot = dot3(v[current], d);
  for (;;) {
    std::uint32_t next = current;
    for (std::uint32_t k = offsets[current], end = offsets[current + 1]; k < end; ++k) {
      const std::uint32_t n = adjacency[k];
      const T s = dot3(v[n], d);
      if (s > currentDot) { currentDot = s; next = n; }
    }
    if (next == current) return current;
    current = next;
  }
}

template <class T> inline bool hasAdjacency(const ConvexMesh<T>& hull) {
  return hull.adjacencyOffsets.size() == hull.vertices.size() + 1 && !hull.adjacency.empty();
}

// Cold start of a climb: the best of kClimbStartSamples evenly spaced vertices along d (cuts the first climb of a
// query short: measured 2% / 6% / 9% fewer instructions in the boolean GJK on hulls of 30 / 100 / 300 vertices).
inline constexpr std::uint32_t kClimbStartSamples = 8;
template <class T> inline std::uint32_t sampledStart(const ConvexMesh<T>& hull, const Vec3<T>& d) {
  const std::uint32_t n = static_cast<std::uint32_t>(hull.vertices.size());
  std::uint32_t best = 0;
  T bestDot = dot3(hull.vertices[0], d);
  for (std::uint32_t k = 1; k < kClimbStartSamples; ++k) {
    const std::uint32_t i = k * n / kClimbStartSamples;
    const T s = dot3(hull.vertices[i], d);
    if (s > bestDot) { bestDot = s; best = i; }
  }
  return best;
}

// Hull vertex extreme along the (scaled, local) direction: climb on large hulls with adjacency (from the start table's
// vertex for d when there is a table, else from `hint`, or from a sampled start when `cold`), else scan.
template <class T>
[[gnu::always_inline]] inline std::uint32_t hullVertex(const ConvexMesh<T>& hull, const SupportStartTable<T>* table, bool climb, const Vec3<T>& d,
                                std::uint32_t& hint, bool& cold) {
  if (!climb) return bruteForceVertex(hull, d);
  if (table && table->hasClimbGraph()) {
    const std::uint32_t entry = table->lookupEntry(d);
    hint = SupportStartTable<T>::vertexOf(entry);
    return SupportStartTable<T>::settled(entry) ? hint : hint = table->climb(hull, d, hint);
  }
  if (table) hint = table->lookup(d);
  else if (cold) hint = sampledStart(hull, d);
  cold = false;
  hint = climbVertex(hull, d, hint);
  return hint;
}

template <class T> class SupportMap {
 public:
  using Kind = typename ConvexShape<T>::Kind;

  explicit SupportMap(const ConvexShape<T>& s)
      : kind_(s.kind), origin_(s.position), halfExtents_(s.halfExtents), hull_(s.hull), table_(s.startTable),
        custom_(s.custom), hint_(s.climbStart), cold_(s.climbStart == 0) {
    const Mat3<T>& r = s.rotation;
    if (kind_ == Kind::Hull && s.hullScaled) {
      toWorld_ = r * s.hullScale;
      toLocal_ = s.hullScale * r.transpose();
    } else {
      toWorld_ = r;
      toLocal_ = r.transpose();
    }
    if (s.localScale != T(1)) toWorld_ *= s.localScale;  // a rescaled pair: local points grow, directions do not
    climb_ = hull_ && hull_->vertices.size() > kHillClimbMinVertices && hasAdjacency(*hull_);
  }

  // Point of the core farthest along the world direction d (need not be unit), in world space.
  Vec3<T> operator()(const Vec3<T>& d) { return at(d); }
  // The same, inline (supportOfDifference's one call does both shapes).
  [[gnu::always_inline]] Vec3<T> at(const Vec3<T>& d) {
    switch (kind_) {
      case Kind::Point: return origin_;
      case Kind::Segment: {
        const T h = dot3(Vec3<T>(toWorld_.col(0)), d) < T(0) ? -halfExtents_.x() : halfExtents_.x();
        return origin_ + h * toWorld_.col(0);
      }
      case Kind::Box: return origin_ + toWorld_ * supportBox(halfExtents_, Vec3<T>(toLocal_ * d));
      case Kind::Hull: {
        const std::uint32_t v = hullVertex(*hull_, table_, climb_, Vec3<T>(toLocal_ * d), hint_, cold_);
        return origin_ + toWorld_ * hull_->vertices[v];
      }
      case Kind::Custom: return origin_ + toWorld_ * custom_->support(Vec3<T>(toLocal_ * d));
    }
    return origin_;
  }

  // Last hill-climbing vertex (to warm-start the next query on the same shape).
  std::uint32_t hint() const { return hint_; }

 private:
  Kind kind_;
  bool climb_ = false;
  Vec3<T> origin_;
  Vec3<T> halfExtents_;
  Mat3<T> toWorld_;
  Mat3<T> toLocal_;
  const ConvexMesh<T>* hull_;
  const SupportStartTable<T>* table_;
  const CustomGeometryCallbacks<T>* custom_;
  std::uint32_t hint_;
  bool cold_;  // no warm start given (ConvexShape::climbStart == 0): the first climb starts from sampledStart
};

// Support point of the Minkowski difference a - b along d: a = s_A(d), b = s_B(-d), written to p. One call for both
// shapes (GJK's and EPA's inner loops call it every step; two calls cost their frames and argument traffic twice).
template <class T>
[[gnu::noinline]] void supportOfDifference(SupportMap<T>& a, SupportMap<T>& b, const Vec3<T>& d, SupportPoint<T>& p) {
  p.a = a.at(d);
  p.b = b.at(Vec3<T>(-d));
  p.w = p.a - p.b;
  p.d = d;
}
template <class T> inline SupportPoint<T> supportOfDifference(SupportMap<T>& a, SupportMap<T>& b, const Vec3<T>& d) {
  SupportPoint<T> p;
  supportOfDifference(a, b, d, p);
  return p;
}

}  // namespace gq::detail
