// Raycasts against heightfields. Spec ("Raycasts against Heightfields"): heightfields are treated like triangle meshes
// whose normals face +Y in shape space; double-sided heightfields like double-sided meshes. Expected answers come from
// closed forms (flat or tilted fields) or a brute force over every triangle in long double.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "gq/cooking.h"
#include "gq/mesh_query.h"
#include "gq/query.h"

namespace {

using LD = long double;
using V3L = Eigen::Matrix<LD, 3, 1>;

template <class T> class HeightFieldRaycast : public ::testing::Test {};
using Scalars = ::testing::Types<float, double>;
TYPED_TEST_SUITE(HeightFieldRaycast, Scalars);

template <class T> T tolerance() { return std::is_same_v<T, float> ? T(2e-4) : T(1e-9); }

template <class T> std::shared_ptr<const gq::HeightField<T>> cook(const gq::HeightFieldDesc<T>& d) {
  std::shared_ptr<const gq::HeightField<T>> hf;
  const gq::Status s = gq::cookHeightField(d, hf);
  EXPECT_TRUE(s.ok()) << s.toString();
  return hf;
}

// rows x columns samples all at height h.
template <class T> std::shared_ptr<const gq::HeightField<T>> flatField(std::uint32_t rows, std::uint32_t columns, T h,
                                                                       std::vector<std::uint32_t> holes = {}) {
  gq::HeightFieldDesc<T> d;
  d.rows = rows;
  d.columns = columns;
  d.heights.assign(std::size_t(rows) * columns, h);
  d.holes = std::move(holes);
  return cook(d);
}

// Bumpy field: a smooth wave plus seeded noise, a few holes.
template <class T> std::shared_ptr<const gq::HeightField<T>> bumpyField(std::uint32_t rows, std::uint32_t columns,
                                                                        unsigned seed, double holeFraction) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  gq::HeightFieldDesc<T> d;
  d.rows = rows;
  d.columns = columns;
  for (std::uint32_t r = 0; r < rows; ++r)
    for (std::uint32_t c = 0; c < columns; ++c)
      d.heights.push_back(T(2 * std::sin(0.4 * r) * std::cos(0.3 * c) + 0.6 * (u(rng) - 0.5)));
  for (std::uint32_t cell = 0; cell < (rows - 1) * (columns - 1); ++cell)
    if (u(rng) < holeFraction) d.holes.push_back(cell);
  return cook(d);
}

template <class T> gq::Transform<T> tiltedPose() {
  return gq::Transform<T>(gq::Vec3<T>(T(0.5), T(-1), T(2)),
                          gq::Quat<T>(Eigen::AngleAxis<T>(T(0.6), gq::Vec3<T>(T(1), T(2), T(-1)).normalized())));
}

template <class T> struct Cast {
  gq::Status status;
  std::uint32_t count = 0;
  std::vector<gq::RaycastHit<T>> hits;
};

template <class T> Cast<T> cast(const gq::HeightFieldGeometry<T>& g, const gq::Transform<T>& pose, const gq::Vec3<T>& o,
                                const gq::Vec3<T>& d, T maxDist, gq::HitFlags flags, std::uint32_t maxHits = 1) {
  Cast<T> c;
  c.hits.resize(maxHits);
  c.status = gq::raycast<T>(o, d, gq::Geometry<T>(g), pose, maxDist, flags, maxHits, c.hits.data(), c.count);
  EXPECT_TRUE(c.status.ok()) << c.status.toString();
  return c;
}

const gq::HitFlags kAll = gq::kDefaultHitFlags | gq::HitFlag::UV;

// ---- Brute force: every triangle of getTriangle, Moller-Trumbore in long double --------------------------------
struct BruteHit {
  LD t;
  std::uint32_t face;
  bool front;   // dot(normal, dir) < 0
  LD minBary;   // smallest barycentric weight: < 0 outside, ~0 on an edge
  LD cosine;    // |dot(unit normal, dir)|: ~0 for grazing rays
};

