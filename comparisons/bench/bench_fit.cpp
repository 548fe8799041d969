// Speed against error at the model level: generated meshes (an L of two boxes, a torus, a sphere: no data needed),
// every shared mesh and every Panda/UR5 collision link, fitted by each
// representation (gq::fitShape, containing fits, the bound refined to within 2 % of the true distance), and the
// time of overlap and distance queries of a moving sphere and a moving box against the fit and against the mesh.
// Writes comparisons/results/fit.csv (date, machine, commit passed in; see --help).
// Timings: the best of 3 rounds of a 128-pose path (a helix through and around the mesh's bounds), ns per query.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "gq/fit.h"
#include "gq/io.h"
#include "gq/query.h"
#include "generated_meshes.h"

namespace {

using Vec3d = gq::Vec3<double>;
using Parts = std::vector<std::pair<gq::Geometry<double>, gq::Transform<double>>>;

struct Timing {
  double overlapSphere = 0, distanceSphere = 0, overlapBox = 0, distanceBox = 0;
};

template <class F> double bestNs(int poses, F&& body) {
  double best = 1e300;
  for (int round = 0; round < 3; ++round) {
    const auto start = std::chrono::steady_clock::now();
    for (int i = 0; i < poses; ++i) body(i);
    best = std::min(best, std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - start).count());
  }
  return best / poses;
}

Timing timeQueries(const Parts& parts, const gq::Bounds3<double>& box) {
  const Vec3d c = box.center(), e = box.extents();
  const double size = e.norm();
  constexpr int kPoses = 128;
  std::vector<gq::Transform<double>> poses;
  for (int i = 0; i < kPoses; ++i) {
    const double a = 4 * M_PI * i / kPoses, s = 0.3 + 1.0 * (0.5 + 0.5 * std::sin(3.0 * a));
    poses.emplace_back(c + Vec3d(s * e.x() * std::cos(a), s * e.y() * std::sin(a), e.z() * (2.0 * i / kPoses - 1)),
                       gq::Quat<double>(Eigen::AngleAxisd(a, Vec3d(1, 1, 0).normalized())));
  }
  const gq::SphereGeometry<double> sphere(0.08 * size);
  const gq::BoxGeometry<double> probeBox(Vec3d(0.08, 0.05, 0.04) * size);
  volatile double sink = 0;
  const auto overlapAll = [&](const gq::Geometry<double>& probe, int i) {
    for (const auto& [g, pose] : parts) {
      bool o = false;
      if (gq::overlap<double>(probe, poses[i], g, pose, o).ok() && o) return 1.0;
    }
    return 0.0;
  };
  const auto distanceAll = [&](const gq::Geometry<double>& probe, int i) {
    double best = 1e300;
    for (const auto& [g, pose] : parts) {
      gq::DistanceResult<double> r;
      if (gq::distance<double>(r, probe, poses[i], g, pose).ok()) best = std::min(best, r.distance);
    }
    return best;
  };
  Timing t;
  t.overlapSphere = bestNs(kPoses, [&](int i) { sink = sink + overlapAll(sphere, i); });
  t.distanceSphere = bestNs(kPoses, [&](int i) { sink = sink + distanceAll(sphere, i); });
  t.overlapBox = bestNs(kPoses, [&](int i) { sink = sink + overlapAll(probeBox, i); });
  t.distanceBox = bestNs(kPoses, [&](int i) { sink = sink + distanceAll(probeBox, i); });
  return t;
}

// An L-shaped prism, the union of the boxes [0,2]x[0,0.5] and [0,0.5]x[0.5,1.5] over z in [-0.25, 0.25].
gq::MeshData<double> lShape() {
  const double xy[7][2] = {{0, 0}, {2, 0}, {2, 0.5}, {0.5, 0.5}, {0.5, 1.5}, {0, 1.5}, {0, 0.5}};
  gq::MeshData<double> m;
  for (double z : {-0.25, 0.25})
    for (const auto& p : xy) m.vertices.emplace_back(p[0], p[1], z);
  const std::uint32_t cap[5][3] = {{0, 1, 2}, {0, 2, 3}, {0, 3, 6}, {6, 3, 4}, {6, 4, 5}};
  for (const auto& t : cap) {
    m.triangles.push_back({t[0] + 7, t[1] + 7, t[2] + 7});
    m.triangles.push_back({t[0], t[2], t[1]});
  }
  for (std::uint32_t i = 0; i < 7; ++i) {
    const std::uint32_t a = i, b = (i + 1) % 7;
    m.triangles.push_back({a, b, b + 7});
    m.triangles.push_back({a, b + 7, a + 7});
  }
  return m;
}

