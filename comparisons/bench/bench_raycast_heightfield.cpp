// Rays against a 512 x 512 heightfield terrain (unit cells, heights a sum of sines spanning about 24 units): gq in
// double and float through prepared shapes vs Bullet's (float) btHeightfieldTerrainShape::performRaycast with a
// btTriangleRaycastCallback, plain and after buildAccelerator() (its chunked min/max grid), on the same terrain
// (same samples, same diagonal split, Bullet's centring reproduced by gq's pose) and the same rays, closest hit.
// Ray sets, seeded: "down" from 5-30 units above the terrain's top towards random points of the grid (sensor-like),
// "grazing" from the terrain's edge at a few units above it, nearly horizontal, across the whole field.
// Before timing, every gq answer is checked against a long-double reference (every cell within one cell of the ray's
// XZ path, both triangles, each intersected in long double): hit/miss must agree and the distance match to 1e-9
// relative (double) or 1e-4 (float); rays whose reference is within 1e-9 of a triangle's edge or of grazing are
// counted, not judged. The run stops with a message on a mismatch. Bullet's agreement with the reference is counted.
// Benchmark names: <backend>/<rays>.
#include <BulletCollision/CollisionShapes/btHeightfieldTerrainShape.h>
#include <BulletCollision/NarrowPhaseCollision/btRaycastCallback.h>
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <map>
#include <memory>
#include <random>
#include <string>
#include <type_traits>
#include <vector>

#include "gq/cooking.h"
#include "gq/geometry.h"
#include "gq/query.h"
#include "gq/shape.h"

