#pragma once
// Independent long double referees for the mesh and primitive modes of the FCL comparison.
//  - Triangle meshes (surfaces) against meshes or boxes: the exact SAT gap of every triangle pair (exact_polytope.h)
//    whose AABBs come within `kNearGap`; the smallest gap's sign says whether the surfaces touch.
//  - Primitives (sphere, capsule, box, cylinder) as solids: alternating projections x <- P_A(y), y <- P_B(x) give
//    points x in A, y in B with |x - y| an upper bound of the distance (-> 0 when the solids meet), and the direction
//    n = (y - x)/|y - x| gives the lower bound min_B n.y - max_A n.x (> 0 proves them disjoint).
#include <algorithm>
#include <cmath>
#include <limits>

#include "exact_polytope.h"
#include "gq/custom_shapes.h"

namespace gq::urdf::test {

// Result of a referee: the exact separation lies in [lower, upper] (<= 0: the shapes touch or overlap).
struct Bracket {
  LD lower = 0, upper = 0;
  bool provesContact() const { return upper <= 0; }
  bool provesSeparation() const { return lower > 0; }
};

// ---- Meshes ----------------------------------------------------------------------------------------------------
inline constexpr LD kNearGap = 1e-3L;  // m: triangle pairs whose AABBs are farther apart cannot decide the sign

struct WorldTriangles {
  std::vector<Polytope> triangles;
  std::vector<std::pair<Vec3L, Vec3L>> bounds;
};

inline WorldTriangles worldTriangles(const TriangleMesh<double>& mesh, const Transform<double>& pose) {
  const Mat3<LD> r = pose.q.normalized().toRotationMatrix().cast<LD>();
  const Vec3L t = pose.p.cast<LD>();
  WorldTriangles out;
  for (const auto& tri : mesh.triangles) {
    const Vec3L a = r * mesh.vertices[tri[0]].cast<LD>() + t, b = r * mesh.vertices[tri[1]].cast<LD>() + t,
                c = r * mesh.vertices[tri[2]].cast<LD>() + t;
    out.triangles.push_back(trianglePolytope(a, b, c));
    out.bounds.push_back({a.cwiseMin(b).cwiseMin(c), a.cwiseMax(b).cwiseMax(c)});
  }
  return out;
}

inline std::pair<Vec3L, Vec3L> polytopeBounds(const Polytope& p) {
  Vec3L lo = p.vertices[0], hi = p.vertices[0];
  for (const auto& v : p.vertices) {
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
  }
  return {lo, hi};
}

inline LD boundsGap(const std::pair<Vec3L, Vec3L>& a, const std::pair<Vec3L, Vec3L>& b) {
  return std::max({LD(0), (a.first - b.second).maxCoeff(), (b.first - a.second).maxCoeff()});
}

// Smallest SAT gap between the triangles of `a` and the pieces (triangles or one box) of `b`; kNearGap when no
// pair comes that close (the shapes are then certainly apart).
inline LD surfaceGap(const WorldTriangles& a, const std::vector<Polytope>& b) {
  std::vector<std::pair<Vec3L, Vec3L>> bBounds;
  for (const auto& p : b) bBounds.push_back(polytopeBounds(p));
  LD best = kNearGap;
  for (std::size_t i = 0; i < a.triangles.size(); ++i)
    for (std::size_t j = 0; j < b.size(); ++j)
      if (boundsGap(a.bounds[i], bBounds[j]) < best) best = std::min(best, satGap(a.triangles[i], b[j]));
  return best;
}

// ---- Primitive solids ------------------------------------------------------------------------------------------
struct Solid {
  enum class Kind { Sphere, Capsule, Box, Cylinder } kind = Kind::Sphere;
  Mat3<LD> r = Mat3<LD>::Identity();  // local -> world
  Vec3L t = Vec3L::Zero();
  LD radius = 0, halfHeight = 0;      // capsule and cylinder along local x
  Vec3L half = Vec3L::Zero();
};

// Returns false for geometry that is not one of the four primitives.
inline bool worldSolid(const Shape<double>& shape, const Transform<double>& pose, Solid& out) {
  out = Solid();
  out.r = pose.q.normalized().toRotationMatrix().cast<LD>();
  out.t = pose.p.cast<LD>();
  const Geometry<double>& g = shape.geometry;
  if (const auto* s = g.getIf<SphereGeometry<double>>()) {
    out.kind = Solid::Kind::Sphere;
    out.radius = s->radius;
  } else if (const auto* c = g.getIf<CapsuleGeometry<double>>()) {
    out.kind = Solid::Kind::Capsule;
    out.radius = c->radius;
    out.halfHeight = c->halfHeight;
  } else if (const auto* b = g.getIf<BoxGeometry<double>>()) {
    out.kind = Solid::Kind::Box;
    out.half = b->halfExtents.cast<LD>();
  } else if (const auto* custom = g.getIf<CustomGeometry<double>>()) {
    const auto* cyl = dynamic_cast<const CylinderCallbacks<double>*>(custom->callbacks.get());
    if (!cyl) return false;
    out.kind = Solid::Kind::Cylinder;
    out.radius = cyl->radius();
    out.halfHeight = cyl->halfHeight();
  } else {
    return false;
  }
  return true;
}

// Nearest point of the solid to p (local frame). The cylinder is the product of an interval and a disk, so its
// projection clamps the axial and the radial part independently.
inline Vec3L projectLocal(const Solid& s, const Vec3L& p) {
  const auto clampRadial = [](const Vec3L& v, LD r) { const LD n = v.norm(); return n > r ? Vec3L(v * (r / n)) : v; };
  switch (s.kind) {
    case Solid::Kind::Sphere: return clampRadial(p, s.radius);
    case Solid::Kind::Capsule: {
      const Vec3L axis(std::clamp(p.x(), -s.halfHeight, s.halfHeight), 0, 0);
      return axis + clampRadial(p - axis, s.radius);
    }
    case Solid::Kind::Box: return p.cwiseMax(-s.half).cwiseMin(s.half);
    case Solid::Kind::Cylinder: {
      const Vec3L radial = clampRadial(Vec3L(0, p.y(), p.z()), s.radius);
      return Vec3L(std::clamp(p.x(), -s.halfHeight, s.halfHeight), radial.y(), radial.z());
    }
  }
  return p;
}

// max over the solid of n.x (local n).
inline LD supportLocal(const Solid& s, const Vec3L& n) {
  switch (s.kind) {
    case Solid::Kind::Sphere: return s.radius * n.norm();
    case Solid::Kind::Capsule: return s.halfHeight * std::abs(n.x()) + s.radius * n.norm();
    case Solid::Kind::Box: return n.cwiseAbs().dot(s.half);
    case Solid::Kind::Cylinder: return s.halfHeight * std::abs(n.x()) + s.radius * std::hypot(n.y(), n.z());
  }
  return 0;
}

inline Vec3L project(const Solid& s, const Vec3L& p) { return s.r * projectLocal(s, s.r.transpose() * (p - s.t)) + s.t; }
inline LD support(const Solid& s, const Vec3L& n) { return supportLocal(s, s.r.transpose() * n) + n.dot(s.t); }

inline Bracket solidGap(const Solid& a, const Solid& b, int iterations = 20000) {
  Vec3L y = b.t, x = project(a, y);
  for (int k = 0; k < iterations; ++k) {
    y = project(b, x);
    const Vec3L next = project(a, y);
    const bool settled = (next - x).norm() <= 1e-17L;
    x = next;
    if (settled) break;
  }
  y = project(b, x);
  Bracket out;
  out.upper = (y - x).norm();
  if (out.upper <= 1e-15L) {  // a common point, up to the projections' rounding
    out.upper = 0;
    out.lower = -std::numeric_limits<LD>::infinity();
    return out;
  }
  const Vec3L n = (y - x) / out.upper;
  out.lower = -support(b, Vec3L(-n)) - support(a, n);  // min_B n.y - max_A n.x
  return out;
}

}  // namespace gq::urdf::test
