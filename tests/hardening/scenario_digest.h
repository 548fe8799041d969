#pragma once
// A fixed, seeded workload over every geometry pair and query family (raycasts, sweeps, overlaps, penetration,
// distances, point distances, bounds, mesh queries) on shared cooked data, folded into a 64-bit digest of the
// output bits. Equal digests = bitwise-identical outputs; the determinism and thread tests compare them.
#include <cstdint>
#include <cstring>
#include <random>
#include <vector>

#include "hardening_fixtures.h"

namespace gq::hardening {

// FNV-1a over raw bytes: any differing output bit changes the digest (up to 2^-64 collisions).
class Digest {
 public:
  void bytes(const void* p, std::size_t n) {
    const auto* b = static_cast<const unsigned char*>(p);
    for (std::size_t i = 0; i < n; ++i) h_ = (h_ ^ b[i]) * 0x100000001b3ull;
  }
  template <class T> void value(const T& x) {
    static_assert(std::is_arithmetic_v<T>);
    bytes(&x, sizeof(T));
  }
  template <class T> void vec(const Vec3<T>& v) { value(v.x()), value(v.y()), value(v.z()); }
  void status(const Status& s) { value(static_cast<int>(s.code)); }
  std::uint64_t get() const { return h_; }

 private:
  std::uint64_t h_ = 0xcbf29ce484222325ull;
};

template <class T> struct Scenario {
  std::size_t geom0 = 0, geom1 = 0;  // indices into everyGeometry<T>()
  Transform<T> pose0, pose1;
  Vec3<T> dir = Vec3<T>::UnitX();    // ray and sweep direction
  Vec3<T> origin = Vec3<T>::Zero();  // ray origin
};

// `count` scenarios cycling over all 64 ordered type pairs; poses within a few units so many pairs touch.
template <class T> std::vector<Scenario<T>> makeScenarios(std::size_t count, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::normal_distribution<double> n;
  // One draw per declarator: argument evaluation order is unspecified (GCC and clang differ).
  auto vec = [&](double half) -> Vec3<T> {
    const double x = u(rng), y = u(rng), z = u(rng);
    return Vec3<T>(T(half * x), T(half * y), T(half * z));
  };
  auto rot = [&]() -> Quat<T> {
    const double w = n(rng), x = n(rng), y = n(rng), z = n(rng);
    return Eigen::Quaterniond(w, x, y, z).normalized().cast<T>();
  };
  auto unit = [&]() -> Vec3<T> {  // explicit type: no Eigen expression of a dead temporary
    const double x = n(rng), y = n(rng), z = n(rng);
    return Eigen::Vector3d(x, y, z).normalized().cast<T>();
  };
  std::vector<Scenario<T>> out(count);
  for (std::size_t i = 0; i < count; ++i) {
    Scenario<T>& s = out[i];
    s.geom0 = i % kGeometryTypeCount;
    s.geom1 = (i / kGeometryTypeCount) % kGeometryTypeCount;
    const Vec3<T> p0 = vec(1.5);
    s.pose0 = Transform<T>(p0, rot());
    const Vec3<T> p1 = vec(1.5);
    s.pose1 = Transform<T>(p1, rot());
    s.dir = unit();
    s.origin = s.pose1.p - T(4) * s.dir + vec(0.3);
  }
  return out;
}

// Runs every family on one scenario and folds statuses and outputs into `d`.
template <class T> void runScenario(const std::vector<Geometry<T>>& geoms, const Scenario<T>& s, Digest& d) {
  const Geometry<T>& g0 = geoms[s.geom0];
  const Geometry<T>& g1 = geoms[s.geom1];
  {
    RaycastHit<T> hits[4];
    std::uint32_t count = 0;
    d.status(raycast(s.origin, s.dir, g1, s.pose1, T(20), kDefaultHitFlags | HitFlag::UV | HitFlag::MeshMultiple, 4u,
                     hits, count));
    d.value(count);
    for (std::uint32_t i = 0; i < count; ++i) {
      d.vec(hits[i].position), d.vec(hits[i].normal), d.value(hits[i].distance), d.value(hits[i].faceIndex);
      d.value(hits[i].u), d.value(hits[i].v);
    }
  }
  {
    SweepHit<T> hit;
    bool hasHit = false;
    d.status(sweep(s.dir, T(5), g0, s.pose0, g1, s.pose1, hit, hasHit, kDefaultHitFlags | HitFlag::Mtd));
    d.value(hasHit);
    if (hasHit) d.vec(hit.position), d.vec(hit.normal), d.value(hit.distance), d.value(hit.faceIndex);
  }
  {
    bool overlapping = false;
    d.status(overlap(g0, s.pose0, g1, s.pose1, overlapping));
    d.value(overlapping);
  }
  {
    PenetrationResult<T> r;
    d.status(computePenetration(r, g0, s.pose0, g1, s.pose1));
    d.value(r.penetrating), d.vec(r.direction), d.value(r.depth);
  }
  {
    DistanceResult<T> r;
    d.status(distance(r, g0, s.pose0, g1, s.pose1));
    d.value(r.distance), d.vec(r.point0), d.vec(r.point1), d.vec(r.normal);
  }
  {
    PointDistanceResult<T> r;
    d.status(pointDistance(s.origin, g1, s.pose1, r));
    d.value(r.distance), d.vec(r.closestPoint), d.value(r.closestIndex);
  }
  {
    Bounds3<T> b;
    d.status(computeGeomBounds(b, g0, s.pose0));
    d.vec(b.min), d.vec(b.max);
  }
  if (const auto* mesh = g1.template getIf<TriangleMeshGeometry<T>>()) {
    std::uint32_t results[16];
    TriangleOverlapPageResult received;
    d.status(findOverlapTriangleMesh(g0, s.pose0, *mesh, s.pose1, TriangleOverlapPage{results, 16u, 0u}, received));
    d.value(received.count), d.value(received.overflow);
    for (std::uint32_t i = 0; i < received.count; ++i) d.value(results[i]);
    PenetrationResult<T> r;
    d.status(computeTriangleMeshPenetration(r, g0, s.pose0, *mesh, s.pose1));
    d.value(r.penetrating), d.vec(r.direction), d.value(r.depth);
  }
  if (const auto* hf = g1.template getIf<HeightFieldGeometry<T>>()) {
    std::uint32_t results[16];
    TriangleOverlapPageResult received;
    d.status(findOverlapHeightField(g0, s.pose0, *hf, s.pose1, TriangleOverlapPage{results, 16u, 0u}, received));
    d.value(received.count), d.value(received.overflow);
    for (std::uint32_t i = 0; i < received.count; ++i) d.value(results[i]);
  }
}

template <class T> std::uint64_t digestOf(const std::vector<Geometry<T>>& geoms, const std::vector<Scenario<T>>& list) {
  Digest d;
  for (const Scenario<T>& s : list) runScenario(geoms, s, d);
  return d.get();
}

}  // namespace gq::hardening
