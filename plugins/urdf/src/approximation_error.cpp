// Measured error of a shape approximation, both one-sided Hausdorff distances:
//  mesh -> approximation: over the mesh vertices and area-weighted random points on its triangles, the largest
//    distance to the approximation solid (gq::pointDistance; 0 inside);
//  approximation -> mesh: over points on the approximation's surface, the largest distance to the mesh surface.
//    Surface points come from rays cast from outside the bounds towards the approximation's centre along
//    uniformly random directions (uniform in direction, not area: every convex shape is reached the same way).
// Both are sampled maxima, i.e. lower bounds of the true Hausdorff distances that converge as samples grow.
#include <cmath>

#include "gq/query.h"
#include "internal.h"

namespace gq::urdf::internal {
namespace {

template <class T> Vec3<T> randomUnitVector(std::uint64_t& rng) {
  const double z = 2.0 * uniform01(rng) - 1.0, phi = 2.0 * M_PI * uniform01(rng);
  const double s = std::sqrt(std::max(0.0, 1.0 - z * z));
  return Vec3<T>(T(s * std::cos(phi)), T(s * std::sin(phi)), T(z));
}

// Uniform point on a triangle (square-root parametrisation).
template <class T> Vec3<T> pointOnTriangle(const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& c, std::uint64_t& rng) {
  const double r1 = std::sqrt(uniform01(rng)), r2 = uniform01(rng);
  return a * T(1 - r1) + b * T(r1 * (1 - r2)) + c * T(r1 * r2);
}

template <class T> std::vector<Vec3<T>> meshSamples(const MeshData<T>& mesh, std::uint32_t count, std::uint64_t& rng) {
  std::vector<Vec3<T>> points = mesh.vertices;
  std::vector<double> cumulative;
  double total = 0;
  for (const auto& t : mesh.triangles) {
    total += 0.5 * ((mesh.vertices[t[1]] - mesh.vertices[t[0]]).cross(mesh.vertices[t[2]] - mesh.vertices[t[0]]))
                       .template cast<double>()
                       .norm();
    cumulative.push_back(total);
  }
  if (!(total > 0)) return points;
  for (std::uint32_t k = 0; k < count; ++k) {
    const auto it = std::lower_bound(cumulative.begin(), cumulative.end(), uniform01(rng) * total);
    const auto& t = mesh.triangles[std::min<std::size_t>(it - cumulative.begin(), mesh.triangles.size() - 1)];
    points.push_back(pointOnTriangle(mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]], rng));
  }
  return points;
}

template <class T>
Status largestDistance(const std::vector<Vec3<T>>& points, const Geometry<T>& geom, const Transform<T>& pose, T& out) {
  T worst = T(0);
  for (const auto& p : points) {
    PointDistanceResult<T> r;
    Status s = pointDistance(p, geom, pose, r);
    if (!s.ok()) return s;
    worst = std::max(worst, r.distance);
  }
  out = worst;
  return {};
}

template <class T>
Status surfaceSamples(const Geometry<T>& geom, const Transform<T>& pose, std::uint32_t count, std::uint64_t& rng,
                      std::vector<Vec3<T>>& points) {
  Bounds3<T> b;
  Status s = computeGeomBounds(b, geom, pose, T(0), T(1));
  if (!s.ok()) return s;
  const Vec3<T> centre = b.center();
  const T reach = T(2) * (b.max - b.min).norm() + T(1e-3);
  for (std::uint32_t k = 0; k < count; ++k) {
    const Vec3<T> d = randomUnitVector<T>(rng);
    RaycastHit<T> hit;
    std::uint32_t hits = 0;
    s = raycast<T>(centre + d * reach, -d, geom, pose, T(2) * reach, HitFlag::Position, 1u, &hit, hits);
    if (!s.ok()) return s;
    if (hits > 0) points.push_back(hit.position);
  }
  return {};
}

}  // namespace

template <class T>
Status measureApproximationError(const MeshData<T>& mesh, const Geometry<T>& approximation, const Transform<T>& fit,
                                 const LoadOptions& options, ApproximationError<T>& error) {
  std::uint64_t rng = options.errorSeed;
  const std::vector<Vec3<T>> onMesh = meshSamples(mesh, options.errorSamplesPerShape, rng);
  ApproximationError<T> e;
  Status s = largestDistance(onMesh, approximation, fit, e.meshToApproximation);
  if (!s.ok()) return s;
  std::shared_ptr<const TriangleMesh<T>> cooked;
  s = cookTriangleMesh(mesh.vertices, mesh.triangles, cooked);
  if (!s.ok()) return s;
  std::vector<Vec3<T>> onApproximation;
  s = surfaceSamples(approximation, fit, options.errorSamplesPerShape, rng, onApproximation);
  if (!s.ok()) return s;
  s = largestDistance(onApproximation, Geometry<T>(TriangleMeshGeometry<T>(cooked)), Transform<T>(),
                      e.approximationToMesh);
  if (!s.ok()) return s;
  error = e;
  return {};
}

template Status measureApproximationError<float>(const MeshData<float>&, const Geometry<float>&,
                                                 const Transform<float>&, const LoadOptions&,
                                                 ApproximationError<float>&);
template Status measureApproximationError<double>(const MeshData<double>&, const Geometry<double>&,
                                                  const Transform<double>&, const LoadOptions&,
                                                  ApproximationError<double>&);

}  // namespace gq::urdf::internal
