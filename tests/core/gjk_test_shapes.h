#pragma once
// Test-side references for the distance/GJK tests: seeded random poses, brute-force convex hulls of points on a
// sphere, and exact polytope distance / penetration depth by brute force over feature pairs in long double.
// Written independently of the library kernels (different formulations on purpose).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include "gq/cooking.h"
#include "gq/geometry.h"
#include "gq/query.h"

namespace gjktest {

using L = long double;
using VL = Eigen::Matrix<L, 3, 1>;

using Scalars = ::testing::Types<float, double>;

// |computed - exact| bound for a quantity of unit size: closed forms, GJK/EPA.
template <class T> constexpr double kClosedFormTol = std::is_same_v<T, double> ? 1e-9 : 1e-4;
template <class T> constexpr double kGjkTol = std::is_same_v<T, double> ? 1e-7 : 1e-4;

template <class T> VL toL(const gq::Vec3<T>& v) { return v.template cast<L>(); }

// One draw per statement (or a braced list): argument evaluation order is unspecified (GCC and clang differ).
struct Rng {
  std::mt19937_64 gen;
  explicit Rng(std::uint64_t seed) : gen(seed) {}
  double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(gen); }
  Eigen::Vector3d vec(double lo, double hi) { return {uniform(lo, hi), uniform(lo, hi), uniform(lo, hi)}; }
  Eigen::Quaterniond rotation() {
    std::normal_distribution<double> n;
    const double w = n(gen);
    const double x = n(gen);
    const double y = n(gen);
    const double z = n(gen);
    return Eigen::Quaterniond(w, x, y, z).normalized();
  }
  Eigen::Vector3d unit() {
    std::normal_distribution<double> n;
    const double x = n(gen);
    const double y = n(gen);
    const double z = n(gen);
    return Eigen::Vector3d(x, y, z).normalized();
  }
};

template <class T> gq::Transform<T> randomPose(Rng& rng, double spread) {
  const gq::Vec3<T> p = rng.vec(-spread, spread).cast<T>();
  return gq::Transform<T>(p, rng.rotation().cast<T>());
}

// Per-axis stretch in [lo, hi) along randomly rotated axes.
template <class T> gq::MeshScale<T> randomScale(Rng& rng, double lo, double hi) {
  const gq::Vec3<T> s = rng.vec(lo, hi).cast<T>();
  return gq::MeshScale<T>(s, rng.rotation().cast<T>());
}

// The pose as the library sees it (rotation renormalised), in long double.
struct PoseL {
  Eigen::Quaternion<L> q;
  VL p;
  VL apply(const VL& x) const { return q * x + p; }
  VL rotate(const VL& x) const { return q * x; }
};
template <class T> PoseL toL(const gq::Transform<T>& t) { return PoseL{t.q.template cast<L>().normalized(), t.p.template cast<L>()}; }

// ---- Polytopes: world vertices, triangles (outward), edges ---------------------------------------------------
struct Polytope {
  std::vector<VL> v;
  std::vector<std::array<int, 3>> tris;
  std::vector<std::pair<int, int>> edges;
};

inline void addEdgesFromTriangles(Polytope& p) {
  std::set<std::pair<int, int>> e;
  for (const auto& t : p.tris)
    for (int k = 0; k < 3; ++k) e.insert(std::minmax(t[k], t[(k + 1) % 3]));
  p.edges.assign(e.begin(), e.end());
}

// Brute-force hull triangles of points in general position: (i,j,k) is a face when all points lie on one side.
inline std::vector<std::array<int, 3>> bruteForceHull(const std::vector<VL>& pts) {
  std::vector<std::array<int, 3>> tris;
  const int n = int(pts.size());
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j)
      for (int k = j + 1; k < n; ++k) {
        const VL nrm = (pts[j] - pts[i]).cross(pts[k] - pts[i]);
        int above = 0, below = 0;
        for (int m = 0; m < n && !(above && below); ++m) {
          if (m == i || m == j || m == k) continue;
          const L s = nrm.dot(pts[m] - pts[i]);
          if (s > 0) ++above;
          if (s < 0) ++below;  // coplanar points (box faces) count for neither side
        }
        if (above && below) continue;
        tris.push_back(above ? std::array<int, 3>{i, k, j} : std::array<int, 3>{i, j, k});
      }
  return tris;
}

