#pragma once
// gq::fcl's full results against FCL 0.7's on seeded random poses, for every pair of Sphere, Box, Capsule, Cylinder,
// Cone, Convex, Halfspace, Plane and BVHModel mesh, in float or double: collide booleans, contact counts, depths,
// normals and positions (also on symmetric tie poses, where several directions are equally deep), distances and
// nearest points, signed distances. Every disagreement beyond the tolerance must be a deliberate difference of
// tests/fcl/deliberate_differences.txt (by id), and there gq must give the exact answer (exact_reference.h, long
// double) where one is known. Within the touch band of touching either boolean is right. GQ_FCL_FULL_RESULT_TESTS (at
// the end) makes the five tests of one scalar; full_result_test.cpp (double) and full_result_float_test.cpp (float)
// each instantiate it once, so FCL's templates compile in two units.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "deliberate_differences.h"
#include "exact_reference.h"
#include "gq/fcl/fcl.h"
#include "scalar_scenes.h"

namespace gq::fcltest {

using Pair = std::pair<Kind, Kind>;

// The pair families compared: every unordered pair of these kinds but two plane-like ones.
inline std::vector<Pair> fullResultPairs() {
  const Kind kinds[] = {Kind::Sphere, Kind::Box,       Kind::Capsule, Kind::Cylinder, Kind::Cone,
                        Kind::Convex, Kind::Halfspace, Kind::Plane,   Kind::Mesh};
  std::vector<Pair> pairs;
  for (std::size_t i = 0; i < std::size(kinds); ++i)
    for (std::size_t j = i; j < std::size(kinds); ++j)
      if (!(isPlaneLike(kinds[i]) && isPlaneLike(kinds[j]))) pairs.emplace_back(kinds[i], kinds[j]);
  return pairs;
}

inline bool isPair(const Pair& p, Kind x, Kind y) {
  return (p.first == x && p.second == y) || (p.first == y && p.second == x);
}
inline bool hasKind(const Pair& p, Kind k) { return p.first == k || p.second == k; }
inline bool isCurvedKind(Kind k) { return k == Kind::Cylinder || k == Kind::Cone; }
// Pairs FCL answers by a closed form (its other pairs run libccd's GJK/MPR/EPA, to libccd's tolerance).
inline bool fclClosedForm(const Pair& p) {
  const auto round = [](Kind k) { return k == Kind::Sphere || k == Kind::Capsule; };
  return isPlaneLike(p.first) || isPlaneLike(p.second) || (round(p.first) && round(p.second)) ||
         isPair(p, Kind::Sphere, Kind::Box) || isPair(p, Kind::Sphere, Kind::Cylinder) ||
         isPair(p, Kind::Sphere, Kind::Mesh);
}

// Tolerances by scalar (shapes 0.3 to 1.4 long, translations in [-1, 1]^3).
template <class S> struct FullResultTolerances {
  static constexpr bool isFloat = std::is_same_v<S, float>;
  double touchBand = isFloat ? 1e-4 : 1e-7;      // |signed distance| within which either boolean is right
  double closedForm = isFloat ? 2e-4 : 1e-9;     // depths, distances, positions, normals of closed forms
  double iterative = isFloat ? 2e-3 : 1e-5;      // the same where FCL runs libccd (its tolerance 1e-6 in double)
  // Nearest points where FCL runs libccd's GJK: a distance within t of the minimum leaves the points free by up to
  // ~sqrt(t x size) along the surfaces (measured up to 5e-4 in double).
  double iterativePoints = isFloat ? 2e-2 : 2e-3;
  double exact = isFloat ? 2e-4 : 1e-9;          // gq against the exact answer
};

template <class S> struct FullResultCase {
  Pair pair;
  TestShape a, b;  // parameters representable in S; double geometries for the exact references
  std::shared_ptr<::fcl::CollisionGeometry<S>> fa, fb;
  bool fclCollide = false, fclDistance = false;
  std::map<std::string, int> listed;  // deliberate difference id -> poses it explains
  int compared = 0;
  double worst = 0;  // largest accepted difference
  std::string label() const { return std::string(name(pair.first)) + "-" + name(pair.second); }
};

template <class S> FullResultCase<S> makeFullResultCase(const Pair& pair, std::uint32_t seed) {
  FullResultCase<S> c;
  c.pair = pair;
  std::mt19937 rng(seed);
  c.a = roundedTo<S>(makeShape(pair.first, rng));
  c.b = roundedTo<S>(makeShape(pair.second, rng));
  c.fa = fclGeometry<S>(c.a);
  c.fb = fclGeometry<S>(c.b);
  c.fclCollide = fclHasCollide(c.a, c.b);
  c.fclDistance = fclHasDistance(c.a, c.b);
  return c;
}

inline bool isListedDifference(const std::string& id) {
  static const std::vector<Difference> list = readDifferences();
  return std::any_of(list.begin(), list.end(), [&](const Difference& d) { return d.id == id; });
}

// Records a disagreement explained by the deliberate difference `id` (which must be listed).
template <class S> void acceptListed(FullResultCase<S>& c, const std::string& id, const std::string& where) {
  EXPECT_TRUE(isListedDifference(id)) << where << ": " << id << " is not in tests/fcl/deliberate_differences.txt";
  ++c.listed[id];
}

template <class S> void printSummary(const FullResultCase<S>& c, const char* what) {
  std::cout << c.label() << (std::is_same_v<S, float> ? " (float) " : " ") << what << ": " << c.compared
            << " compared, largest accepted difference " << c.worst;
  for (const auto& [id, n] : c.listed) std::cout << "; " << id << " x" << n;
  std::cout << "\n";
}

template <class S> double signedDistanceOf(const FullResultCase<S>& c, const ::fcl::Transform3<S>& ta,
                                           const ::fcl::Transform3<S>& tb) {
  ::fcl::DistanceRequest<S> request(true);
  request.enable_signed_distance = true;
  ::fcl::DistanceResult<S> result;
  gq::fcl::distance<S>(c.fa.get(), ta, c.fb.get(), tb, request, result);
  return double(result.min_distance);
}

// The signed distance deciding the pose: exact where known, else gq's.
template <class S> double touchDistance(const FullResultCase<S>& c, const ExactAnswer& exact,
                                        const ::fcl::Transform3<S>& ta, const ::fcl::Transform3<S>& tb) {
  return exact.distanceKnown ? double(exact.distance) : signedDistanceOf(c, ta, tb);
}

template <class S> struct PosePair {
  ::fcl::Transform3<S> ta, tb;
  ::fcl::Transform3d pa, pb;  // exactly the same values in double
};
template <class S> PosePair<S> nextPoses(std::mt19937& rng) {
  PosePair<S> p;
  p.ta = poseIn<S>(randomPose(rng, 1.0));
  p.tb = poseIn<S>(randomPose(rng, 1.0));
  p.pa = poseInDouble(p.ta);
  p.pb = poseInDouble(p.tb);
  return p;
}

// A symmetric tie: b centred where a is, its axes a's turned by one of the 24 rotations of the cube (several
// directions of minimum translation are equally deep). A plane-like side passes through the other's centre.
template <class S> PosePair<S> nextTiePoses(std::mt19937& rng, const FullResultCase<S>& c) {
  const ::fcl::Transform3d base = randomPose(rng, 1.0);
  const int k = std::uniform_int_distribution<int>(0, 23)(rng);
  static const int perms[6][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {1, 0, 2}, {0, 2, 1}, {2, 1, 0}};
  Eigen::Matrix3d turn = Eigen::Matrix3d::Zero();
  turn(perms[k % 6][0], 0) = (k / 6) & 1 ? -1 : 1;
  turn(perms[k % 6][1], 1) = (k / 12) & 1 ? -1 : 1;
  turn.col(2) = turn.col(0).cross(turn.col(1));
  ::fcl::Transform3d ta = base, tb = base;
  tb.linear() = base.linear() * turn;
  const auto throughCentre = [](const TestShape& plane, ::fcl::Transform3d& pose, const ::fcl::Vector3d& centre) {
    const ::fcl::Vector3d n = pose.linear() * plane.planeNormal;
    pose.translation() += n * (n.dot(centre - pose.translation()) - plane.planeOffset);
  };
  if (isPlaneLike(c.a.kind)) throughCentre(c.a, ta, tb.translation());
  if (isPlaneLike(c.b.kind)) throughCentre(c.b, tb, ta.translation());
  PosePair<S> p;
  p.ta = poseIn<S>(ta);
  p.tb = poseIn<S>(tb);
  p.pa = poseInDouble(p.ta);
  p.pb = poseInDouble(p.tb);
  return p;
}


// Collide booleans (no contacts asked): FCL's, except within the touch band and where a listed difference shows FCL
// wrong against the exact answer.
template <class S> void checkCollideBooleans(FullResultCase<S>& c, int poses, std::uint32_t seed) {
  const FullResultTolerances<S> tol;
  std::mt19937 rng(seed);
  for (int i = 0; i < poses; ++i) {
    const PosePair<S> p = nextPoses<S>(rng);
    if (!c.fclCollide) continue;
    ::fcl::CollisionResult<S> gq, fcl;
    gq::fcl::collide<S>(c.fa.get(), p.ta, c.fb.get(), p.tb, ::fcl::CollisionRequest<S>(), gq);
    ::fcl::collide<S>(c.fa.get(), p.ta, c.fb.get(), p.tb, ::fcl::CollisionRequest<S>(), fcl);
    const ExactAnswer exact = exactAnswer(c.a, p.pa, c.b, p.pb);
    const double touch = touchDistance(c, exact, p.ta, p.tb);
    if (std::fabs(touch) <= tol.touchBand) continue;
    ++c.compared;
    if (gq.isCollision() == fcl.isCollision()) continue;
    const std::string where = c.label() + " pose " + std::to_string(i) + " (signed distance " + std::to_string(touch) + ")";
    ASSERT_TRUE(exact.known) << where << ": booleans differ and no exact answer decides it";
    EXPECT_EQ(gq.isCollision(), exact.colliding) << where << ": gq is not the exact answer";
    const char* id = isPair(c.pair, Kind::Cylinder, Kind::Plane)    ? "cylinder-plane"
                     : isPair(c.pair, Kind::Cone, Kind::Halfspace) ? "cone-into-halfspace"
                                                                    : "unlisted";
    acceptListed(c, id, where + ": FCL " + std::to_string(fcl.isCollision()));
  }
}

// Contacts (enable_contact, room for every triangle): the same count; each contact's depth, normal and position FCL's within the
// tolerance (BVHModel contacts matched by triangle id). The listed differences are accepted where gq's depth is exact.
template <class S> bool contactLess(const ::fcl::Contact<S>& x, const ::fcl::Contact<S>& y) {
  return std::make_pair(x.b1, x.b2) < std::make_pair(y.b1, y.b2);
}
template <class S> std::vector<::fcl::Contact<S>> sortedContacts(const ::fcl::CollisionResult<S>& r) {
  std::vector<::fcl::Contact<S>> v;
  for (std::size_t i = 0; i < r.numContacts(); ++i) v.push_back(r.getContact(i));
  std::stable_sort(v.begin(), v.end(), contactLess<S>);
  return v;
}
template <class S> double contactDifference(const ::fcl::Contact<S>& x, const ::fcl::Contact<S>& y) {
  return std::max({double(std::fabs(x.penetration_depth - y.penetration_depth)), double((x.normal - y.normal).norm()),
                   double((x.pos - y.pos).norm())});
}

// FCL 0.7 answers a shape (o1) against a BVHModel (o2) in the swapped order (Contact::b1 the triangle, the normal
// from the model to the shape, nearest_points[0] on the model): its answer turned back to the caller's order, which
// gq::fcl keeps (deliberate difference "shape-bvh-order").
template <class S> bool fclSwaps(const FullResultCase<S>& c) { return c.pair.first != Kind::Mesh && c.pair.second == Kind::Mesh; }
template <class S> std::vector<::fcl::Contact<S>> inCallerOrder(const FullResultCase<S>& c, std::vector<::fcl::Contact<S>> v) {
  if (!fclSwaps(c)) return v;
  for (::fcl::Contact<S>& x : v) {
    std::swap(x.o1, x.o2);
    std::swap(x.b1, x.b2);
    x.normal = -x.normal;
  }
  std::stable_sort(v.begin(), v.end(), contactLess<S>);
  return v;
}

// Two boxes' contacts carry no primitive ids: FCL's put in the order of gq's by nearest position (a set compared as a
// set; FCL's clipping starts its polygon at another corner).
template <class S> void matchByPosition(const std::vector<::fcl::Contact<S>>& gq, std::vector<::fcl::Contact<S>>& fcl) {
  for (std::size_t k = 0; k < gq.size() && k < fcl.size(); ++k) {
    std::size_t nearest = k;
    for (std::size_t j = k + 1; j < fcl.size(); ++j)
      if ((fcl[j].pos - gq[k].pos).norm() < (fcl[nearest].pos - gq[k].pos).norm()) nearest = j;
    std::swap(fcl[k], fcl[nearest]);
  }
}

// Two boxes: FCL's normal (its axis chosen with a 5 % bias towards face axes) is not a direction of minimum
// translation ("box-box-face-bias": gq's normal is, checked), or both are, differing, with the centres together (a
// tie: "box-box-tie").
template <class S>
std::string boxBoxDifferenceId(const FullResultCase<S>& c, const PosePair<S>& p,
                               const std::vector<::fcl::Contact<S>>& gq, const std::vector<::fcl::Contact<S>>& fcl) {
  long double depth = 0;
  if (gq.empty() || fcl.empty() || !exactDepth(c.a, p.pa, c.b, p.pb, depth)) return "unlisted";
  const double tol = FullResultTolerances<S>().exact;
  const auto along = [&](const ::fcl::Vector3<S>& n) {
    return -double(certifiedGap(c.a, p.pa, c.b, p.pb, n.template cast<double>().normalized()));
  };
  EXPECT_NEAR(along(gq[0].normal), double(depth), tol) << c.label() << ": gq's normal is not a minimum translation";
  if (along(fcl[0].normal) > double(depth) + tol) return "box-box-face-bias";
  const bool together = p.pa.translation() == p.pb.translation();
  if (together && (gq[0].normal - fcl[0].normal).norm() > S(1e-3)) return "box-box-tie";
  return "unlisted";
}

// A sphere against a BVHModel: each of gq's triangle contacts is the exact one (depth r - the distance to the
// triangle's nearest point, placed at that point), whatever FCL answers.
template <class S>
void expectExactSphereTriangleContacts(const FullResultCase<S>& c, const PosePair<S>& p,
                                       const std::vector<::fcl::Contact<S>>& gq, const std::string& where) {
  const bool sphereFirst = c.pair.first == Kind::Sphere;
  for (const ::fcl::Contact<S>& x : gq) {
    ::fcl::Vector3d nearest;
    long double depth = 0;
    exactSphereTriangleContact(sphereFirst ? c.a : c.b, sphereFirst ? p.pa : p.pb, sphereFirst ? c.b : c.a,
                               sphereFirst ? p.pb : p.pa, sphereFirst ? x.b2 : x.b1, nearest, depth);
    EXPECT_NEAR(double(x.penetration_depth), double(depth), FullResultTolerances<S>().exact) << where;
    EXPECT_NEAR((x.pos.template cast<double>() - nearest).norm(), 0.0, FullResultTolerances<S>().exact) << where;
  }
}

// FCL 0.7's sphere-triangle contact carries minus the depth (listed "sphere-bvh-contact"): its contacts with the
// sign turned, so that the rest is compared.
template <class S> void turnSphereTriangleDepths(FullResultCase<S>& c, std::vector<::fcl::Contact<S>>& fcl,
                                                 const std::string& where) {
  bool turned = false;
  for (::fcl::Contact<S>& y : fcl)
    if (y.penetration_depth < 0) y.penetration_depth = -y.penetration_depth, turned = true;
  if (turned) acceptListed(c, "sphere-bvh-contact", where);
}

// The listed difference that explains FCL's contact at a pose where gq's differs, or "unlisted".
template <class S>
std::string contactDifferenceId(const FullResultCase<S>& c, const PosePair<S>& p, double touch,
                                const std::vector<::fcl::Contact<S>>& gq, const std::vector<::fcl::Contact<S>>& fcl) {
  // A symmetric tie where FCL's normal is not a unit normal (zero: a sphere centred on the other sphere's centre or
  // on a capsule's axis): gq keeps a unit one.
  if (gq.size() == 1 && fcl.size() == 1 && fcl[0].normal.norm() < S(0.5)) {
    EXPECT_NEAR(double(gq[0].normal.norm()), 1.0, FullResultTolerances<S>().exact) << c.label();
    if (isPair(c.pair, Kind::Sphere, Kind::Sphere)) return "concentric-spheres";
    if (isPair(c.pair, Kind::Sphere, Kind::Capsule)) return "sphere-on-capsule-axis";
  }
  if (isPair(c.pair, Kind::Cylinder, Kind::Plane)) {
    EXPECT_EQ(gq.size(), 1u) << c.label();
    if (!gq.empty()) EXPECT_NEAR(double(gq[0].penetration_depth), -touch, FullResultTolerances<S>().exact) << c.label();
    return "cylinder-plane";
  }
  if (isPair(c.pair, Kind::Sphere, Kind::Mesh)) return "sphere-bvh-contact";  // gq's checked exact by the caller
  if (isPair(c.pair, Kind::Box, Kind::Box)) return boxBoxDifferenceId(c, p, gq, fcl);
  if (isPair(c.pair, Kind::Cone, Kind::Halfspace)) {
    const bool coneFirst = c.pair.first == Kind::Cone;
    const ::fcl::Transform3<S>& cone = coneFirst ? p.ta : p.tb;
    const ::fcl::Transform3<S>& half = coneFirst ? p.tb : p.ta;
    const ::fcl::Vector3<S> n = half.linear() * (coneFirst ? c.b : c.a).planeNormal.template cast<S>();
    if (cone.linear().col(2).dot(n) <= -S(std::is_same_v<S, float> ? 1e-4 : 1e-7)) return "cone-into-halfspace";
  }
  return "unlisted";
}

template <class S> void checkContacts(FullResultCase<S>& c, int poses, std::uint32_t seed, bool ties = false) {
  const FullResultTolerances<S> tol;
  // FCL's box-box contacts are a closed form too (its distance is not: libccd's GJK).
  const double within = fclClosedForm(c.pair) || isPair(c.pair, Kind::Box, Kind::Box) ? tol.closedForm : tol.iterative;
  std::mt19937 rng(seed);
  for (int i = 0; i < poses; ++i) {
    const PosePair<S> p = ties ? nextTiePoses<S>(rng, c) : nextPoses<S>(rng);
    if (!c.fclCollide) continue;
    const ::fcl::CollisionRequest<S> request(1000, true);  // room for every triangle
    ::fcl::CollisionResult<S> gq, fcl;
    gq::fcl::collide<S>(c.fa.get(), p.ta, c.fb.get(), p.tb, request, gq);
    ::fcl::collide<S>(c.fa.get(), p.ta, c.fb.get(), p.tb, request, fcl);
    if (!gq.isCollision() && !fcl.isCollision()) continue;
    const ExactAnswer exact = exactAnswer(c.a, p.pa, c.b, p.pb);
    const double touch = touchDistance(c, exact, p.ta, p.tb);
    if (std::fabs(touch) <= tol.touchBand) continue;
    const std::string where = c.label() + " pose " + std::to_string(i) + " (signed distance " + std::to_string(touch) + ")";
    if (gq.isCollision() != fcl.isCollision()) continue;  // a boolean difference: checkCollideBooleans
    ++c.compared;
    const auto g = sortedContacts(gq);
    auto f = inCallerOrder(c, sortedContacts(fcl));
    if (isPair(c.pair, Kind::Sphere, Kind::Mesh)) {
      expectExactSphereTriangleContacts(c, p, g, where);
      turnSphereTriangleDepths(c, f, where);
    }
    // gq's deepest contact is the exact depth where gq computes the contact (not FCL's MPR contacts, docs/fcl.md).
    long double depth = 0;
    const bool ownContact = hasKind(c.pair, Kind::Sphere) || isPair(c.pair, Kind::Box, Kind::Box);
    if (ownContact && exactDepth(c.a, p.pa, c.b, p.pb, depth) && !g.empty()) {
      double deepest = 0;
      for (const auto& x : g) deepest = std::max(deepest, double(x.penetration_depth));
      EXPECT_NEAR(deepest, double(depth), tol.exact) << where;
    }
    if (isPair(c.pair, Kind::Box, Kind::Box)) matchByPosition(g, f);
    double worst = g.size() == f.size() ? 0 : HUGE_VAL;
    for (std::size_t k = 0; k < g.size() && k < f.size(); ++k) {
      const ::fcl::Contact<S>& x = g[k];
      const ::fcl::Contact<S>& y = f[k];
      EXPECT_EQ(x.b1, y.b1) << where;
      EXPECT_EQ(x.b2, y.b2) << where;
      worst = std::max({worst, double(std::fabs(x.penetration_depth - y.penetration_depth)),
                        double((x.normal - y.normal).norm()), double((x.pos - y.pos).norm())});
    }
    if (fclSwaps(c) && !f.empty()) acceptListed(c, "shape-bvh-order", where);
    if (worst <= within) {
      c.worst = std::max(c.worst, worst);
      continue;
    }
    std::ostringstream what;
    what << where << ": " << g.size() << " contacts, FCL " << f.size();
    if (!g.empty() && !f.empty())
      what << "; first depth " << g[0].penetration_depth << " / " << f[0].penetration_depth << ", normal ("
           << g[0].normal.transpose() << ") / (" << f[0].normal.transpose() << "), pos (" << g[0].pos.transpose()
           << ") / (" << f[0].pos.transpose() << ")";
    acceptListed(c, contactDifferenceId(c, p, touch, g, f), what.str());
  }
}

// The listed difference that explains a distance of FCL's that differs from gq's, or "unlisted". `touch` is the
// exact signed distance where known, else gq's.
template <class S>
std::string distanceDifferenceId(const FullResultCase<S>& c, const ExactAnswer& exact, double touch, bool signedDistance,
                                 const ::fcl::DistanceResult<S>& gq, const ::fcl::DistanceResult<S>& fcl) {
  const FullResultTolerances<S> tol;
  const double g = double(gq.min_distance), f = double(fcl.min_distance);
  if (exact.distanceKnown && (touch > 0 || signedDistance || !hasKind(c.pair, Kind::Mesh)))
    EXPECT_NEAR(g, double(exact.distance), tol.exact) << c.label() << ": gq is not exact";
  // FCL's sphere-triangle distance writes its points in another frame (or leaves them uninitialised) and answers 0
  // for an overlapping sphere.
  if (isPair(c.pair, Kind::Sphere, Kind::Mesh)) return "sphere-bvh-distance";
  if (touch > 0) {
    // Both answers come with points on the shapes, so each is an upper bound of the distance: the smaller is nearer
    // the truth. libccd's GJK stops when an iteration gains less than its tolerance, which bounds nothing.
    EXPECT_NEAR(double((gq.nearest_points[1] - gq.nearest_points[0]).norm()), g, tol.exact) << c.label();
    return g <= f + tol.closedForm ? "gjk-distance" : "unlisted";
  }
  // A BVHModel is a surface: FCL's signed distance is its collide's first contact's depth (libccd per triangle),
  // gq's the deepest triangle contact's.
  if (hasKind(c.pair, Kind::Mesh)) return signedDistance ? "bvh-signed-distance" : "unlisted";
  if (!signedDistance) return f == -1 && g < 0 ? "unsigned-distance-overlap" : "unlisted";
  return "epa-signed-distance";
}

// Distances (nearest points asked; signed on request): min_distance and both nearest points FCL's within the
// tolerance. With enable_signed_distance FCL runs libccd's GJK/EPA for every pair, hence its tolerance there.
template <class S> void checkDistances(FullResultCase<S>& c, int poses, std::uint32_t seed, bool signedDistance) {
  const FullResultTolerances<S> tol;
  const bool closed = fclClosedForm(c.pair) && !signedDistance;
  const double within = closed ? tol.closedForm : tol.iterative;
  const double withinPoints = closed ? tol.closedForm : tol.iterativePoints;
  std::mt19937 rng(seed);
  std::map<std::string, std::pair<double, double>> worstListed;  // id -> largest distance and point difference
  for (int i = 0; i < poses; ++i) {
    const PosePair<S> p = nextPoses<S>(rng);
    if (!c.fclDistance) continue;
    // FCL 0.7 asserts (distance-inl.h:163) on a cone against a BVHModel with signed distance.
    if (signedDistance && isPair(c.pair, Kind::Cone, Kind::Mesh)) continue;
    ::fcl::DistanceRequest<S> request(true);
    request.enable_signed_distance = signedDistance;
    ::fcl::DistanceResult<S> gq, fcl;
    gq::fcl::distance<S>(c.fa.get(), p.ta, c.fb.get(), p.tb, request, gq);
    const ExactAnswer exact = exactAnswer(c.a, p.pa, c.b, p.pb);
    const double touch = touchDistance(c, exact, p.ta, p.tb);
    if (std::fabs(touch) <= tol.touchBand) continue;
    ::fcl::distance<S>(c.fa.get(), p.ta, c.fb.get(), p.tb, request, fcl);
    if (fclSwaps(c)) {
      std::swap(fcl.nearest_points[0], fcl.nearest_points[1]);
      acceptListed(c, "shape-bvh-order", c.label());
    }
    ++c.compared;
    const double dd = std::fabs(double(gq.min_distance - fcl.min_distance));
    // Two crossing surfaces are 0 apart at every point of their intersection: any common point is right.
    const bool crossing = gq.min_distance == 0 && fcl.min_distance == 0;
    if (crossing) EXPECT_EQ(gq.nearest_points[0], gq.nearest_points[1]) << c.label() << " pose " << i;
    const double dp = crossing ? 0
                               : std::max(double((gq.nearest_points[0] - fcl.nearest_points[0]).norm()),
                                          double((gq.nearest_points[1] - fcl.nearest_points[1]).norm()));
    if (dd <= within && dp <= withinPoints) {
      c.worst = std::max(c.worst, dd);
      continue;
    }
    std::ostringstream what;
    what << c.label() << " pose " << i << ": distance " << gq.min_distance << ", FCL " << fcl.min_distance
         << ", exact " << (exact.distanceKnown ? std::to_string(double(exact.distance)) : std::string("unknown"))
         << "; nearest points (" << gq.nearest_points[0].transpose() << "), (" << gq.nearest_points[1].transpose()
         << ") / FCL (" << fcl.nearest_points[0].transpose() << "), (" << fcl.nearest_points[1].transpose() << ")";
    const std::string id = distanceDifferenceId(c, exact, touch, signedDistance, gq, fcl);
    if (id == "epa-signed-distance" || id == "gjk-distance") {
      worstListed[id].first = std::max(worstListed[id].first, dd);
      worstListed[id].second = std::max(worstListed[id].second, dp);
    }
    acceptListed(c, id, what.str());
  }
  for (const auto& [id, w] : worstListed)
    std::cout << c.label() << " " << id << ": FCL's distance off gq's by up to " << w.first << ", nearest points by "
              << w.second << "\n";
}

// What one full-result test compares.
enum class FullResultCheck { Booleans, Contacts, TieContacts, Distances, SignedDistances };

// One full-result test of `pair` in S over `poses` seeded poses; seeds derive from `seedBase` and the pair. Every
// disagreement with FCL must be a listed difference.
template <class S> void runFullResultCheck(const Pair& pair, FullResultCheck check, std::uint32_t seedBase, int poses) {
  const std::uint32_t seed = seedBase + 100u * std::uint32_t(pair.first) + std::uint32_t(pair.second);
  FullResultCase<S> c = makeFullResultCase<S>(pair, seed);
  switch (check) {
    case FullResultCheck::Booleans: checkCollideBooleans(c, poses, seed + 1); printSummary(c, "booleans"); break;
    case FullResultCheck::Contacts: checkContacts(c, poses, seed + 2); printSummary(c, "contacts"); break;
    case FullResultCheck::TieContacts:
      checkContacts(c, poses / 4, seed + 5, true);
      printSummary(c, "tie contacts");
      break;
    case FullResultCheck::Distances: checkDistances(c, poses, seed + 3, false); printSummary(c, "distances"); break;
    case FullResultCheck::SignedDistances:
      checkDistances(c, poses, seed + 4, true);
      printSummary(c, "signed distances");
      break;
  }
  EXPECT_EQ(c.listed.count("unlisted"), 0u);
}

inline constexpr int kFullResultPoses = 200;

}  // namespace gq::fcltest