struct WorldTriangle {
  std::uint32_t face;
  V3L v0, e1, e2;
};

// Every non-hole triangle of the field in world space, as getTriangle reports it.
template <class T>
std::vector<WorldTriangle> worldTriangles(const gq::HeightFieldGeometry<T>& g, const gq::Transform<T>& pose) {
  std::vector<WorldTriangle> out;
  const std::uint32_t tris = 2 * (g.heightField->rows - 1) * (g.heightField->columns - 1);
  for (std::uint32_t f = 0; f < tris; ++f) {
    if (g.heightField->hole[f / 2]) continue;
    gq::Triangle<T> tri;
    EXPECT_TRUE(gq::getTriangle(g, pose, f, tri).ok());
    const V3L v0 = tri.verts[0].template cast<LD>();
    out.push_back({f, v0, tri.verts[1].template cast<LD>() - v0, tri.verts[2].template cast<LD>() - v0});
  }
  return out;
}

template <class T>
std::vector<BruteHit> bruteForce(const std::vector<WorldTriangle>& tris, const gq::Vec3<T>& o, const gq::Vec3<T>& d) {
  std::vector<BruteHit> out;
  const V3L O = o.template cast<LD>(), D = d.template cast<LD>();
  for (const WorldTriangle& w : tris) {
    const V3L p = D.cross(w.e2);
    const LD det = w.e1.dot(p);  // = -dot(cross(e1, e2), D)
    if (det == 0) continue;
    const V3L s = O - w.v0, q = s.cross(w.e1);
    const LD u = s.dot(p) / det, v = D.dot(q) / det, t = w.e2.dot(q) / det;
    const LD minBary = std::min({u, v, 1 - u - v});
    if (minBary < -0.01L) continue;
    out.push_back({t, w.face, det > 0, minBary, std::abs(det) / w.e1.cross(w.e2).norm()});
  }
  std::sort(out.begin(), out.end(), [](const BruteHit& a, const BruteHit& b) { return a.t < b.t; });
  return out;
}

// Hits certainly reported (strict) or possibly reported (loose), given rounding near edges, grazing angles and the
// ends of the ray.
struct Classified {
  std::vector<BruteHit> strict, loose;
};
Classified classify(const std::vector<BruteHit>& all, LD maxDist, bool cull, LD slack, LD tSlack) {
  Classified c;
  for (const BruteHit& h : all) {
    const bool strict = h.minBary >= slack && h.t >= tSlack && h.t <= maxDist - tSlack &&
                        (!cull || (h.front && h.cosine >= slack));
    const bool loose = h.minBary >= -slack && h.t >= -tSlack && h.t <= maxDist + tSlack &&
                       (!cull || h.front || h.cosine < slack);
    if (strict) c.strict.push_back(h);
    if (loose) c.loose.push_back(h);
  }
  return c;
}

const BruteHit* findFace(const std::vector<BruteHit>& hits, std::uint32_t face) {
  for (const BruteHit& h : hits)
    if (h.face == face) return &h;
  return nullptr;
}

// ---- Rules -------------------------------------------------------------------------------------------------------

