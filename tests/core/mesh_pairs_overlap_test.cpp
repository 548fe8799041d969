// Overlap of sphere / capsule / box / convex / mesh / heightfield against triangle meshes and heightfields (thin
// surfaces; touching counts), checked against long-double brute force over every triangle.
#include <gtest/gtest.h>

#include <map>
#include <memory>
#include <vector>

#include "gq/cooking.h"
#include "gq/query.h"
#include "mesh_pairs_reference.h"
#include "mesh_test_helpers.h"
#include "overlap_test_support.h"

namespace gq::meshpairs {
namespace {

template <class T> class MeshOverlap : public ::testing::Test {};
TYPED_TEST_SUITE(MeshOverlap, test::Scalars);

// Relative width of the band around touching where float/double rounding may legitimately flip the answer.
template <class T> LD ambiguityBand() { return std::is_same_v<T, float> ? 2e-6L : 1e-9L; }

// An octahedron with semi-axes (a, b, c), built by hand (independent of qhull).
template <class T> std::shared_ptr<const ConvexMesh<T>> octahedron(T a, T b, T c) {
  const std::vector<Vec3<T>> v = {{a, 0, 0}, {-a, 0, 0}, {0, b, 0}, {0, -b, 0}, {0, 0, c}, {0, 0, -c}};
  const std::vector<std::vector<std::uint32_t>> f = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                                                     {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  return test::makeHull(v, f);
}

// Largest normalized separation of two point sets over the axes (> 0: separated by that much along an axis; for
// polytopes with the complete SAT axis set, the maximum is the signed distance when > 0 and minus the MTD else).
inline LD satSeparation(const std::vector<Vec3L>& a, const std::vector<Vec3L>& b, const std::vector<Vec3L>& axes) {
  LD best = -std::numeric_limits<LD>::infinity();
  for (const Vec3L& axis : axes) {
    const LD len = axis.norm();
    if (len < 1e-12L) continue;
    LD loA = std::numeric_limits<LD>::infinity(), hiA = -loA, loB = loA, hiB = -loA;
    for (const auto& p : a) { loA = std::min(loA, axis.dot(p)); hiA = std::max(hiA, axis.dot(p)); }
    for (const auto& p : b) { loB = std::min(loB, axis.dot(p)); hiB = std::max(hiB, axis.dot(p)); }
    best = std::max(best, std::max(loB - hiA, loA - hiB) / len);
  }
  return best;
}

// The query shape with an independent signed gap to one triangle (<= 0: overlapping).
template <class T> struct ShapeCase {
  Geometry<T> geom;
  Transform<T> pose;
  enum Kind { Sphere, Capsule, Box, Convex } kind;
  LD radius = 0;
  Vec3L a, b;                   // capsule segment / sphere centre
  std::vector<Vec3L> verts;     // box / convex vertices (world)
  std::vector<Vec3L> axes;      // box / convex face normals (world)
  std::vector<std::pair<int, int>> edges;
  Vec3L lo, hi;                 // world AABB

  LD gap(const TriL& t) const {
    if (kind == Sphere) return std::sqrt(pointTriangleDistSq(a, t)) - radius;
    if (kind == Capsule) return std::sqrt(segmentTriangleDistSq(a, b, t)) - radius;
    std::vector<Vec3L> all = axes;
    const Vec3L n = (t[1] - t[0]).cross(t[2] - t[0]);
    all.push_back(n);
    for (const auto& e : edges)
      for (int j = 0; j < 3; ++j) {
        const Vec3L f = t[(j + 1) % 3] - t[j];
        all.push_back(Vec3L(verts[e.second] - verts[e.first]).cross(f));
      }
    return satSeparation(verts, std::vector<Vec3L>(t.begin(), t.end()), all);
  }
};

template <class T> ShapeCase<T> randomShape(test::Rng& rng, int kind, double spread, double size,
                                            const std::shared_ptr<const ConvexMesh<T>>& hull) {
  ShapeCase<T> s;
  s.kind = typename ShapeCase<T>::Kind(kind);
  s.pose = rng.pose<T>(spread);
  const Mat3L r = test::rotationLD(s.pose.q);
  const Vec3L p = test::toLD(s.pose.p);
  if (kind == ShapeCase<T>::Sphere) {
    const T radius = T(rng.uniform(0.05, 1.0) * size);
    s.geom = SphereGeometry<T>(radius);
    s.radius = radius;
    s.a = s.b = p;
    s.lo = p.array() - s.radius;
    s.hi = p.array() + s.radius;
  } else if (kind == ShapeCase<T>::Capsule) {
    const T radius = T(rng.uniform(0.05, 0.6) * size), hh = T(rng.uniform(0.0, 1.0) * size);
    s.geom = CapsuleGeometry<T>(radius, hh);
    s.radius = radius;
    s.a = p - r.col(0) * LD(hh);
    s.b = p + r.col(0) * LD(hh);
    s.lo = s.a.cwiseMin(s.b).array() - s.radius;
    s.hi = s.a.cwiseMax(s.b).array() + s.radius;
  } else {
    std::vector<Vec3<T>> local;
    std::vector<std::vector<std::uint32_t>> faces;
    if (kind == ShapeCase<T>::Box) {
      const double x = rng.uniform(0.05, 1.0), y = rng.uniform(0.05, 1.0), z = rng.uniform(0.05, 1.0);
      const Vec3<T> he(T(x * size), T(y * size), T(z * size));
      s.geom = BoxGeometry<T>(he);
      for (int k = 0; k < 8; ++k) local.push_back(Vec3<T>((k & 1) ? he.x() : -he.x(), (k & 2) ? he.y() : -he.y(), (k & 4) ? he.z() : -he.z()));
      for (int k = 0; k < 3; ++k) s.axes.push_back(r.col(k));
      for (int k = 0; k < 8; ++k)
        for (int bit = 1; bit < 8; bit <<= 1)
          if (!(k & bit)) s.edges.push_back({k, k | bit});
    } else {
      s.geom = ConvexMeshGeometry<T>(hull);
      local = hull->vertices;
      for (const auto& poly : hull->polygons) {
        s.axes.push_back(r * poly.normal.template cast<LD>());
        for (std::uint32_t i = 0; i < poly.indexCount; ++i)
          s.edges.push_back({int(hull->polygonVertices[poly.indexBase + i]),
                             int(hull->polygonVertices[poly.indexBase + (i + 1) % poly.indexCount])});
      }
    }
    s.lo = Vec3L::Constant(std::numeric_limits<LD>::infinity());
    s.hi = -s.lo;
    for (const auto& v : local) {
      const Vec3L w = r * v.template cast<LD>() + p;
      s.verts.push_back(w);
      s.lo = s.lo.cwiseMin(w);
      s.hi = s.hi.cwiseMax(w);
    }
  }
  return s;
}

// Brute force over all triangles: the overlap answer, or "ambiguous" when a triangle is within `band` of touching.
struct Reference {
  bool overlap = false;
  bool ambiguous = false;
};
template <class T>
Reference bruteForce(const ShapeCase<T>& s, const std::vector<TriL>& tris, const std::vector<bool>* valid, LD band) {
  Reference ref;
  for (std::size_t i = 0; i < tris.size(); ++i) {
    if (valid && !(*valid)[i]) continue;
    if (!boxesOverlap(tris[i], s.lo.array() - band, s.hi.array() + band)) continue;
    const LD g = s.gap(tris[i]);
    if (std::abs(g) <= band) ref.ambiguous = true;
    if (g <= 0) ref.overlap = true;
  }
  return ref;
}

// Random scaled (sometimes mirrored) icosphere instance.
template <class T> MeshScale<T> randomScale(test::Rng& rng) {
  Vec3<T> s = rng.vec<T>(0.6, 1.4);
  if (rng.chance(0.3)) s.x() = -s.x();
  return MeshScale<T>(s, rng.rotation<T>());
}

template <class T>
void checkShapesAgainstMesh(const MeshData<T>& data, double spread, double size, int posesPerKind, std::uint64_t seed,
                            bool scaled) {
  const auto cooked = meshtest::cook(data.vertices, data.triangles);
  const auto hull = octahedron<T>(T(0.5 * size), T(0.3 * size), T(0.7 * size));
  test::Rng rng(seed);
  int ambiguous = 0, overlaps = 0, total = 0;
  for (int kind = 0; kind < 4; ++kind) {
    const MeshScale<T> scale = scaled ? randomScale<T>(rng) : MeshScale<T>();
    const Transform<T> meshPose = scaled ? rng.pose<T>(0.3 * size) : Transform<T>();
    const Geometry<T> mesh = TriangleMeshGeometry<T>(cooked, scale);
    const std::vector<TriL> tris = worldTriangles(data, scale, meshPose);
    for (int i = 0; i < posesPerKind; ++i) {
      const ShapeCase<T> s = randomShape<T>(rng, kind, spread, size, hull);
      const Reference ref = bruteForce(s, tris, nullptr, ambiguityBand<T>() * LD(spread + size));
      bool got = false;
      ASSERT_TRUE(overlap(s.geom, s.pose, mesh, meshPose, got).ok());
      bool swappedGot = false;
      ASSERT_TRUE(overlap(mesh, meshPose, s.geom, s.pose, swappedGot).ok());
      ++total;
      if (ref.ambiguous) { ++ambiguous; continue; }
      overlaps += ref.overlap;
      ASSERT_EQ(got, ref.overlap) << "shape kind " << kind << " pose " << i;
      ASSERT_EQ(swappedGot, ref.overlap) << "swapped, shape kind " << kind << " pose " << i;
    }
  }
  EXPECT_LT(ambiguous, total / 50) << "too many near-touching cases to be a meaningful check";
  EXPECT_GT(overlaps, total / 20);
  EXPECT_LT(overlaps, total - total / 20);
}

TYPED_TEST(MeshOverlap, ShapesVsScaledIcosphereMatchBruteForceOverAllTriangles) {
  checkShapesAgainstMesh<TypeParam>(meshtest::icosphere<TypeParam>(3), 1.4, 0.5, 1000, 11, true);
}

// The bunny from the shared data folder (skipped when it is missing).
template <class T> class MeshOverlapData : public ::testing::Test {};
TYPED_TEST_SUITE(MeshOverlapData, test::Scalars);

TYPED_TEST(MeshOverlapData, ShapesVsBunnyMatchBruteForceOverAllTriangles) {
  GQ_REQUIRE_BUNNY();
  // The bunny is about 0.15 across, centred near (-0.02, 0.1, 0).
  const MeshData<TypeParam> bunny = meshtest::bunny<TypeParam>();
  Bounds3<double> b;
  for (const auto& v : bunny.vertices) b.include(v.template cast<double>());
  MeshData<TypeParam> centred = bunny;
  for (auto& v : centred.vertices) v -= b.center().template cast<TypeParam>();
  checkShapesAgainstMesh<TypeParam>(centred, 0.09, 0.03, 300, 12, false);  // 69k triangles: 1200 poses in all
}

TYPED_TEST(MeshOverlap, ShapeInsideClosedMeshDoesNotOverlapTheSurface) {
  using T = TypeParam;
  const MeshData<T> data = meshtest::icosphere<T>(2);
  const Geometry<T> mesh = TriangleMeshGeometry<T>(meshtest::cook(data.vertices, data.triangles));
  bool got = true;
  ASSERT_TRUE(overlap(Geometry<T>(SphereGeometry<T>(T(0.5))), Transform<T>(), mesh, Transform<T>(), got).ok());
  EXPECT_FALSE(got);
  ASSERT_TRUE(overlap(Geometry<T>(BoxGeometry<T>(T(0.4), T(0.4), T(0.4))), Transform<T>(), mesh, Transform<T>(), got).ok());
  EXPECT_FALSE(got);
}

TYPED_TEST(MeshOverlap, TouchingCountsAsOverlapping) {
  using T = TypeParam;
  const MeshData<T> quad = meshtest::quadStack<T>(1);  // [-1,1]^2 at z = 0
  const Geometry<T> mesh = TriangleMeshGeometry<T>(meshtest::cook(quad.vertices, quad.triangles));
  bool got = false;
  ASSERT_TRUE(overlap(Geometry<T>(SphereGeometry<T>(T(0.5))), Transform<T>(Vec3<T>(0, 0, T(0.5))), mesh, Transform<T>(), got).ok());
  EXPECT_TRUE(got);
  ASSERT_TRUE(overlap(Geometry<T>(BoxGeometry<T>(T(0.5), T(0.5), T(0.25))), Transform<T>(Vec3<T>(T(0.2), 0, T(-0.25))), mesh,
                      Transform<T>(), got).ok());
  EXPECT_TRUE(got);
  ASSERT_TRUE(overlap(Geometry<T>(CapsuleGeometry<T>(T(0.25), T(1))), Transform<T>(Vec3<T>(0, T(1.25), 0)), mesh,
                      Transform<T>(), got).ok());
  EXPECT_TRUE(got);  // the capsule's side touches the quad's edge y = 1
  ASSERT_TRUE(overlap(Geometry<T>(SphereGeometry<T>(T(0.5))), Transform<T>(Vec3<T>(0, 0, T(0.5) * (1 + 4 * std::numeric_limits<T>::epsilon()) + T(1e-3))), mesh, Transform<T>(), got).ok());
  EXPECT_FALSE(got);
}

// Bunny vs bunny: candidate triangle pairs by AABB (a uniform grid over b's triangle boxes), exact LD test.
inline bool bruteForceMeshMesh(const std::vector<TriL>& a, const std::vector<TriL>& b) {
  if (a.empty() || b.empty()) return false;
  auto boxOf = [](const TriL& t, Vec3L& lo, Vec3L& hi) {
    lo = t[0].cwiseMin(t[1]).cwiseMin(t[2]);
    hi = t[0].cwiseMax(t[1]).cwiseMax(t[2]);
  };
  Vec3L origin = Vec3L::Constant(std::numeric_limits<LD>::infinity());
  LD widest = 0;
  for (const auto& t : b) {
    Vec3L lo, hi;
    boxOf(t, lo, hi);
    origin = origin.cwiseMin(lo);
    widest = std::max(widest, (hi - lo).maxCoeff());
  }
  const LD cell = std::max<LD>(widest, 1e-9L);
  auto key = [&](const Vec3L& p, int k) { return long(std::floor((p[k] - origin[k]) / cell)); };
  std::map<std::array<long, 3>, std::vector<std::size_t>> grid;
  for (std::size_t j = 0; j < b.size(); ++j) {
    Vec3L lo, hi;
    boxOf(b[j], lo, hi);
    grid[{key(lo, 0), key(lo, 1), key(lo, 2)}].push_back(j);  // a box no wider than a cell: lo's cell and the next
  }
  for (const auto& ta : a) {
    Vec3L lo, hi;
    boxOf(ta, lo, hi);
    for (long x = key(lo, 0) - 1; x <= key(hi, 0); ++x)
      for (long y = key(lo, 1) - 1; y <= key(hi, 1); ++y)
        for (long z = key(lo, 2) - 1; z <= key(hi, 2); ++z) {
          const auto it = grid.find({x, y, z});
          if (it == grid.end()) continue;
          for (std::size_t j : it->second)
            if (boxesOverlap(b[j], lo, hi) && trianglesIntersect(ta, b[j])) return true;
        }
  }
  return false;
}

TYPED_TEST(MeshOverlapData, BunnyVsBunnyMatchesBruteForceOverAabbFilteredTrianglePairs) {
  using T = TypeParam;
  GQ_REQUIRE_BUNNY();
  const MeshData<T> bunny = meshtest::bunny<T>();
  Bounds3<double> bb;
  for (const auto& v : bunny.vertices) bb.include(v.template cast<double>());
  MeshData<T> centred = bunny;
  for (auto& v : centred.vertices) v -= bb.center().template cast<T>();
  const auto cooked = meshtest::cook(centred.vertices, centred.triangles);
  const Geometry<T> mesh = TriangleMeshGeometry<T>(cooked);
  const std::vector<TriL> a = worldTriangles(centred, MeshScale<T>(), Transform<T>());
  // Keep only the part of A near B's bounds per pose (B's box), so the sweep stays small.
  test::Rng rng(21);
  int overlaps = 0;
  const int poses = 1000;
  for (int i = 0; i < poses; ++i) {
    const Transform<T> pose = rng.pose<T>(0.12);
    const std::vector<TriL> b = worldTriangles(centred, MeshScale<T>(), pose);
    Vec3L lo = Vec3L::Constant(1e30L), hi = -lo;
    for (const auto& t : b)
      for (const auto& v : t) { lo = lo.cwiseMin(v); hi = hi.cwiseMax(v); }
    std::vector<TriL> nearA;
    for (const auto& t : a)
      if (boxesOverlap(t, lo, hi)) nearA.push_back(t);
    Vec3L loA = Vec3L::Constant(1e30L), hiA = -loA;
    for (const auto& t : nearA)
      for (const auto& v : t) { loA = loA.cwiseMin(v); hiA = hiA.cwiseMax(v); }
    std::vector<TriL> nearB;
    for (const auto& t : b)
      if (boxesOverlap(t, loA, hiA)) nearB.push_back(t);
    const bool expected = bruteForceMeshMesh(nearA, nearB);
    bool got = !expected;
    ASSERT_TRUE(overlap(mesh, Transform<T>(), mesh, pose, got).ok());
    ASSERT_EQ(got, expected) << "pose " << i;
    overlaps += expected;
  }
  EXPECT_GT(overlaps, poses / 10);
  EXPECT_LT(overlaps, poses - poses / 10);
}

// ---- Heightfields ----------------------------------------------------------------------------------------------
template <class T> HeightFieldDesc<T> bumpyDesc(std::uint32_t rows, std::uint32_t columns, std::uint64_t seed) {
  test::Rng rng(seed);
  HeightFieldDesc<T> d;
  d.rows = rows;
  d.columns = columns;
  for (std::uint32_t r = 0; r < rows; ++r)
    for (std::uint32_t c = 0; c < columns; ++c) d.heights.push_back(T(0.8 * std::sin(0.7 * r) * std::cos(0.5 * c) + rng.uniform(-0.2, 0.2)));
  for (std::uint32_t cell = 0; cell < (rows - 1) * (columns - 1); cell += 7) d.holes.push_back(cell);
  return d;
}

template <class T> class HeightFieldOverlap : public ::testing::Test {};
TYPED_TEST_SUITE(HeightFieldOverlap, test::Scalars);

TYPED_TEST(HeightFieldOverlap, ShapesMatchBruteForceOverAllCells) {
  using T = TypeParam;
  const HeightFieldDesc<T> desc = bumpyDesc<T>(12, 10, 3);
  std::shared_ptr<const HeightField<T>> field;
  ASSERT_TRUE(cookHeightField(desc, field).ok());
  const T hs = T(1.5), rs = T(0.5), cs = T(0.6);
  const Transform<T> fieldPose(Vec3<T>(T(-2.5), T(0.3), T(-2.5)), Quat<T>(Eigen::AngleAxis<T>(T(0.3), Vec3<T>::UnitZ())));
  const Geometry<T> hf = HeightFieldGeometry<T>(field, hs, rs, cs);
  std::vector<bool> valid;
  const std::vector<TriL> tris = heightFieldTriangles(desc, hs, rs, cs, fieldPose, valid);
  const auto hull = octahedron<T>(T(0.5), T(0.3), T(0.7));
  test::Rng rng(5);
  int ambiguous = 0, overlaps = 0, total = 0;
  for (int kind = 0; kind < 4; ++kind)
    for (int i = 0; i < 1000; ++i) {
      ShapeCase<T> s = randomShape<T>(rng, kind, 2.0, 0.6, hull);
      const Reference ref = bruteForce(s, tris, &valid, ambiguityBand<T>() * 4);
      bool got = false;
      ASSERT_TRUE(overlap(s.geom, s.pose, hf, fieldPose, got).ok());
      ++total;
      if (ref.ambiguous) { ++ambiguous; continue; }
      overlaps += ref.overlap;
      ASSERT_EQ(got, ref.overlap) << "kind " << kind << " pose " << i;
    }
  EXPECT_LT(ambiguous, total / 50);
  EXPECT_GT(overlaps, total / 10);
  EXPECT_LT(overlaps, total - total / 10);
}

TYPED_TEST(HeightFieldOverlap, MeshVsHeightFieldMatchesBruteForceOverTrianglePairs) {
  using T = TypeParam;
  const HeightFieldDesc<T> desc = bumpyDesc<T>(9, 9, 4);
  std::shared_ptr<const HeightField<T>> field;
  ASSERT_TRUE(cookHeightField(desc, field).ok());
  const Geometry<T> hf = HeightFieldGeometry<T>(field, T(1), T(0.5), T(0.5));
  std::vector<bool> valid;
  const Transform<T> fieldPose(Vec3<T>(T(-2), T(0), T(-2)));
  const std::vector<TriL> ftris = heightFieldTriangles(desc, T(1), T(0.5), T(0.5), fieldPose, valid);
  const MeshData<T> sphere = meshtest::icosphere<T>(1);
  const Geometry<T> mesh = TriangleMeshGeometry<T>(meshtest::cook(sphere.vertices, sphere.triangles), MeshScale<T>(T(0.6)));
  test::Rng rng(8);
  int overlaps = 0;
  for (int i = 0; i < 1000; ++i) {
    const double x = rng.uniform(-1.5, 1.5), y = rng.uniform(-1.2, 1.2), z = rng.uniform(-1.5, 1.5);
    const Transform<T> pose(Vec3<T>(T(x), T(y), T(z)), rng.rotation<T>());
    const std::vector<TriL> mtris = worldTriangles(sphere, MeshScale<T>(T(0.6)), pose);
    bool expected = false;
    for (const auto& m : mtris)
      for (std::size_t k = 0; k < ftris.size() && !expected; ++k)
        if (valid[k] && trianglesIntersect(m, ftris[k])) expected = true;
    bool got = !expected, swappedGot = !expected;
    ASSERT_TRUE(overlap(mesh, pose, hf, fieldPose, got).ok());
    ASSERT_TRUE(overlap(hf, fieldPose, mesh, pose, swappedGot).ok());
    ASSERT_EQ(got, expected) << "pose " << i;
    ASSERT_EQ(swappedGot, expected) << "pose " << i;
    overlaps += expected;
  }
  EXPECT_GT(overlaps, 100);
  EXPECT_LT(overlaps, 900);
}

TYPED_TEST(HeightFieldOverlap, HeightFieldVsHeightFieldCrossingAndApart) {
  using T = TypeParam;
  HeightFieldDesc<T> flat;
  flat.rows = flat.columns = 3;
  flat.heights.assign(9, T(0));
  std::shared_ptr<const HeightField<T>> field;
  ASSERT_TRUE(cookHeightField(flat, field).ok());
  const Geometry<T> hf = HeightFieldGeometry<T>(field, T(1), T(1), T(1));
  // A flat 2x2 field in y = 0 and a copy stood up (rotated 90 degrees about X: it spans y in [t-2, t]) crossing
  // it at t = 1, then entirely below it at t = -0.25.
  const Quat<T> up(Eigen::AngleAxis<T>(T(EIGEN_PI / 2), Vec3<T>::UnitX()));
  bool got = false;
  ASSERT_TRUE(overlap(hf, Transform<T>(), hf, Transform<T>(Vec3<T>(T(0.5), T(1), T(1)), up), got).ok());
  EXPECT_TRUE(got);
  ASSERT_TRUE(overlap(hf, Transform<T>(), hf, Transform<T>(Vec3<T>(T(0.5), T(-0.25), T(1)), up), got).ok());
  EXPECT_FALSE(got);
}

// Two bumpy fields, both unrotated and apart by a translation: the pair's frame leaves one of them at a pure
// translation, where a field's vertices are moved without a rotation product (HeightFieldSurface). Brute force over
// the triangle pairs decides.
TYPED_TEST(HeightFieldOverlap, TranslatedUnrotatedHeightFieldsMatchBruteForce) {
  using T = TypeParam;
  const HeightFieldDesc<T> descA = bumpyDesc<T>(6, 6, 9), descB = bumpyDesc<T>(5, 7, 10);
  std::shared_ptr<const HeightField<T>> fieldA, fieldB;
  ASSERT_TRUE(cookHeightField(descA, fieldA).ok());
  ASSERT_TRUE(cookHeightField(descB, fieldB).ok());
  const Geometry<T> a = HeightFieldGeometry<T>(fieldA, T(1), T(0.5), T(0.5));
  const Geometry<T> b = HeightFieldGeometry<T>(fieldB, T(0.8), T(0.4), T(0.6));
  const Transform<T> poseA(Vec3<T>(T(1.5), T(-0.5), T(2)));
  std::vector<bool> validA, validB;
  const std::vector<TriL> trisA = heightFieldTriangles(descA, T(1), T(0.5), T(0.5), poseA, validA);
  test::Rng rng(11);
  int overlaps = 0;
  for (int i = 0; i < 300; ++i) {
    const Transform<T> poseB(Vec3<T>(T(rng.uniform(-0.5, 3.5)), T(rng.uniform(-1.5, 0.5)), T(rng.uniform(0, 4))));
    const std::vector<TriL> trisB = heightFieldTriangles(descB, T(0.8), T(0.4), T(0.6), poseB, validB);
    bool expected = false;
    for (std::size_t j = 0; j < trisA.size() && !expected; ++j)
      for (std::size_t k = 0; k < trisB.size() && !expected; ++k)
        if (validA[j] && validB[k] && trianglesIntersect(trisA[j], trisB[k])) expected = true;
    bool got = !expected;
    ASSERT_TRUE(overlap(a, poseA, b, poseB, got).ok());
    ASSERT_EQ(got, expected) << "pose " << i;
    overlaps += expected;
  }
  EXPECT_GT(overlaps, 30);
  EXPECT_LT(overlaps, 270);
}

}  // namespace
}  // namespace gq::meshpairs
