#pragma once
// Helpers of the fit tests: generated meshes, surface sampling and an independent distance to a fit's surface.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <random>
#include <vector>

#include "gq/cooking.h"
#include "gq/custom_shapes.h"
#include "gq/fit.h"
#include "gq/query.h"
#include "generated_meshes.h"

namespace gq::fittest {

using Vec3d = Vec3<double>;

// A closed mesh of the unit-radius sphere (subdivided octahedron, vertices pushed out).
inline MeshData<double> sphereMesh(int levels, double radius = 1.0) {
  MeshData<double> m;
  m.vertices = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  m.triangles = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  for (int l = 0; l < levels; ++l) {
    std::vector<TriangleIndices> next;
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> mid;
    const auto middle = [&](std::uint32_t a, std::uint32_t b) {
      const auto key = std::minmax(a, b);
      auto it = mid.find(key);
      if (it != mid.end()) return it->second;
      m.vertices.push_back((m.vertices[a] + m.vertices[b]).normalized());
      mid[key] = std::uint32_t(m.vertices.size() - 1);
      return mid[key];
    };
    for (const auto& t : m.triangles) {
      const std::uint32_t ab = middle(t[0], t[1]), bc = middle(t[1], t[2]), ca = middle(t[2], t[0]);
      next.push_back({t[0], ab, ca});
      next.push_back({ab, t[1], bc});
      next.push_back({ca, bc, t[2]});
      next.push_back({ab, bc, ca});
    }
    m.triangles = std::move(next);
  }
  for (auto& v : m.vertices) v *= radius;
  return m;
}

// A closed box mesh of the given half extents, rotated and moved.
inline MeshData<double> boxMesh(const Vec3d& half, const Transform<double>& pose = Transform<double>()) {
  MeshData<double> m;
  for (int i = 0; i < 8; ++i)
    m.vertices.push_back(pose.transform(Vec3d((i & 1 ? 1 : -1) * half.x(), (i & 2 ? 1 : -1) * half.y(),
                                              (i & 4 ? 1 : -1) * half.z())));
  m.triangles = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                 {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  return m;
}

using gqtest::torusMesh;

// An L-shaped prism (not convex): the L polygon (0,0) (2,0) (2,0.5) (0.5,0.5) (0.5,1.5) (0,1.5) extruded over
// z in [-0.25, 0.25], closed and outward-facing.
inline MeshData<double> lShapeMesh() {
  const double xy[7][2] = {{0, 0}, {2, 0}, {2, 0.5}, {0.5, 0.5}, {0.5, 1.5}, {0, 1.5}, {0, 0.5}};
  MeshData<double> m;
  for (double z : {-0.25, 0.25})
    for (const auto& p : xy) m.vertices.emplace_back(p[0], p[1], z);
  // Caps: the L as two rectangles [0,2]x[0,0.5] and [0,0.5]x[0.5,1.5] (vertex 6 splits the left edge).
  const std::uint32_t cap[5][3] = {{0, 1, 2}, {0, 2, 3}, {0, 3, 6}, {6, 3, 4}, {6, 4, 5}};
  for (const auto& t : cap) {
    m.triangles.push_back({t[0] + 7, t[1] + 7, t[2] + 7});  // top, counter-clockwise from +z
    m.triangles.push_back({t[0], t[2], t[1]});              // bottom
  }
  const std::uint32_t ring[7] = {0, 1, 2, 3, 4, 5, 6};
  for (int i = 0; i < 7; ++i) {
    const std::uint32_t a = ring[i], b = ring[(i + 1) % 7];
    m.triangles.push_back({a, b, b + 7});
    m.triangles.push_back({a, b + 7, a + 7});
  }
  return m;
}

template <class T> MeshData<T> castMesh(const MeshData<double>& m) {
  MeshData<T> out;
  for (const auto& v : m.vertices) out.vertices.push_back(v.cast<T>());
  out.triangles = m.triangles;
  return out;
}

// Uniform points on the mesh surface (area-weighted triangles, uniform in each).
inline std::vector<Vec3d> sampleMesh(const MeshData<double>& m, std::size_t n, unsigned seed) {
  std::vector<double> cum;
  double total = 0;
  for (const auto& t : m.triangles) {
    total += 0.5 * (m.vertices[t[1]] - m.vertices[t[0]]).cross(m.vertices[t[2]] - m.vertices[t[0]]).norm();
    cum.push_back(total);
  }
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<Vec3d> out;
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t k = std::lower_bound(cum.begin(), cum.end(), u(rng) * total) - cum.begin();
    const auto& t = m.triangles[std::min(k, m.triangles.size() - 1)];
    double a = u(rng), b = u(rng);
    if (a + b > 1) {
      a = 1 - a;
      b = 1 - b;
    }
    out.push_back(m.vertices[t[0]] + a * (m.vertices[t[1]] - m.vertices[t[0]]) + b * (m.vertices[t[2]] - m.vertices[t[0]]));
  }
  return out;
}

// A fit part's surface as a triangle mesh fine enough to sample (its vertices lie on the exact surface and the
// triangles are flat, so samples are within a chord of it; tests sample the exact surface by projecting on it).
struct PartSampler {
  // Points exactly on the part's surface, `n` of them, roughly uniform.
  static std::vector<Vec3d> sample(const Geometry<double>& g, const Transform<double>& pose, std::size_t n,
                                   unsigned seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0, 1);
    std::normal_distribution<double> gauss;
    std::vector<Vec3d> out;
    const auto unit = [&] {
      Vec3d d(gauss(rng), gauss(rng), gauss(rng));
      return Vec3d(d.normalized());
    };
    switch (g.type()) {
      case GeometryType::Sphere: {
        const double r = g.get<SphereGeometry<double>>().radius;
        for (std::size_t i = 0; i < n; ++i) out.push_back(pose.transform(r * unit()));
        break;
      }
      case GeometryType::Capsule: {
        const auto& c = g.get<CapsuleGeometry<double>>();
        const double side = 2 * c.halfHeight * 2 * M_PI * c.radius, caps = 4 * M_PI * c.radius * c.radius;
        for (std::size_t i = 0; i < n; ++i) {
          if (u(rng) * (side + caps) < side) {
            const double phi = 2 * M_PI * u(rng);
            out.push_back(pose.transform(
                Vec3d((2 * u(rng) - 1) * c.halfHeight, c.radius * std::cos(phi), c.radius * std::sin(phi))));
          } else {
            const Vec3d d = unit();
            out.push_back(pose.transform(c.radius * d + Vec3d(d.x() >= 0 ? c.halfHeight : -c.halfHeight, 0, 0)));
          }
        }
        break;
      }
      case GeometryType::Box: {
        const Vec3d h = g.get<BoxGeometry<double>>().halfExtents;
        const double areas[3] = {h.y() * h.z(), h.x() * h.z(), h.x() * h.y()};
        for (std::size_t i = 0; i < n; ++i) {
          double pick = u(rng) * (areas[0] + areas[1] + areas[2]);
          int axis = pick < areas[0] ? 0 : pick < areas[0] + areas[1] ? 1 : 2;
          Vec3d l((2 * u(rng) - 1) * h.x(), (2 * u(rng) - 1) * h.y(), (2 * u(rng) - 1) * h.z());
          l[axis] = (u(rng) < 0.5 ? -1 : 1) * h[axis];
          out.push_back(pose.transform(l));
        }
        break;
      }
      case GeometryType::Custom: {
        const auto* cyl = dynamic_cast<const CylinderCallbacks<double>*>(g.get<CustomGeometry<double>>().callbacks.get());
        const double r = cyl->radius(), hh = cyl->halfHeight();
        const double side = 2 * hh * 2 * M_PI * r, caps = 2 * M_PI * r * r;
        for (std::size_t i = 0; i < n; ++i) {
          const double phi = 2 * M_PI * u(rng);
          if (u(rng) * (side + caps) < side)
            out.push_back(pose.transform(Vec3d((2 * u(rng) - 1) * hh, r * std::cos(phi), r * std::sin(phi))));
          else {
            const double rho = r * std::sqrt(u(rng));
            out.push_back(pose.transform(Vec3d(u(rng) < 0.5 ? -hh : hh, rho * std::cos(phi), rho * std::sin(phi))));
          }
        }
        break;
      }
      case GeometryType::ConvexMesh: {
        const auto& hull = *g.get<ConvexMeshGeometry<double>>().mesh;
        MeshData<double> m;
        m.vertices = hull.vertices;
        for (const auto& p : hull.polygons)
          for (std::uint32_t k = 1; k + 1 < p.indexCount; ++k)
            m.triangles.push_back({hull.polygonVertices[p.indexBase], hull.polygonVertices[p.indexBase + k],
                                   hull.polygonVertices[p.indexBase + k + 1]});
        for (const Vec3d& p : sampleMesh(m, n, seed)) out.push_back(pose.transform(p));
        break;
      }
      default: break;
    }
    return out;
  }
};

