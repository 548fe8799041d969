// Raycast suite: random rays, rays grazing edges and vertices, rays starting on surfaces, sliver triangles and
// far poses against every solid, planes and triangle meshes; exact hits from exact.h.
#include <array>
#include <cmath>
#include <cstdio>

#include "suite.h"

namespace gq::suites {
namespace {

constexpr double kMaxDist = 100;

std::optional<Ld> exactRayHit(const Placed& t, const V3& o, const V3& d) {
  switch (t.shape.kind) {
    case Kind::Plane: return rayHit(halfSpaceOf(t), o, d, kMaxDist);
    case Kind::Mesh: return rayHit(soupOf(t), o, d, kMaxDist);
    default: return rayHit(coreOf(t), o, d, kMaxDist);
  }
}

// Conditioning of the exact answer under moves of the origin by eps * scale, across the ray (8 directions) and
// along it: `margin` is the largest such move (in length units, steps 1e-12 .. 1e-3 of the scale) that never
// flips hit/miss; spread[k] is the largest change of the hit distance (relative to scale) for eps = kSpreadEps[k].
// Grazing rays have a tiny margin and, near a tangent, a spread much larger than eps.
constexpr std::array<double, 3> kSpreadEps = {1e-9, 1e-7, 1e-4};

struct Conditioning {
  double margin = 0;
  std::array<double, 3> spread = {0, 0, 0};
};

Conditioning conditioning(const Placed& t, const V3& o, const V3& d, const std::optional<Ld>& hit, double scale) {
  const V3 u = d.unitOrthogonal(), v = d.cross(u);
  std::vector<V3> moves = {d, -d};
  for (int k = 0; k < 8; ++k) {
    const Ld angle = Ld(k) * Ld(M_PI) / 4;
    moves.push_back(std::cos(angle) * u + std::sin(angle) * v);
  }
  Conditioning c;
  bool flipped = false;
  for (double eps = 1e-12; eps < 2e-3 && !flipped; eps *= 10) {
    for (const V3& w : moves)
      if (exactRayHit(t, o + Ld(eps * scale) * w, d).has_value() != hit.has_value()) flipped = true;
    if (!flipped) c.margin = eps * scale;
  }
  if (!hit) return c;
  for (std::size_t k = 0; k < kSpreadEps.size(); ++k)
    for (const V3& w : moves)
      if (auto moved = exactRayHit(t, o + Ld(kSpreadEps[k] * scale) * w, d))
        c.spread[k] = std::max(c.spread[k], double(std::abs(*moved - *hit)) / scale);
  return c;
}

std::string spreadKey(double eps) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "%.0e", eps);
  return buf;
}

std::string rayClass(Kind k) {
  return k == Kind::Sphere || k == Kind::Capsule || k == Kind::Box || k == Kind::Plane ? "analytic" : "iterative";
}

class RaySuiteBuilder {
 public:
  RaySuiteBuilder(const SuiteOptions& o, std::vector<nlohmann::json>& out) : options_(o), rng_(o.seed + 1), out_(out) {}

  void add(const std::string& group, const std::string& name, const Placed& t, const V3d& origin, const V3d& dir) {
    const V3d d = dir.normalized();
    const V3 o = origin.cast<Ld>(), dl = d.cast<Ld>();
    const std::optional<Ld> hit = exactRayHit(t, o, dl);
    const double scale = std::max({sizeOf(t.shape), t.pose.p.norm(), origin.norm()});
    nlohmann::json j = {{"query", "raycast"},       {"geom", toJson(t.shape)},
                        {"pose", toJson(t.pose)},   {"origin", {origin.x(), origin.y(), origin.z()}},
                        {"dir", {d.x(), d.y(), d.z()}}, {"maxDist", kMaxDist},
                        {"flags", {"position", "normal"}}};
    const Conditioning cond = conditioning(t, o, dl, hit, scale);
    j["expect"] = {{"group", group}, {"class", rayClass(t.shape.kind)}, {"scale", scale},
                   {"margin", cond.margin}, {"hit", hit.has_value()}};
    if (hit) {
      j["expect"]["distance"] = double(*hit);
      for (std::size_t k = 0; k < kSpreadEps.size(); ++k)
        if (cond.spread[k] > 0) j["expect"]["spread"][spreadKey(kSpreadEps[k])] = cond.spread[k];
    }
    emitBothPrecisions(j, group + "/" + name + "#" + std::to_string(count_++), out_);
  }