TYPED_TEST(HeightFieldRaycast, RayFromAboveHitsClosestTriangleWithUpNormalInShapeSpace) {
  using T = TypeParam;
  const gq::HeightFieldGeometry<T> g(flatField<T>(5, 6, T(2)), T(0.5), T(1), T(2));  // surface at y = 1
  const gq::Transform<T> pose = tiltedPose<T>();
  // Shape-space ray straight down onto cell (2, 3) at (2.25, ., 6.5): first triangle (v00, v01, v10) there.
  const gq::Vec3<T> target(T(2.25), T(1), T(6.5));
  const gq::Vec3<T> o = pose.transform(target + gq::Vec3<T>(0, T(3), 0)), d = pose.rotate(gq::Vec3<T>(0, -1, 0));
  const Cast<T> c = cast(g, pose, o, d, T(10), kAll);
  ASSERT_EQ(c.count, 1u);
  const gq::RaycastHit<T>& h = c.hits[0];
  EXPECT_NEAR(h.distance, T(3), tolerance<T>() * 10);
  EXPECT_EQ(h.faceIndex, 2u * (2 * 5 + 3));
  EXPECT_TRUE(h.flags.has(gq::HitFlag::Position) && h.flags.has(gq::HitFlag::Normal) &&
              h.flags.has(gq::HitFlag::FaceIndex) && h.flags.has(gq::HitFlag::UV));
  EXPECT_LT((h.normal - pose.rotate(gq::Vec3<T>(0, 1, 0))).norm(), tolerance<T>() * 10);
  EXPECT_LT((h.position - pose.transform(target)).norm(), tolerance<T>() * 10);
  // u, v relate to the triangle getTriangle returns: position = (1-u-v) v0 + u v1 + v v2.
  gq::Triangle<T> tri;
  ASSERT_TRUE(gq::getTriangle(g, pose, h.faceIndex, tri).ok());
  EXPECT_LT((tri.pointFromUV(h.u, h.v) - h.position).norm(), tolerance<T>() * 10);
}

TYPED_TEST(HeightFieldRaycast, BackFaceHitsAreCulledByDefault) {
  using T = TypeParam;
  const gq::HeightFieldGeometry<T> g(flatField<T>(4, 4, T(0)), T(1), T(1), T(1));
  const Cast<T> c = cast(g, gq::Transform<T>(), gq::Vec3<T>(T(1.3), T(-2), T(1.6)), gq::Vec3<T>(0, 1, 0), T(10), kAll);
  EXPECT_EQ(c.count, 0u);
}

TYPED_TEST(HeightFieldRaycast, MeshBothSidesHitsBackFaceAndKeepsTheTriangleNormal) {
  using T = TypeParam;
  const gq::HeightFieldGeometry<T> g(flatField<T>(4, 4, T(0)), T(1), T(1), T(1));
  const gq::Transform<T> pose = tiltedPose<T>();
  const gq::Vec3<T> o = pose.transform(gq::Vec3<T>(T(1.3), T(-2), T(1.6))), d = pose.rotate(gq::Vec3<T>(0, 1, 0));
  const Cast<T> c = cast(g, pose, o, d, T(10), kAll | gq::HitFlag::MeshBothSides);
  ASSERT_EQ(c.count, 1u);
  EXPECT_NEAR(c.hits[0].distance, T(2), tolerance<T>() * 10);
  // Single-sided field: the normal is the triangle's (+Y in shape space), pointing along the ray.
  EXPECT_LT((c.hits[0].normal - pose.rotate(gq::Vec3<T>(0, 1, 0))).norm(), tolerance<T>() * 10);
  EXPECT_GT(c.hits[0].normal.dot(d), T(0));
}

TYPED_TEST(HeightFieldRaycast, DoubleSidedFieldHitsBackFaceWithReversedNormal) {
  using T = TypeParam;
  const gq::HeightFieldGeometry<T> g(flatField<T>(4, 4, T(0)), T(1), T(1), T(1), gq::MeshGeometryFlag::DoubleSided);
  const gq::Transform<T> pose = tiltedPose<T>();
  const gq::Vec3<T> o = pose.transform(gq::Vec3<T>(T(1.3), T(-2), T(1.6))), d = pose.rotate(gq::Vec3<T>(0, 1, 0));
  for (gq::HitFlags flags : {kAll, kAll | gq::HitFlag::MeshBothSides}) {
    const Cast<T> c = cast(g, pose, o, d, T(10), flags);
    ASSERT_EQ(c.count, 1u);
    EXPECT_NEAR(c.hits[0].distance, T(2), tolerance<T>() * 10);
    EXPECT_LT((c.hits[0].normal - pose.rotate(gq::Vec3<T>(0, -1, 0))).norm(), tolerance<T>() * 10);
    EXPECT_LT(c.hits[0].normal.dot(d), T(0));
  }
  // Front faces of a double-sided field keep the +Y normal.
  const Cast<T> top = cast(g, pose, pose.transform(gq::Vec3<T>(T(1.3), T(2), T(1.6))), pose.rotate(gq::Vec3<T>(0, -1, 0)),
                           T(10), kAll);
  ASSERT_EQ(top.count, 1u);
  EXPECT_LT((top.hits[0].normal - pose.rotate(gq::Vec3<T>(0, 1, 0))).norm(), tolerance<T>() * 10);
}

