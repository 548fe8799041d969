// The sign conventions of gq/query.h checked against each other on seeded random poses, >= 1000 per pair of
// {sphere, capsule, box, convex hull, plane, cylinder, cone, triangle mesh, heightfield}, float and double, wherever
// two of overlap, computePenetration and distance answer the pair (the others return Unsupported and are skipped;
// every pair of two convex shapes must answer all three). Each pose draws which shape is geom0, so both orders run.
//
// Length tolerance per pair: tol = kFactor<T> * tol::Rel<T>::kEpsilon * size, size = the larger bounding radius of
// the two shapes; kFactor is 1e2 in float (tol = 1e-3 * size) and 1e6 in double (tol = 1e-6 * size), the accuracy of
// the GJK/EPA pairs (cylinder, cone) at these sizes; closed forms and SAT are far tighter.
//
// Convex pairs (both shapes solid and convex, plane included):
//  1. distance < 0 <=> penetrating, outside a band of tol around 0: distance > tol gives penetrating false and
//     overlap false; distance < -tol gives penetrating true and overlap true;
//  2. when penetrating, -distance == depth within tol;
//  3. moving geom0 by direction * (depth + tol) separates (overlap false), and by direction * (depth - tol) it still
//     overlaps (the depth is the one that separates, not just enough);
//  4. the distance normal is -direction: moving geom0 by -normal * (depth + tol) separates too; where the two
//     differ by more than rounding, the MTD is not unique, which check 4 proves harmless.
// Surface pairs (a triangle mesh or heightfield, a surface, not a solid: a shape inside a closed mesh does not
// overlap it), where distance is the unsigned surface distance and computePenetration the iterative push-out:
//  5. distance >= 0 (but against a plane); overlap <=> distance <= 0 outside the band;
//  6. overlap false => not penetrating; when penetrating, depth >= 0 and the direction is unit.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "gq/cooking.h"
#include "gq/custom_shapes.h"
#include "gq/query.h"
#include "gq/tolerances.h"
#include "mesh_test_helpers.h"
#include "test_util.h"

