// Shape descriptions: their case-format JSON, their exact world-frame form, random shapes and test meshes.
#include <cmath>
#include <map>

#include "suite.h"

namespace gq::suites {
namespace {

nlohmann::json vec(const V3d& v) { return nlohmann::json::array({v.x(), v.y(), v.z()}); }

}  // namespace

const char* kindName(Kind k) {
  switch (k) {
    case Kind::Sphere: return "sphere";
    case Kind::Capsule: return "capsule";
    case Kind::Box: return "box";
    case Kind::Plane: return "plane";
    case Kind::Convex: return "convex";
    case Kind::Mesh: return "mesh";
    case Kind::Cylinder: return "cylinder";
  }
  return "";
}

nlohmann::json toJson(const Shape& s) {
  nlohmann::json j;
  j["type"] = kindName(s.kind);
  switch (s.kind) {
    case Kind::Sphere: j["radius"] = s.radius; break;
    case Kind::Capsule:
    case Kind::Cylinder:
      j["radius"] = s.radius;
      j["halfHeight"] = s.halfHeight;
      break;
    case Kind::Box: j["halfExtents"] = vec(s.halfExtents); break;
    case Kind::Plane: break;
    case Kind::Convex:
      j["points"] = nlohmann::json::array();
      for (const V3d& p : s.points) j["points"].push_back(vec(p));
      break;
    case Kind::Mesh:
      j["vertices"] = nlohmann::json::array();
      for (const V3d& p : s.points) j["vertices"].push_back(vec(p));
      j["triangles"] = s.triangles;
      if (s.doubleSided) j["doubleSided"] = true;
      break;
  }
  return j;
}

nlohmann::json toJson(const Pose& p) {
  return {{"p", vec(p.p)}, {"q", nlohmann::json::array({p.q.x(), p.q.y(), p.q.z(), p.q.w()})}};
}

Q rotationOf(const Pose& p) {
  Q q(Ld(p.q.w()), Ld(p.q.x()), Ld(p.q.y()), Ld(p.q.z()));
  q.coeffs() /= q.coeffs().norm();
  return q;
}

V3 toWorld(const Pose& p, const V3d& local) { return rotationOf(p) * local.cast<Ld>() + p.p.cast<Ld>(); }

Core coreOf(const Placed& s) {
  Core c;
  const Shape& sh = s.shape;
  switch (sh.kind) {
    case Kind::Sphere:
      c.points = {toWorld(s.pose, V3d::Zero())};
      c.radius = sh.radius;
      break;
    case Kind::Capsule:
      c.points = {toWorld(s.pose, V3d(-sh.halfHeight, 0, 0)), toWorld(s.pose, V3d(sh.halfHeight, 0, 0))};
      c.radius = sh.radius;
      break;
    case Kind::Box:
      for (int i = 0; i < 8; ++i)
        c.points.push_back(toWorld(s.pose, V3d((i & 1) ? sh.halfExtents.x() : -sh.halfExtents.x(),
                                               (i & 2) ? sh.halfExtents.y() : -sh.halfExtents.y(),
                                               (i & 4) ? sh.halfExtents.z() : -sh.halfExtents.z())));
      break;
    default:
      for (const V3d& p : sh.points) c.points.push_back(toWorld(s.pose, p));
      break;
  }
  return c;
}

HalfSpace halfSpaceOf(const Placed& s) {
  HalfSpace h;
  h.normal = rotationOf(s.pose) * V3::UnitX();
  h.origin = s.pose.p.cast<Ld>();
  return h;
}

TriangleSoup soupOf(const Placed& s) {
  TriangleSoup t;
  for (const V3d& p : s.shape.points) t.vertices.push_back(toWorld(s.pose, p));
  t.triangles = s.shape.triangles;
  t.doubleSided = s.shape.doubleSided;
  return t;
}

double sizeOf(const Shape& s) {
  switch (s.kind) {
    case Kind::Sphere: return s.radius;
    case Kind::Capsule:
    case Kind::Cylinder: return std::hypot(s.radius, s.halfHeight) + s.radius;
    case Kind::Box: return s.halfExtents.norm();
    case Kind::Plane: return 1.0;  // unbounded: the other shape sets the scale
    default: {
      double r = 0;
      for (const V3d& p : s.points) r = std::max(r, p.norm());
      return r;
    }
  }
}

bool isPolytopeOrRound(Kind k) { return k == Kind::Sphere || k == Kind::Capsule || k == Kind::Box || k == Kind::Convex; }

V3d Random::unitVector() {
  std::normal_distribution<double> g;
  V3d v(g(engine_), g(engine_), g(engine_));
  return v.normalized();
}

Eigen::Vector4d Random::rotation() {
  std::normal_distribution<double> g;
  Eigen::Vector4d q(g(engine_), g(engine_), g(engine_), g(engine_));
  return q.normalized();
}

Placed Random::placed(Kind k) {
  Placed t;
  t.shape = k == Kind::Mesh ? ellipsoidMesh(V3d(1.0, 0.8, 0.6), 1) : shape(k);
  t.shape.kind = k;
  t.pose.p = inBox(1.0);
  t.pose.q = rotation();
  return t;
}

Shape Random::shape(Kind k) {
  Shape s;
  s.kind = k;
  switch (k) {
    case Kind::Sphere: s.radius = uniform(0.3, 1.2); break;
    case Kind::Capsule:
      s.radius = uniform(0.2, 0.6);
      s.halfHeight = uniform(0.3, 1.0);
      break;
    case Kind::Box: s.halfExtents = V3d(uniform(0.3, 1.2), uniform(0.3, 1.2), uniform(0.3, 1.2)); break;
    case Kind::Convex: {
      // Points on an ellipsoid: all of them are hull vertices.
      const V3d axes(uniform(0.4, 1.2), uniform(0.4, 1.2), uniform(0.4, 1.2));
      for (int i = 0; i < 12; ++i) s.points.push_back(unitVector().cwiseProduct(axes));
      break;
    }
    default: break;
  }
  return s;
}

Eigen::Vector4d axisAngle(const V3d& axis, double angle) {
  const V3d a = axis.normalized() * std::sin(angle / 2);
  return Eigen::Vector4d(a.x(), a.y(), a.z(), std::cos(angle / 2));
}

Eigen::Vector4d compose(const Eigen::Vector4d& q, const Eigen::Vector4d& r) {
  const Eigen::Quaterniond a(q.w(), q.x(), q.y(), q.z()), b(r.w(), r.x(), r.y(), r.z());
  const Eigen::Quaterniond c = a * b;
  return Eigen::Vector4d(c.x(), c.y(), c.z(), c.w());
}

Shape ellipsoidMesh(const V3d& radii, int subdivisions) {
  std::vector<V3d> v = {V3d::UnitX(), -V3d::UnitX(), V3d::UnitY(), -V3d::UnitY(), V3d::UnitZ(), -V3d::UnitZ()};
  // Octahedron faces, counter-clockwise seen from outside.
  std::vector<std::array<std::uint32_t, 3>> f = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                                                 {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  for (int level = 0; level < subdivisions; ++level) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> mid;
    const auto midpoint = [&](std::uint32_t a, std::uint32_t b) {
      const auto key = std::minmax(a, b);
      auto it = mid.find(key);
      if (it != mid.end()) return it->second;
      v.push_back((v[a] + v[b]).normalized());
      return mid[key] = std::uint32_t(v.size() - 1);
    };
    std::vector<std::array<std::uint32_t, 3>> next;
    for (const auto& t : f) {
      const std::uint32_t ab = midpoint(t[0], t[1]), bc = midpoint(t[1], t[2]), ca = midpoint(t[2], t[0]);
      next.push_back({t[0], ab, ca});
      next.push_back({ab, t[1], bc});
      next.push_back({ca, bc, t[2]});
      next.push_back({ab, bc, ca});
    }
    f = std::move(next);
  }
  Shape s;
  s.kind = Kind::Mesh;
  for (const V3d& p : v) s.points.push_back(p.cwiseProduct(radii));
  s.triangles = f;
  return s;
}

Shape sliverQuadMesh(double halfSize, int slivers, double sliverWidth) {
  // The quad x = 0, |y|,|z| <= halfSize. The top edge carries `slivers` vertices packed within sliverWidth of
  // y = 0; fans from both bottom corners make triangles thinner than sliverWidth / halfSize.
  Shape s;
  s.kind = Kind::Mesh;
  s.doubleSided = true;
  s.points = {V3d(0, -halfSize, -halfSize), V3d(0, halfSize, -halfSize), V3d(0, -halfSize, halfSize)};
  for (int i = 0; i < slivers; ++i)
    s.points.push_back(V3d(0, sliverWidth * (i - 0.5 * (slivers - 1)), halfSize));
  s.points.push_back(V3d(0, halfSize, halfSize));
  const std::uint32_t n = std::uint32_t(s.points.size());
  const std::uint32_t mid = 3 + std::uint32_t(slivers / 2);
  // Left corner fans over the top vertices up to the middle one; the right corner over the rest.
  for (std::uint32_t i = 2; i < mid; ++i) s.triangles.push_back({0, i, i + 1});
  for (std::uint32_t i = mid; i + 1 < n; ++i) s.triangles.push_back({1, i, i + 1});
  s.triangles.push_back({0, 1, mid});
  return s;
}

}  // namespace gq::suites
