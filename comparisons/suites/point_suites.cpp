// pointDistance suite: random points around every solid and mesh, points within +-1e-12 .. 1e-3 of surfaces,
// points near sliver triangles, far poses. Solids are filled (distance 0 inside); meshes are surfaces.
#include <cmath>

#include "suite.h"

namespace gq::suites {
namespace {

// Signed distance to a solid (negative inside) or unsigned distance to a mesh surface.
Ld exactPointSigned(const Placed& t, const V3& p) {
  if (t.shape.kind == Kind::Mesh) return pointMeshDistance(p, soupOf(t));
  Core point;
  point.points = {p};
  return signedDistance(point, coreOf(t));
}

std::string pointClass(Kind k) {
  return k == Kind::Sphere || k == Kind::Capsule || k == Kind::Box ? "analytic" : "iterative";
}

class PointSuiteBuilder {
 public:
  PointSuiteBuilder(const SuiteOptions& o, std::vector<nlohmann::json>& out) : options_(o), rng_(o.seed + 2), out_(out) {}

  void add(const std::string& group, const std::string& name, const Placed& t, const V3d& point) {
    const Ld sd = exactPointSigned(t, point.cast<Ld>());
    const double scale = std::max({sizeOf(t.shape), t.pose.p.norm(), point.norm()});
    nlohmann::json j = {{"query", "pointDistance"}, {"point", {point.x(), point.y(), point.z()}},
                        {"geom", toJson(t.shape)}, {"pose", toJson(t.pose)}};
    j["expect"] = {{"group", group}, {"class", pointClass(t.shape.kind)}, {"scale", scale},
                   {"margin", double(sd)}, {"distance", double(std::max(Ld(0), sd))}};
    emitBothPrecisions(j, group + "/" + name + "#" + std::to_string(count_++), out_);
  }

  // Points in a box of twice the size around the shape: inside and outside.
  void random(const std::string& group, double shift) {
    for (Kind k : {Kind::Sphere, Kind::Capsule, Kind::Box, Kind::Convex, Kind::Mesh})
      for (int i = 0; i < options_.randomPoints; ++i) {
        Placed t = rng_.placed(k);
        t.pose.p += rng_.unitVector() * shift;
        add(group, std::string(toJson(t.shape)["type"]), t, t.pose.p + rng_.inBox(2 * sizeOf(t.shape)));
      }
  }

  // Points at +-1e-12 .. 1e-3 of the size from a box face, a sphere, a capsule side and a hull vertex.
  void nearSurface() {
    for (double rel : {1e-12, 1e-9, 1e-6, 1e-3})
      for (double sign : {-1.0, 1.0}) {
        const double delta = sign * rel;
        const std::string tag = (sign < 0 ? "-" : "+") + std::to_string(int(std::round(-std::log10(rel))));
        Placed box = rng_.placed(Kind::Box);
        const V3d h = box.shape.halfExtents;
        near(box, "box_face" + tag, V3d(h.x(), 0.2 * h.y(), -0.4 * h.z()), V3d::UnitX(), delta * sizeOf(box.shape));
        Placed ball = rng_.placed(Kind::Sphere);
        const V3d n = rng_.unitVector();
        near(ball, "sphere" + tag, n * ball.shape.radius, n, delta * ball.shape.radius);
        Placed cap = rng_.placed(Kind::Capsule);
        near(cap, "capsule_side" + tag, V3d(0.3 * cap.shape.halfHeight, 0, cap.shape.radius), V3d::UnitZ(),
             delta * sizeOf(cap.shape));
        Placed hull = rng_.placed(Kind::Convex);
        const V3d w = rng_.unitVector();
        V3d support = hull.shape.points[0];
        for (const V3d& p : hull.shape.points) if (p.dot(w) > support.dot(w)) support = p;
        near(hull, "convex_vertex" + tag, support, w, delta * sizeOf(hull.shape));
        Placed mesh = rng_.placed(Kind::Mesh);
        const auto& tri = mesh.shape.triangles[7];
        const V3d a = mesh.shape.points[tri[0]], b = mesh.shape.points[tri[1]], c = mesh.shape.points[tri[2]];
        near(mesh, "mesh_face" + tag, (a + b + c) / 3, (b - a).cross(c - a), std::abs(delta) * sizeOf(mesh.shape));
      }
  }

  // Points in front of a quad made of 1e-6-wide slivers.
  void slivers() {
    Placed quad;
    quad.shape = sliverQuadMesh(1.0, 16, 1e-6);
    quad.pose.p = rng_.inBox(1.0);
    quad.pose.q = rng_.rotation();
    for (int i = 0; i < 6 * options_.orientations; ++i)
      add("sliver", "quad", quad,
          toWorld(quad.pose, V3d(rng_.uniform(-0.5, 0.5), 1e-6 * rng_.uniform(-10, 10), rng_.uniform(0.9, 1.1)))
              .cast<double>());
  }

 private:
  void near(const Placed& t, const std::string& name, const V3d& surfaceLocal, const V3d& normalLocal, double offset) {
    add("nearSurface", name, t, toWorld(t.pose, surfaceLocal + offset * normalLocal.normalized()).cast<double>());
  }

  const SuiteOptions& options_;
  Random rng_;
  std::vector<nlohmann::json>& out_;
  std::size_t count_ = 0;
};

}  // namespace

void addPointSuite(const SuiteOptions& options, std::vector<nlohmann::json>& out) {
  PointSuiteBuilder b(options, out);
  b.random("random", 0.0);
  b.nearSurface();
  b.slivers();
  for (double far : {1e3, 1e6}) b.random("farPose", far);
}

}  // namespace gq::suites
