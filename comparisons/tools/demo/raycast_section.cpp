// Section "raycast": a seeded ray set per geometry, timed in float and double, checked against exact distances.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <optional>
#include <ostream>
#include <random>
#include <sstream>
#include <vector>

#include "gq/query.h"
#include "report.h"
#include "scene.h"

namespace gq::demo {
namespace {

constexpr double kMaxDist = 100.0;  // far beyond every shape: no ray is cut short

struct Ray {
  Vec3<double> origin, dir;
};

// Rays from a sphere of 3x the bounding radius towards random points inside the bounding sphere.
std::vector<Ray> aimRays(const Vec3<double>& center, double radius, std::uint32_t count, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> gauss;
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const auto onSphere = [&] {
    Vec3<double> v(gauss(rng), gauss(rng), gauss(rng));
    return Vec3<double>(v / std::max(v.norm(), 1e-300));
  };
  std::vector<Ray> rays(count);
  for (Ray& ray : rays) {
    ray.origin = center + 3.0 * radius * onSphere();
    const Vec3<double> target = center + radius * std::cbrt(unit(rng)) * onSphere();
    ray.dir = (target - ray.origin).normalized();
  }
  return rays;
}

struct Row {
  std::size_t shapeIndex = 0;
  std::string geometry, precision, error;
  std::uint32_t rays = 0, hits = 0;
  double nsPerRay = 0;
  std::optional<double> maxError;      // |d - d_exact| over rays both hit
  std::optional<double> maxRelError;   // |d - d_exact| / max(d_exact, bounding radius)
  std::optional<std::uint32_t> mismatches;  // hit/miss disagreements with the exact answer
};

template <class T> std::vector<T> castRays(const DemoShape<T>& shape, const std::vector<Ray>& rays, int reps,
                                           double& nsPerRay, Status& status) {
  std::vector<T> distances(rays.size(), T(-1));
  std::vector<double> passes;
  RaycastHit<T> hit;
  for (int pass = 0; pass < reps; ++pass) {
    const auto start = std::chrono::steady_clock::now();
    for (std::size_t i = 0; i < rays.size(); ++i) {
      const Vec3<T> o = rays[i].origin.cast<T>(), d = rays[i].dir.cast<T>().normalized();
      std::uint32_t count = 0;
      status = raycast<T>(o, d, shape.geom, shape.pose, T(kMaxDist), kDefaultHitFlags, 1, &hit, count);
      if (!status.ok()) return distances;
      distances[i] = count > 0 ? hit.distance : T(-1);
    }
    passes.push_back(std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - start).count());
  }
  std::nth_element(passes.begin(), passes.begin() + passes.size() / 2, passes.end());
  nsPerRay = passes[passes.size() / 2] / double(rays.size());
  return distances;
}

// Compares against the exact distance of the ray the kernel saw (inputs rounded to T), in the local frame.
template <class T> void checkExact(const DemoShape<T>& shape, const std::vector<Ray>& rays,
                                   const std::vector<T>& distances, Row& row) {
  const Eigen::Quaternion<Real> q = shape.pose.q.template cast<Real>();
  const VecR p = shape.pose.p.template cast<Real>();
  double maxError = 0, maxRelError = 0;
  const Real scale = Real(shape.boundingRadius);
  std::uint32_t mismatches = 0;
  for (std::size_t i = 0; i < rays.size(); ++i) {
    const VecR o = rays[i].origin.cast<T>().template cast<Real>();
    const VecR d = rays[i].dir.cast<T>().normalized().template cast<Real>();
    const Real exact = shape.exact(q.conjugate() * (o - p), (q.conjugate() * d).normalized(), Real(kMaxDist));
    const bool exactHit = exact >= 0, gqHit = distances[i] >= T(0);
    if (exactHit != gqHit) ++mismatches;
    if (exactHit != gqHit || !exactHit) continue;
    const Real err = std::abs(Real(distances[i]) - exact);
    maxError = std::max(maxError, double(err));
    maxRelError = std::max(maxRelError, double(err / std::max(exact, scale)));
  }
  row.maxError = maxError;
  row.maxRelError = maxRelError;
  row.mismatches = mismatches;
}

template <class T> void measure(const char* precision, const DemoOptions& options, std::vector<Row>& rows) {
  const std::vector<DemoShape<T>> scene = buildScene<T>();
  for (std::size_t s = 0; s < scene.size(); ++s) {
    const DemoShape<T>& shape = scene[s];
    Row row;
    row.shapeIndex = s;
    row.geometry = shape.name;
    row.precision = precision;
    row.rays = options.rays;
    if (!shape.status.ok()) {
      row.error = shape.status.detailedMessage();
      rows.push_back(row);
      continue;
    }
    const Vec3<double> center = shape.pose.template cast<double>().transform(shape.localCenter);
    const std::vector<Ray> rays = aimRays(center, shape.boundingRadius, options.rays, options.seed + s);
    Status status;
    const std::vector<T> distances = castRays(shape, rays, options.repetitions, row.nsPerRay, status);
    if (!status.ok()) {
      row.error = status.detailedMessage();
      rows.push_back(row);
      continue;
    }
    row.hits = std::uint32_t(std::count_if(distances.begin(), distances.end(), [](T d) { return d >= T(0); }));
    if (shape.exact) checkExact(shape, rays, distances, row);
    rows.push_back(row);
  }
}

std::string formatError(const std::optional<double>& error) {
  if (!error) return "-";
  std::ostringstream s;
  s << std::scientific << std::setprecision(2) << *error;
  return s.str();
}

void printTable(const std::vector<Row>& rows, std::ostream& out) {
  out << std::left << std::setw(14) << "geometry" << std::setw(10) << "precision" << std::right << std::setw(9)
      << "rays" << std::setw(9) << "hits" << std::setw(8) << "hit %" << std::setw(10) << "ns/ray" << std::setw(12)
      << "max |err|" << std::setw(12) << "max rel" << std::setw(12) << "mismatches" << '\n';
  for (const Row& row : rows) {
    out << std::left << std::setw(14) << row.geometry << std::setw(10) << row.precision << std::right;
    if (!row.error.empty()) {
      out << "  error: " << row.error << '\n';
      continue;
    }
    out << std::setw(9) << row.rays << std::setw(9) << row.hits << std::setw(8) << std::fixed << std::setprecision(1)
        << 100.0 * row.hits / std::max<std::uint32_t>(row.rays, 1) << std::setw(10) << row.nsPerRay
        << std::setw(12) << formatError(row.maxError) << std::setw(12) << formatError(row.maxRelError) << std::setw(12)
        << (row.mismatches ? std::to_string(*row.mismatches) : std::string("-")) << '\n';
  }
}

}  // namespace

void printRaycastSection(const DemoOptions& options, std::ostream& out) {
  out << "== Raycast: " << options.rays << " seeded rays per geometry, flags position|normal|faceIndex ==\n"
      << "ns/ray: median of " << options.repetitions << " passes. max |err|: largest |distance - exact| (closed form "
      << "in long double) over rays both hit; max rel: the same over max(exact, shape radius); mismatches: hit/miss disagreements. '-': no closed form.\n";
  std::vector<Row> rows;
  measure<float>("float", options, rows);
  measure<double>("double", options, rows);
  // Group rows by geometry: float then double.
  std::stable_sort(rows.begin(), rows.end(), [](const Row& a, const Row& b) { return a.shapeIndex < b.shapeIndex; });
  printTable(rows, out);
  out << '\n';
}

}  // namespace gq::demo
