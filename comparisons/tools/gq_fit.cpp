// gq-fit MESH --tolerance T [--contain] [--allow sphere,capsule,...] [--max-parts N] [--out PREFIX]
// Fits a mesh file (OBJ, STL, anything gq::loadMeshFile reads) by the cheapest shape within the tolerance
// (gq::fitShape, docs/fit.md) and writes PREFIX_partN.obj, one tessellated part each (hulls exact, curved
// primitives tessellated for viewing), and a JSON report (PREFIX.json: representation, certified bound, relative
// query cost, each part's exact parameters and pose, and every representation tried with its bound and, for one
// part, its volume over the hull's).
#include <cmath>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "gq/custom_shapes.h"
#include "gq/fit.h"
#include "gq/io.h"

namespace {

using Vec3d = gq::Vec3<double>;
using Part = std::pair<gq::Geometry<double>, gq::Transform<double>>;

struct Tessellation {
  std::vector<Vec3d> vertices;
  std::vector<std::vector<std::uint32_t>> faces;
};

// A surface of revolution about local X: rings of (x, radius) from one pole to the other, `segments` around.
Tessellation revolve(const std::vector<std::pair<double, double>>& rings, int segments) {
  Tessellation t;
  for (const auto& [x, r] : rings)
    for (int k = 0; k < segments; ++k) {
      const double a = 2 * M_PI * k / segments;
      t.vertices.emplace_back(x, r * std::cos(a), r * std::sin(a));
    }
  for (std::size_t i = 0; i + 1 < rings.size(); ++i)
    for (int k = 0; k < segments; ++k) {
      const std::uint32_t a = std::uint32_t(i * segments + k), b = std::uint32_t(i * segments + (k + 1) % segments);
      t.faces.push_back({a, b, b + std::uint32_t(segments), a + std::uint32_t(segments)});
    }
  return t;
}

std::vector<std::pair<double, double>> capRings(double r, double offset, bool start, int n) {
  std::vector<std::pair<double, double>> rings;
  for (int i = 0; i <= n; ++i) {
    const double a = M_PI / 2 * (start ? double(n - i) / n : double(i) / n);
    rings.emplace_back(start ? offset - r * std::sin(a) : offset + r * std::sin(a), r * std::cos(a));
  }
  return rings;
}

Tessellation tessellate(const gq::Geometry<double>& g, nlohmann::json& params) {
  Tessellation t;
  switch (g.type()) {
    case gq::GeometryType::Sphere: {
      const double r = g.get<gq::SphereGeometry<double>>().radius;
      params = {{"type", "sphere"}, {"radius", r}};
      return revolve(capRings(r, 0, true, 12), 32);
    }
    case gq::GeometryType::Capsule: {
      const auto& c = g.get<gq::CapsuleGeometry<double>>();
      params = {{"type", "capsule"}, {"radius", c.radius}, {"halfHeight", c.halfHeight}, {"axis", "x"}};
      auto rings = capRings(c.radius, -c.halfHeight, true, 8);
      for (const auto& ring : capRings(c.radius, c.halfHeight, false, 8)) rings.push_back(ring);
      return revolve(rings, 32);
    }
    case gq::GeometryType::Box: {
      const Vec3d h = g.get<gq::BoxGeometry<double>>().halfExtents;
      params = {{"type", "box"}, {"halfExtents", {h.x(), h.y(), h.z()}}};
      for (int i = 0; i < 8; ++i)
        t.vertices.emplace_back((i & 1 ? 1 : -1) * h.x(), (i & 2 ? 1 : -1) * h.y(), (i & 4 ? 1 : -1) * h.z());
      t.faces = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
      return t;
    }
    case gq::GeometryType::Custom: {
      const auto* c = dynamic_cast<const gq::CylinderCallbacks<double>*>(g.get<gq::CustomGeometry<double>>().callbacks.get());
      if (c == nullptr) break;
      params = {{"type", "cylinder"}, {"radius", c->radius()}, {"halfHeight", c->halfHeight()}, {"axis", "x"}};
      return revolve({{-c->halfHeight(), 0}, {-c->halfHeight(), c->radius()}, {c->halfHeight(), c->radius()},
                      {c->halfHeight(), 0}},
                     48);
    }
    case gq::GeometryType::ConvexMesh: {
      const auto& hull = *g.get<gq::ConvexMeshGeometry<double>>().mesh;
      params = {{"type", "hull"}, {"vertices", hull.vertices.size()}, {"faces", hull.polygons.size()}};
      t.vertices = hull.vertices;
      for (const auto& p : hull.polygons)
        t.faces.emplace_back(hull.polygonVertices.begin() + p.indexBase,
                             hull.polygonVertices.begin() + p.indexBase + p.indexCount);
      return t;
    }
    case gq::GeometryType::TriangleMesh: {
      const auto& mesh = *g.get<gq::TriangleMeshGeometry<double>>().mesh;
      params = {{"type", "mesh"}, {"triangles", mesh.triangles.size()}};
      t.vertices = mesh.vertices;
      for (const auto& tri : mesh.triangles) t.faces.push_back({tri[0], tri[1], tri[2]});
      return t;
    }
    default: break;
  }
  params = {{"type", "unknown"}};
  return t;
}

bool writeObj(const std::string& path, const Tessellation& t, const gq::Transform<double>& pose) {
  std::ofstream out(path);
  out.precision(17);
  for (const Vec3d& v : t.vertices) {
    const Vec3d w = pose.transform(v);
    out << "v " << w.x() << ' ' << w.y() << ' ' << w.z() << '\n';
  }
  for (const auto& f : t.faces) {
    out << 'f';
    for (std::uint32_t i : f) out << ' ' << i + 1;
    out << '\n';
  }
  return bool(out);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Fits a mesh by the cheapest shape within a tolerance; writes OBJ parts and a JSON report."};
  std::string meshPath, prefix = "fit", allow;
  double tolerance = 0;
  bool contain = false;
  std::uint32_t maxParts = 16;
  app.add_option("mesh", meshPath, "mesh file (OBJ, STL, ...)")->required();
  app.add_option("--tolerance", tolerance, "largest error allowed, in the mesh's units")->required();
  app.add_flag("--contain", contain, "the fit must enclose the mesh");
  app.add_option("--allow", allow,
                 "comma-separated representations: sphere, capsule, box, cylinder, simplified-hull, hull, "
                 "decomposition, mesh (default: all)");
  app.add_option("--max-parts", maxParts, "most parts of a convex decomposition")->check(CLI::PositiveNumber);
  app.add_option("--out", prefix, "output prefix: PREFIX_partN.obj and PREFIX.json");
  CLI11_PARSE(app, argc, argv);

  gq::FitOptions<double> options;
  options.tolerance = tolerance;
  options.contain = contain;
  options.maxParts = maxParts;
  if (!allow.empty()) {
    options.allowed = 0;
    std::stringstream list(allow);
    std::string name;
    while (std::getline(list, name, ',')) {
      bool known = false;
      for (std::size_t r = 0; r < gq::kFitRepresentationCount; ++r)
        if (name == gq::toString(gq::FitRepresentation(r))) {
          options.allowed |= gq::fitBit(gq::FitRepresentation(r));
          known = true;
        }
      if (!known) {
        std::cerr << "gq-fit: unknown representation '" << name << "'\n";
        return 2;
      }
    }
  }
  gq::MeshData<double> mesh;
  gq::Status s = gq::loadMeshFile(meshPath, mesh);
  if (!s.ok()) {
    std::cerr << "gq-fit: " << s.toString() << '\n';
    return 1;
  }
  gq::FitResult<double> fit;
  s = gq::fitShape(mesh, options, fit);
  if (!s.ok()) {
    std::cerr << "gq-fit: " << s.toString() << '\n';
    return 1;
  }
  if (s.code == gq::StatusCode::Warning) std::cerr << "gq-fit: " << s.toString() << '\n';
  nlohmann::json report = {{"mesh", meshPath},
                           {"triangles", mesh.triangles.size()},
                           {"tolerance", tolerance},
                           {"contain", contain},
                           {"representation", gq::toString(fit.representation)},
                           {"errorBound", fit.errorBound},
                           {"withinTolerance", s.code == gq::StatusCode::Ok},
                           {"relativeCost", fit.relativeCost}};
  for (const auto& c : fit.candidates)
    report["candidates"].push_back({{"representation", gq::toString(c.representation)},
                                    {"errorBound", c.errorBound},
                                    {"parts", c.parts},
                                    {"vertices", c.vertices},
                                    {"volumeRatio", c.volumeRatio}});
  for (std::size_t i = 0; i < fit.parts.size(); ++i) {
    nlohmann::json params;
    const Tessellation t = tessellate(fit.parts[i].first, params);
    const std::string file = prefix + "_part" + std::to_string(i) + ".obj";
    if (!writeObj(file, t, fit.parts[i].second)) {
      std::cerr << "gq-fit: cannot write " << file << '\n';
      return 1;
    }
    const auto& pose = fit.parts[i].second;
    params["obj"] = file;
    params["position"] = {pose.p.x(), pose.p.y(), pose.p.z()};
    params["rotationXYZW"] = {pose.q.x(), pose.q.y(), pose.q.z(), pose.q.w()};
    report["parts"].push_back(params);
  }
  std::ofstream json(prefix + ".json");
  json << report.dump(2) << '\n';
  if (!json) {
    std::cerr << "gq-fit: cannot write " << prefix << ".json\n";
    return 1;
  }
  std::cout << gq::toString(fit.representation) << " error bound " << fit.errorBound << " (tolerance " << tolerance
            << "), " << fit.parts.size() << " part(s), relative cost " << fit.relativeCost << '\n';
  return 0;
}
