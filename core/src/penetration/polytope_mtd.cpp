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
  std::vector<T> boundA, boundB;  // per face: the lower bound of its push-out (the ellipsoid's)
  std::vector<T> ballA, ballB;    // per face: the same bound from the ellipsoid's inner ball
  std::vector<std::uint32_t> edgesA, edgesB;
};
template <class T> MtdScratch<T>& mtdScratch() {
  thread_local MtdScratch<T> s;
  return s;
}

// Lower bounds of the faces' push-outs against the other shape's ellipsoid (and its ball); returns the largest
// |offset| (the scale of the rounding).
template <class T>
T faceBounds(const Polytope<T>& p, const InnerEllipsoid<T>& other, std::vector<T>& bounds, std::vector<T>& ball) {
  const std::size_t count = p.faceCount();
  bounds.resize(count);
  ball.resize(count);
  const Mat3<T> axesT = other.axes.transpose();
  T scale = T(0);
  for (std::size_t f = 0; f < count; ++f) {
    const Vec3<T>& n = p.faceNormals[f];
    const T offset = p.faceOffsets[f];
    const T base = -offset - n.dot(other.centre);
    bounds[f] = base + (axesT * n).norm();
    ball[f] = base + other.radius;
    scale = std::max(scale, std::abs(offset));
  }
  return scale;
}

// A lower bound of u.z over the arc from n1 to n2, from the endpoint values e1 = n1.z, e2 = n2.z: the smaller when
// it is positive, else it over cos(theta/2) (the arc bulges towards -z by at most that); -max for nearly opposite
// normals (no usable arc).
template <class T> T arcMinimum(T e1, T e2, T halfCos) {
  const T low = std::min(e1, e2);
  if (low > T(0)) return low;
  return halfCos > T(1e-3) ? low / halfCos : -std::numeric_limits<T>::max();
}

// The point of the ellipsoid (about its centre) supporting n: M M^T n / |M^T n|.
template <class T> Vec3<T> supportOffset(const InnerEllipsoid<T>& e, const Vec3<T>& n) {
  const Vec3<T> v = e.axes.transpose() * n;
  const T len = v.norm();
  return len > T(0) ? Vec3<T>(e.axes * (v / len)) : Vec3<T>::Zero();
}

// Cooked polygons are planar to far better than this fraction of the hull's size (their vertices lie within the
// cooking's plane tolerance, 1e-9 by default, of the face plane): a face bound stands for its edges' vertices to it.
template <class T> inline constexpr T kPlanarity = T(1e-2);