TYPED_TEST(HeightFieldRaycast, MaxDistZeroNeverHits) {
  using T = TypeParam;
  const gq::HeightFieldGeometry<T> g(flatField<T>(4, 4, T(0)), T(1), T(1), T(1), gq::MeshGeometryFlag::DoubleSided);
  // Origin exactly on the surface: a zero-length ray still reports nothing.
  const Cast<T> c = cast(g, gq::Transform<T>(), gq::Vec3<T>(T(1.5), T(0), T(1.25)), gq::Vec3<T>(0, -1, 0), T(0), kAll);
  EXPECT_EQ(c.count, 0u);
}

TYPED_TEST(HeightFieldRaycast, SurfaceBeyondMaxDistIsNotHit) {
  using T = TypeParam;
  const gq::HeightFieldGeometry<T> g(flatField<T>(4, 4, T(0)), T(1), T(1), T(1));
  const gq::Vec3<T> o(T(1.5), T(3), T(1.25)), d(0, -1, 0);
  EXPECT_EQ(cast(g, gq::Transform<T>(), o, d, T(2.9), kAll).count, 0u);
  EXPECT_EQ(cast(g, gq::Transform<T>(), o, d, T(3.1), kAll).count, 1u);
}

TYPED_TEST(HeightFieldRaycast, HolesAreNeverHit) {
  using T = TypeParam;
  // 3 x 3 cells; the centre cell (1, 1) = 4 is a hole.
  const gq::HeightFieldGeometry<T> g(flatField<T>(4, 4, T(0), {4}), T(1), T(1), T(1), gq::MeshGeometryFlag::DoubleSided);
  for (T x : {T(1.1), T(1.5), T(1.9)})
    for (T z : {T(1.1), T(1.5), T(1.9)}) {
      EXPECT_EQ(cast(g, gq::Transform<T>(), gq::Vec3<T>(x, T(1), z), gq::Vec3<T>(0, -1, 0), T(5), kAll).count, 0u);
      EXPECT_EQ(cast(g, gq::Transform<T>(), gq::Vec3<T>(x, T(-1), z), gq::Vec3<T>(0, 1, 0), T(5),
                     kAll | gq::HitFlag::MeshMultiple, 4).count, 0u);
    }
  // A neighbouring cell is still solid.
  EXPECT_EQ(cast(g, gq::Transform<T>(), gq::Vec3<T>(T(0.5), T(1), T(1.5)), gq::Vec3<T>(0, -1, 0), T(5), kAll).count, 1u);
}

// A ray grazing a wave crosses the surface several times: closest, any and multiple differ.
template <class T> struct WaveCase {
  gq::HeightFieldGeometry<T> g;
  gq::Vec3<T> o, d;
  std::vector<BruteHit> brute;
};
template <class T> WaveCase<T> waveCase() {
  gq::HeightFieldDesc<T> desc;
  desc.rows = 41;
  desc.columns = 3;
  for (std::uint32_t r = 0; r < desc.rows; ++r)
    for (std::uint32_t c = 0; c < desc.columns; ++c) desc.heights.push_back(T(std::sin(0.5 * r)));
  WaveCase<T> w{gq::HeightFieldGeometry<T>(cook(desc), T(1), T(1), T(1)), gq::Vec3<T>(T(-0.5), T(0.1), T(1.3)),
                gq::Vec3<T>(1, T(-0.01), 0).normalized(), {}};
  w.brute = bruteForce(worldTriangles(w.g, gq::Transform<T>()), w.o, w.d);
  return w;
}

