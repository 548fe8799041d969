// Certified pruning of the SAT axes (see polytope_mtd.h).
#include "penetration/polytope_mtd.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "shapes/hull_scale.h"

namespace gq::detail {
namespace {

template <class T> struct MtdScratch {
  std::vector<T> boundA, boundB;  // per face: the lower bound of its push-out
  std::vector<std::uint32_t> edgesA, edgesB;
};
template <class T> MtdScratch<T>& mtdScratch() {
  thread_local MtdScratch<T> s;
  return s;
}

// Lower bounds of the faces' push-outs against the other shape's ball, and the largest |offset| (the scale of the
// rounding).
template <class T>
T faceBounds(const Polytope<T>& p, const InnerBall<T>& other, std::vector<T>& bounds) {
  const std::size_t count = p.faceCount();
  bounds.resize(count);
  T scale = T(0);
  for (std::size_t f = 0; f < count; ++f) {
    const T offset = p.faceOffsets[f];
    bounds[f] = -offset - p.faceNormals[f].dot(other.centre) + other.radius;
    scale = std::max(scale, std::abs(offset));
  }
  return scale;
}

// Cooked polygons are planar to far better than this fraction of the hull's size (their vertices lie within the
// cooking's plane tolerance, 1e-9 by default, of the face plane): a face bound stands for its edges' vertices to it.
template <class T> inline constexpr T kPlanarity = T(1e-2);

// Edges of p whose lower bound lies below `limit`, against the other shape's ball. The bound of an edge with vertex v
// is min over its arc of u.(v - centre) + radius: the smaller endpoint value when that is positive, else that value
// over cos(theta/2) (the arc bulges towards the centre by at most that); an arc between nearly opposite faces is
// always kept. `margin` is the rounding of these values. Edges whose faces' bounds are far above the limit are
// pruned by those (the faces' planes pass within kPlanarity of the edge's vertex), without reading the vertex.
template <class T>
void candidateEdges(const Polytope<T>& p, const std::vector<T>& faceBound, const InnerBall<T>& other, T margin,
                    T coarse, T limit, std::vector<std::uint32_t>& edges) {
  const PolytopeTopology& topo = *p.topology;
  edges.clear();
  for (std::size_t e = 0; e < topo.edges.size(); ++e) {
    const std::uint32_t f1 = topo.edgeFaces[e][0], f2 = topo.edgeFaces[e][1];
    const T faces = std::min(faceBound[f1], faceBound[f2]);
    if (faces >= limit + coarse && faces > other.radius + coarse) continue;
    const Vec3<T>& n1 = p.faceNormals[f1];
    const Vec3<T>& n2 = p.faceNormals[f2];
    const Vec3<T> w = p.vertices[topo.edges[e][0]] - other.centre;
    T low = std::min(n1.dot(w), n2.dot(w)) - margin;
    if (!(low > T(0))) {
      const T halfCos2 = (T(1) + n1.dot(n2)) / T(2);
      low = halfCos2 > T(1e-6) ? low / std::sqrt(halfCos2) : -std::numeric_limits<T>::max();
    }
    if (!(low + other.radius >= limit)) edges.push_back(std::uint32_t(e));
  }
}

template <class T> Vec3<T> vertexMean(const Polytope<T>& p) {
  T x = 0, y = 0, z = 0;
  const std::size_t n = p.xs.size();
  for (std::size_t i = 0; i < n; ++i) {
    x += p.xs[i];
    y += p.ys[i];
    z += p.zs[i];
  }
  return Vec3<T>(x, y, z) / T(n);
}

}  // namespace

PolytopeMtdCounts& polytopeMtdCounts() {
  thread_local PolytopeMtdCounts counts;
  return counts;
}

template <class T> InnerBall<T> boxInnerBall(const BoxGeometry<T>& box, const Transform<T>& pose) {
  return {pose.p, box.halfExtents.minCoeff()};
}

template <class T>
InnerBall<T> hullInnerBall(const ConvexMeshGeometry<T>& hull, const Transform<T>& pose, const Polytope<T>& posed) {
  const ConvexMesh<T>& mesh = *hull.mesh;
  if (mesh.innerRadius > T(0)) {
    const HullScale<T> scale(hull.scale);
    const T shrink = scale.identity ? T(1) : hull.scale.scale.cwiseAbs().minCoeff();
    return {pose.transform(scale.pointToShape(mesh.center)), mesh.innerRadius * shrink};
  }
  InnerBall<T> ball{vertexMean(posed), std::numeric_limits<T>::max()};
  for (std::size_t f = 0; f < posed.faceCount(); ++f)
    ball.radius = std::min(ball.radius, -(posed.faceNormals[f].dot(ball.centre) + posed.faceOffsets[f]));
  ball.radius = std::max(ball.radius, T(0));
  return ball;
}

template <class T>
bool penetrationPolytopesCertified(const Polytope<T>& a, const InnerBall<T>& ballA, const Polytope<T>& b,
                                   const InnerBall<T>& ballB, Vec3<T>& direction, T& depth) {
  PolytopeMtdCounts& counts = polytopeMtdCounts();
  ++counts.searches;
  SatResult<T> best{std::numeric_limits<T>::max(), Vec3<T>::UnitX()};
  const bool certifiable = a.faceCount() > 0 && b.faceCount() > 0 && a.edgeCount() > 0 && b.edgeCount() > 0 &&
                           a.edgeFacesKnown() && b.edgeFacesKnown() && std::isfinite(ballA.radius) &&
                           std::isfinite(ballB.radius) && isFinite(ballA.centre) && isFinite(ballB.centre);
  if (!certifiable) {
    ++counts.fullSat;
    best = satMinimumOverlap(a, b, false);
  } else {
    MtdScratch<T>& s = mtdScratch<T>();
    // Rounding of the bounds (and of the push-outs they are compared with): a few ulps of the pair's coordinates;
    // a bound less `margin` is sound (a cooked radius is rounded inward already, the posing rounds again).
    const T scale = std::max(faceBounds(a, ballB, s.boundA), faceBounds(b, ballA, s.boundB)) +
                    ballA.centre.cwiseAbs().maxCoeff() + ballB.centre.cwiseAbs().maxCoeff() + ballA.radius + ballB.radius;
    const T margin = T(128) * std::numeric_limits<T>::epsilon() * scale;
    const auto faceA = [&](std::size_t f) {
      const Vec3<T>& n = a.faceNormals[f];
      const T push = -a.faceOffsets[f] - minProjection(b, n);
      if (push < best.depth) best = {push, Vec3<T>(-n)};
    };
    const auto faceB = [&](std::size_t g) {
      const Vec3<T>& m = b.faceNormals[g];
      const T push = -b.faceOffsets[g] - minProjection(a, m);
      if (push < best.depth) best = {push, m};
    };
    // First the face of each side with the smallest bound: usually next to the answer, it sets the limit.
    const std::size_t firstA = std::size_t(std::min_element(s.boundA.begin(), s.boundA.end()) - s.boundA.begin());
    const std::size_t firstB = std::size_t(std::min_element(s.boundB.begin(), s.boundB.end()) - s.boundB.begin());
    faceA(firstA);
    faceB(firstB);
    for (std::size_t f = 0; f < s.boundA.size() && best.depth >= T(0); ++f)
      if (f != firstA && !(s.boundA[f] - margin >= best.depth)) faceA(f);
    for (std::size_t g = 0; g < s.boundB.size() && best.depth >= T(0); ++g)
      if (g != firstB && !(s.boundB[g] - margin >= best.depth)) faceB(g);
    if (best.depth < T(0)) return false;  // a separating face
    const T coarse = kPlanarity<T> * scale;
    candidateEdges(a, s.boundA, ballB, margin, coarse, best.depth, s.edgesA);
    candidateEdges(b, s.boundB, ballA, margin, coarse, best.depth, s.edgesB);
    satEdgePairs(a, b, s.edgesA, s.edgesB, best);
  }
  if (!(best.depth >= T(0))) return false;
  direction = best.direction;
  depth = best.depth;
  return true;
}

template InnerBall<float> boxInnerBall<float>(const BoxGeometry<float>&, const Transform<float>&);
template InnerBall<double> boxInnerBall<double>(const BoxGeometry<double>&, const Transform<double>&);
template InnerBall<float> hullInnerBall<float>(const ConvexMeshGeometry<float>&, const Transform<float>&, const Polytope<float>&);
template InnerBall<double> hullInnerBall<double>(const ConvexMeshGeometry<double>&, const Transform<double>&, const Polytope<double>&);
template bool penetrationPolytopesCertified<float>(const Polytope<float>&, const InnerBall<float>&, const Polytope<float>&,
                                                   const InnerBall<float>&, Vec3<float>&, float&);
template bool penetrationPolytopesCertified<double>(const Polytope<double>&, const InnerBall<double>&, const Polytope<double>&,
                                                    const InnerBall<double>&, Vec3<double>&, double&);

}  // namespace gq::detail