// A cooked-looking ConvexMesh built directly (triangular polygons, edge adjacency), so these tests do not depend
// on the qhull cooker.
template <class T> std::shared_ptr<const gq::ConvexMesh<T>> makeHull(const std::vector<gq::Vec3<T>>& pts) {
  std::vector<VL> ptsL;
  for (const auto& p : pts) ptsL.push_back(toL(p));
  const auto tris = bruteForceHull(ptsL);
  auto mesh = std::make_shared<gq::ConvexMesh<T>>();
  mesh->vertices = pts;
  std::vector<std::set<std::uint32_t>> adj(pts.size());
  for (const auto& t : tris) {
    const VL n = (ptsL[t[1]] - ptsL[t[0]]).cross(ptsL[t[2]] - ptsL[t[0]]).normalized();
    gq::HullPolygon<T> poly{n.cast<T>(), T(-n.dot(ptsL[t[0]])), std::uint32_t(mesh->polygonVertices.size()), 3};
    mesh->polygons.push_back(poly);
    for (int k = 0; k < 3; ++k) {
      mesh->polygonVertices.push_back(std::uint32_t(t[k]));
      adj[t[k]].insert(std::uint32_t(t[(k + 1) % 3]));
      adj[t[(k + 1) % 3]].insert(std::uint32_t(t[k]));
    }
  }
  mesh->adjacencyOffsets.push_back(0);
  for (const auto& a : adj) {
    mesh->adjacency.insert(mesh->adjacency.end(), a.begin(), a.end());
    mesh->adjacencyOffsets.push_back(std::uint32_t(mesh->adjacency.size()));
  }
  gq::Vec3<T> c = gq::Vec3<T>::Zero();
  for (const auto& p : pts) {
    mesh->localBounds.include(p);
    c += p;
  }
  mesh->center = c / T(pts.size());
  return mesh;
}

template <class T> std::vector<gq::Vec3<T>> pointsOnEllipsoid(Rng& rng, int n, const Eigen::Vector3d& radii) {
  std::vector<gq::Vec3<T>> pts;
  for (int i = 0; i < n; ++i) pts.push_back(rng.unit().cwiseProduct(radii).cast<T>());
  return pts;
}

template <class T> Polytope hullPolytope(const gq::ConvexMesh<T>& mesh, const gq::Transform<T>& pose) {
  Polytope p;
  const PoseL t = toL(pose);
  for (const auto& v : mesh.vertices) p.v.push_back(t.apply(toL(v)));
  for (const auto& poly : mesh.polygons)
    p.tris.push_back({int(mesh.polygonVertices[poly.indexBase]), int(mesh.polygonVertices[poly.indexBase + 1]),
                      int(mesh.polygonVertices[poly.indexBase + 2])});
  addEdgesFromTriangles(p);
  return p;
}

template <class T> Polytope boxPolytope(const gq::Vec3<T>& h, const gq::Transform<T>& pose) {
  Polytope p;
  const PoseL t = toL(pose);
  std::vector<VL> local;
  for (int i = 0; i < 8; ++i)
    local.push_back(VL((i & 1) ? L(h.x()) : -L(h.x()), (i & 2) ? L(h.y()) : -L(h.y()), (i & 4) ? L(h.z()) : -L(h.z())));
  for (const auto& v : local) p.v.push_back(t.apply(v));
  // Coplanar corners: all four corner triangles of each face are kept; the extra diagonal edges and triangles are
  // harmless for the brute force (they lie on the surface).
  p.tris = bruteForceHull(local);
  addEdgesFromTriangles(p);
  return p;
}

// ---- Exact distances in long double ----------------------------------------------------------------------------
inline L pointSegment(const VL& x, const VL& a, const VL& b) {
  const VL d = b - a;
  const L dd = d.squaredNorm();
  const L t = dd > 0 ? std::clamp((x - a).dot(d) / dd, L(0), L(1)) : L(0);
  return (a + t * d - x).norm();
}

// Point to triangle: the plane distance if the projection falls inside, else the nearest edge.
inline L pointTriangle(const VL& x, const VL& a, const VL& b, const VL& c) {
  const VL n = (b - a).cross(c - a);
  const L nn = n.squaredNorm();
  const VL proj = x - n * (n.dot(x - a) / nn);
  const L u = n.dot((b - proj).cross(c - proj)), v = n.dot((c - proj).cross(a - proj)), w = n.dot((a - proj).cross(b - proj));
  if (u >= 0 && v >= 0 && w >= 0) return std::abs(n.dot(x - a)) / std::sqrt(nn);
  return std::min({pointSegment(x, a, b), pointSegment(x, b, c), pointSegment(x, c, a)});
}

// Segment to segment: the interior stationary point if it lies in [0,1]^2, else the best end point vs segment.
inline L segmentSegment(const VL& p0, const VL& q0, const VL& p1, const VL& q1) {
  const VL d0 = q0 - p0, d1 = q1 - p1, r = p0 - p1;
  const L a = d0.dot(d0), b = d0.dot(d1), e = d1.dot(d1), c = d0.dot(r), f = d1.dot(r);
  const L det = a * e - b * b;
  if (det > L(1e-12) * a * e) {  // else (near-)parallel: an end point attains the minimum
    const L s = (b * f - c * e) / det, t = (a * f - b * c) / det;
    if (s >= 0 && s <= 1 && t >= 0 && t <= 1) return (p0 + s * d0 - p1 - t * d1).norm();
  }
  return std::min({pointSegment(p0, p1, q1), pointSegment(q0, p1, q1), pointSegment(p1, p0, q0), pointSegment(q1, p0, q0)});
}

