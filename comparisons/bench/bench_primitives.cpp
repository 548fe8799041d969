// Primitive pairs (sphere, capsule, box) in double: gq vs FCL 0.7 (default GST_LIBCCD request, as hosts use it) on
// the same 64 seeded pose pairs per pair type, about half of them overlapping. Three queries per pair:
//  - overlap:      gq::overlap            vs fcl::collide, enable_contact = false
//  - contact:      gq::computePenetration vs fcl::collide, enable_contact = true, one contact (normal, depth, point)
//  - distance:     gq::distance           vs fcl::distance, signed, nearest points
// Rows `gq` query prepared shapes (gq::Shape, made once outside the timed loop, as FCL's collision objects are);
// rows `gq_geometry` pass the Geometry<T> itself, validated on every call.
// FCL's capsule lies along local Z with full length lz; gq's along local X with a half height: FCL poses are the gq
// pose times Ry(90 deg), which carries Z onto X, so both libraries see the same solids.
// Counter `hits` = pairs reported overlapping (both backends must agree on it).
#include <benchmark/benchmark.h>
#include <fcl/fcl.h>

#include <memory>
#include <random>
#include <vector>

#include "gq/query.h"
#include "gq/shape.h"

namespace {

constexpr int kPairs = 64;
enum class Shape { Sphere, Capsule, Box };

gq::Geometry<double> gqShape(Shape s) {
  switch (s) {
    case Shape::Sphere: return gq::SphereGeometry<double>(0.5);
    case Shape::Capsule: return gq::CapsuleGeometry<double>(0.3, 0.5);
    case Shape::Box: break;
  }
  return gq::BoxGeometry<double>(gq::Vec3<double>(0.5, 0.4, 0.3));
}

std::shared_ptr<fcl::CollisionGeometryd> fclShape(Shape s) {
  switch (s) {
    case Shape::Sphere: return std::make_shared<fcl::Sphered>(0.5);
    case Shape::Capsule: return std::make_shared<fcl::Capsuled>(0.3, 1.0);
    case Shape::Box: break;
  }
  return std::make_shared<fcl::Boxd>(1.0, 0.8, 0.6);
}

struct Poses {
  std::vector<gq::Transform<double>> a, b;
};

const Poses& poses() {
  static const Poses p = [] {
    Poses out;
    std::mt19937_64 gen(2026);
    std::uniform_real_distribution<double> u(-0.9, 0.9);
    std::normal_distribution<double> n;
    const auto pose = [&] {
      return gq::Transform<double>(gq::Vec3<double>(u(gen), u(gen), u(gen)),
                                   gq::Quat<double>(n(gen), n(gen), n(gen), n(gen)).normalized());
    };
    for (int i = 0; i < kPairs; ++i) {
      out.a.push_back(pose());
      out.b.push_back(pose());
    }
    return out;
  }();
  return p;
}

fcl::Transform3d fclPose(const gq::Transform<double>& p, Shape s) {
  if (s != Shape::Capsule) return p.toIsometry();
  const Eigen::AngleAxisd zToX(EIGEN_PI / 2, Eigen::Vector3d::UnitY());
  return p.toIsometry() * zToX;
}

enum class Query { Overlap, Contact, Distance };

template <class G>
void runGq(benchmark::State& state, const G& g0, const G& g1, Query q) {
  const Poses& p = poses();
  int hits = 0;
  for (auto _ : state) {
    hits = 0;
    for (int i = 0; i < kPairs; ++i) {
      if (q == Query::Overlap) {
        bool hit = false;
        (void)gq::overlap(g0, p.a[i], g1, p.b[i], hit);  // valid inputs: Ok (the counter checks the answers)
        hits += hit;
      } else if (q == Query::Contact) {
        gq::PenetrationResult<double> r;
        (void)gq::computePenetration(r, g0, p.a[i], g1, p.b[i]);
        hits += r.penetrating;
        benchmark::DoNotOptimize(r);
      } else {
        gq::DistanceResult<double> r;
        (void)gq::distance(r, g0, p.a[i], g1, p.b[i]);
        hits += r.distance <= 0;
        benchmark::DoNotOptimize(r);
      }
    }
  }
  state.counters["hits"] = hits;
  state.SetItemsProcessed(state.iterations() * kPairs);
}

void BM_gq(benchmark::State& state, Shape s0, Shape s1, Query q) {
  gq::Shape<double> g0, g1;
  if (!gq::Shape<double>::make(gqShape(s0), g0).ok() || !gq::Shape<double>::make(gqShape(s1), g1).ok()) {
    state.SkipWithError("shape rejected");
    return;
  }
  runGq(state, g0, g1, q);
}

void BM_gq_geometry(benchmark::State& state, Shape s0, Shape s1, Query q) {
  runGq(state, gqShape(s0), gqShape(s1), q);
}

void BM_fcl(benchmark::State& state, Shape s0, Shape s1, Query q) {
  const Poses& p = poses();
  std::vector<std::unique_ptr<fcl::CollisionObjectd>> o0, o1;
  for (int i = 0; i < kPairs; ++i) {
    o0.push_back(std::make_unique<fcl::CollisionObjectd>(fclShape(s0), fclPose(p.a[i], s0)));
    o1.push_back(std::make_unique<fcl::CollisionObjectd>(fclShape(s1), fclPose(p.b[i], s1)));
  }
  fcl::CollisionRequestd collide;
  collide.enable_contact = q == Query::Contact;
  fcl::DistanceRequestd dist;
  dist.enable_signed_distance = true;
  dist.enable_nearest_points = true;
  int hits = 0;
  for (auto _ : state) {
    hits = 0;
    for (int i = 0; i < kPairs; ++i) {
      if (q == Query::Distance) {
        fcl::DistanceResultd r;
        fcl::distance(o0[i].get(), o1[i].get(), dist, r);
        hits += r.min_distance <= 0;
        benchmark::DoNotOptimize(r);
      } else {
        fcl::CollisionResultd r;
        fcl::collide(o0[i].get(), o1[i].get(), collide, r);
        hits += r.isCollision();
        benchmark::DoNotOptimize(r);
      }
    }
  }
  state.counters["hits"] = hits;
  state.SetItemsProcessed(state.iterations() * kPairs);
}

struct PairName {
  Shape s0, s1;
  const char* name;
};
const PairName kPairList[] = {{Shape::Sphere, Shape::Sphere, "sphere_sphere"},   {Shape::Sphere, Shape::Capsule, "sphere_capsule"},
                              {Shape::Sphere, Shape::Box, "sphere_box"},         {Shape::Capsule, Shape::Capsule, "capsule_capsule"},
                              {Shape::Capsule, Shape::Box, "capsule_box"},       {Shape::Box, Shape::Box, "box_box"}};
const std::pair<Query, const char*> kQueries[] = {
    {Query::Overlap, "overlap"}, {Query::Contact, "contact"}, {Query::Distance, "distance"}};

const bool kRegistered = [] {
  for (const auto& [query, qname] : kQueries)
    for (const PairName& pair : kPairList) {
      const std::string stem = std::string(qname) + "/" + pair.name;
      benchmark::RegisterBenchmark((stem + "/gq").c_str(), BM_gq, pair.s0, pair.s1, query);
      benchmark::RegisterBenchmark((stem + "/gq_geometry").c_str(), BM_gq_geometry, pair.s0, pair.s1, query);
      benchmark::RegisterBenchmark((stem + "/fcl").c_str(), BM_fcl, pair.s0, pair.s1, query);
    }
  return true;
}();

}  // namespace

BENCHMARK_MAIN();