  // Random rays from 3 sizes away aimed at points of the bounding region: a mix of hits and misses.
  void random(const std::string& group, double shift) {
    for (Kind k : {Kind::Sphere, Kind::Capsule, Kind::Box, Kind::Convex, Kind::Plane, Kind::Mesh})
      for (int i = 0; i < options_.randomRays; ++i) {
        Placed t = rng_.placed(k);
        const V3d s = rng_.unitVector() * shift;
        t.pose.p += s;
        const double size = k == Kind::Plane ? 1.0 : sizeOf(t.shape);
        const V3d origin = t.pose.p + rng_.unitVector() * 3 * size;
        const V3d aim = t.pose.p + rng_.inBox(size);
        add(group, std::string(toJson(t.shape)["type"]), t, origin, aim - origin);
      }
  }

  // Rays passing at +-1e-12 .. 1e-3 of the size from box edges, box vertices, hull vertices, sphere and
  // capsule silhouettes (negative offsets clip the feature: hit).
  void grazing() {
    for (double rel : {1e-12, 1e-9, 1e-6, 1e-3})
      for (double sign : {-1.0, 1.0}) {
        const double delta = sign * rel;
        const std::string tag = (sign < 0 ? "-" : "+") + std::to_string(int(std::round(-std::log10(rel))));
        Placed box = rng_.placed(Kind::Box);
        const V3d h = box.shape.halfExtents;
        const double size = sizeOf(box.shape);
        graze(box, "box_edge" + tag, V3d(h.x(), h.y(), 0.3 * h.z()), V3d(1, 1, 0), V3d(-1, 1, 0), delta * size);
        graze(box, "box_vertex" + tag, h, V3d(1, 1, 1), V3d(1, -1, 0), delta * size);
        Placed hull = rng_.placed(Kind::Convex);
        const V3d w = rng_.unitVector();
        V3d support = hull.shape.points[0];
        for (const V3d& p : hull.shape.points) if (p.dot(w) > support.dot(w)) support = p;
        graze(hull, "convex_vertex" + tag, support, w, w.unitOrthogonal(), delta * sizeOf(hull.shape));
        Placed ball = rng_.placed(Kind::Sphere);
        const V3d n = rng_.unitVector();
        graze(ball, "sphere_silhouette" + tag, n * ball.shape.radius, n, n.unitOrthogonal(), delta * ball.shape.radius);
        Placed cap = rng_.placed(Kind::Capsule);
        graze(cap, "capsule_side" + tag, V3d(0.2 * cap.shape.halfHeight, cap.shape.radius, 0), V3d::UnitY(),
              V3d::UnitZ(), delta * sizeOf(cap.shape));
      }
    // Through the shared edges and vertices of a closed mesh, towards its centre: watertight meshes hit.
    Placed mesh = rng_.placed(Kind::Mesh);
    for (int i = 0; i < 4 * options_.orientations; ++i) {
      const auto& tri = mesh.shape.triangles[std::size_t(rng_.index(int(mesh.shape.triangles.size())))];
      const V3d a = mesh.shape.points[tri[0]], b = mesh.shape.points[tri[1]];
      for (const auto& [name, local] : {std::pair<std::string, V3d>{"mesh_edge", 0.5 * (a + b)}, {"mesh_vertex", a}}) {
        const V3d p = toWorld(mesh.pose, local).cast<double>();
        const V3d inward = (mesh.pose.p - p).normalized();
        add("grazing", name, mesh, p - 2 * inward, inward);
      }
    }
  }