// A UV sphere of the given radius, poles collapsed to one vertex each.
gq::MeshData<double> uvSphere(double radius, std::uint32_t nu, std::uint32_t nv) {
  gq::MeshData<double> m;
  m.vertices.emplace_back(0, 0, -radius);
  for (std::uint32_t j = 1; j < nv; ++j)
    for (std::uint32_t i = 0; i < nu; ++i) {
      const double u = 2 * M_PI * i / nu, v = M_PI * j / nv - M_PI / 2;
      m.vertices.emplace_back(radius * std::cos(v) * std::cos(u), radius * std::cos(v) * std::sin(u), radius * std::sin(v));
    }
  m.vertices.emplace_back(0, 0, radius);
  const auto at = [&](std::uint32_t ring, std::uint32_t i) { return 1 + (ring - 1) * nu + i % nu; };
  const std::uint32_t top = std::uint32_t(m.vertices.size() - 1);
  for (std::uint32_t i = 0; i < nu; ++i) {
    m.triangles.push_back({0, at(1, i + 1), at(1, i)});
    m.triangles.push_back({top, at(nv - 1, i), at(nv - 1, i + 1)});
    for (std::uint32_t ring = 1; ring + 1 < nv; ++ring) {
      m.triangles.push_back({at(ring, i), at(ring, i + 1), at(ring + 1, i + 1)});
      m.triangles.push_back({at(ring, i), at(ring + 1, i + 1), at(ring + 1, i)});
    }
  }
  return m;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Error bound against query cost for every fit representation; writes a CSV."};
  std::string shared = GQ_SHARED_DIR, out = "comparisons/results/fit.csv", date, machine, commit;
  double relTolerance = 0.002;
  std::vector<std::string> skip;
  app.add_option("--shared", shared, "the shared data folder");
  app.add_option("--out", out, "CSV to write");
  app.add_option("--date", date)->required();
  app.add_option("--machine", machine)->required();
  app.add_option("--commit", commit)->required();
  app.add_option("--tolerance", relTolerance, "tolerance relative to the mesh size (bounds refine down to it)");
  app.add_option("--skip", skip, "representations not to fit (e.g. decomposition, slow on large meshes)");
  CLI11_PARSE(app, argc, argv);

  std::vector<std::string> files = {"generated/l-shape", "generated/torus", "generated/sphere",
                                    "meshes/stanford-bunny.obj", "meshes/spot.obj", "meshes/teapot.obj",
                                    "meshes/fandisk.obj"};
  const std::string panda = "robots/example-robot-data/robots/panda_description/meshes/collision/";
  const std::string ur5 = "robots/example-robot-data/robots/ur_description/meshes/ur5/collision/";
  for (const char* l : {"link0", "link1", "link2", "link3", "link4", "link5", "link6", "link7", "hand"})
    files.push_back(panda + l + ".stl");
  for (const char* l : {"base", "shoulder", "upperarm", "forearm", "wrist1", "wrist2", "wrist3"})
    files.push_back(ur5 + l + ".stl");

  std::ofstream csv(out);
  csv << "date,machine,commit,mesh,triangles,size,representation,parts,hull_vertices,error_bound,error_bound_rel,"
         "fit_ms,overlap_sphere_ns,distance_sphere_ns,overlap_box_ns,distance_box_ns,overlap_sphere_vs_mesh,"
         "distance_sphere_vs_mesh,overlap_box_vs_mesh,distance_box_vs_mesh\n";
  for (const std::string& file : files) {
    gq::MeshData<double> mesh;
    if (file == "generated/l-shape") mesh = lShape();
    else if (file == "generated/torus") mesh = gqtest::torusMesh(1.0, 0.3, 48, 24);
    else if (file == "generated/sphere") mesh = uvSphere(1.0, 48, 24);
    else if (!gq::loadMeshFile(shared + "/" + file, mesh).ok()) {
      std::cerr << "bench_fit: skipping " << file << " (not readable)\n";
      continue;
    }
    gq::Bounds3<double> box;
    for (const Vec3d& v : mesh.vertices) box.include(v);
    const double size = (box.max - box.min).norm();
    // The mesh itself first: every row's ratios are against it.
    Timing meshTime;
    {
      gq::FitOptions<double> o;
      o.tolerance = relTolerance * size;
      o.allowed = gq::fitBit(gq::FitRepresentation::Mesh);
      o.measureCost = false;
      gq::FitResult<double> fit;
      if (!gq::fitShape(mesh, o, fit).ok()) continue;
      meshTime = timeQueries(fit.parts, box);
    }
    for (std::size_t r = 0; r < gq::kFitRepresentationCount; ++r) {
      const auto rep = gq::FitRepresentation(r);
      if (std::find(skip.begin(), skip.end(), gq::toString(rep)) != skip.end()) continue;
      gq::FitOptions<double> o;
      o.tolerance = relTolerance * size;
      o.allowed = gq::fitBit(rep);
      o.contain = rep != gq::FitRepresentation::SimplifiedHull;
      o.measureCost = false;
      o.maxParts = 16;
      o.maxBoundPatches = 200000;
      gq::FitResult<double> fit;
      const auto start = std::chrono::steady_clock::now();
      const gq::Status s = gq::fitShape(mesh, o, fit);
      const double fitMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
      if (!s.ok() || fit.parts.empty()) continue;  // e.g. no simplified hull when the hull is beyond the tolerance
      const Timing t = timeQueries(fit.parts, box);
      std::uint32_t vertices = fit.candidates.empty() ? 0 : fit.candidates.back().vertices;
      const std::string name = file.substr(file.find_last_of('/') + 1);
      const std::string label = file.find("panda") != std::string::npos       ? "panda/" + name
                                : file.find("ur5") != std::string::npos       ? "ur5/" + name
                                : file.find("generated/") != std::string::npos ? file
                                                                               : name;
      csv << date << ",\"" << machine << "\"," << commit << ',' << label << ',' << mesh.triangles.size() << ','
          << size << ',' << gq::toString(rep) << ',' << fit.parts.size() << ',' << vertices << ','
          << fit.errorBound << ',' << fit.errorBound / size << ',' << fitMs << ',' << t.overlapSphere << ','
          << t.distanceSphere << ',' << t.overlapBox << ',' << t.distanceBox;
      csv << ',' << t.overlapSphere / meshTime.overlapSphere << ',' << t.distanceSphere / meshTime.distanceSphere << ','
          << t.overlapBox / meshTime.overlapBox << ',' << t.distanceBox / meshTime.distanceBox << std::endl;
      std::cerr << label << ' ' << gq::toString(rep) << " bound " << fit.errorBound << '\n';
    }
  }
  return 0;
}
