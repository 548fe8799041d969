// Raycasts against sphere, plane, capsule, box, convex and custom geometry: every rule of the spec's Raycasts
// section for these shapes, and seeded random rays against independent long-double closed forms.
#include <gtest/gtest.h>

#include <functional>
#include <limits>
#include <optional>

#include "gq/cooking.h"
#include "gq/custom.h"
#include "gq/query.h"
#include "test_util.h"

namespace gq {
namespace {

using test::LD;
using test::Mat3L;
using test::Vec3L;

template <class T> std::shared_ptr<const ConvexMesh<T>> cookBox(const Vec3<T>& h) {
  std::vector<Vec3<T>> pts;
  for (int i = 0; i < 8; ++i)
    pts.emplace_back((i & 1) ? h.x() : -h.x(), (i & 2) ? h.y() : -h.y(), (i & 4) ? h.z() : -h.z());
  std::shared_ptr<const ConvexMesh<T>> mesh;
  EXPECT_TRUE(cookConvexMesh(pts, mesh).ok());
  return mesh;
}

// A custom shape: a sphere of `radius` about its local origin, answering raycasts in the local frame.
template <class T> class CustomSphere : public CustomGeometryCallbacks<T> {
 public:
  explicit CustomSphere(T r) : r_(r) {}
  const char* name() const override { return "custom-sphere"; }
  Bounds3<T> localBounds() const override { return Bounds3<T>::fromCenterExtents(Vec3<T>::Zero(), Vec3<T>::Constant(r_)); }
  Vec3<T> support(const Vec3<T>& d) const override { return d.normalized() * r_; }
  bool raycast(const Vec3<T>& o, const Vec3<T>& d, T maxDist, HitFlags, RaycastHit<T>& hit) const override {
    const T b = o.dot(d), c = o.squaredNorm() - r_ * r_;
    if (c <= 0) {
      hit.distance = 0;
      hit.position = o;
      hit.normal = -d;
      hit.flags = HitFlag::Position | HitFlag::Normal;
      return true;
    }
    const T disc = b * b - c;
    if (b >= 0 || disc < 0) return false;
    const T t = -b - std::sqrt(disc);
    if (t > maxDist) return false;
    hit.distance = t;
    hit.position = o + t * d;
    hit.normal = hit.position / r_;
    hit.flags = HitFlag::Position | HitFlag::Normal;
    return true;
  }

 private:
  T r_;
};

template <class T> struct Shapes {
  Transform<T> pose = Transform<T>(Vec3<T>(T(1), T(-2), T(0.5)), Quat<T>(Eigen::AngleAxis<T>(T(0.7), Vec3<T>(1, 2, 3).normalized())));
  std::vector<Geometry<T>> solids() const {
    return {SphereGeometry<T>(T(1.5)), CapsuleGeometry<T>(T(0.5), T(1.25)), BoxGeometry<T>(T(1), T(0.5), T(2)),
            ConvexMeshGeometry<T>(cookBox<T>(Vec3<T>(T(1), T(0.75), T(0.5))),
                                  MeshScale<T>(Vec3<T>(T(2), T(1), T(0.5)), Quat<T>(Eigen::AngleAxis<T>(T(0.4), Vec3<T>::UnitZ())))),
            CustomGeometry<T>(std::make_shared<CustomSphere<T>>(T(1.5)))};
  }
};

template <class T> struct Ray {
  Status status;
  std::uint32_t count = 0;
  RaycastHit<T> hit;
};

template <class T>
Ray<T> cast(const Vec3<T>& o, const Vec3<T>& d, const Geometry<T>& g, const Transform<T>& pose,
            T maxDist = std::numeric_limits<T>::infinity(), HitFlags flags = kDefaultHitFlags, std::uint32_t maxHits = 1) {
  Ray<T> r;
  RaycastHit<T> hits[4];
  hits[0].position = hits[0].normal = Vec3<T>::Constant(T(-777));  // sentinel: untouched fields keep it
  r.status = raycast(o, d, g, pose, maxDist, flags, maxHits, hits, r.count);
  r.hit = hits[0];
  return r;
}

template <class T> class Raycast : public ::testing::Test {};
TYPED_TEST_SUITE(Raycast, test::Scalars);

TYPED_TEST(Raycast, RayStartingInsideSolidReportsZeroDistance) {
  using T = TypeParam;
  Shapes<T> s;
  const Vec3<T> dir = Vec3<T>(1, -1, 2).normalized();
  for (const Geometry<T>& g : s.solids()) {
    const Vec3<T> origin = s.pose.transform(Vec3<T>(T(0.1), T(0.05), T(-0.1)));
    for (HitFlags flags : {kDefaultHitFlags, HitFlags()}) {
      const Ray<T> r = cast<T>(origin, dir, g, s.pose, T(10), flags);
      ASSERT_TRUE(r.status.ok()) << toString(g.type());
      ASSERT_EQ(r.count, 1u) << toString(g.type());
      EXPECT_EQ(r.hit.distance, T(0));
      EXPECT_TRUE(r.hit.flags.has(HitFlag::Position) && r.hit.flags.has(HitFlag::Normal)) << toString(g.type());
      EXPECT_EQ(r.hit.position, origin);
      EXPECT_LT((r.hit.normal + dir).norm(), T(1e-5)) << toString(g.type());
    }
  }
}

TYPED_TEST(Raycast, MaxDistZeroHitsOnlyWhenOriginInside) {
  using T = TypeParam;
  Shapes<T> s;
  const Vec3<T> dir = s.pose.rotate(Vec3<T>(-1, 0, 0));
  for (const Geometry<T>& g : s.solids()) {
    const Ray<T> inside = cast<T>(s.pose.p, dir, g, s.pose, T(0));
    EXPECT_EQ(inside.count, 1u) << toString(g.type());
    const Ray<T> outside = cast<T>(s.pose.transform(Vec3<T>(10, 0, 0)), dir, g, s.pose, T(0));
    EXPECT_EQ(outside.count, 0u) << toString(g.type());
    const Ray<T> far = cast<T>(s.pose.transform(Vec3<T>(10, 0, 0)), dir, g, s.pose, T(5));
    EXPECT_EQ(far.count, 0u) << toString(g.type()) << " hit beyond maxDist";
    const Ray<T> reach = cast<T>(s.pose.transform(Vec3<T>(10, 0, 0)), dir, g, s.pose, T(9.5));
    EXPECT_EQ(reach.count, 1u) << toString(g.type());
  }
}

TYPED_TEST(Raycast, NegativeOrNanMaxDistIsRejected) {
  using T = TypeParam;
  Shapes<T> s;
  for (T bad : {T(-1), std::numeric_limits<T>::quiet_NaN()}) {
    const Ray<T> r = cast<T>(Vec3<T>(10, 0, 0), Vec3<T>(-1, 0, 0), SphereGeometry<T>(T(1)), Transform<T>(), bad);
    EXPECT_EQ(r.status.code, StatusCode::InvalidArgument);
    EXPECT_EQ(r.hit.position, Vec3<T>::Constant(T(-777)));
  }
}

TYPED_TEST(Raycast, SolidsReportAtMostOneHit) {
  using T = TypeParam;
  Shapes<T> s;
  for (const Geometry<T>& g : s.solids()) {
    const Ray<T> r = cast<T>(s.pose.transform(Vec3<T>(0, 0, -20)), s.pose.rotate(Vec3<T>::UnitZ()), g, s.pose,
                             T(100), kDefaultHitFlags | HitFlag::MeshMultiple | HitFlag::MeshBothSides, 4);
    EXPECT_EQ(r.count, 1u) << toString(g.type());
  }
}

TYPED_TEST(Raycast, PlaneIsSingleSidedAndOriginBehindGivesNoHit) {
  using T = TypeParam;
  const Transform<T> pose(Vec3<T>(0, 1, 0), Quat<T>(Eigen::AngleAxis<T>(T(0.3), Vec3<T>::UnitY())));
  const Vec3<T> n = pose.rotate(Vec3<T>::UnitX());
  // Behind, moving towards and through the plane: no hit.
  EXPECT_EQ(cast<T>(pose.p - 2 * n, n, PlaneGeometry<T>(), pose).count, 0u);
  // In front, moving towards it: hit at distance 2 with the plane normal.
  const Ray<T> front = cast<T>(pose.p + 2 * n, -n, PlaneGeometry<T>(), pose);
  ASSERT_EQ(front.count, 1u);
  EXPECT_NEAR(front.hit.distance, T(2), T(1e-5));
  EXPECT_LT((front.hit.normal - n).norm(), T(1e-5));
  EXPECT_LT((front.hit.position - pose.p).norm(), T(1e-5));
  EXPECT_EQ(front.hit.faceIndex, kInvalidFaceIndex);
  // In front, moving away or parallel: no hit.
  EXPECT_EQ(cast<T>(pose.p + 2 * n, n, PlaneGeometry<T>(), pose).count, 0u);
  EXPECT_EQ(cast<T>(pose.p + 2 * n, pose.rotate(Vec3<T>::UnitY()), PlaneGeometry<T>(), pose).count, 0u);
}

TYPED_TEST(Raycast, PlaneIncludesItsBoundary) {
  using T = TypeParam;
  const Transform<T> pose(Vec3<T>(3, 0, 0));
  const Ray<T> on = cast<T>(Vec3<T>(3, 5, -2), Vec3<T>(0, 1, 0), PlaneGeometry<T>(), pose, T(0));
  ASSERT_EQ(on.count, 1u);
  EXPECT_EQ(on.hit.distance, T(0));
  EXPECT_EQ(on.hit.position, Vec3<T>(3, 5, -2));
}

TYPED_TEST(Raycast, FaceIndexIsPolygonIndexForConvexAndInvalidOtherwise) {
  using T = TypeParam;
  Shapes<T> s;
  const auto hull = cookBox<T>(Vec3<T>(1, 1, 1));
  const Geometry<T> convex = ConvexMeshGeometry<T>(hull);
  for (int axis = 0; axis < 3; ++axis) {
    for (T sign : {T(-1), T(1)}) {
      Vec3<T> n = Vec3<T>::Zero();
      n[axis] = sign;
      Vec3<T> offset(T(0.1), T(0.2), T(0.3));
      offset[axis] = T(0);
      const Ray<T> r = cast<T>(Vec3<T>(5 * n + offset), -n, convex, Transform<T>());
      ASSERT_EQ(r.count, 1u);
      ASSERT_TRUE(r.hit.flags.has(HitFlag::FaceIndex));
      ASSERT_LT(r.hit.faceIndex, hull->polygons.size());
      EXPECT_LT((hull->polygons[r.hit.faceIndex].normal - n).norm(), T(1e-6));
      EXPECT_LT((r.hit.normal - n).norm(), T(1e-6));
      EXPECT_NEAR(r.hit.distance, T(4), T(1e-5));
    }
  }
  for (const Geometry<T>& g : s.solids()) {
    if (g.type() == GeometryType::ConvexMesh) continue;
    const Ray<T> r = cast<T>(s.pose.transform(Vec3<T>(0, 0, -20)), s.pose.rotate(Vec3<T>::UnitZ()), g, s.pose);
    ASSERT_EQ(r.count, 1u);
    EXPECT_EQ(r.hit.faceIndex, kInvalidFaceIndex) << toString(g.type());
  }
}

TYPED_TEST(Raycast, HitFlagsSayWhichFieldsAreValidAndOmittedFieldsAreSkipped) {
  using T = TypeParam;
  Shapes<T> s;
  std::vector<Geometry<T>> shapes = s.solids();
  shapes.push_back(PlaneGeometry<T>());
  for (const Geometry<T>& g : shapes) {
    const Vec3<T> origin = s.pose.transform(Vec3<T>(20, T(0.1), T(0.1)));
    const Vec3<T> dir = s.pose.rotate(Vec3<T>(-1, 0, 0));
    const Ray<T> none = cast<T>(origin, dir, g, s.pose, T(100), HitFlags());
    ASSERT_EQ(none.count, 1u) << toString(g.type());
    EXPECT_FALSE(none.hit.flags.has(HitFlag::Position) || none.hit.flags.has(HitFlag::Normal)) << toString(g.type());
    EXPECT_EQ(none.hit.position, Vec3<T>::Constant(T(-777))) << toString(g.type());
    EXPECT_EQ(none.hit.normal, Vec3<T>::Constant(T(-777))) << toString(g.type());
    const Ray<T> pos = cast<T>(origin, dir, g, s.pose, T(100), HitFlag::Position);
    EXPECT_TRUE(pos.hit.flags.has(HitFlag::Position));
    EXPECT_FALSE(pos.hit.flags.has(HitFlag::Normal));
    EXPECT_LT((pos.hit.position - (origin + pos.hit.distance * dir)).norm(), T(1e-4));
    EXPECT_EQ(pos.hit.normal, Vec3<T>::Constant(T(-777)));
    EXPECT_EQ(pos.hit.distance, none.hit.distance);
  }
}

TYPED_TEST(Raycast, UvIsNeverSetForTheseShapes) {
  using T = TypeParam;
  Shapes<T> s;
  std::vector<Geometry<T>> shapes = s.solids();
  shapes.push_back(PlaneGeometry<T>());
  for (const Geometry<T>& g : shapes) {
    const Ray<T> r = cast<T>(s.pose.transform(Vec3<T>(20, 0, 0)), s.pose.rotate(Vec3<T>(-1, 0, 0)), g, s.pose,
                             T(100), kDefaultHitFlags | HitFlag::UV);
    ASSERT_EQ(r.count, 1u);
    EXPECT_FALSE(r.hit.flags.has(HitFlag::UV)) << toString(g.type());
  }
}

TYPED_TEST(Raycast, ScaledConvexNormalIsPerpendicularToTheScaledFace) {
  using T = TypeParam;
  // A unit cube scaled by (3, 1, 1) along axes rotated 30 degrees about Z is a slanted prism: the face normals are
  // S^-T n, not S n.
  const auto hull = cookBox<T>(Vec3<T>(1, 1, 1));
  const MeshScale<T> scale(Vec3<T>(3, 1, 1), Quat<T>(Eigen::AngleAxis<T>(T(M_PI / 6), Vec3<T>::UnitZ())));
  const Geometry<T> g = ConvexMeshGeometry<T>(hull, scale);
  const Ray<T> r = cast<T>(Vec3<T>(10, T(0.05), 0), Vec3<T>(-1, 0, 0), g, Transform<T>());
  ASSERT_EQ(r.count, 1u);
  const HullPolygon<T>& face = hull->polygons[r.hit.faceIndex];
  const Mat3<T> S = scale.toMatrix();
  for (std::uint32_t k = 0; k < face.indexCount; ++k) {
    const Vec3<T> a = S * hull->vertices[hull->polygonVertices[face.indexBase + k]];
    const Vec3<T> b = S * hull->vertices[hull->polygonVertices[face.indexBase + (k + 1) % face.indexCount]];
    EXPECT_NEAR(r.hit.normal.dot((b - a).normalized()), T(0), T(1e-5));
  }
  EXPECT_NEAR(r.hit.normal.norm(), T(1), T(1e-5));
  EXPECT_GT(r.hit.normal.x(), T(0));
}

TYPED_TEST(Raycast, CustomGeometryHitIsTransformedBackToWorld) {
  using T = TypeParam;
  Shapes<T> s;
  const Geometry<T> custom = CustomGeometry<T>(std::make_shared<CustomSphere<T>>(T(1.5)));
  const Geometry<T> sphere = SphereGeometry<T>(T(1.5));
  const Vec3<T> origin = s.pose.p + Vec3<T>(7, 1, -1);
  const Vec3<T> dir = (s.pose.p - origin).normalized();
  const Ray<T> a = cast<T>(origin, dir, custom, s.pose), b = cast<T>(origin, dir, sphere, s.pose);
  ASSERT_EQ(a.count, 1u);
  ASSERT_EQ(b.count, 1u);
  EXPECT_NEAR(a.hit.distance, b.hit.distance, T(1e-4));
  EXPECT_LT((a.hit.position - b.hit.position).norm(), T(1e-4));
  EXPECT_LT((a.hit.normal - b.hit.normal).norm(), T(1e-4));
  EXPECT_EQ(a.hit.faceIndex, kInvalidFaceIndex);
}

TYPED_TEST(Raycast, FarAwaySphereRaysKeepPrecision) {
  using T = TypeParam;
  const T far = std::is_same_v<T, float> ? T(1e4) : T(1e7);
  // Aimed 0.6 off-centre at a unit sphere: exact distance far - 0.8.
  const Ray<T> r = cast<T>(Vec3<T>(far, T(0.6), 0), Vec3<T>(-1, 0, 0), SphereGeometry<T>(T(1)), Transform<T>());
  ASSERT_EQ(r.count, 1u);
  EXPECT_NEAR(double(r.hit.distance), double(far) - 0.8, test::Tol<T>::kRel * double(far));
  EXPECT_LT((r.hit.normal - Vec3<T>(T(0.8), T(0.6), 0)).norm(), T(1e-3));
}

// ---- Seeded random rays against long-double closed forms ---------------------------------------------------
// A reference answers, for a ray in world space, the entry distance into the shape grown by `grow` (negative
// shrinks), or nothing. Rays whose answer changes between the shape grown and shrunk by a small margin are
// grazing (ill-conditioned); only their existence is not compared.
using Reference = std::function<std::optional<LD>(const Vec3L& o, const Vec3L& d, LD grow)>;
// The error of a reported unit normal at an exact surface point (world), given the tolerance used to decide which
// faces the point lies on; 0 when exact.
using NormalError = std::function<LD(const Vec3L& position, const Vec3L& normal, LD onFace)>;

// Box faces |x_i| = h_i in a frame where x_frame = toFrame * (x - origin): the smallest error against the normal of
// any face the point is on; face normals are toFrame^T e_i (the inverse-transpose of the point map), normalised.
LD boxFaceNormalError(const Mat3L& toFrame, const Vec3L& origin, const Vec3L& h, const Vec3L& position,
                      const Vec3L& normal, LD onFace) {
  const Vec3L x = toFrame * (position - origin);
  LD best = std::numeric_limits<LD>::infinity();
  for (int i = 0; i < 3; ++i) {
    for (int sign : {-1, 1}) {
      if (std::abs(x[i] - sign * h[i]) > onFace) continue;
      const Vec3L n = (toFrame.transpose() * Vec3L::Unit(i) * LD(sign)).normalized();
      best = std::min(best, (n - normal).norm());
    }
  }
  return best;
}

std::optional<LD> sphereEntryLD(const Vec3L& m, const Vec3L& d, LD r) {
  const LD a = d.squaredNorm(), b = m.dot(d), c = m.squaredNorm() - r * r;
  if (c <= 0) return LD(0);
  const LD disc = b * b - a * c;
  if (b >= 0 || disc < 0) return std::nullopt;
  return (-b - std::sqrt(disc)) / a;
}

// Slab test against the box |x_i| <= h_i (in the frame of o, d).
std::optional<LD> boxEntryLD(const Vec3L& o, const Vec3L& d, const Vec3L& h) {
  LD t0 = 0, t1 = std::numeric_limits<LD>::infinity();
  for (int i = 0; i < 3; ++i) {
    if (d[i] == 0) {
      if (std::abs(o[i]) > h[i]) return std::nullopt;
      continue;
    }
    LD a = (-h[i] - o[i]) / d[i], b = (h[i] - o[i]) / d[i];
    if (a > b) std::swap(a, b);
    t0 = std::max(t0, a);
    t1 = std::min(t1, b);
  }
  if (t0 > t1) return std::nullopt;
  return t0;
}

template <class T> Vec3L toLocal(const Transform<T>& pose, const Vec3L& p) {
  return test::rotationLD(pose.q).transpose() * (p - test::toLD(pose.p));
}

template <class T>
void checkRandomRays(const Geometry<T>& g, const Transform<T>& pose, double size, const Reference& ref,
                     const NormalError& normalError, std::uint64_t seed) {
  test::Rng rng(seed);
  int compared = 0, hits = 0, inside = 0;
  for (int i = 0; i < 10000; ++i) {
    Vec3<T> origin;
    if (rng.chance(0.15)) {  // far away
      const Vec3<T> away = rng.unitVector<T>();
      origin = pose.p + away * T(size * rng.uniform(50, 5000));
    } else {
      origin = pose.p + rng.inBox<T>(3 * size);
    }
    Vec3<T> dir = rng.chance(0.1) ? rng.unitVector<T>()
                                  : Vec3<T>((pose.p + rng.inBox<T>(1.2 * size) - origin).normalized());
    if (!(dir.norm() > 0)) continue;
    const Ray<T> r = cast<T>(origin, dir, g, pose);
    ASSERT_TRUE(r.status.ok()) << r.status.toString();
    const Vec3L o = test::toLD(origin), d = test::toLD(dir);
    const LD margin = LD(std::is_same_v<T, float> ? 1e-3 : 1e-6) * LD(size);
    const auto exact = ref(o, d, 0), grown = ref(o, d, margin), shrunk = ref(o, d, -margin);
    if (grown.has_value() != shrunk.has_value()) continue;  // grazing
    ++compared;
    ASSERT_EQ(r.count, exact.has_value() ? 1u : 0u) << "ray " << i << " origin " << origin.transpose() << " dir "
                                                     << dir.transpose() << " exact " << double(exact.value_or(-1))
                                                     << " got " << r.hit.distance;
    if (!exact) continue;
    ++hits;
    if (*exact == 0) ++inside;
    const double scale = std::max({double(size), double(*exact), double((o - test::toLD(pose.p)).norm())});
    ASSERT_NEAR(double(r.hit.distance), double(*exact), test::Tol<T>::kRel * scale) << "ray " << i;
    const Vec3L position = o + *exact * d;
    ASSERT_LT(double((test::toLD(r.hit.position) - position).norm()), test::Tol<T>::kRel * scale * 2) << "ray " << i;
    if (*exact > 0) {  // from outside: the surface normal at the exact hit point (inside hits are -dir, tested apart)
      const LD onFace = LD(test::Tol<T>::kRel * scale * 2);
      ASSERT_LT(double(normalError(position, test::toLD(r.hit.normal), onFace)), 10 * test::Tol<T>::kRel * scale / size)
          << "ray " << i << " normal " << r.hit.normal.transpose();
    }
  }
  EXPECT_GT(compared, 9000);
  EXPECT_GT(hits, 1000);
  EXPECT_GT(inside, 10);
}

TYPED_TEST(Raycast, RandomRaysMatchClosedFormSphere) {
  using T = TypeParam;
  test::Rng rng(11);
  for (int shape = 0; shape < 2; ++shape) {
    const T r = T(rng.uniform(0.2, 3));
    const Transform<T> pose = rng.pose<T>(20);
    const Reference ref = [&](const Vec3L& o, const Vec3L& d, LD grow) {
      return sphereEntryLD(o - test::toLD(pose.p), d, LD(r) + grow);
    };
    const NormalError normal = [&](const Vec3L& p, const Vec3L& n, LD) {
      return (n - (p - test::toLD(pose.p)) / LD(r)).norm();
    };
    checkRandomRays<T>(SphereGeometry<T>(r), pose, double(r), ref, normal, 100 + shape);
  }
}

TYPED_TEST(Raycast, RandomRaysMatchClosedFormCapsule) {
  using T = TypeParam;
  test::Rng rng(12);
  for (int shape = 0; shape < 2; ++shape) {
    const T r = T(rng.uniform(0.2, 1.5)), hh = T(rng.uniform(0.1, 2));
    const Transform<T> pose = rng.pose<T>(20);
    const Reference ref = [&](const Vec3L& ow, const Vec3L& dw, LD grow) -> std::optional<LD> {
      const Vec3L o = toLocal(pose, ow), d = test::rotationLD(pose.q).transpose() * dw;
      const LD rad = LD(r) + grow, h = LD(hh);
      const LD cx = std::clamp(o.x(), -h, h);
      if ((o - Vec3L(cx, 0, 0)).squaredNorm() <= rad * rad) return LD(0);
      std::optional<LD> best;
      auto take = [&](std::optional<LD> t) { if (t && (!best || *t < *best)) best = t; };
      take(sphereEntryLD(o - Vec3L(h, 0, 0), d, rad));
      take(sphereEntryLD(o + Vec3L(h, 0, 0), d, rad));
      // Side of the cylinder: a t^2 + 2 b t + c = 0 in (y, z).
      const LD a = d.y() * d.y() + d.z() * d.z(), b = o.y() * d.y() + o.z() * d.z();
      const LD c = o.y() * o.y() + o.z() * o.z() - rad * rad, disc = b * b - a * c;
      if (a > 0 && c > 0 && disc >= 0) {
        const LD t = (-b - std::sqrt(disc)) / a;
        if (t >= 0 && std::abs(o.x() + t * d.x()) <= h) take(t);
      }
      return best;
    };
    const NormalError normal = [&](const Vec3L& p, const Vec3L& n, LD) {
      const Vec3L local = toLocal(pose, p);
      const Vec3L axis(std::clamp(local.x(), -LD(hh), LD(hh)), 0, 0);
      return (n - test::rotationLD(pose.q) * (local - axis).normalized()).norm();
    };
    checkRandomRays<T>(CapsuleGeometry<T>(r, hh), pose, double(r + hh), ref, normal, 200 + shape);
  }
}

TYPED_TEST(Raycast, RandomRaysMatchClosedFormBox) {
  using T = TypeParam;
  test::Rng rng(13);
  for (int shape = 0; shape < 2; ++shape) {
    const Vec3<T> h = rng.vec<T>(0.2, 2);
    const Transform<T> pose = rng.pose<T>(20);
    const Reference ref = [&](const Vec3L& o, const Vec3L& d, LD grow) {
      return boxEntryLD(toLocal(pose, o), test::rotationLD(pose.q).transpose() * d,
                        test::toLD(h) + Vec3L::Constant(grow));
    };
    const NormalError normal = [&](const Vec3L& p, const Vec3L& n, LD onFace) {
      return boxFaceNormalError(test::rotationLD(pose.q).transpose(), test::toLD(pose.p), test::toLD(h), p, n, onFace);
    };
    checkRandomRays<T>(BoxGeometry<T>(h), pose, double(h.norm()), ref, normal, 300 + shape);
  }
}

TYPED_TEST(Raycast, RandomRaysMatchClosedFormScaledConvexBox) {
  using T = TypeParam;
  test::Rng rng(14);
  for (int shape = 0; shape < 2; ++shape) {
    const Vec3<T> h = rng.vec<T>(0.3, 1.5);
    const MeshScale<T> scale = rng.meshScale<T>(0.5, 2);
    const Transform<T> pose = rng.pose<T>(20);
    // In the hull frame: x_mesh = S^-1 x_shape, S = R diag(s) R^T, computed in long double. The shape grown by
    // `grow` is approximated by growing the unscaled box by grow / max(s): a margin, not an exact offset, which
    // is all the grazing test needs (exact answers use grow = 0).
    const Mat3L R = test::rotationLD(scale.rotation);
    const Mat3L Sinv = R * test::toLD(scale.scale).cwiseInverse().asDiagonal() * R.transpose();
    const LD smax = test::toLD(scale.scale).maxCoeff();
    const Reference ref = [&](const Vec3L& o, const Vec3L& d, LD grow) {
      const Mat3L toMesh = Sinv * test::rotationLD(pose.q).transpose();
      return boxEntryLD(toMesh * (o - test::toLD(pose.p)), toMesh * d, test::toLD(h) + Vec3L::Constant(grow / smax));
    };
    const NormalError normal = [&](const Vec3L& p, const Vec3L& n, LD onFace) {
      return boxFaceNormalError(Mat3L(Sinv * test::rotationLD(pose.q).transpose()), test::toLD(pose.p), test::toLD(h),
                                p, n, onFace);
    };
    checkRandomRays<T>(ConvexMeshGeometry<T>(cookBox<T>(h), scale), pose, double(h.norm() * smax), ref, normal,
                       400 + shape);
  }
}

TYPED_TEST(Raycast, RandomRaysMatchClosedFormPlane) {
  using T = TypeParam;
  test::Rng rng(15);
  for (int shape = 0; shape < 2; ++shape) {
    const Transform<T> pose = rng.pose<T>(20);
    // Plane through p with normal R e_x; single-sided; `grow` moves it along its normal.
    const Reference ref = [&](const Vec3L& o, const Vec3L& d, LD grow) -> std::optional<LD> {
      const Vec3L n = test::rotationLD(pose.q).col(0);
      const LD s = n.dot(o - test::toLD(pose.p)) - grow;
      if (s < 0) return std::nullopt;
      if (s == 0) return LD(0);
      const LD approach = n.dot(d);
      if (approach >= 0) return std::nullopt;
      return -s / approach;
    };
    test::Rng rays(500 + shape);
    int hits = 0;
    for (int i = 0; i < 10000; ++i) {
      const Vec3<T> origin = pose.p + rays.inBox<T>(rays.chance(0.1) ? 5000 : 5);
      const Vec3<T> dir = rays.unitVector<T>();
      const Ray<T> r = cast<T>(origin, dir, PlaneGeometry<T>(), pose);
      const Vec3L o = test::toLD(origin), d = test::toLD(dir);
      const LD margin = LD(std::is_same_v<T, float> ? 1e-3 : 1e-7);
      const auto exact = ref(o, d, 0), a = ref(o, d, margin), b = ref(o, d, -margin);
      // Grazing: the ray crosses the plane within the margin, or runs so nearly parallel (|n.d| small) that the
      // distance s / |n.d| is ill-conditioned in the direction.
      if (a.has_value() != b.has_value()) continue;
      if (std::abs(test::rotationLD(pose.q).col(0).dot(d)) < LD(std::is_same_v<T, float> ? 1e-3 : 1e-6)) continue;
      ASSERT_EQ(r.count, exact.has_value() ? 1u : 0u) << "ray " << i;
      if (!exact) continue;
      ++hits;
      const double scale = std::max({1.0, double(*exact), double((o - test::toLD(pose.p)).norm())});
      ASSERT_NEAR(double(r.hit.distance), double(*exact), test::Tol<T>::kRel * scale) << "ray " << i;
    }
    EXPECT_GT(hits, 2000);
  }
}

}  // namespace
}  // namespace gq