namespace gq::test {
namespace {

enum class Kind { Sphere, Capsule, Box, Hull, Plane, Cylinder, Cone, Mesh, HeightField };
constexpr Kind kKinds[] = {Kind::Sphere, Kind::Capsule,  Kind::Box,  Kind::Hull,       Kind::Plane,
                           Kind::Cylinder, Kind::Cone, Kind::Mesh, Kind::HeightField};
const char* kindName(Kind k) {
  static const char* names[] = {"sphere", "capsule", "box", "hull", "plane", "cylinder", "cone", "mesh", "heightfield"};
  return names[int(k)];
}
bool isSurface(Kind k) { return k == Kind::Mesh || k == Kind::HeightField; }

template <class T> constexpr double kFactor = std::is_same_v<T, float> ? 1e2 : 1e6;
template <class T> double relTol() { return kFactor<T> * double(tol::Rel<T>::kEpsilon); }
constexpr int kPosesPerPair = 1000;

template <class T> struct Shapes {
  std::shared_ptr<const ConvexMesh<T>> hull;
  std::shared_ptr<const TriangleMesh<T>> mesh;
  std::shared_ptr<const HeightField<T>> field;

  Shapes() {
    Rng rng(2718);
    std::vector<Vec3<T>> pts;
    for (int k = 0; k < 16; ++k) pts.push_back(rng.inBox<T>(0.7));
    EXPECT_TRUE(cookConvexMesh(pts, hull).ok());
    const MeshData<T> sphere = meshtest::icosphere<T>(1);
    mesh = meshtest::cook(sphere.vertices, sphere.triangles);
    HeightFieldDesc<T> desc;
    desc.rows = desc.columns = 7;
    for (std::uint32_t i = 0; i < desc.rows * desc.columns; ++i) desc.heights.push_back(T(rng.uniform(-0.3, 0.3)));
    EXPECT_TRUE(cookHeightField(desc, field).ok());
  }

  Geometry<T> make(Kind kind, Rng& rng) const {
    switch (kind) {
      case Kind::Sphere: return SphereGeometry<T>(T(rng.uniform(0.2, 1.0)));
      case Kind::Capsule: {
        const T radius = T(rng.uniform(0.1, 0.6));
        return CapsuleGeometry<T>(radius, T(rng.uniform(0, 1)));
      }
      case Kind::Box: return BoxGeometry<T>(rng.vec<T>(0.1, 1.0));
      case Kind::Hull: return ConvexMeshGeometry<T>(hull, rng.meshScale<T>(0.5, 1.5));
      case Kind::Plane: return PlaneGeometry<T>();
      case Kind::Cylinder: {
        const T radius = T(rng.uniform(0.1, 0.8));
        return CustomGeometry<T>(std::make_shared<CylinderCallbacks<T>>(radius, T(rng.uniform(0.1, 1.0))));
      }
      case Kind::Cone: {
        const T radius = T(rng.uniform(0.2, 0.8));
        return CustomGeometry<T>(std::make_shared<ConeCallbacks<T>>(radius, T(rng.uniform(0.2, 1.0))));
      }
      case Kind::Mesh: return TriangleMeshGeometry<T>(mesh, rng.meshScale<T>(0.6, 1.2));
      case Kind::HeightField: return HeightFieldGeometry<T>(field, T(1), T(0.4), T(0.4));
    }
    return SphereGeometry<T>(T(1));
  }
};

// Centre and bounding radius of a shape at `pose` (a plane: its origin and 0).
template <class T> void extent(const Geometry<T>& g, const Transform<T>& pose, Vec3<T>& centre, T& radius) {
  if (g.type() == GeometryType::Plane) {
    centre = pose.p;
    radius = T(0);
    return;
  }
  Bounds3<T> b;
  EXPECT_TRUE(computeGeomBounds(b, g, pose, T(0), T(1)).ok());
  centre = b.center();
  radius = b.extents().norm();
}

template <class T> Transform<T> moved(const Transform<T>& pose, const Vec3<T>& by) {
  return Transform<T>(Vec3<T>(pose.p + by), pose.q);
}

template <class T> std::string describe(std::uint64_t seed, int i, Kind k0, Kind k1, const Transform<T>& p0,
                                        const Transform<T>& p1) {
  std::ostringstream o;
  o.precision(17);
  o << kindName(k0) << " vs " << kindName(k1) << ", seed " << seed << ", pose " << i << ": pose0 p ("
    << p0.p.transpose() << ") q (" << p0.q.coeffs().transpose() << "), pose1 p (" << p1.p.transpose() << ") q ("
    << p1.q.coeffs().transpose() << ")";
  return o.str();
}

struct Counts {
  int answered = 0, penetrating = 0, separated = 0, banded = 0, failed = 0, unconverged = 0;
};

template <class T> std::string str(const Vec3<T>& v) {
  std::ostringstream o;
  o.precision(9);
  o << "(" << v.x() << ", " << v.y() << ", " << v.z() << ")";
  return o.str();
}

template <class T> Counts checkPair(const Shapes<T>& shapes, Kind a, Kind b, std::uint64_t seed) {
  Rng rng(seed);
  Counts counts;
  const bool surfacePair = isSurface(a) || isSurface(b);
  for (int i = 0; counts.answered < kPosesPerPair && i < 2 * kPosesPerPair; ++i) {
    const bool swap = rng.chance(0.5);
    const Kind k0 = swap ? b : a, k1 = swap ? a : b;
    const Geometry<T> g0 = shapes.make(k0, rng), g1 = shapes.make(k1, rng);
    const Transform<T> p1 = rng.pose<T>(1.0);
    // geom0's pose: around geom1's centre within reach of both, or across the plane.
    Transform<T> p0 = Transform<T>(Vec3<T>::Zero(), rng.rotation<T>());
    Vec3<T> c0, c1;
    T r0, r1;
    extent(g0, p0, c0, r0);
    extent(g1, p1, c1, r1);
    const T size = std::max({r0, r1, T(0.1)});
    if (k1 == Kind::Plane || k0 == Kind::Plane) {
      const Transform<T>& planePose = k1 == Kind::Plane ? p1 : p0;
      const Vec3<T> normal = planePose.q * Vec3<T>::UnitX();
      const Vec3<T> offset = normal * T(rng.uniform(-1.2, 1.2) * double(std::max(r0, r1))) + rng.inBox<T>(1.0);
      if (k1 == Kind::Plane) p0.p = p1.p + offset - c0;
      else p0.p = c1 - offset;  // the plane is geom0: geom1 sits on either side of it
    } else {
      const T reach = T(rng.uniform(0, 1.1)) * (r0 + r1);
      p0.p = c1 + rng.unitVector<T>() * reach - c0;
    }
    const T tol = T(relTol<T>()) * size;
    // Full report of the first few failures of the pair (seed, pose index, poses), a count of the rest.
    auto expect = [&](bool ok, auto what) {
      if (ok || ++counts.failed > 3) return;
      ADD_FAILURE() << describe(seed, i, k0, k1, p0, p1) << ": " << what();
    };

    bool overlapping = false;
    const Status so = overlap(g0, p0, g1, p1, overlapping);
    PenetrationResult<T> pen;
    const Status sp = computePenetration(pen, g0, p0, g1, p1);
    DistanceResult<T> dist;
    const Status sd = distance(dist, g0, p0, g1, p1);
    // NotConverged would be a refusal: penetration answers an EPA out of iterations with its upper bound under a
    // Warning, as distance does. Counted (and the pose replaced) so that the count can be required to be zero.
    if (so.code == StatusCode::NotConverged || sp.code == StatusCode::NotConverged ||
        sd.code == StatusCode::NotConverged) {
      ++counts.unconverged;
      continue;
    }
    for (const Status* st : {&so, &sp, &sd})
      expect(st->ok() || st->code == StatusCode::Unsupported, [&] { return st->toString(); });
    const int families = int(so.ok()) + int(sp.ok()) + int(sd.ok());
    const bool planes = k0 == Kind::Plane && k1 == Kind::Plane;  // no solid meaning: Unsupported
    if (!surfacePair && !planes)
      expect(families == 3, [] { return std::string("a convex pair not answered by every family"); });
    if (families < 2) return counts;
    ++counts.answered;
    if (sp.ok() && pen.penetrating)
      expect(pen.depth >= T(0) && std::abs(double(pen.direction.norm()) - 1.0) <= 1e-3,
             [&] { return "depth " + std::to_string(double(pen.depth)) + ", direction " + str(pen.direction); });

    if (surfacePair) {
      if (sd.ok()) {
        if (k0 != Kind::Plane && k1 != Kind::Plane)  // a plane is a solid half-space: its distance may be signed
          expect(dist.distance >= T(0), [&] { return "negative surface distance " + std::to_string(dist.distance); });
        if (so.ok() && std::abs(dist.distance) > tol)
          expect(overlapping == (dist.distance <= T(0)), [&] {
            return "overlap " + std::to_string(overlapping) + ", distance " + std::to_string(dist.distance);
          });
      }
      if (so.ok() && sp.ok())
        expect(overlapping || !pen.penetrating, [&] {
          return "penetrating without overlapping, depth " + std::to_string(pen.depth);
        });
      counts.penetrating += sp.ok() && pen.penetrating;
      counts.separated += so.ok() && !overlapping;
      continue;
    }

    // Convex pairs: all three answered.
    const T d = dist.distance;
    auto numbers = [&] {
      std::ostringstream o;
      o.precision(9);
      o << "overlap " << overlapping << ", distance " << d << ", normal " << str(dist.normal) << ", penetrating "
        << pen.penetrating << ", depth " << pen.depth << ", direction " << str(pen.direction) << ", tol " << tol;
      return o.str();
    };
    if (std::abs(d) <= tol) {
      ++counts.banded;
    } else if (d > tol) {
      ++counts.separated;
      expect(!overlapping && !pen.penetrating, [&] { return "apart but overlapping: " + numbers(); });
    } else {
      ++counts.penetrating;
      expect(overlapping && pen.penetrating, [&] { return "penetrating but not overlapping: " + numbers(); });
    }
    if (!pen.penetrating) continue;
    expect(std::abs(double(-d) - double(pen.depth)) <= double(tol),
           [&] { return "-distance != depth: " + numbers(); });
    bool after = true;
    const bool okAfter = overlap(g0, moved(p0, Vec3<T>(pen.direction * (pen.depth + tol))), g1, p1, after).ok();
    expect(okAfter && !after, [&] { return "direction * (depth + tol) does not separate: " + numbers(); });
    if (pen.depth > tol) {
      bool before = false;
      const bool okBefore = overlap(g0, moved(p0, Vec3<T>(pen.direction * (pen.depth - tol))), g1, p1, before).ok();
      expect(okBefore && before, [&] { return "direction * (depth - tol) already separates: " + numbers(); });
      if (dist.normal.dot(pen.direction) > T(-1) + T(relTol<T>())) {
        bool byNormal = true;
        const bool okNormal = overlap(g0, moved(p0, Vec3<T>(-dist.normal * (-d + tol))), g1, p1, byNormal).ok();
        expect(okNormal && !byNormal, [&] { return "-normal * (-distance + tol) does not separate: " + numbers(); });
      }
    }
  }
  return counts;
}

template <class T> class SignConventions : public ::testing::Test {};
TYPED_TEST_SUITE(SignConventions, Scalars);

TYPED_TEST(SignConventions, DistancePenetrationAndOverlapAgreeOnEveryPair) {
  using T = TypeParam;
  const Shapes<T> shapes;
  std::uint64_t seed = 9100;
  for (std::size_t ia = 0; ia < std::size(kKinds); ++ia)
    for (std::size_t ib = ia; ib < std::size(kKinds); ++ib) {
      const Kind a = kKinds[ia], b = kKinds[ib];
      const Counts c = checkPair<T>(shapes, a, b, ++seed);
      if (c.answered == 0) continue;  // at most one family answers the pair
      EXPECT_EQ(c.failed, 0) << kindName(a) << " vs " << kindName(b) << ": failed checks";
      EXPECT_EQ(c.unconverged, 0) << kindName(a) << " vs " << kindName(b) << ": poses NotConverged";
      EXPECT_EQ(c.answered, kPosesPerPair) << kindName(a) << " vs " << kindName(b);
      if (!isSurface(a) && !isSurface(b)) {
        // The poses reach both sides of the sign change.
        EXPECT_GT(c.penetrating, kPosesPerPair / 10) << kindName(a) << " vs " << kindName(b);
        EXPECT_GT(c.separated, kPosesPerPair / 10) << kindName(a) << " vs " << kindName(b);
      }
    }
}

}  // namespace
}  // namespace gq::test
