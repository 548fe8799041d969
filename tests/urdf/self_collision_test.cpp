// Self-collision and self-distance on the real robots: home poses are free, folded poses report the expected
// pair in every mode (exact meshes included), distance and collision agree, batches match single checks.
#include <gtest/gtest.h>

#include <algorithm>
#include <limits>

#include "../../plugins/urdf/src/pair_order.h"
#include "robot_paths.h"

namespace gq::urdf::test {
namespace {

// On the real robots of the shared data folder (skipped when it does not hold them).
template <class T> class SelfCollisionData : public RobotDataTest {};
TYPED_TEST_SUITE(SelfCollisionData, Scalars);

const Representation kCheckedModes[] = {Representation::Mesh, Representation::Hull, Representation::BestPrimitive,
                                        Representation::Capsule};

TYPED_TEST(SelfCollisionData, SrdfHomePoseIsCollisionFree) {
  using T = TypeParam;
  for (const RobotFiles* r : {&kPanda, &kPandaPrimitives, &kUr5})
    for (Representation rep : kCheckedModes) {
      const auto m = loadCached<T>(*r, rep);
      ASSERT_TRUE(m);
      SelfCollisionChecker<T> checker(m);
      CollisionResult result;
      const Status s = checker.checkSelfCollision(m->home, result);
      ASSERT_TRUE(s.ok()) << s.toString();
      EXPECT_FALSE(result.colliding) << r->name << " " << toString(rep) << ": "
                                     << (result.pairs.empty() ? "" : m->links[result.pairs[0].a].name + " - " +
                                                                          m->links[result.pairs[0].b].name);
      SelfDistanceResult<T> d;
      ASSERT_TRUE(checker.selfDistance(m->home, d).ok());
      EXPECT_GT(d.distance, T(0)) << r->name << " " << toString(rep);
    }
}

// Folded by hand: Panda's shoulder pitched forward (joint2 = 1.7) with the elbow folded shut (joint4 = -3.0) brings
// the forearm (link5) back down onto the base; UR5 with the upper arm horizontal (shoulder_lift = 0) and the elbow
// folded (3.0 rad) lays the forearm onto the base.
struct Folded {
  const RobotFiles* robot;
  std::map<std::string, double> q;
  const char* linkA;
  const char* linkB;
};

const std::map<std::string, double> kFoldedPanda = {{"panda_joint2", 1.7}, {"panda_joint4", -3.0}, {"panda_joint6", 0.0}};

std::vector<Folded> foldedPoses() {
  return {
      {&kPanda, kFoldedPanda, "panda_link0", "panda_link5"},
      {&kPandaPrimitives, kFoldedPanda, "panda_link0", "panda_link5"},
      {&kUr5, {{"shoulder_lift_joint", 0.0}, {"elbow_joint", 3.0}}, "base_link", "forearm_link"},
  };
}

TYPED_TEST(SelfCollisionData, FoldedArmReportsTheExpectedPair) {
  using T = TypeParam;
  for (const Folded& f : foldedPoses())
    for (Representation rep : kCheckedModes) {
      const auto m = loadCached<T>(*f.robot, rep);
      ASSERT_TRUE(m);
      SelfCollisionChecker<T> checker(m);
      CollisionResult result;
      ASSERT_TRUE(checker.checkSelfCollision(namedConfiguration(*m, f.q), result).ok());
      EXPECT_TRUE(result.colliding) << f.robot->name << " " << toString(rep);
      EXPECT_NE(std::find(result.pairs.begin(), result.pairs.end(), pairOf(*m, f.linkA, f.linkB)), result.pairs.end())
          << f.robot->name << " " << toString(rep) << ": expected " << f.linkA << " - " << f.linkB;
      SelfDistanceResult<T> d;
      ASSERT_TRUE(checker.selfDistance(namedConfiguration(*m, f.q), d).ok());
      EXPECT_LE(d.distance, T(0));
    }
}

TYPED_TEST(SelfCollisionData, DistanceIsPositiveExactlyWhenNoPairCollides) {
  using T = TypeParam;
  const T tol = std::is_same_v<T, float> ? T(1e-4) : T(1e-8);
  // Mesh mode measures surfaces (distance 0 in contact, never negative); the primitive URDF has exact cylinders.
  const std::pair<const RobotFiles*, Representation> cases[] = {
      {&kPanda, Representation::Hull}, {&kUr5, Representation::Hull}, {&kPanda, Representation::Mesh},
      {&kUr5, Representation::Mesh}, {&kPandaPrimitives, Representation::Hull}};
  for (const auto& [r, rep] : cases) {
    const auto m = loadCached<T>(*r, rep);
    ASSERT_TRUE(m);
    SelfCollisionChecker<T> checker(m);
    std::uint64_t rng = 99;
    std::size_t separated = 0;
    for (int k = 0; k < 300; ++k) {
      const std::vector<T> q = randomConfiguration(*m, rng);
      CollisionResult c;
      SelfDistanceResult<T> d;
      ASSERT_TRUE(checker.checkSelfCollision(q, c).ok());
      const Status s = checker.selfDistance(q, d);
      ASSERT_TRUE(s.ok()) << r->name << " " << toString(rep) << " config " << k << ": " << s.toString();
      EXPECT_TRUE(std::isfinite(d.distance));
      if (std::abs(d.distance) <= tol) continue;  // touching: either answer is right
      EXPECT_EQ(c.colliding, d.distance < T(0)) << r->name << " " << toString(rep) << " config " << k << " distance " << d.distance;
      if (d.distance > T(0)) {  // witnesses are that far apart
        ++separated;
        EXPECT_NEAR((d.point1 - d.point0).norm(), d.distance, tol) << r->name << " config " << k;
      }
    }
    EXPECT_GT(separated, 100u) << r->name << " " << toString(rep);
  }
}

TYPED_TEST(SelfCollisionData, BatchMatchesSingleChecks) {
  using T = TypeParam;
  const auto m = loadCached<T>(kPanda, Representation::Hull);
  ASSERT_TRUE(m);
  SelfCollisionChecker<T> checker(m);
  std::uint64_t rng = 5;
  std::vector<std::vector<T>> qs;
  for (int k = 0; k < 500; ++k) qs.push_back(randomConfiguration(*m, rng));
  std::vector<std::uint8_t> batch;
  ASSERT_TRUE(checker.checkSelfCollisionBatch(qs, batch).ok());
  ASSERT_EQ(batch.size(), qs.size());
  std::size_t colliding = 0;
  for (std::size_t k = 0; k < qs.size(); ++k) {
    CollisionResult r;
    ASSERT_TRUE(checker.checkSelfCollision(qs[k], r).ok());
    EXPECT_EQ(batch[k] != 0, r.colliding) << k;
    colliding += r.colliding;
  }
  EXPECT_GT(colliding, 0u);
}

// The batch on gq's pool answers every configuration as the single checker does, on 1 thread, 2 threads and every
// hardware thread; self-distances bitwise equal.
TYPED_TEST(SelfCollisionData, ThreadedBatchesAreTheSingleChecksWhateverTheThreadCount) {
  using T = TypeParam;
  const auto m = loadCached<T>(kPanda, Representation::Hull);
  ASSERT_TRUE(m);
  const std::size_t dof = m->variables.size(), n = 300;
  std::uint64_t rng = 11;
  std::vector<T> rows;
  for (std::size_t k = 0; k < n; ++k) {
    const std::vector<T> q = randomConfiguration(*m, rng);
    rows.insert(rows.end(), q.begin(), q.end());
  }
  const StridedArray<T> configs(rows.data(), n, dof * sizeof(T));
  SelfCollisionChecker<T> single(m);
  std::vector<std::uint8_t> expected(n);
  std::vector<SelfDistanceResult<T>> expectedDistance(n);
  for (std::size_t k = 0; k < n; ++k) {
    const std::vector<T> q(rows.begin() + std::ptrdiff_t(k * dof), rows.begin() + std::ptrdiff_t((k + 1) * dof));
    CollisionResult r;
    ASSERT_TRUE(single.checkSelfCollision(q, r).ok());
    expected[k] = r.colliding ? 1 : 0;
    ASSERT_TRUE(single.selfDistance(q, expectedDistance[k]).ok());
  }
  EXPECT_GT(std::count(expected.begin(), expected.end(), 1), 0);
  for (std::uint32_t threads : {1u, 2u, 0u}) {
    BatchSettings settings;
    settings.threads = threads;
    settings.grain = 7;
    std::vector<std::uint8_t> colliding(n, 2);
    std::vector<Status> statuses(n);
    ASSERT_EQ(checkSelfCollisionBatch<T>(m, configs, dof, colliding.data(), statuses.data(), settings).code,
              StatusCode::Ok);
    EXPECT_EQ(colliding, expected) << threads << " threads";
    std::vector<SelfDistanceResult<T>> distances(n);
    ASSERT_EQ(selfDistanceBatch<T>(m, configs, dof, distances.data(), nullptr, settings).code, StatusCode::Ok);
    for (std::size_t k = 0; k < n; ++k) {
      EXPECT_EQ(distances[k].distance, expectedDistance[k].distance) << k << ", " << threads << " threads";
      EXPECT_EQ(distances[k].pair, expectedDistance[k].pair) << k;
    }
  }
}

// A NaN in one configuration fails that configuration only; a wrong row length, a short stride or a null output is
// rejected before anything is written.
TYPED_TEST(SelfCollisionData, BatchBadInputFailsItsItemOrTheCallAndWritesNothing) {
  using T = TypeParam;
  const auto m = loadCached<T>(kPanda, Representation::Hull);
  ASSERT_TRUE(m);
  const std::size_t dof = m->variables.size();
  std::uint64_t rng = 3;
  std::vector<T> rows;
  for (int k = 0; k < 3; ++k) {
    const std::vector<T> q = randomConfiguration(*m, rng);
    rows.insert(rows.end(), q.begin(), q.end());
  }
  rows[dof + 2] = std::numeric_limits<T>::quiet_NaN();
  std::vector<std::uint8_t> colliding(3, 7);
  std::vector<Status> statuses(3);
  const Status s = checkSelfCollisionBatch<T>(m, StridedArray<T>(rows.data(), 3, dof * sizeof(T)), dof,
                                              colliding.data(), statuses.data());
  EXPECT_EQ(s.code, StatusCode::Warning);
  EXPECT_EQ(s.index(), 1u);
  EXPECT_TRUE(statuses[0].ok());
  EXPECT_EQ(statuses[1].code, StatusCode::InvalidArgument);
  EXPECT_TRUE(statuses[2].ok());
  std::vector<std::uint8_t> untouched(3, 7);
  EXPECT_EQ(checkSelfCollisionBatch<T>(m, StridedArray<T>(rows.data(), 3, dof * sizeof(T)), dof - 1, untouched.data())
                .code,
            StatusCode::InvalidArgument);
  EXPECT_EQ(checkSelfCollisionBatch<T>(m, StridedArray<T>(rows.data(), 3, sizeof(T)), dof, untouched.data()).code,
            StatusCode::InvalidArgument);
  EXPECT_EQ(checkSelfCollisionBatch<T>(m, StridedArray<T>(rows.data(), 3, dof * sizeof(T)), dof, nullptr).code,
            StatusCode::InvalidArgument);
  EXPECT_EQ(untouched, std::vector<std::uint8_t>(3, 7));
}

// The checker visits link pairs most-often-touching first and culls before the narrow phase; neither may change
// the answer. Reference: every link pair the allowed-collision matrix leaves, every shape pair, gq::overlap at the
// forward-kinematics poses (no culling, link order). A first-hit check reports one pair of that set.
TYPED_TEST(SelfCollisionData, PairsFoundAreEveryShapePairOverlapSortedAndFirstHitIsOneOfThem) {
  using T = TypeParam;
  for (const RobotFiles* robot : {&kPanda, &kUr5}) {
    const auto m = loadCached<T>(*robot, Representation::Hull);
    ASSERT_TRUE(m);
    SelfCollisionChecker<T> checker(m);
    std::uint64_t rng = 11;
    std::size_t colliding = 0;
    for (int k = 0; k < 300; ++k) {
      const std::vector<T> q = randomConfiguration(*m, rng);
      std::vector<Transform<T>> links;
      ASSERT_TRUE(forwardKinematics(*m, q, links).ok());
      std::vector<LinkPair> expected;
      for (std::uint32_t a = 0; a < m->links.size(); ++a)
        for (std::uint32_t b = a + 1; b < m->links.size(); ++b) {
          if (m->isAllowed(a, b)) continue;
          bool hit = false;
          for (std::uint32_t sa : m->links[a].shapes)
            for (std::uint32_t sb : m->links[b].shapes) {
              bool touch = false;
              ASSERT_TRUE(overlap(m->shapes[sa].geometry, links[a] * m->shapes[sa].origin, m->shapes[sb].geometry,
                                  links[b] * m->shapes[sb].origin, touch).ok());
              hit = hit || touch;
            }
          if (hit) expected.push_back({a, b});
        }
      CollisionResult all, first;
      ASSERT_TRUE(checker.checkSelfCollision(q, all).ok());
      CollisionRequest firstOnly;
      firstOnly.allPairs = false;
      ASSERT_TRUE(checker.checkSelfCollision(q, first, firstOnly).ok());
      EXPECT_EQ(all.pairs, expected) << robot->name << " configuration " << k;
      EXPECT_EQ(first.colliding, !expected.empty()) << robot->name << " configuration " << k;
      if (first.colliding) {
        ASSERT_EQ(first.pairs.size(), 1u);
        EXPECT_TRUE(std::count(expected.begin(), expected.end(), first.pairs[0]) == 1) << robot->name << " " << k;
      }
      colliding += !expected.empty();
    }
    EXPECT_GT(colliding, 10u) << robot->name;  // the pair order matters only when something collides
  }
}

// The order helper: pairs by decreasing contact count over its samples, ties in their given order, and a failing
// check leaves the order as it was.
TYPED_TEST(SelfCollisionData, PairOrderIsByDecreasingContactCountAndStableOnTies) {
  using T = TypeParam;
  const auto m = loadCached<T>(kPanda, Representation::Hull);
  ASSERT_TRUE(m);
  const std::vector<LinkPair> given = {{0, 2}, {1, 3}, {2, 4}, {3, 5}};
  std::vector<LinkPair> pairs = given;
  std::uint64_t call = 0;
  internal::orderByContactFrequency(*m, pairs, [](const LinkPair& p) { return p; },
                                  [&](const std::vector<T>&, CollisionResult& r) {
                                    r.pairs.clear();
                                    r.pairs.push_back({2, 4});                   // every sample
                                    if (call++ % 2 == 0) r.pairs.push_back({3, 5});  // every other sample
                                    return Status();
                                  });
  EXPECT_EQ(pairs, (std::vector<LinkPair>{{2, 4}, {3, 5}, {0, 2}, {1, 3}}));
  EXPECT_EQ(call, internal::kOrderingSamples);
  pairs = given;
  internal::orderByContactFrequency(*m, pairs, [](const LinkPair& p) { return p; },
                                  [&](const std::vector<T>&, CollisionResult& r) {
                                    r.pairs = {{3, 5}};
                                    return Status::invalid("refused");
                                  });
  EXPECT_EQ(pairs, given);
  call = 0;  // no samples: no check, the given order
  internal::orderByContactFrequency(*m, pairs, [](const LinkPair& p) { return p; },
                                  [&](const std::vector<T>&, CollisionResult& r) {
                                    ++call;
                                    r.pairs = {{3, 5}};
                                    return Status();
                                  }, 0);
  EXPECT_EQ(call, 0u);
  EXPECT_EQ(pairs, given);
}

// selfDistance is the minimum signed distance over every shape pair the allowed-collision matrix leaves: the deepest
// penetration in colliding configurations (each pair evaluated here with gq::distance on forwardKinematics poses).
// Hulls, and meshes (thin surfaces: 0 in contact), whose pairs selfDistance orders and prunes by their hulls.
TYPED_TEST(SelfCollisionData, SelfDistanceIsTheDeepestOverAllCheckedShapePairs) {
  using T = TypeParam;
  for (const Representation rep : {Representation::Hull, Representation::Mesh}) {
  const auto m = loadCached<T>(kPanda, rep);
  ASSERT_TRUE(m);
  SelfCollisionChecker<T> checker(m);
  std::uint64_t rng = 7;
  int colliding = 0;
  for (int i = 0; i < 200; ++i) {
    const std::vector<T> q = randomConfiguration(*m, rng);
    std::vector<Transform<T>> links;
    ASSERT_TRUE(forwardKinematics(*m, q, links).ok());
    T deepest = std::numeric_limits<T>::infinity();
    for (std::uint32_t a = 0; a < m->links.size(); ++a)
      for (std::uint32_t b = a + 1; b < m->links.size(); ++b) {
        if (m->isAllowed(a, b)) continue;
        for (std::uint32_t sa : m->links[a].shapes)
          for (std::uint32_t sb : m->links[b].shapes) {
            DistanceResult<T> d;
            ASSERT_TRUE(distance(d, m->shapes[sa].geometry, links[a] * m->shapes[sa].origin, m->shapes[sb].geometry,
                                 links[b] * m->shapes[sb].origin).ok());
            deepest = std::min(deepest, d.distance);
          }
      }
    SelfDistanceResult<T> r;
    ASSERT_TRUE(checker.selfDistance(q, r).ok());
    EXPECT_NEAR(r.distance, deepest, T(1e-4)) << (rep == Representation::Hull ? "hull" : "mesh") << " configuration " << i;
    colliding += deepest <= T(0);
  }
  EXPECT_GT(colliding, rep == Representation::Hull ? 10 : 4);  // both regimes are exercised
  }
}

// CheckerOptions::orderingSamples changes only the order pairs are tried in: every colliding pair and the minimum
// distance stay the same, also with no ordering at all.
TYPED_TEST(SelfCollisionData, OrderingSamplesChangeNoAnswer) {
  using T = TypeParam;
  const auto m = loadCached<T>(kPanda, Representation::Hull);
  ASSERT_TRUE(m);
  SelfCollisionChecker<T> ordered(m);
  CheckerOptions none;
  none.orderingSamples = 0;
  SelfCollisionChecker<T> unordered(m, none);
  std::uint64_t rng = 7;
  int colliding = 0;
  for (int i = 0; i < 200; ++i) {
    const std::vector<T> q = randomConfiguration(*m, rng);
    CollisionResult a, b;
    ASSERT_TRUE(ordered.checkSelfCollision(q, a).ok());
    ASSERT_TRUE(unordered.checkSelfCollision(q, b).ok());
    EXPECT_EQ(a.colliding, b.colliding);
    EXPECT_EQ(a.pairs, b.pairs);
    colliding += a.colliding;
    SelfDistanceResult<T> da, db;
    ASSERT_TRUE(ordered.selfDistance(q, da).ok());
    ASSERT_TRUE(unordered.selfDistance(q, db).ok());
    EXPECT_EQ(da.distance, db.distance);
  }
  EXPECT_GT(colliding, 0);  // the sample has colliding configurations
}

TYPED_TEST(SelfCollisionData, InvalidConfigurationReturnsInvalidArgumentAndKeepsTheResult) {
  using T = TypeParam;
  const auto m = loadCached<T>(kUr5, Representation::Hull);
  ASSERT_TRUE(m);
  SelfCollisionChecker<T> checker(m);
  CollisionResult r;
  r.colliding = true;
  EXPECT_EQ(checker.checkSelfCollision(std::vector<T>(3, T(0)), r).code, StatusCode::InvalidArgument);
  std::vector<T> q = m->home;
  q[1] = T(100);  // shoulder_lift beyond 2 pi
  EXPECT_EQ(checker.checkSelfCollision(q, r).code, StatusCode::InvalidArgument);
  EXPECT_TRUE(r.colliding);
}

// Mesh mode tests the links' convex hulls before their triangles: hulls that touch while the meshes do not (UR5's
// links are far from convex) must come out free, and the triangles decide.
TYPED_TEST(SelfCollisionData, MeshModeIsNeverMoreCollidingThanHullModeAndSometimesLess) {
  using T = TypeParam;
  const auto meshes = loadCached<T>(kUr5, Representation::Mesh);
  ASSERT_TRUE(meshes);
  const auto hulls = loadCached<T>(kUr5, Representation::Hull);
  ASSERT_TRUE(hulls);
  SelfCollisionChecker<T> meshChecker(meshes), hullChecker(hulls);
  std::uint64_t rng = 17;
  std::size_t onlyHulls = 0;
  for (int k = 0; k < 2000; ++k) {
    const std::vector<T> q = randomConfiguration(*meshes, rng);
    CollisionResult m, h;
    ASSERT_TRUE(meshChecker.checkSelfCollision(q, m).ok());
    ASSERT_TRUE(hullChecker.checkSelfCollision(q, h).ok());
    for (const LinkPair& p : m.pairs)  // a mesh contact is a hull contact (the hull encloses the mesh)
      EXPECT_NE(std::find(h.pairs.begin(), h.pairs.end(), p), h.pairs.end()) << "configuration " << k;
    onlyHulls += h.pairs.size() - m.pairs.size();
  }
  EXPECT_GT(onlyHulls, 0u) << "UR5's hulls overreach its meshes by up to 37 mm: some hull contacts are not mesh contacts";
}

}  // namespace
}  // namespace gq::urdf::test
