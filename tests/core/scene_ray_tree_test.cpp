// The scene's 8-wide ray tree (scene/ray_tree.h) visits every instance whose box a ray enters within its limit,
// each once, after a build, refits and removals, on long rays with zero or tiny direction components too; a visit's
// lowered limit prunes farther boxes; boxes or origins beyond float's reach leave the tree unused rather than tested
// wrongly. Boxes entered are decided in long double.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <type_traits>
#include <vector>

#include "scene/ray_tree.h"
#include "test_util.h"

namespace gq {
namespace {

using test::Rng;

template <class T> class SceneRayTreeTest : public ::testing::Test {};
TYPED_TEST_SUITE(SceneRayTreeTest, test::Scalars);

// Whether o + t d enters [lo, hi] for some t in [0, limit], by slabs in long double.
template <class T> bool entersExactly(const Vec3<T>& o, const Vec3<T>& d, const Bounds3<T>& b, T limit) {
  long double t0 = 0, t1 = limit;
  for (int a = 0; a < 3; ++a) {
    const long double oa = o[a], da = d[a], lo = b.min[a], hi = b.max[a];
    if (da == 0) {
      if (oa < lo || oa > hi) return false;
      continue;
    }
    long double ta = (lo - oa) / da, tb = (hi - oa) / da;
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
  }
  return t0 <= t1;
}

template <class T> Bounds3<T> randomBox(Rng& rng, double half) {
  const Vec3<T> c = rng.inBox<T>(half);
  const Vec3<T> e = rng.vec<T>(0.05, 1.0);
  return Bounds3<T>{Vec3<T>(c - e), Vec3<T>(c + e)};
}

// Collects the instances visited; every visit returns `limit`.
template <class T> struct Collect {
  std::vector<std::uint32_t> visited;
  T limit;
  static T call(void* context, std::uint32_t instance) {
    auto& c = *static_cast<Collect*>(context);
    c.visited.push_back(instance);
    return c.limit;
  }
};

// The ray o + t d against every box: each one it enters within limit is visited, and no instance twice.
template <class T>
void expectVisitsEveryBoxEntered(const detail::SceneRayTree<T>& tree, const std::vector<std::uint32_t>& instances,
                                 const std::vector<Bounds3<T>>& boxes, const Vec3<T>& o, const Vec3<T>& d, T limit) {
  Collect<T> c{{}, limit};
  ASSERT_TRUE(tree.walkRay(o, d, limit, &Collect<T>::call, &c));
  std::vector<std::uint32_t> visited = c.visited;
  std::sort(visited.begin(), visited.end());
  EXPECT_TRUE(std::adjacent_find(visited.begin(), visited.end()) == visited.end()) << "an instance visited twice";
  for (std::uint32_t v : visited) {  // only live instances (a removed one's number may belong to another)
    EXPECT_TRUE(std::find(instances.begin(), instances.end(), v) != instances.end()) << "visited " << v;
  }
  for (std::size_t j = 0; j < instances.size(); ++j) {
    if (entersExactly(o, d, boxes[j], limit)) {
      EXPECT_TRUE(std::binary_search(visited.begin(), visited.end(), instances[j])) << "missed " << instances[j];
    }
  }
}

template <class T>
void expectVisitsEveryBoxEntered(const detail::SceneRayTree<T>& tree, const std::vector<std::uint32_t>& instances,
                                 const std::vector<Bounds3<T>>& boxes, Rng& rng, int rays) {
  for (int r = 0; r < rays; ++r) {
    SCOPED_TRACE(r);
    const Vec3<T> o = rng.inBox<T>(15);
    Vec3<T> d = rng.unitVector<T>();
    if (r % 4 == 0) d = Vec3<T>(T(0), T(0), d.z() < 0 ? T(-1) : T(1));  // axis-aligned: zero components
    const T limit = T(rng.uniform(1, 40));
    expectVisitsEveryBoxEntered(tree, instances, boxes, o, d, limit);
  }
}

TYPED_TEST(SceneRayTreeTest, VisitsEveryInstanceWhoseBoxTheRayEntersAfterBuildAndRefits) {
  using T = TypeParam;
  Rng rng(81);
  std::vector<std::uint32_t> instances;
  std::vector<Bounds3<T>> boxes;
  for (std::uint32_t i = 0; i < 600; ++i) {
    instances.push_back(3 * i + 1);  // instance numbers need not be dense
    boxes.push_back(randomBox<T>(rng, 12));
  }
  detail::SceneRayTree<T> tree;
  ASSERT_TRUE(tree.build(instances, boxes));
  ASSERT_TRUE(tree.ready());
  expectVisitsEveryBoxEntered(tree, instances, boxes, rng, 300);
  // Moves: a third jump anywhere (their leaves' and ancestors' lanes grow), a third shrink to points.
  for (std::size_t j = 0; j < boxes.size(); j += 3) {
    boxes[j] = randomBox<T>(rng, 14);
    ASSERT_TRUE(tree.refit(instances[j], boxes[j]));
  }
  for (std::size_t j = 1; j < boxes.size(); j += 3) {
    const Vec3<T> c = boxes[j].center();
    boxes[j] = Bounds3<T>{c, c};
    ASSERT_TRUE(tree.refit(instances[j], boxes[j]));
  }
  expectVisitsEveryBoxEntered(tree, instances, boxes, rng, 300);
}

// The scene's removal: instance `gone` leaves, the last instance takes its number.
template <class T>
void removeAsTheScene(detail::SceneRayTree<T>& tree, std::vector<std::uint32_t>& instances,
                      std::vector<Bounds3<T>>& boxes, std::size_t gone) {
  const std::uint32_t last = std::uint32_t(instances.size() - 1);
  tree.remove(instances[gone], last);
  const auto moved = std::find(instances.begin(), instances.end(), last);
  if (moved != instances.end()) *moved = instances[gone];
  instances.erase(instances.begin() + std::ptrdiff_t(gone));
  boxes.erase(boxes.begin() + std::ptrdiff_t(gone));
}

TYPED_TEST(SceneRayTreeTest, RemovalsEmptyTheirLanesAndRenumberTheLastInstance) {
  using T = TypeParam;
  Rng rng(83);
  std::vector<std::uint32_t> instances;
  std::vector<Bounds3<T>> boxes;
  for (std::uint32_t i = 0; i < 400; ++i) {  // dense numbers 0..399, as the scene's
    instances.push_back(i);
    boxes.push_back(randomBox<T>(rng, 10));
  }
  detail::SceneRayTree<T> tree;
  ASSERT_TRUE(tree.build(instances, boxes));
  for (int k = 0; k < 150; ++k) {
    removeAsTheScene(tree, instances, boxes, std::size_t(rng.uniform(0, double(instances.size()))));
  }
  ASSERT_TRUE(tree.ready());
  for (std::size_t j = 0; j < boxes.size(); j += 4) {  // the renumbered instances still refit their own leaves
    boxes[j] = randomBox<T>(rng, 12);
    ASSERT_TRUE(tree.refit(instances[j], boxes[j]));
  }
  expectVisitsEveryBoxEntered(tree, instances, boxes, rng, 300);
  // Removed instances are never visited: every visit names a live instance.
  for (int r = 0; r < 100; ++r) {
    Collect<T> c{{}, T(40)};
    ASSERT_TRUE(tree.walkRay(rng.inBox<T>(15), rng.unitVector<T>(), T(40), &Collect<T>::call, &c));
    for (std::uint32_t v : c.visited) EXPECT_LT(v, instances.size());
  }
}

TYPED_TEST(SceneRayTreeTest, InsertionsFromEmptyAndIntoEmptiedLanesVisitEveryBoxEntered) {
  using T = TypeParam;
  Rng rng(84);
  detail::SceneRayTree<T> tree;  // constructed empty and ready
  ASSERT_TRUE(tree.ready());
  std::vector<std::uint32_t> instances;
  std::vector<Bounds3<T>> boxes;
  for (std::uint32_t i = 0; i < 500; ++i) {
    instances.push_back(i);
    boxes.push_back(randomBox<T>(rng, 12));
    ASSERT_TRUE(tree.insert(i, boxes.back()));
    if (i < 3) expectVisitsEveryBoxEntered(tree, instances, boxes, rng, 20);  // a root leaf, then a root node
  }
  expectVisitsEveryBoxEntered(tree, instances, boxes, rng, 300);
  for (int k = 0; k < 200; ++k) {
    removeAsTheScene(tree, instances, boxes, std::size_t(rng.uniform(0, double(instances.size()))));
  }
  for (int k = 0; k < 300; ++k) {
    const auto i = std::uint32_t(instances.size());
    instances.push_back(i);
    boxes.push_back(randomBox<T>(rng, 12));
    ASSERT_TRUE(tree.insert(i, boxes.back()));
  }
  expectVisitsEveryBoxEntered(tree, instances, boxes, rng, 300);
  // Inserted instances refit their own leaves (including those moved under a node an insertion made).
  for (std::size_t j = 0; j < boxes.size(); j += 3) {
    boxes[j] = randomBox<T>(rng, 14);
    ASSERT_TRUE(tree.refit(instances[j], boxes[j]));
  }
  expectVisitsEveryBoxEntered(tree, instances, boxes, rng, 200);
  // Everything removed, then inserted again (a root node with every lane emptied takes them).
  while (!instances.empty()) removeAsTheScene(tree, instances, boxes, instances.size() - 1);
  Collect<T> none{{}, T(100)};
  ASSERT_TRUE(tree.walkRay(Vec3<T>::Zero(), Vec3<T>::UnitX(), T(100), &Collect<T>::call, &none));
  EXPECT_TRUE(none.visited.empty());
  for (std::uint32_t i = 0; i < 50; ++i) {
    instances.push_back(i);
    boxes.push_back(randomBox<T>(rng, 12));
    ASSERT_TRUE(tree.insert(i, boxes.back()));
  }
  expectVisitsEveryBoxEntered(tree, instances, boxes, rng, 200);
  // A cleared tree takes no insertion until reset or built.
  tree.clear();
  EXPECT_FALSE(tree.insert(50, randomBox<T>(rng, 12)));
  tree.reset();
  EXPECT_TRUE(tree.ready());
  EXPECT_TRUE(tree.insert(0, boxes[0]));
}

TYPED_TEST(SceneRayTreeTest, InsertionsInSortedOrderStayWithinTheWalkStackOrLeaveTheTree) {
  using T = TypeParam;
  Rng rng(85);
  detail::SceneRayTree<T> tree;
  std::vector<std::uint32_t> instances;
  std::vector<Bounds3<T>> boxes;
  // Boxes along x in increasing order: each lands in the lane of the last, chaining nodes. The ray along x enters
  // every box, so its walk holds the most stack entries the chain makes (7 a level).
  bool ready = true;
  std::uint32_t inserted = 0;
  for (std::uint32_t i = 0; i < 3000 && ready; ++i) {
    instances.push_back(i);
    const T x = T(i);
    boxes.push_back(Bounds3<T>{Vec3<T>(x, T(0), T(0)), Vec3<T>(x + T(0.5), T(1), T(1))});
    ready = tree.insert(i, boxes.back());
    EXPECT_EQ(ready, tree.ready());
    if (ready && (++inserted % 25 == 0 || i + 1 == 3000)) {
      const Vec3<T> o(T(-1), T(rng.uniform(0, 1)), T(rng.uniform(0, 1)));
      expectVisitsEveryBoxEntered(tree, instances, boxes, o, Vec3<T>(Vec3<T>::UnitX()), T(4000));
    }
  }
  EXPECT_FALSE(ready);  // the chain reached the depth limit
  EXPECT_GT(inserted, 300u);
  Collect<T> c{{}, T(10)};
  EXPECT_FALSE(tree.walkRay(Vec3<T>::Zero(), Vec3<T>::UnitX(), T(10), &Collect<T>::call, &c));
  ASSERT_TRUE(tree.build(instances, boxes));  // a build starts it again
  expectVisitsEveryBoxEntered(tree, instances, boxes, Vec3<T>(T(-1), T(0.5), T(0.5)), Vec3<T>(Vec3<T>::UnitX()),
                              T(4000));
}

TYPED_TEST(SceneRayTreeTest, OneInstanceIsTheRootLeafAndRefitsAndLeaves) {
  using T = TypeParam;
  std::vector<std::uint32_t> instances{0};
  std::vector<Bounds3<T>> boxes{Bounds3<T>{Vec3<T>::Zero(), Vec3<T>::Ones()}};
  detail::SceneRayTree<T> tree;
  ASSERT_TRUE(tree.build(instances, boxes));
  ASSERT_TRUE(tree.refit(0, Bounds3<T>{Vec3<T>::Constant(T(5)), Vec3<T>::Constant(T(6))}));
  Collect<T> c{{}, T(100)};
  ASSERT_TRUE(tree.walkRay(Vec3<T>::Zero(), Vec3<T>::UnitX(), T(100), &Collect<T>::call, &c));
  EXPECT_EQ(c.visited, std::vector<std::uint32_t>{0});  // a root leaf is visited without a box test
  tree.remove(0, 0);
  c.visited.clear();
  ASSERT_TRUE(tree.walkRay(Vec3<T>::Zero(), Vec3<T>::UnitX(), T(100), &Collect<T>::call, &c));
  EXPECT_TRUE(c.visited.empty());
}

// Rays far longer than the scene whose direction has a zero or tiny component, from near a face of a box: the
// clamped inverse of such a component must not end the ray's stay in that slab early.
TYPED_TEST(SceneRayTreeTest, LongRaysWithZeroOrTinyComponentsVisitTheBoxesTheyEnter) {
  using T = TypeParam;
  std::vector<std::uint32_t> instances{0, 1};
  std::vector<Bounds3<T>> boxes{Bounds3<T>{Vec3<T>::Zero(), Vec3<T>::Ones()},
                                Bounds3<T>{Vec3<T>(T(3), T(3), T(3)), Vec3<T>(T(4), T(4), T(4))}};
  detail::SceneRayTree<T> tree;
  ASSERT_TRUE(tree.build(instances, boxes));
  const T inf = std::numeric_limits<T>::infinity();
  // x just inside the box's max face (inexact in float for double rays), z far before the box.
  const T nearFace = std::is_same_v<T, double> ? T(0.9999999999) : std::nextafter(T(1), T(0));
  int entering = 0;
  for (const T dx : {T(0), T(-0.0), T(1e-25), T(-1e-25), T(1e-21)}) {
    for (const T z0 : {T(-1e14), T(-1e18), T(-1e25)}) {
      SCOPED_TRACE(testing::Message() << dx << " " << z0);
      const Vec3<T> o(nearFace, T(0.5), z0), d(dx, T(0), T(1));
      entering += entersExactly(o, d, boxes[0], inf) ? 1 : 0;
      expectVisitsEveryBoxEntered(tree, instances, boxes, o, d, inf);
    }
  }
  EXPECT_GE(entering, 8);  // zero components: all 6; 1e-25 and -1e-25 from 1e14 away, -1e-25 from 1e18
}

TYPED_TEST(SceneRayTreeTest, ALoweredLimitPrunesFartherBoxes) {
  using T = TypeParam;
  // Unit boxes along +x at 10, 20, ..., 100: a ray from the origin along +x whose visits lower the limit to 15
  // visits the box at 10 and none beyond 20.
  std::vector<std::uint32_t> instances;
  std::vector<Bounds3<T>> boxes;
  for (std::uint32_t i = 1; i <= 10; ++i) {
    instances.push_back(i);
    boxes.push_back(Bounds3<T>{Vec3<T>(T(10 * i), T(-1), T(-1)), Vec3<T>(T(10 * i + 1), T(1), T(1))});
  }
  detail::SceneRayTree<T> tree;
  ASSERT_TRUE(tree.build(instances, boxes));
  Collect<T> c{{}, T(15)};
  ASSERT_TRUE(tree.walkRay(Vec3<T>::Zero(), Vec3<T>::UnitX(), T(200), &Collect<T>::call, &c));
  EXPECT_EQ(c.visited, std::vector<std::uint32_t>{1});
}

TYPED_TEST(SceneRayTreeTest, ANegativeLimitStopsTheWalk) {
  using T = TypeParam;
  Rng rng(82);
  std::vector<std::uint32_t> instances;
  std::vector<Bounds3<T>> boxes;
  for (std::uint32_t i = 0; i < 200; ++i) {
    instances.push_back(i);
    const T x = T(i);
    boxes.push_back(Bounds3<T>{Vec3<T>(x, T(-1), T(-1)), Vec3<T>(x + T(0.5), T(1), T(1))});
  }
  detail::SceneRayTree<T> tree;
  ASSERT_TRUE(tree.build(instances, boxes));
  Collect<T> c{{}, T(-1)};
  ASSERT_TRUE(tree.walkRay(Vec3<T>(T(-1), T(0), T(0)), Vec3<T>::UnitX(), T(500), &Collect<T>::call, &c));
  EXPECT_EQ(c.visited.size(), 1u);
}

TYPED_TEST(SceneRayTreeTest, BoxesAndOriginsBeyondFloatReachLeaveTheTreeUnused) {
  using T = TypeParam;
  std::vector<std::uint32_t> instances{0, 1};
  std::vector<Bounds3<T>> boxes{Bounds3<T>{Vec3<T>::Zero(), Vec3<T>::Ones()},
                                Bounds3<T>{Vec3<T>(T(1e31), T(0), T(0)), Vec3<T>(T(2e31), T(1), T(1))}};
  detail::SceneRayTree<T> tree;
  EXPECT_FALSE(tree.build(instances, boxes));
  EXPECT_FALSE(tree.ready());
  Collect<T> c{{}, T(10)};
  EXPECT_FALSE(tree.walkRay(Vec3<T>::Zero(), Vec3<T>::UnitX(), T(10), &Collect<T>::call, &c));

  boxes.pop_back();
  instances.pop_back();
  ASSERT_TRUE(tree.build(instances, boxes));
  EXPECT_FALSE(tree.walkRay(Vec3<T>(T(-1e31), T(0), T(0)), Vec3<T>::UnitX(), T(10), &Collect<T>::call, &c));
  EXPECT_TRUE(c.visited.empty());
  // A move beyond reach clears the tree (the scene then walks its binary tree).
  EXPECT_FALSE(tree.refit(0, Bounds3<T>{Vec3<T>(T(5e30), T(0), T(0)), Vec3<T>(T(6e30), T(1), T(1))}));
  EXPECT_FALSE(tree.ready());
}

TYPED_TEST(SceneRayTreeTest, AnEmptySceneBuildsATreeThatVisitsNothing) {
  using T = TypeParam;
  detail::SceneRayTree<T> tree;
  ASSERT_TRUE(tree.build({}, {}));
  Collect<T> c{{}, T(10)};
  EXPECT_TRUE(tree.walkRay(Vec3<T>::Zero(), Vec3<T>::UnitX(), T(10), &Collect<T>::call, &c));
  EXPECT_TRUE(c.visited.empty());
}

}  // namespace
}  // namespace gq