// Distance from p to the surface of a convex part, computed independently of the fitter: closed forms for the
// primitives, and for a hull the nearest face plane inside (the hull's own planes) or gq's point distance outside.
inline double surfaceDistance(const Geometry<double>& g, const Transform<double>& pose, const Vec3d& point) {
  const Vec3d p = pose.transformInv(point);
  switch (g.type()) {
    case GeometryType::Sphere: return std::abs(p.norm() - g.get<SphereGeometry<double>>().radius);
    case GeometryType::Capsule: {
      const auto& c = g.get<CapsuleGeometry<double>>();
      const double t = std::clamp(p.x(), -c.halfHeight, c.halfHeight);
      return std::abs((p - Vec3d(t, 0, 0)).norm() - c.radius);
    }
    case GeometryType::Box: {
      const Vec3d d = p.cwiseAbs() - g.get<BoxGeometry<double>>().halfExtents;
      if ((d.array() <= 0).all()) return -d.maxCoeff();
      return d.cwiseMax(0.0).norm();
    }
    case GeometryType::Custom: {
      const auto* cyl = dynamic_cast<const CylinderCallbacks<double>*>(g.get<CustomGeometry<double>>().callbacks.get());
      const double dx = std::abs(p.x()) - cyl->halfHeight(), dr = std::hypot(p.y(), p.z()) - cyl->radius();
      if (dx <= 0 && dr <= 0) return -std::max(dx, dr);
      return std::hypot(std::max(dx, 0.0), std::max(dr, 0.0));
    }
    case GeometryType::ConvexMesh: {
      const auto& hull = *g.get<ConvexMeshGeometry<double>>().mesh;
      double most = -1e300;
      for (const auto& poly : hull.polygons) most = std::max(most, poly.normal.dot(p) + poly.d);
      if (most <= 0) return -most;
      PointDistanceResult<double> r;
      EXPECT_TRUE(pointDistance<double>(point, g, pose, r).ok());
      return r.distance;
    }
    default: ADD_FAILURE() << "unexpected part type"; return 0;
  }
}