// Edges of p whose lower bound lies below `limit`, against the other shape's ellipsoid (polytope_mtd.h): the ball's
// bound and the two endpoint linearisations of the ellipsoid's, the largest. `margin` is the rounding of these
// values. Edges whose faces' ball bounds are far above the limit are pruned by those (the faces' planes pass within
// kPlanarity of the edge's vertex), without reading the vertex.
template <class T>
void candidateEdges(const Polytope<T>& p, const std::vector<T>& faceBall, const InnerEllipsoid<T>& other, T margin,
                    T coarse, T limit, std::vector<std::uint32_t>& edges) {
  const PolytopeTopology& topo = *p.topology;
  edges.clear();
  for (std::size_t e = 0; e < topo.edges.size(); ++e) {
    const std::uint32_t f1 = topo.edgeFaces[e][0], f2 = topo.edgeFaces[e][1];
    const T faces = std::min(faceBall[f1], faceBall[f2]);
    if (faces >= limit + coarse && faces > other.radius + coarse) continue;
    const Vec3<T>& n1 = p.faceNormals[f1];
    const Vec3<T>& n2 = p.faceNormals[f2];
    const T halfCos = std::sqrt(std::max((T(1) + n1.dot(n2)) / T(2), T(0)));
    const Vec3<T> w = p.vertices[topo.edges[e][0]] - other.centre;
    T bound = arcMinimum(n1.dot(w) - margin, n2.dot(w) - margin, halfCos) + other.radius;
    if (!(bound >= limit)) {
      const Vec3<T> z1 = w + supportOffset(other, n1), z2 = w + supportOffset(other, n2);
      bound = std::max(arcMinimum(n1.dot(z1) - margin, n2.dot(z1) - margin, halfCos),
                       arcMinimum(n1.dot(z2) - margin, n2.dot(z2) - margin, halfCos));
    }
    if (!(bound >= limit)) edges.push_back(std::uint32_t(e));
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

template <class T> InnerEllipsoid<T> boxInnerEllipsoid(const BoxGeometry<T>& box, const Transform<T>& pose) {
  return {pose.p, Mat3<T>(pose.q.toRotationMatrix() * box.halfExtents.asDiagonal()), box.halfExtents.minCoeff()};
}

template <class T>
InnerEllipsoid<T> hullInnerEllipsoid(const ConvexMeshGeometry<T>& hull, const Transform<T>& pose, const Polytope<T>& posed) {
  const ConvexMesh<T>& mesh = *hull.mesh;
  const Vec3<T> extents = (mesh.localBounds.max - mesh.localBounds.min) / T(2);
  if (mesh.innerRadius > T(0) && extents.allFinite() && extents.minCoeff() > T(0)) {
    // Semi-axes t * extents along the mesh axes: inside the face n.x + d <= 0 iff n.c + t |extents * n| <= -d.
    T t = std::numeric_limits<T>::max();
    for (const HullPolygon<T>& poly : mesh.polygons) {
      const T room = -(poly.normal.dot(mesh.center) + poly.d);
      const T reach = extents.cwiseProduct(poly.normal).norm();
      if (reach > T(0)) t = std::min(t, room / reach);
    }
    // Less kPlanarity: the faces' planes stand for the hull to that (a vertex may lie off its polygon's plane).
    t = std::max(t, T(0)) * (T(1) - kPlanarity<T>);
    const HullScale<T> scale(hull.scale);
    const T shrink = scale.identity ? T(1) : hull.scale.scale.cwiseAbs().minCoeff();
    const Mat3<T> local = scale.toShape * (t * extents).asDiagonal();
    return {pose.transform(scale.pointToShape(mesh.center)), Mat3<T>(pose.q.toRotationMatrix() * local),
            t * extents.minCoeff() * shrink};
  }
  InnerEllipsoid<T> ball{vertexMean(posed), Mat3<T>::Zero(), std::numeric_limits<T>::max()};
  for (std::size_t f = 0; f < posed.faceCount(); ++f)
    ball.radius = std::min(ball.radius, -(posed.faceNormals[f].dot(ball.centre) + posed.faceOffsets[f]));
  ball.radius = std::max(ball.radius, T(0));
  ball.axes = Mat3<T>::Identity() * ball.radius;
  return ball;
}

template <class T>
bool penetrationPolytopesCertified(const Polytope<T>& a, const InnerEllipsoid<T>& innerA, const Polytope<T>& b,
                                   const InnerEllipsoid<T>& innerB, Vec3<T>& direction, T& depth) {
  PolytopeMtdCounts& counts = polytopeMtdCounts();
  ++counts.searches;
  SatResult<T> best{std::numeric_limits<T>::max(), Vec3<T>::UnitX()};
  const bool certifiable = a.faceCount() > 0 && b.faceCount() > 0 && a.edgeCount() > 0 && b.edgeCount() > 0 &&
                           a.edgeFacesKnown() && b.edgeFacesKnown() && std::isfinite(innerA.radius) &&
                           std::isfinite(innerB.radius) && isFinite(innerA.centre) && isFinite(innerB.centre) &&
                           innerA.axes.allFinite() && innerB.axes.allFinite();
  if (!certifiable) {
    ++counts.fullSat;
    best = satMinimumOverlap(a, b, false);
  } else {
    MtdScratch<T>& s = mtdScratch<T>();
    // Rounding of the bounds (and of the push-outs they are compared with): a few ulps of the pair's coordinates;
    // a bound less `margin` is sound (the fitted ellipsoids and a cooked radius are rounded, the posing rounds again).
    const T scale = std::max(faceBounds(a, innerB, s.boundA, s.ballA), faceBounds(b, innerA, s.boundB, s.ballB)) +
                    innerA.centre.cwiseAbs().maxCoeff() + innerB.centre.cwiseAbs().maxCoeff() +
                    innerA.axes.cwiseAbs().maxCoeff() + innerB.axes.cwiseAbs().maxCoeff();
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
    candidateEdges(a, s.ballA, innerB, margin, coarse, best.depth, s.edgesA);
    candidateEdges(b, s.ballB, innerA, margin, coarse, best.depth, s.edgesB);
    satEdgePairs(a, b, s.edgesA, s.edgesB, best);
  }
  if (!(best.depth >= T(0))) return false;
  direction = best.direction;
  depth = best.depth;
  return true;
}

template InnerEllipsoid<float> boxInnerEllipsoid<float>(const BoxGeometry<float>&, const Transform<float>&);
template InnerEllipsoid<double> boxInnerEllipsoid<double>(const BoxGeometry<double>&, const Transform<double>&);
template InnerEllipsoid<float> hullInnerEllipsoid<float>(const ConvexMeshGeometry<float>&, const Transform<float>&,
                                                         const Polytope<float>&);
template InnerEllipsoid<double> hullInnerEllipsoid<double>(const ConvexMeshGeometry<double>&, const Transform<double>&,
                                                           const Polytope<double>&);
template bool penetrationPolytopesCertified<float>(const Polytope<float>&, const InnerEllipsoid<float>&,
                                                   const Polytope<float>&, const InnerEllipsoid<float>&, Vec3<float>&,
                                                   float&);
template bool penetrationPolytopesCertified<double>(const Polytope<double>&, const InnerEllipsoid<double>&,
                                                    const Polytope<double>&, const InnerEllipsoid<double>&, Vec3<double>&,
                                                    double&);

}  // namespace gq::detail