TYPED_TEST(HeightFieldRaycast, MeshMultipleReportsTheClosestHitsUpToMaxHits) {
  using T = TypeParam;
  const WaveCase<T> w = waveCase<T>();
  std::vector<BruteHit> front;
  for (const BruteHit& h : w.brute)
    if (h.front && h.minBary > 1e-6L && h.t >= 0 && h.t <= 100) front.push_back(h);
  ASSERT_GE(front.size(), 4u);  // the wave is crossed downward at least 4 times
  const Cast<T> c = cast(w.g, gq::Transform<T>(), w.o, w.d, T(100), kAll | gq::HitFlag::MeshMultiple, 3);
  ASSERT_EQ(c.count, 3u);
  for (std::uint32_t i = 0; i < 3; ++i) {
    EXPECT_EQ(c.hits[i].faceIndex, front[i].face);
    EXPECT_NEAR(double(c.hits[i].distance), double(front[i].t), 10 * double(tolerance<T>()));
    EXPECT_LT(c.hits[i].normal.dot(w.d), T(0));
  }
  // Without MeshMultiple maxHits > 1 still reports only the closest.
  const Cast<T> one = cast(w.g, gq::Transform<T>(), w.o, w.d, T(100), kAll, 3);
  ASSERT_EQ(one.count, 1u);
  EXPECT_EQ(one.hits[0].faceIndex, front[0].face);
}

TYPED_TEST(HeightFieldRaycast, ClosestHitIsReportedByDefaultAndAnyHitReportsARealHit) {
  using T = TypeParam;
  const WaveCase<T> w = waveCase<T>();
  std::vector<BruteHit> front;
  for (const BruteHit& h : w.brute)
    if (h.front && h.minBary > 1e-6L && h.t >= 0 && h.t <= 100) front.push_back(h);
  ASSERT_GE(front.size(), 2u);
  const Cast<T> closest = cast(w.g, gq::Transform<T>(), w.o, w.d, T(100), kAll);
  ASSERT_EQ(closest.count, 1u);
  EXPECT_EQ(closest.hits[0].faceIndex, front[0].face);
  const Cast<T> any = cast(w.g, gq::Transform<T>(), w.o, w.d, T(100), kAll | gq::HitFlag::AnyHit);
  ASSERT_EQ(any.count, 1u);
  const BruteHit* match = findFace(front, any.hits[0].faceIndex);
  ASSERT_NE(match, nullptr);
  EXPECT_NEAR(double(any.hits[0].distance), double(match->t), 10 * double(tolerance<T>()));
}