// The sampled two-sided Hausdorff distance between the mesh surface and the fit (one convex part, or several whose
// union's surface is approximated by the part surfaces outside the other parts): n points each way. It never
// exceeds the true distance by more than the hull's plane rounding.
inline double sampledHausdorff(const MeshData<double>& mesh,
                               const std::vector<std::pair<Geometry<double>, Transform<double>>>& parts,
                               std::size_t n) {
  double worst = 0;
  for (const Vec3d& p : sampleMesh(mesh, n, 7)) {
    double d = 1e300;
    if (parts.size() == 1) {
      d = surfaceDistance(parts[0].first, parts[0].second, p);
    } else {
      // Outside every part: the distance to the union is the nearest part's. Inside some: its depth in any one part
      // is at most its distance to the union's surface (the ball of that radius lies in the part), so the largest
      // depth is a distance from below.
      bool inside = false;
      double deepest = 0;
      for (const auto& part : parts) {
        PointDistanceResult<double> r;
        EXPECT_TRUE(pointDistance<double>(p, part.first, part.second, r).ok());
        if (r.distance == 0) {
          inside = true;
          deepest = std::max(deepest, surfaceDistance(part.first, part.second, p));
        }
        d = std::min(d, r.distance);
      }
      if (inside) d = deepest;
    }
    worst = std::max(worst, d);
  }
  std::shared_ptr<const TriangleMesh<double>> cooked;
  EXPECT_TRUE(cookTriangleMesh(mesh.vertices, mesh.triangles, cooked).ok());
  const TriangleMeshGeometry<double> surface(cooked);
  for (std::size_t k = 0; k < parts.size(); ++k) {
    for (const Vec3d& q : PartSampler::sample(parts[k].first, parts[k].second, n / parts.size() + 1, 11 + unsigned(k))) {
      bool buried = false;  // a point inside another part is not on the union's surface
      for (std::size_t j = 0; j < parts.size() && !buried; ++j) {
        if (j == k) continue;
        PointDistanceResult<double> r;
        EXPECT_TRUE(pointDistance<double>(q, parts[j].first, parts[j].second, r).ok());
        if (r.distance == 0) buried = true;
      }
      if (buried) continue;
      PointDistanceResult<double> r;
      EXPECT_TRUE(pointDistance<double>(q, surface, Transform<double>(), r).ok());
      worst = std::max(worst, r.distance);
    }
  }
  return worst;
}