// Separation of two disjoint convex polytopes: min over vertex-face and edge-edge feature pairs.
inline L polytopeDistance(const Polytope& A, const Polytope& B) {
  L best = std::numeric_limits<L>::infinity();
  for (const auto& v : A.v)
    for (const auto& t : B.tris) best = std::min(best, pointTriangle(v, B.v[t[0]], B.v[t[1]], B.v[t[2]]));
  for (const auto& v : B.v)
    for (const auto& t : A.tris) best = std::min(best, pointTriangle(v, A.v[t[0]], A.v[t[1]], A.v[t[2]]));
  for (const auto& ea : A.edges)
    for (const auto& eb : B.edges) best = std::min(best, segmentSegment(A.v[ea.first], A.v[ea.second], B.v[eb.first], B.v[eb.second]));
  return best;
}

// Penetration depth of two overlapping convex polytopes: min over the SAT axes (face normals, edge cross
// products) of the projected overlap. Returns a negative number if some axis separates.
inline L polytopePenetration(const Polytope& A, const Polytope& B) {
  std::vector<VL> axes;
  for (const Polytope* P : {&A, &B})
    for (const auto& t : P->tris) axes.push_back((P->v[t[1]] - P->v[t[0]]).cross(P->v[t[2]] - P->v[t[0]]).normalized());
  for (const auto& ea : A.edges)
    for (const auto& eb : B.edges) {
      const VL c = (A.v[ea.second] - A.v[ea.first]).cross(B.v[eb.second] - B.v[eb.first]);
      if (c.norm() > L(1e-9)) axes.push_back(c.normalized());
    }
  L best = std::numeric_limits<L>::infinity();
  for (const auto& n : axes) {
    L minA = std::numeric_limits<L>::infinity(), maxA = -minA, minB = minA, maxB = -minA;
    for (const auto& v : A.v) { minA = std::min(minA, n.dot(v)); maxA = std::max(maxA, n.dot(v)); }
    for (const auto& v : B.v) { minB = std::min(minB, n.dot(v)); maxB = std::max(maxB, n.dot(v)); }
    best = std::min(best, std::min(maxA - minB, maxB - minA));
  }
  return best;
}

// Signed distance from x to a polytope surface: >= 0 outside (exact), < 0 inside (minus the nearest face plane).
inline L signedDistanceToPolytope(const VL& x, const Polytope& P) {
  L outside = -std::numeric_limits<L>::infinity();
  for (const auto& t : P.tris) {
    const VL n = (P.v[t[1]] - P.v[t[0]]).cross(P.v[t[2]] - P.v[t[0]]).normalized();
    outside = std::max(outside, n.dot(x - P.v[t[0]]));
  }
  if (outside <= 0) return outside;
  L best = std::numeric_limits<L>::infinity();
  for (const auto& t : P.tris) best = std::min(best, pointTriangle(x, P.v[t[0]], P.v[t[1]], P.v[t[2]]));
  return best;
}

// ---- Common result checks --------------------------------------------------------------------------------------
// The normal is unit and point1 = point0 + distance * normal (so |point1 - point0| = |distance|).
template <class T> void expectConsistent(const gq::DistanceResult<T>& r, double tol) {
  EXPECT_NEAR(double(toL(r.normal).norm()), 1.0, tol);
  const VL gap = toL(r.point1) - toL(r.point0);
  EXPECT_NEAR(double(gap.norm()), std::abs(double(r.distance)), tol);
  EXPECT_LE(double((gap - L(r.distance) * toL(r.normal)).norm()), tol);
}

template <class T> gq::Geometry<T> sphere(double r) { return gq::SphereGeometry<T>(T(r)); }
template <class T> gq::Geometry<T> capsule(double r, double hh) { return gq::CapsuleGeometry<T>(T(r), T(hh)); }
template <class T> gq::Geometry<T> box(const Eigen::Vector3d& h) { return gq::BoxGeometry<T>(h.cast<T>()); }

// Capsule segment end points in world (long double).
template <class T> std::pair<VL, VL> capsuleSegment(const gq::CapsuleGeometry<T>& c, const gq::Transform<T>& pose) {
  const PoseL t = toL(pose);
  const VL a = t.rotate(VL(L(c.halfHeight), 0, 0));
  return {t.p - a, t.p + a};
}

}  // namespace gjktest