TYPED_TEST(HeightFieldRaycast, RaysThroughGridVerticesAndCellDiagonalsHit) {
  using T = TypeParam;
  // Exactly representable scales and heights so that the rays pass exactly through vertices and shared edges.
  gq::HeightFieldDesc<T> desc;
  desc.rows = 6;
  desc.columns = 7;
  for (std::uint32_t r = 0; r < desc.rows; ++r)
    for (std::uint32_t c = 0; c < desc.columns; ++c) desc.heights.push_back(T(int(r * 5 + c * 3) % 4) * T(0.25));
  const gq::HeightFieldGeometry<T> g(cook(desc), T(1), T(0.5), T(0.25));
  int rays = 0;
  for (std::uint32_t r = 0; r < desc.rows; ++r)
    for (std::uint32_t c = 0; c < desc.columns; ++c) {
      // Vertical and slanted rays through the sample (r, c), and through the middle of the diagonal of cell (r, c).
      const gq::Vec3<T> vertex(T(r) * T(0.5), desc.heights[r * desc.columns + c], T(c) * T(0.25));
      std::vector<gq::Vec3<T>> targets = {vertex};
      if (r + 1 < desc.rows && c + 1 < desc.columns) {
        const gq::Vec3<T> a(T(r + 1) * T(0.5), desc.heights[(r + 1) * desc.columns + c], T(c) * T(0.25));
        const gq::Vec3<T> b(T(r) * T(0.5), desc.heights[r * desc.columns + c + 1], T(c + 1) * T(0.25));
        targets.push_back((a + b) * T(0.5));
      }
      // Slanted rays are not exactly representable, so only a vertex shared by a closed fan of triangles (interior)
      // must catch them; a vertical ray is exact and must hit boundary vertices too.
      const bool interior = r > 0 && c > 0 && r + 1 < desc.rows && c + 1 < desc.columns;
      for (std::size_t k = 0; k < targets.size(); ++k)
        for (const gq::Vec3<T>& dir : {gq::Vec3<T>(0, -1, 0), gq::Vec3<T>(0, -4, 3).normalized(),
                                       gq::Vec3<T>(-3, -4, 0).normalized()}) {
          if (k == 0 && !interior && dir.y() != T(-1)) continue;
          const gq::Vec3<T> o = targets[k] - T(2) * dir;
          const Cast<T> hit = cast(g, gq::Transform<T>(), o, dir, T(10), kAll);
          ++rays;
          ASSERT_EQ(hit.count, 1u) << "leak at sample (" << r << "," << c << ") target " << targets[k].transpose()
                                   << " dir " << dir.transpose();
          EXPECT_LE(double(hit.hits[0].distance), 2.0 + 1e-4);  // the vertex or an earlier crossing
        }
    }
  EXPECT_GT(rays, 150);
}

TYPED_TEST(HeightFieldRaycast, OmittedOutputFlagsAreNotWritten) {
  using T = TypeParam;
  const gq::HeightFieldGeometry<T> g(flatField<T>(4, 4, T(0)), T(1), T(1), T(1));
  gq::RaycastHit<T> hit;
  hit.position = gq::Vec3<T>::Constant(T(77));
  hit.normal = gq::Vec3<T>::Constant(T(77));
  hit.u = T(77);
  std::uint32_t n = 0;
  ASSERT_TRUE(gq::raycast<T>(gq::Vec3<T>(T(1.5), T(1), T(1.5)), gq::Vec3<T>(0, -1, 0), gq::Geometry<T>(g),
                             gq::Transform<T>(), T(5), gq::HitFlags(gq::HitFlag::FaceIndex), 1, &hit, n).ok());
  ASSERT_EQ(n, 1u);
  EXPECT_EQ(hit.flags, gq::HitFlags(gq::HitFlag::FaceIndex));
  EXPECT_EQ(hit.position, gq::Vec3<T>::Constant(T(77)));
  EXPECT_EQ(hit.normal, gq::Vec3<T>::Constant(T(77)));
  EXPECT_EQ(hit.u, T(77));
  EXPECT_NEAR(hit.distance, T(1), tolerance<T>());
  EXPECT_LT(hit.faceIndex, 18u);
}

// ---- Seeded random rays against brute force --------------------------------------------------------------------

