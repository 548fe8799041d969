#include "scene.h"

#include <cmath>

#include "gq/cooking.h"

namespace gq::demo {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Every shape sits at the same non-trivial pose so the kernels' frame changes are exercised.
template <class T> Transform<T> scenePose() {
  const Quat<double> q = Quat<double>(0.9, 0.3, -0.2, 0.1).normalized();
  return Transform<T>(Vec3<double>(0.5, -0.25, 1.0).cast<T>(), q.cast<T>());
}

template <class T> DemoShape<T> named(const char* name, double boundingRadius) {
  DemoShape<T> s;
  s.name = name;
  s.pose = scenePose<T>();
  s.boundingRadius = boundingRadius;
  return s;
}

template <class T> DemoShape<T> sphere() {
  const T r = T(0.8);
  DemoShape<T> s = named<T>("sphere", 0.8);
  s.geom = SphereGeometry<T>(r);
  s.exact = [r](const VecR& o, const VecR& d, Real maxDist) { return exactRaySphere(o, d, Real(r), maxDist); };
  return s;
}

template <class T> DemoShape<T> plane() {
  DemoShape<T> s = named<T>("plane", 2.0);
  s.geom = PlaneGeometry<T>();
  s.exact = [](const VecR& o, const VecR& d, Real maxDist) { return exactRayPlane(o, d, maxDist); };
  return s;
}

template <class T> DemoShape<T> capsule() {
  const T r = T(0.4), hh = T(0.7);
  DemoShape<T> s = named<T>("capsule", 1.1);
  s.geom = CapsuleGeometry<T>(r, hh);
  s.exact = [r, hh](const VecR& o, const VecR& d, Real maxDist) {
    return exactRayCapsule(o, d, Real(r), Real(hh), maxDist);
  };
  return s;
}

template <class T> DemoShape<T> box() {
  const Vec3<T> he(T(0.9), T(0.5), T(0.3));
  DemoShape<T> s = named<T>("box", 1.1);
  s.geom = BoxGeometry<T>(he);
  s.exact = [he](const VecR& o, const VecR& d, Real maxDist) {
    return exactRayBox(o, d, he.template cast<Real>(), maxDist);
  };
  return s;
}

// The 12 vertices of an icosahedron (circumradius sqrt(1 + phi^2)), scaled to radius ~1.
template <class T> std::vector<Vec3<T>> icosahedronPoints() {
  const double phi = (1.0 + std::sqrt(5.0)) / 2.0, k = 1.0 / std::sqrt(1.0 + phi * phi);
  std::vector<Vec3<T>> pts;
  for (double a : {-1.0, 1.0})
    for (double b : {-phi, phi}) {
      pts.push_back((Vec3<double>(0, a, b) * k).cast<T>());
      pts.push_back((Vec3<double>(a, b, 0) * k).cast<T>());
      pts.push_back((Vec3<double>(b, 0, a) * k).cast<T>());
    }
  return pts;
}

template <class T> DemoShape<T> convex() {
  DemoShape<T> s = named<T>("convex", 1.0);
  std::shared_ptr<const ConvexMesh<T>> hull;
  s.status = cookConvexMesh<T>(icosahedronPoints<T>(), hull);
  if (s.status.ok()) s.geom = ConvexMeshGeometry<T>(hull);
  return s;
}

// Torus around local Y: ring radius R, tube radius r, nu x nv quads split into two triangles each.
template <class T> MeshData<T> torus(double R, double r, std::uint32_t nu, std::uint32_t nv) {
  MeshData<T> m;
  for (std::uint32_t i = 0; i < nu; ++i)
    for (std::uint32_t j = 0; j < nv; ++j) {
      const double u = 2 * kPi * i / nu, v = 2 * kPi * j / nv;
      const double ring = R + r * std::cos(v);
      m.vertices.push_back(Vec3<double>(ring * std::cos(u), r * std::sin(v), ring * std::sin(u)).cast<T>());
    }
  const auto at = [&](std::uint32_t i, std::uint32_t j) { return (i % nu) * nv + (j % nv); };
  for (std::uint32_t i = 0; i < nu; ++i)
    for (std::uint32_t j = 0; j < nv; ++j) {
      m.triangles.push_back({at(i, j), at(i, j + 1), at(i + 1, j)});
      m.triangles.push_back({at(i + 1, j), at(i, j + 1), at(i + 1, j + 1)});
    }
  return m;
}

template <class T> DemoShape<T> mesh() {
  DemoShape<T> s = named<T>("mesh (torus)", 1.0);
  const MeshData<T> m = torus<T>(0.7, 0.3, 64, 32);
  std::shared_ptr<const TriangleMesh<T>> cooked;
  s.status = cookTriangleMesh<T>(m.vertices, m.triangles, cooked);
  if (s.status.ok()) s.geom = TriangleMeshGeometry<T>(cooked);
  return s;
}

// Sine terrain: 128 x 128 samples, height sin(x) * cos(z) over a 4 x 4 patch.
template <class T> DemoShape<T> heightField() {
  constexpr std::uint32_t kSamples = 128;
  const double spacing = 4.0 / (kSamples - 1), heightScale = 0.25;
  HeightFieldDesc<T> desc;
  desc.rows = desc.columns = kSamples;
  for (std::uint32_t r = 0; r < kSamples; ++r)
    for (std::uint32_t c = 0; c < kSamples; ++c)
      desc.heights.push_back(T(std::sin(3.0 * r * spacing) * std::cos(2.0 * c * spacing)));
  DemoShape<T> s = named<T>("heightfield", std::sqrt(8.0));
  s.localCenter = Vec3<double>(2.0, 0.0, 2.0);
  std::shared_ptr<const HeightField<T>> hf;
  s.status = cookHeightField<T>(desc, hf);
  if (s.status.ok()) s.geom = HeightFieldGeometry<T>(hf, T(heightScale), T(spacing), T(spacing));
  return s;
}

}  // namespace

template <class T> std::vector<DemoShape<T>> buildScene() {
  return {sphere<T>(), plane<T>(), capsule<T>(), box<T>(), convex<T>(), mesh<T>(), heightField<T>()};
}

template std::vector<DemoShape<float>> buildScene<float>();
template std::vector<DemoShape<double>> buildScene<double>();

}  // namespace gq::demo
