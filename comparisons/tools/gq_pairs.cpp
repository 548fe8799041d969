// gq-pairs: prints the pair matrix of every query family by asking the library itself — each cell is the Status
// the query returns for one canonical pair of overlapping geometries. The README's matrix is this program's output
// (a ctest compares them), so the README cannot drift from the dispatch tables.
#include <cstdlib>
#include <array>
#include <cstdio>
#include <functional>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "gq/cooking.h"
#include "gq/custom_shapes.h"
#include "gq/query.h"

namespace {

using T = double;
using gq::Geometry;
using gq::Status;
using gq::StatusCode;
using gq::Transform;
using gq::Vec3;

constexpr std::array<const char*, gq::kGeometryTypeCount> kNames = {"sphere", "plane",  "capsule", "box",
                                                                    "convex", "mesh",   "hfield",  "custom"};

// A unit-sized instance of every geometry type, all around the origin so that every pair overlaps.
std::vector<Geometry<T>> canonicalGeometries() {
  std::vector<Vec3<T>> cube;
  for (int i = 0; i < 8; ++i) cube.emplace_back(i & 1 ? 0.5 : -0.5, i & 2 ? 0.5 : -0.5, i & 4 ? 0.5 : -0.5);
  std::shared_ptr<const gq::ConvexMesh<T>> hull;
  if (!gq::cookConvexMesh(cube, hull).ok()) std::abort();  // fixed, valid inputs: cooking cannot fail
  // A closed octahedron surface.
  const std::vector<Vec3<T>> v = {{0.6, 0, 0}, {-0.6, 0, 0}, {0, 0.6, 0}, {0, -0.6, 0}, {0, 0, 0.6}, {0, 0, -0.6}};
  const std::vector<gq::TriangleIndices> t = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                                              {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  std::shared_ptr<const gq::TriangleMesh<T>> mesh;
  if (!gq::cookTriangleMesh(v, t, mesh).ok()) std::abort();
  gq::HeightFieldDesc<T> desc;
  desc.rows = desc.columns = 3;
  desc.heights.assign(9, 0.0);
  std::shared_ptr<const gq::HeightField<T>> hf;
  if (!gq::cookHeightField(desc, hf).ok()) std::abort();
  gq::CustomGeometry<T> cylinder;
  if (!gq::makeCylinder<T>(0.4, 0.4, cylinder).ok()) std::abort();
  return {gq::SphereGeometry<T>(0.5),
          gq::PlaneGeometry<T>(),
          gq::CapsuleGeometry<T>(0.3, 0.4),
          gq::BoxGeometry<T>(0.5, 0.5, 0.5),
          gq::ConvexMeshGeometry<T>(hull),
          gq::TriangleMeshGeometry<T>(mesh),
          gq::HeightFieldGeometry<T>(hf, 1.0, 0.5, 0.5),
          cylinder};
}

// The heightfield spans [0,1] x {0} x [0,1]: put it under the others' centre.
Transform<T> poseOf(std::size_t type) {
  if (type == std::size_t(gq::GeometryType::HeightField)) return Transform<T>(Vec3<T>(-0.5, 0.0, -0.5));
  return Transform<T>(Vec3<T>(0.01, 0.02, 0.03));
}

const char* cell(const Status& s) {
  if (s.ok()) return "yes";
  if (s.code == StatusCode::Unsupported) return "-";
  return "ERR";
}

using PairProbe = std::function<Status(const Geometry<T>&, const Transform<T>&, const Geometry<T>&, const Transform<T>&)>;
using SingleProbe = std::function<Status(const Geometry<T>&, const Transform<T>&)>;

void printPairFamily(const char* family, const std::vector<Geometry<T>>& geoms, const PairProbe& probe,
                     std::ostream& out) {
  char line[256];
  std::snprintf(line, sizeof line, "%-12s", family);
  out << line;
  for (const char* n : kNames) {
    std::snprintf(line, sizeof line, " %-7s", n);
    out << line;
  }
  out << "\n";
  for (std::size_t a = 0; a < geoms.size(); ++a) {
    std::snprintf(line, sizeof line, "  %-10s", kNames[a]);
    out << line;
    for (std::size_t b = 0; b < geoms.size(); ++b) {
      std::snprintf(line, sizeof line, " %-7s", cell(probe(geoms[a], poseOf(a), geoms[b], poseOf(b))));
      out << line;
    }
    out << "\n";
  }
}

void printSingleFamily(const char* family, const std::vector<Geometry<T>>& geoms, const SingleProbe& probe,
                       std::ostream& out) {
  char line[256];
  std::snprintf(line, sizeof line, "%-12s", family);
  out << line;
  for (std::size_t a = 0; a < geoms.size(); ++a) {
    std::snprintf(line, sizeof line, " %-7s", cell(probe(geoms[a], poseOf(a))));
    out << line;
  }
  out << "\n";
}

}  // namespace

int main() {
  const std::vector<Geometry<T>> g = canonicalGeometries();
  std::ostringstream out;
  out << "(rows: geom0, columns: geom1; yes = answered, - = unsupported status)\n\n";
  printPairFamily("overlap", g, [](auto& g0, auto& p0, auto& g1, auto& p1) {
    bool o = false;
    return gq::overlap(g0, p0, g1, p1, o);
  }, out);
  out << "\n";
  printPairFamily("penetration", g, [](auto& g0, auto& p0, auto& g1, auto& p1) {
    gq::PenetrationResult<T> r;
    return gq::computePenetration(r, g0, p0, g1, p1);
  }, out);
  out << "\n";
  printPairFamily("distance", g, [](auto& g0, auto& p0, auto& g1, auto& p1) {
    gq::DistanceResult<T> r;
    return gq::distance(r, g0, p0, g1, p1);
  }, out);
  out << "\n";
  printPairFamily("sweep", g, [](auto& g0, auto& p0, auto& g1, auto& p1) {
    gq::SweepHit<T> hit;
    bool has = false;
    return gq::sweep<T>(Vec3<T>(1, 0, 0), 1.0, g0, p0, g1, p1, hit, has);
  }, out);
  out << "\n";
  char header[256];
  std::snprintf(header, sizeof header, "%-12s", "");
  out << header;
  for (const char* n : kNames) {
    std::snprintf(header, sizeof header, " %-7s", n);
    out << header;
  }
  out << "\n";
  printSingleFamily("raycast", g, [](auto& geom, auto& pose) {
    gq::RaycastHit<T> hit;
    std::uint32_t n = 0;
    return gq::raycast<T>(Vec3<T>(0, 3, 0.1), Vec3<T>(0, -1, 0), geom, pose, 10.0, gq::kDefaultHitFlags, 1, &hit, n);
  }, out);
  printSingleFamily("bounds", g, [](auto& geom, auto& pose) {
    gq::Bounds3<T> b;
    return gq::computeGeomBounds(b, geom, pose);
  }, out);
  printSingleFamily("pointDist", g, [](auto& geom, auto& pose) {
    gq::PointDistanceResult<T> r;
    return gq::pointDistance<T>(Vec3<T>(2, 2, 2), geom, pose, r);
  }, out);
  std::cout << out.str();
  return 0;
}