template <class T> void randomRaysMatchBruteForce(gq::HitFlags flags, gq::MeshGeometryFlag geomFlag, std::uint32_t maxHits,
                                                  int rayCount, unsigned seed) {
  const gq::HeightFieldGeometry<T> g(bumpyField<T>(27, 22, seed, 0.05), T(0.7), T(0.5), T(0.8), geomFlag);
  const gq::Transform<T> pose = tiltedPose<T>();
  const std::vector<WorldTriangle> tris = worldTriangles(g, pose);
  const bool cull = !g.doubleSided() && !flags.has(gq::HitFlag::MeshBothSides);
  const bool multiple = flags.has(gq::HitFlag::MeshMultiple) && maxHits > 1;
  const LD slack = std::is_same_v<T, float> ? 1e-3L : 1e-9L;
  const LD tTol = std::is_same_v<T, float> ? 1e-3L : 1e-9L;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  int hitsSeen = 0;
  for (int i = 0; i < rayCount; ++i) {
    // Aim from a random point around the field at a random point over it; about a third start below.
    const double tx = u(rng), ty = u(rng), tz = u(rng), sx = u(rng), sy = u(rng), sz = u(rng);
    const gq::Vec3<T> target(T(13 * 0.5 * tx), T(4 * ty - 2), T(21 * 0.8 * tz));
    const gq::Vec3<T> start = target + gq::Vec3<T>(T(16 * sx - 8), T(12 * sy - 4), T(16 * sz - 8));
    const gq::Vec3<T> o = pose.transform(start), d = pose.rotate((target - start).normalized());
    const T maxDist = T((target - start).norm() * (0.5 + 1.5 * u(rng)));
    const Cast<T> c = cast(g, pose, o, d, maxDist, kAll | flags, maxHits);
    const Classified expected = classify(bruteForce(tris, o, d), LD(maxDist), cull, slack, tTol);
    const std::size_t cap = multiple ? maxHits : 1;
    ASSERT_GE(c.count, std::min(cap, expected.strict.size())) << "ray " << i;
    ASSERT_LE(c.count, std::min(cap, expected.loose.size())) << "ray " << i;
    hitsSeen += c.count > 0;
    for (std::uint32_t k = 0; k < c.count; ++k) {
      const gq::RaycastHit<T>& h = c.hits[k];
      const BruteHit* match = findFace(expected.loose, h.faceIndex);
      ASSERT_NE(match, nullptr) << "ray " << i << " reported a triangle it does not hit";
      EXPECT_NEAR(double(h.distance), double(match->t), double(tTol) * 20) << "ray " << i;
      // The k-th hit is no farther than the k-th certain hit (closest first; AnyHit may report any).
      if (!flags.has(gq::HitFlag::AnyHit) && k < expected.strict.size())
        EXPECT_LE(LD(h.distance), expected.strict[k].t + tTol * 20) << "ray " << i;
      if (cull) EXPECT_LT(h.normal.dot(d), T(0));
      if (g.doubleSided()) EXPECT_LE(h.normal.dot(d), T(0));
      gq::Triangle<T> tri;
      ASSERT_TRUE(gq::getTriangle(g, pose, h.faceIndex, tri).ok());
      EXPECT_LT((tri.pointFromUV(h.u, h.v) - h.position).norm(), T(tTol * 50)) << "ray " << i;
      EXPECT_LT((o + h.distance * d - h.position).norm(), T(tTol * 50)) << "ray " << i;
    }
  }
  EXPECT_GT(hitsSeen, rayCount / 5);  // the rays do exercise hits
}

TYPED_TEST(HeightFieldRaycast, RandomRaysClosestHitMatchesBruteForce) {
  randomRaysMatchBruteForce<TypeParam>(gq::HitFlags(), gq::MeshGeometryFlag::None, 1, 10000, 11);
}

TYPED_TEST(HeightFieldRaycast, RandomRaysBothSidesAndDoubleSidedMatchBruteForce) {
  randomRaysMatchBruteForce<TypeParam>(gq::HitFlag::MeshBothSides, gq::MeshGeometryFlag::None, 1, 3000, 12);
  randomRaysMatchBruteForce<TypeParam>(gq::HitFlags(), gq::MeshGeometryFlag::DoubleSided, 1, 3000, 13);
}

TYPED_TEST(HeightFieldRaycast, RandomRaysMeshMultipleAndAnyHitMatchBruteForce) {
  randomRaysMatchBruteForce<TypeParam>(gq::HitFlag::MeshMultiple | gq::HitFlag::MeshBothSides,
                                       gq::MeshGeometryFlag::None, 4, 3000, 14);
  randomRaysMatchBruteForce<TypeParam>(gq::HitFlags(gq::HitFlag::AnyHit), gq::MeshGeometryFlag::None, 1, 3000, 15);
}

}  // namespace