namespace {

constexpr int kSamples = 512;
constexpr std::size_t kRays = 4096;
constexpr double kMaxDist = 2000.0;
using LD = long double;

double terrainHeight(int row, int column) {
  const double x = row, z = column;
  return 6.0 * std::sin(x * 0.031) * std::cos(z * 0.027) + 3.0 * std::sin(x * 0.11 + z * 0.07) +
         1.5 * std::cos(x * 0.37 - z * 0.29) + 0.5 * std::sin(x * 1.3 + z * 0.9);
}

struct Terrain {
  std::vector<float> samples;  // row-major: samples[row * kSamples + column], row along X, column along Z
  float minHeight = 0, maxHeight = 0;
  Terrain() {
    for (int r = 0; r < kSamples; ++r)
      for (int c = 0; c < kSamples; ++c) samples.push_back(float(terrainHeight(r, c)));
    minHeight = *std::min_element(samples.begin(), samples.end());
    maxHeight = *std::max_element(samples.begin(), samples.end());
  }
  float at(int r, int c) const { return samples[std::size_t(r) * kSamples + std::size_t(c)]; }
  // Bullet centres its terrain on its box: vertex (x, h, z) of sample (r, c) is (r - 255.5, h - mid, c - 255.5).
  double offsetXZ() const { return -(kSamples - 1) / 2.0; }
  double offsetY() const { return -(double(minHeight) + double(maxHeight)) / 2.0; }
};

const Terrain& terrain() {
  static const Terrain t;
  return t;
}

struct Rays {
  std::vector<gq::Vec3<double>> origin, dir;  // world (Bullet's centred frame)
};

Rays makeRays(const std::string& kind) {
  const Terrain& t = terrain();
  std::mt19937_64 rng(kind == "down" ? 11 : 12);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double half = (kSamples - 1) / 2.0, top = t.maxHeight + t.offsetY();
  Rays r;
  for (std::size_t i = 0; i < kRays; ++i) {
    gq::Vec3<double> o, target;
    if (kind == "down") {
      o = {half * (2 * u(rng) - 1), top + 5 + 25 * u(rng), half * (2 * u(rng) - 1)};
      target = {half * (2 * u(rng) - 1), t.offsetY(), half * (2 * u(rng) - 1)};
    } else {
      const double a = 2 * M_PI * u(rng);
      o = {half * std::cos(a), top - 4 * u(rng), half * std::sin(a)};
      target = {-o.x() + 40 * (2 * u(rng) - 1), top - 12 - 8 * u(rng), -o.z() + 40 * (2 * u(rng) - 1)};
    }
    r.origin.push_back(o);
    r.dir.push_back((target - o).normalized());
  }
  return r;
}

const Rays& rays(const std::string& kind) {
  static const Rays down = makeRays("down"), grazing = makeRays("grazing");
  return kind == "down" ? down : grazing;
}

template <class T> const gq::Shape<T>& terrainShape() {
  static const gq::Shape<T> shape = [] {
    const Terrain& t = terrain();
    gq::HeightFieldDesc<T> desc;
    desc.rows = desc.columns = kSamples;
    for (float h : t.samples) desc.heights.push_back(T(h));
    std::shared_ptr<const gq::HeightField<T>> field;
    gq::Shape<T> s;
    if (!gq::cookHeightField(desc, field).ok() ||
        !gq::Shape<T>::make(gq::HeightFieldGeometry<T>(field, T(1), T(1), T(1)), s).ok()) {
      std::fprintf(stderr, "heightfield cooking failed\n");
      std::exit(1);
    }
    return s;
  }();
  return shape;
}

template <class T> gq::Transform<T> terrainPose() {
  const Terrain& t = terrain();
  return gq::Transform<T>(gq::Vec3<T>(T(t.offsetXZ()), T(t.offsetY()), T(t.offsetXZ())));
}

const gq::HitFlags kClosest = gq::kDefaultHitFlags | gq::HitFlag::MeshBothSides;  // Bullet reports both faces

// ---- long-double reference -----------------------------------------------------------------------------------
struct Reference {
  bool hit = false;
  LD t = 0;
  bool ambiguous = false;  // a hit or near-miss within 1e-9 of an edge, or a ray grazing a triangle's plane
};

using V3 = Eigen::Matrix<LD, 3, 1>;

// Möller-Trumbore in long double, both faces; a hit or near-miss within `m` of an edge (barycentric) is ambiguous.
void intersect(const V3& o, const V3& d, const V3& a, const V3& b, const V3& c, LD m, Reference& ref) {
  const V3 e1 = b - a, e2 = c - a, p = d.cross(e2);
  const LD det = e1.dot(p);
  if (std::abs(det) < 1e-12L * e1.norm() * e2.norm()) {
    ref.ambiguous = ref.ambiguous || std::abs(det) > 0;
    return;
  }
  const V3 s = o - a, q = s.cross(e1);
  const LD u = s.dot(p) / det, v = d.dot(q) / det, t = e2.dot(q) / det;
  if (t < 0 || t > kMaxDist) return;
  const bool inside = u >= 0 && v >= 0 && u + v <= 1;
  const bool near = u >= -m && v >= -m && u + v <= 1 + m;
  if (near && !(u >= m && v >= m && u + v <= 1 - m)) ref.ambiguous = true;
  if (inside && (!ref.hit || t < ref.t)) {
    ref.hit = true;
    ref.t = t;
  }
}

// Every cell within one cell of the ray's XZ path (row strip by row strip), both triangles, in terrain space.
Reference reference(const gq::Vec3<double>& worldOrigin, const gq::Vec3<double>& dir, LD margin) {
  const Terrain& t = terrain();
  const V3 o(LD(worldOrigin.x()) - t.offsetXZ(), LD(worldOrigin.y()) - t.offsetY(), LD(worldOrigin.z()) - t.offsetXZ());
  const V3 d = dir.cast<LD>();
  const V3 e = o + d * LD(kMaxDist);
  auto vertex = [&](int r, int c) { return V3(LD(r), LD(t.at(r, c)), LD(c)); };
  Reference ref;
  const int last = kSamples - 2;  // cells 0..510
  const int r0 = std::max(0, int(std::floor(std::min(o.x(), e.x()))) - 1);
  const int r1 = std::min(last, int(std::floor(std::max(o.x(), e.x()))) + 1);
  for (int r = r0; r <= r1; ++r) {
    // z range of the path while x is within [r - 1, r + 2].
    LD zLo, zHi;
    if (std::abs(d.x()) < 1e-300L) {
      zLo = std::min(o.z(), e.z());
      zHi = std::max(o.z(), e.z());
    } else {
      LD ta = (LD(r - 1) - o.x()) / d.x(), tb = (LD(r + 2) - o.x()) / d.x();
      if (ta > tb) std::swap(ta, tb);
      ta = std::max(ta, LD(0));
      tb = std::min(tb, LD(kMaxDist));
      if (ta > tb) continue;
      zLo = std::min(o.z() + ta * d.z(), o.z() + tb * d.z());
      zHi = std::max(o.z() + ta * d.z(), o.z() + tb * d.z());
    }
    const int c0 = std::max(0, int(std::floor(zLo)) - 1), c1 = std::min(last, int(std::floor(zHi)) + 1);
    for (int c = c0; c <= c1; ++c) {
      const V3 v00 = vertex(r, c), v01 = vertex(r, c + 1), v10 = vertex(r + 1, c), v11 = vertex(r + 1, c + 1);
      intersect(o, d, v00, v01, v10, margin, ref);
      intersect(o, d, v01, v11, v10, margin, ref);
    }
  }
  return ref;
}

// ---- Bullet ---------------------------------------------------------------------------------------------------
struct BulletTerrain {
  std::vector<float> data;  // Bullet's order: data[z * width + x]
  std::unique_ptr<btHeightfieldTerrainShape> shape;
  explicit BulletTerrain(bool accelerated) {
    const Terrain& t = terrain();
    data.resize(t.samples.size());
    for (int r = 0; r < kSamples; ++r)
      for (int c = 0; c < kSamples; ++c) data[std::size_t(c) * kSamples + std::size_t(r)] = t.at(r, c);
    shape = std::make_unique<btHeightfieldTerrainShape>(kSamples, kSamples, data.data(), t.minHeight, t.maxHeight,
                                                        1, false);
    if (accelerated) shape->buildAccelerator();
  }
};

class ClosestTriangle : public btTriangleRaycastCallback {
 public:
  ClosestTriangle(const btVector3& from, const btVector3& to) : btTriangleRaycastCallback(from, to) {}
  btScalar reportHit(const btVector3&, btScalar fraction, int, int) override {
    hit = true;
    return fraction;  // the returned fraction bounds later triangles
  }
  bool hit = false;
};

bool bulletRay(const BulletTerrain& bt, const gq::Vec3<double>& o, const gq::Vec3<double>& d, double& distance) {
  const gq::Vec3<double> to = o + d * kMaxDist;
  const btVector3 a(btScalar(o.x()), btScalar(o.y()), btScalar(o.z()));
  const btVector3 b(btScalar(to.x()), btScalar(to.y()), btScalar(to.z()));
  ClosestTriangle cb(a, b);
  bt.shape->performRaycast(&cb, a, b);
  distance = double(cb.m_hitFraction) * kMaxDist;
  return cb.hit;
}

// ---- exactness, before any timing -------------------------------------------------------------------------------
template <class T> bool gqRay(const gq::Vec3<double>& o, const gq::Vec3<double>& d, double& distance) {
  gq::RaycastHit<T> hit;
  std::uint32_t n = 0;
  const gq::Status s = gq::raycast(gq::Vec3<T>(o.cast<T>()), gq::Vec3<T>(d.cast<T>()), terrainShape<T>(),
                                   terrainPose<T>(), T(kMaxDist), kClosest, 1, &hit, n);
  if (!s.ok()) {
    std::fprintf(stderr, "gq raycast failed: %s\n", s.toString().c_str());
    std::exit(1);
  }
  distance = double(hit.distance);
  return n > 0;
}

// gq must agree with the long-double answer for the same ray (rounded to T) on every unambiguous ray (edge margin
// 1e-9 in double, 1e-4 in float: the rounding of a float watertight test); returns how many rays were ambiguous.
template <class T> std::size_t checkGq(const std::string& kind) {
  const bool isFloat = std::is_same_v<T, float>;
  const double rel = isFloat ? 1e-4 : 1e-9;
  const Rays& r = rays(kind);
  std::size_t ambiguous = 0;
  for (std::size_t i = 0; i < kRays; ++i) {
    const gq::Vec3<double> o = r.origin[i].cast<T>().template cast<double>(), d = r.dir[i].cast<T>().template cast<double>();
    const Reference ref = reference(o, d, isFloat ? 1e-4L : 1e-9L);
    if (ref.ambiguous) {
      ++ambiguous;
      continue;
    }
    double t = 0;
    const bool hit = gqRay<T>(o, d, t);
    const double want = double(ref.t);
    if (hit != ref.hit || (hit && std::abs(t - want) > rel * std::max(1.0, want))) {
      std::fprintf(stderr, "gq %s ray %zu (%s): hit %d at %.17g, reference hit %d at %.17g\n", isFloat ? "float" : "double",
                   i, kind.c_str(), int(hit), t, int(ref.hit), want);
      std::exit(1);
    }
  }
  return ambiguous;
}

struct Check {
  std::size_t ambiguousDouble = 0, ambiguousFloat = 0, bulletMismatch = 0, hits = 0;
};

const Check& checked(const std::string& kind) {
  static std::map<std::string, Check> done;
  auto it = done.find(kind);
  if (it != done.end()) return it->second;
  Check c;
  c.ambiguousDouble = checkGq<double>(kind);
  c.ambiguousFloat = checkGq<float>(kind);
  const Rays& r = rays(kind);
  const BulletTerrain bt(true);
  for (std::size_t i = 0; i < kRays; ++i) {
    const Reference ref = reference(r.origin[i], r.dir[i], 1e-9L);
    c.hits += ref.hit;
    if (ref.ambiguous) continue;
    double t = 0;
    const bool hit = bulletRay(bt, r.origin[i], r.dir[i], t);
    if (hit != ref.hit || (hit && std::abs(t - double(ref.t)) > 1e-3 * (1 + double(ref.t)))) ++c.bulletMismatch;
  }
  return done.emplace(kind, c).first->second;
}

void counters(benchmark::State& state, const std::string& kind, std::size_t hits) {
  const Check& c = checked(kind);
  state.SetItemsProcessed(std::int64_t(state.iterations() * kRays));
  state.counters["hits_per_ray"] = double(hits) / double(kRays);
  state.counters["reference_hits_per_ray"] = double(c.hits) / double(kRays);
  state.counters["ambiguous_double"] = double(c.ambiguousDouble);
  state.counters["ambiguous_float"] = double(c.ambiguousFloat);
  state.counters["bullet_mismatches"] = double(c.bulletMismatch);
}

// ---- timed -------------------------------------------------------------------------------------------------------
template <class T> void gqRays(benchmark::State& state, std::string kind) {
  checked(kind);
  const gq::Shape<T>& shape = terrainShape<T>();
  const gq::Transform<T> pose = terrainPose<T>();
  const Rays& r = rays(kind);
  std::vector<gq::Vec3<T>> o, d;
  for (std::size_t i = 0; i < kRays; ++i) {
    o.push_back(r.origin[i].template cast<T>());
    d.push_back(r.dir[i].template cast<T>());
  }
  gq::RaycastHit<T> hit;
  std::size_t hits = 0;
  for (auto _ : state) {
    hits = 0;
    for (std::size_t i = 0; i < kRays; ++i) {
      std::uint32_t n = 0;
      (void)gq::raycast(o[i], d[i], shape, pose, T(kMaxDist), kClosest, 1, &hit, n);  // valid input: timed
      hits += n;
      benchmark::DoNotOptimize(hit);
    }
  }
  counters(state, kind, hits);
}

void bulletRays(benchmark::State& state, std::string kind, bool accelerated) {
  checked(kind);
  const BulletTerrain bt(accelerated);
  const Rays& r = rays(kind);
  std::size_t hits = 0;
  for (auto _ : state) {
    hits = 0;
    for (std::size_t i = 0; i < kRays; ++i) {
      double t = 0;
      hits += bulletRay(bt, r.origin[i], r.dir[i], t);
      benchmark::DoNotOptimize(t);
    }
  }
  counters(state, kind, hits);
}

// gq and Bullet alternate within each ray set, so they see the same machine load.
void registerAll() {
  auto reg = [](const std::string& n, auto fn) {
    benchmark::RegisterBenchmark(n.c_str(), fn)->Unit(benchmark::kNanosecond);
  };
  for (const char* kind : {"down", "grazing"}) {
    const std::string k = kind;
    reg("gq_double/" + k, [=](benchmark::State& s) { gqRays<double>(s, k); });
    reg("gq_float/" + k, [=](benchmark::State& s) { gqRays<float>(s, k); });
    reg("bullet/" + k, [=](benchmark::State& s) { bulletRays(s, k, false); });
    reg("bullet_accelerated/" + k, [=](benchmark::State& s) { bulletRays(s, k, true); });
  }
}

// Registered before main runs (the rays and terrains are built on first use).
const bool kRegistered = (registerAll(), true);

}  // namespace

BENCHMARK_MAIN();