// Whether every mesh vertex is inside the union of the parts (within `slack`).
inline bool containsVertices(const MeshData<double>& mesh,
                             const std::vector<std::pair<Geometry<double>, Transform<double>>>& parts, double slack) {
  for (const Vec3d& v : mesh.vertices) {
    double best = 1e300;
    for (const auto& part : parts) {
      if (part.first.type() == GeometryType::Custom) {
        const Vec3d p = part.second.transformInv(v);
        const auto* cyl =
            dynamic_cast<const CylinderCallbacks<double>*>(part.first.get<CustomGeometry<double>>().callbacks.get());
        const double dx = std::abs(p.x()) - cyl->halfHeight(), dr = std::hypot(p.y(), p.z()) - cyl->radius();
        best = std::min(best, std::hypot(std::max(dx, 0.0), std::max(dr, 0.0)));
      } else {
        PointDistanceResult<double> r;
        EXPECT_TRUE(pointDistance<double>(v, part.first, part.second, r).ok());
        best = std::min(best, r.distance);
      }
    }
    if (best > slack) return false;
  }
  return true;
}

// Every number a fit hands out (bound, representation, part poses and shapes, candidates' bounds), in order.
template <class T> std::vector<double> fingerprint(const FitResult<T>& fit) {
  std::vector<double> f = {double(fit.errorBound), double(fit.representation), double(fit.parts.size())};
  for (const auto& [g, pose] : fit.parts) {
    for (int i = 0; i < 3; ++i) f.push_back(double(pose.p[i]));
    for (int i = 0; i < 4; ++i) f.push_back(double(pose.q.coeffs()[i]));
    if (const auto* c = g.template getIf<ConvexMeshGeometry<T>>())
      for (const auto& v : c->mesh->vertices) f.insert(f.end(), v.data(), v.data() + 3);
    if (const auto* b = g.template getIf<BoxGeometry<T>>()) f.insert(f.end(), b->halfExtents.data(), b->halfExtents.data() + 3);
    if (const auto* s = g.template getIf<SphereGeometry<T>>()) f.push_back(double(s->radius));
    if (const auto* c = g.template getIf<CapsuleGeometry<T>>()) f.insert(f.end(), {double(c->radius), double(c->halfHeight)});
    if (const auto* c = g.template getIf<CustomGeometry<T>>())
      if (const auto* cyl = dynamic_cast<const CylinderCallbacks<T>*>(c->callbacks.get()))
        f.insert(f.end(), {double(cyl->radius()), double(cyl->halfHeight())});
  }
  for (const auto& c : fit.candidates) f.push_back(double(c.errorBound));
  return f;
}

// Whether two fingerprints are equal bit for bit (NaN and -0 included).
inline bool sameBits(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0);
}

inline const FitRepresentation kSolidRepresentations[] = {
    FitRepresentation::Sphere,         FitRepresentation::Capsule,    FitRepresentation::Box,
    FitRepresentation::Cylinder,       FitRepresentation::SimplifiedHull, FitRepresentation::ConvexHull,
    FitRepresentation::ConvexDecomposition};

}  // namespace gq::fittest
