// FCL 0.7's whole public query API through gq::fcl: every free collide / distance / continuousCollide overload and
// every public member and typedef of DynamicAABBTreeCollisionManager, called as gq::fcl::X in float and double.
// Building this file is the compile check; the assertions check that each call reached an answer.
#include <gtest/gtest.h>

#include <memory>
#include <type_traits>
#include <vector>

#include "gq/fcl/fcl.h"

namespace {

template <typename S> struct Scene {
  std::shared_ptr<gq::fcl::Sphere<S>> sphere = std::make_shared<gq::fcl::Sphere<S>>(S(0.5));
  std::shared_ptr<gq::fcl::Box<S>> box = std::make_shared<gq::fcl::Box<S>>(S(1), S(1), S(1));
  gq::fcl::Transform3<S> tf1 = gq::fcl::Transform3<S>::Identity();
  gq::fcl::Transform3<S> tf2 = gq::fcl::Transform3<S>::Identity();
  Scene() { tf2.translation() = gq::fcl::Vector3<S>(S(0.8), S(0), S(0)); }  // overlapping by 0.2
};

template <typename S> class FclApi : public ::testing::Test {};
using Scalars = ::testing::Types<float, double>;
TYPED_TEST_SUITE(FclApi, Scalars);

TYPED_TEST(FclApi, EveryCollideOverloadResolvesThroughGqFcl) {
  using S = TypeParam;
  namespace coll = gq::fcl;
  Scene<S> s;
  coll::CollisionObject<S> a(s.sphere, s.tf1), b(s.box, s.tf2);
  coll::CollisionRequest<S> request(4, true);

  coll::CollisionResult<S> r1, r2, r3, r4, r5, r6;
  EXPECT_EQ(coll::collide(&a, &b, request, r1), 1u);                                      // gq
  EXPECT_EQ(coll::collide(s.sphere.get(), s.tf1, s.box.get(), s.tf2, request, r2), 1u);  // gq
  EXPECT_EQ(coll::collide(&a, &b, request, r3, coll::Options()), 1u);                      // gq, Options
  EXPECT_EQ(coll::collide(s.sphere.get(), s.tf1, s.box.get(), s.tf2, request, r4, coll::Options()), 1u);
  const coll::detail::GJKSolver_libccd<S> libccd;
  const coll::detail::GJKSolver_indep<S> indep;
  EXPECT_EQ(coll::collide(&a, &b, &libccd, request, r5), 1u);  // FCL, with the host's solver
  EXPECT_EQ(coll::collide(s.sphere.get(), s.tf1, s.box.get(), s.tf2, &indep, request, r6), 1u);
  EXPECT_NEAR(r1.getContact(0).penetration_depth, S(0.2), S(1e-4));
  EXPECT_NEAR(r5.getContact(0).penetration_depth, S(0.2), S(1e-4));
  EXPECT_NEAR(r6.getContact(0).penetration_depth, S(0.2), S(1e-4));
}

TYPED_TEST(FclApi, EveryDistanceOverloadResolvesThroughGqFcl) {
  using S = TypeParam;
  namespace coll = gq::fcl;
  Scene<S> s;
  s.tf2.translation() = coll::Vector3<S>(S(2), S(0), S(0));  // 1 apart
  coll::CollisionObject<S> a(s.sphere, s.tf1), b(s.box, s.tf2);
  coll::DistanceRequest<S> request(true);
  coll::DistanceResult<S> r1, r2, r3, r4, r5, r6;
  EXPECT_NEAR(coll::distance(&a, &b, request, r1), S(1), S(1e-5));
  EXPECT_NEAR(coll::distance(s.sphere.get(), s.tf1, s.box.get(), s.tf2, request, r2), S(1), S(1e-5));
  EXPECT_NEAR(coll::distance(&a, &b, request, r3, coll::Options()), S(1), S(1e-5));
  EXPECT_NEAR(coll::distance(s.sphere.get(), s.tf1, s.box.get(), s.tf2, request, r4, coll::Options()), S(1),
              S(1e-5));
  const coll::detail::GJKSolver_libccd<S> libccd;
  const coll::detail::GJKSolver_indep<S> indep;
  EXPECT_NEAR(coll::distance(&a, &b, &libccd, request, r5), S(1), S(1e-3));
  EXPECT_NEAR(coll::distance(s.sphere.get(), s.tf1, s.box.get(), s.tf2, &indep, request, r6), S(1), S(1e-3));
}

TYPED_TEST(FclApi, ContinuousCollisionResolvesThroughGqFcl) {
  using S = TypeParam;
  namespace coll = gq::fcl;
  Scene<S> s;
  coll::Transform3<S> start = coll::Transform3<S>::Identity(), end = start;
  start.translation() = coll::Vector3<S>(S(-3), S(0), S(0));
  end.translation() = coll::Vector3<S>(S(3), S(0), S(0));
  const coll::Transform3<S> still = coll::Transform3<S>::Identity();
  coll::ContinuousCollisionRequest<S> request;

  // A sphere swept through a box at the origin hits it; continuousCollide is FCL's, found through gq::fcl.
  coll::ContinuousCollisionResult<S> r1, r2, r3, r4;
  coll::TranslationMotion<S> m1(start, end), m2(still, still);
  coll::continuousCollide(s.sphere.get(), &m1, s.box.get(), &m2, request, r2);
  EXPECT_TRUE(r2.is_collide);
  // FCL 0.7's two overloads that build a motion from two transforms do not compile in float (they instantiate
  // InterpMotion<float>, which is abstract there): called in double only.
  if constexpr (std::is_same_v<S, double>) {
    coll::continuousCollide(s.sphere.get(), start, end, s.box.get(), still, still, request, r1);
    EXPECT_TRUE(r1.is_collide);
    coll::CollisionObject<S> a(s.sphere, start), b(s.box, still);
    coll::continuousCollide(&a, end, &b, still, request, r3);
    EXPECT_TRUE(r3.is_collide);
  }
  coll::ContinuousCollisionObject<S> ca(s.sphere, std::make_shared<coll::TranslationMotion<S>>(start, end));
  coll::ContinuousCollisionObject<S> cb(s.box, std::make_shared<coll::TranslationMotion<S>>(still, still));
  coll::collide(&ca, &cb, request, r4);
  EXPECT_TRUE(r4.is_collide);
  EXPECT_GT(r4.time_of_contact, S(0));
  EXPECT_LT(r4.time_of_contact, S(1));
}

TYPED_TEST(FclApi, ManagerHasFclsPublicMembersTypedefsAndTree) {
  using S = TypeParam;
  namespace coll = gq::fcl;
  using Manager = coll::DynamicAABBTreeCollisionManager<S>;
  static_assert(std::is_base_of_v<::fcl::BroadPhaseCollisionManager<S>, Manager>);
  static_assert(std::is_same_v<typename Manager::DynamicAABBNode, ::fcl::detail::NodeBase<::fcl::AABB<S>>>);
  static_assert(std::is_same_v<typename Manager::DynamicAABBTable,
                               typename ::fcl::DynamicAABBTreeCollisionManager<S>::DynamicAABBTable>);
  Manager m;
  // FCL's defaults.
  EXPECT_EQ(m.max_tree_nonbalanced_level, 10);
  EXPECT_EQ(m.tree_incremental_balance_pass, 10);
  EXPECT_EQ(m.tree_topdown_balance_threshold, 2);
  EXPECT_EQ(m.tree_topdown_level, 0);
  EXPECT_EQ(m.tree_init_level, 0);
  EXPECT_TRUE(m.octree_as_geometry_collide);
  EXPECT_FALSE(m.octree_as_geometry_distance);
  m.max_tree_nonbalanced_level = 5;
  m.tree_incremental_balance_pass = 3;
  m.tree_topdown_balance_threshold = 4;
  m.tree_topdown_level = 1;
  m.octree_as_geometry_collide = false;
  m.octree_as_geometry_distance = true;

  Scene<S> s;
  std::vector<std::unique_ptr<coll::CollisionObject<S>>> objects;
  std::vector<coll::CollisionObject<S>*> raw;
  for (int i = 0; i < 6; ++i) {
    coll::Transform3<S> tf = coll::Transform3<S>::Identity();
    tf.translation() = coll::Vector3<S>(S(0.9) * S(i), S(0), S(0));  // neighbours overlap
    objects.push_back(std::make_unique<coll::CollisionObject<S>>(s.sphere, tf));
    raw.push_back(objects.back().get());
  }
  for (int level : {0, 1, 2, 3}) {  // every FCL init method builds a tree over every object
    m.tree_init_level = level;
    m.clear();
    m.registerObjects(raw);
    m.setup();
    const ::fcl::detail::HierarchyTree<::fcl::AABB<S>>& tree = m.getTree();
    EXPECT_EQ(tree.size(), raw.size()) << level;
    // Its leaves (FCL's const extractLeaves does not compile in 0.7: walked by hand).
    std::vector<const typename Manager::DynamicAABBNode*> leaves, stack{tree.getRoot()};
    while (!stack.empty()) {
      const auto* node = stack.back();
      stack.pop_back();
      if (node->isLeaf()) leaves.push_back(node);
      else stack.insert(stack.end(), {node->children[0], node->children[1]});
    }
    ASSERT_EQ(leaves.size(), raw.size());
    for (const auto* leaf : leaves) EXPECT_TRUE(leaf->bv.contain(static_cast<coll::CollisionObject<S>*>(leaf->data)->getTranslation()));
  }

  // Every manager member, through the base class as FCL's hosts use it.
  ::fcl::BroadPhaseCollisionManager<S>& base = m;
  base.unregisterObject(raw.back());
  base.registerObject(raw.back());
  base.update();
  base.update(raw.front());
  base.update(raw);
  std::vector<coll::CollisionObject<S>*> got;
  base.getObjects(got);
  EXPECT_EQ(got.size(), raw.size());
  EXPECT_FALSE(base.empty());
  EXPECT_EQ(base.size(), raw.size());

  coll::DefaultCollisionData<S> self;
  self.request.num_max_contacts = 100;
  base.collide(&self, coll::DefaultCollisionFunction<S>);
  EXPECT_EQ(self.result.numContacts(), raw.size() - 1);  // each neighbour pair once

  coll::DefaultCollisionData<S> one;
  base.collide(raw.front(), &one, coll::DefaultCollisionFunction<S>);
  EXPECT_TRUE(one.result.isCollision());

  coll::DefaultDistanceData<S> selfDistance;
  base.distance(&selfDistance, coll::DefaultDistanceFunction<S>);
  EXPECT_LE(selfDistance.result.min_distance, S(0));

  coll::Transform3<S> far = coll::Transform3<S>::Identity();
  far.translation() = coll::Vector3<S>(S(0), S(3), S(0));
  coll::CollisionObject<S> lone(s.sphere, far);
  coll::DefaultDistanceData<S> oneDistance;
  base.distance(&lone, &oneDistance, coll::DefaultDistanceFunction<S>);
  EXPECT_NEAR(oneDistance.result.min_distance, S(2), S(1e-4));

  Manager other;
  other.registerObject(&lone);
  other.setup();
  coll::DefaultCollisionData<S> cross;
  base.collide(&other, &cross, coll::DefaultCollisionFunction<S>);
  EXPECT_FALSE(cross.result.isCollision());
  coll::DefaultDistanceData<S> crossDistance;
  base.distance(&other, &crossDistance, coll::DefaultDistanceFunction<S>);
  EXPECT_NEAR(crossDistance.result.min_distance, S(2), S(1e-4));

  base.clear();
  EXPECT_TRUE(base.empty());
  EXPECT_EQ(m.getTree().size(), 0u);
}

TEST(FclApi, ManagerTypedefsExistInBothPrecisions) {
  static_assert(std::is_same_v<gq::fcl::DynamicAABBTreeCollisionManagerf, gq::fcl::DynamicAABBTreeCollisionManager<float>>);
  static_assert(std::is_same_v<gq::fcl::DynamicAABBTreeCollisionManagerd, gq::fcl::DynamicAABBTreeCollisionManager<double>>);
  gq::fcl::DynamicAABBTreeCollisionManagerd m;
  EXPECT_TRUE(m.empty());
}

}  // namespace