  // Rays starting on the surface of a box, a sphere and a mesh: inward, outward, tangential and oblique.
  void onSurface() {
    Placed box = rng_.placed(Kind::Box);
    const V3d h = box.shape.halfExtents;
    const V3d local(h.x(), 0.3 * h.y(), -0.2 * h.z());
    Placed ball = rng_.placed(Kind::Sphere);
    const V3d n = rng_.unitVector();
    Placed mesh = rng_.placed(Kind::Mesh);
    const auto& tri = mesh.shape.triangles[5];
    const V3d c = (mesh.shape.points[tri[0]] + mesh.shape.points[tri[1]] + mesh.shape.points[tri[2]]) / 3;
    const V3d mn = (mesh.shape.points[tri[1]] - mesh.shape.points[tri[0]])
                       .cross(mesh.shape.points[tri[2]] - mesh.shape.points[tri[0]]).normalized();
    const std::vector<std::pair<std::string, V3d>> dirs = {{"inward", V3d(-1, 0, 0)}, {"outward", V3d(1, 0, 0)},
                                                           {"tangent", V3d(0, 1, 0)}, {"oblique", V3d(-1, 1, 1)}};
    for (const auto& [name, d] : dirs) {
      onSurfaceRay(box, "box_" + name, local, d);
      // Sphere and mesh: local frame with x along the outward normal at the start point.
      const Eigen::Matrix3d frameS = frameWithX(n), frameM = frameWithX(mn);
      onSurfaceRay(ball, "sphere_" + name, n * ball.shape.radius, frameS * d);
      onSurfaceRay(mesh, "mesh_" + name, c, frameM * d);
    }
  }

  // A double-sided quad made of triangles 1e-6 wide: rays inside the slivers, on their shared edges, and
  // just beyond the quad's top edge.
  void slivers() {
    const double width = 1e-6, half = 1.0;
    Placed quad;
    quad.shape = sliverQuadMesh(half, 16, width);
    quad.pose.p = rng_.inBox(1.0);
    quad.pose.q = rng_.rotation();
    for (int i = 0; i < 8 * options_.orientations; ++i) {
      const double y = width * rng_.uniform(-8, 8), z = half * (1 - std::pow(10.0, -rng_.uniform(1, 6)));
      shoot(quad, "inside", V3d(0, y, z));
    }
    for (int i = 0; i < 4; ++i) shoot(quad, "shared_edge", V3d(0, width * (i - 7.5) * 0.999999, half * (1 - 1e-3)));
    for (double over : {1e-9, 1e-6, 1e-3}) shoot(quad, "above_top", V3d(0, 0.1, half + over));
  }

 private:
  void graze(const Placed& t, const std::string& name, const V3d& featureLocal, const V3d& outward, const V3d& along,
             double offset) {
    const V3d b = outward.normalized(), d = (along - along.dot(b) * b).normalized();
    const V3d pLocal = featureLocal + offset * b - 3 * sizeOf(t.shape) * d;
    const V3d origin = toWorld(t.pose, pLocal).cast<double>();
    const V3d dir = (rotationOf(t.pose).cast<double>() * d);
    add("grazing", name, t, origin, dir);
  }

  void onSurfaceRay(const Placed& t, const std::string& name, const V3d& pointLocal, const V3d& dirLocal) {
    add("onSurface", name, t, toWorld(t.pose, pointLocal).cast<double>(),
        rotationOf(t.pose).cast<double>() * dirLocal.normalized());
  }

  void shoot(const Placed& quad, const std::string& name, const V3d& hitLocal) {
    const V3d origin = toWorld(quad.pose, hitLocal + V3d(2, 0, 0)).cast<double>();
    add("sliver", name, quad, origin, rotationOf(quad.pose).cast<double>() * V3d(-1, 0, 0));
  }

  static Eigen::Matrix3d frameWithX(const V3d& x) {
    Eigen::Matrix3d m;
    m.col(0) = x.normalized();
    m.col(1) = m.col(0).unitOrthogonal();
    m.col(2) = m.col(0).cross(m.col(1));
    return m;
  }

  const SuiteOptions& options_;
  Random rng_;
  std::vector<nlohmann::json>& out_;
  std::size_t count_ = 0;
};

}  // namespace

void addRaySuite(const SuiteOptions& options, std::vector<nlohmann::json>& out) {
  RaySuiteBuilder b(options, out);
  b.random("random", 0.0);
  b.grazing();
  b.onSurface();
  b.slivers();
  for (double far : {1e3, 1e6}) b.random("farPose", far);
}

}  // namespace gq::suites