// The five full-result tests of scalar S as the suite `Suite`, over every pair family (fullResultPairs), seeds from
// `seedBase`. One body for float and double; each test file instantiates it once.
#define GQ_FCL_FULL_RESULT_TESTS(Suite, S, seedBase)                                                                  \
  class Suite : public ::testing::TestWithParam<::gq::fcltest::Pair> {                                              \
   protected:                                                                                                       \
    void run(::gq::fcltest::FullResultCheck check) {                                                                \
      ::gq::fcltest::runFullResultCheck<S>(GetParam(), check, seedBase, ::gq::fcltest::kFullResultPoses);            \
    }                                                                                                               \
  };                                                                                                                \
  TEST_P(Suite, CollideBooleansEqualFclsOutsideTheTouchBand) { run(::gq::fcltest::FullResultCheck::Booleans); }      \
  TEST_P(Suite, ContactsEqualFcls) { run(::gq::fcltest::FullResultCheck::Contacts); }                               \
  TEST_P(Suite, TieContactsEqualFcls) { run(::gq::fcltest::FullResultCheck::TieContacts); }                         \
  TEST_P(Suite, DistancesAndNearestPointsEqualFcls) { run(::gq::fcltest::FullResultCheck::Distances); }             \
  TEST_P(Suite, SignedDistancesEqualFcls) { run(::gq::fcltest::FullResultCheck::SignedDistances); }                 \
  INSTANTIATE_TEST_SUITE_P(AllFamilies, Suite, ::testing::ValuesIn(::gq::fcltest::fullResultPairs()),               \
                           ::gq::fcltest::PairName())
