// gq::distance (GJK/EPA, hill-climbing support) vs libccd's ccdGJKIntersect / ccdGJKPenetration, FCL 0.7's
// GST_INDEP solver (fcl::distance with signed distance, fcl::collide) on fcl::Convex, and Bullet's (float64 build)
// btGjkPairDetector + btGjkEpaPenetrationDepthSolver on margin-free btConvexHullShape, all on the same convex hulls
// (30, 100, 300 random points on an ellipsoid, all hull vertices) and the same 64 seeded pose pairs (about half of
// them overlapping), plus box-box, capsule-box and cylinder-box (gq's custom CylinderCallbacks) on the 30-point
// scene's poses (libccd only). Also the boolean
// overlaps: gq's GJK early-out kernel and the public gq::overlap vs ccdGJKIntersect and fcl::collide. And the
// penetration depth (MTD) of hull pairs on 64 overlapping pose pairs (drawn as above, the separated ones skipped):
// gq::computePenetration (exact) and gq::distance (signed: EPA) vs libccd's ccdGJKPenetration and
// ccdMPRPenetration, Bullet's GJK + EPA and FCL's collide with a contact (GST_LIBCCD). Counters:
// `overlapping` = pairs the backend reported as intersecting. `--once-penetration-errors N` prints each
// penetration backend's depth error against the exact MTD (long double SAT over every face normal and edge pair).
#include <BulletCollision/CollisionShapes/btConvexHullShape.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkEpaPenetrationDepthSolver.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkPairDetector.h>
#include <BulletCollision/NarrowPhaseCollision/btPointCollector.h>
#include <BulletCollision/NarrowPhaseCollision/btVoronoiSimplexSolver.h>
#include <benchmark/benchmark.h>
#include <ccd/ccd.h>
#include <fcl/fcl.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "gq/cooking.h"
#include "gq/custom_shapes.h"
#include "gq/query.h"
#include "gjk/gjk.h"
#if GQ_BENCH_PENETRATION_ERRORS
#include "exact_polytope.h"  // tests/urdf: the long double SAT referee
#endif

namespace {

constexpr int kPairs = 64;

struct Scene {
  std::shared_ptr<const gq::ConvexMesh<double>> hull;
  std::vector<gq::Transform<double>> pose0, pose1;
};

std::shared_ptr<const gq::ConvexMesh<double>> randomHull(int n, std::mt19937_64& gen) {
  std::normal_distribution<double> normal;
  std::vector<gq::Vec3<double>> pts;
  for (int i = 0; i < n; ++i)
    pts.push_back(gq::Vec3<double>(normal(gen), normal(gen), normal(gen)).normalized().cwiseProduct(gq::Vec3<double>(1, 0.8, 0.6)));
  std::shared_ptr<const gq::ConvexMesh<double>> out;
  if (!gq::cookConvexMesh(pts, out).ok()) return nullptr;
  return out;
}

const Scene& scene(int n) {
  static std::vector<std::unique_ptr<Scene>> cache(512);
  if (!cache[n]) {
    auto s = std::make_unique<Scene>();
    std::mt19937_64 gen(1234 + n);
    s->hull = randomHull(n, gen);
    std::uniform_real_distribution<double> u(-1.1, 1.1);
    std::normal_distribution<double> normal;
    for (int i = 0; i < kPairs; ++i) {
      const auto rot = [&] { return gq::Quat<double>(normal(gen), normal(gen), normal(gen), normal(gen)).normalized(); };
      s->pose0.emplace_back(gq::Vec3<double>(u(gen), u(gen), u(gen)), rot());
      s->pose1.emplace_back(gq::Vec3<double>(u(gen), u(gen), u(gen)), rot());
    }
    cache[n] = std::move(s);
  }
  return *cache[n];
}

// The same hull and pose distribution, only the overlapping pairs (gq::distance < 0), 64 of them.
const Scene& overlappingScene(int n) {
  static std::vector<std::unique_ptr<Scene>> cache(512);
  if (!cache[n]) {
    auto s = std::make_unique<Scene>();
    std::mt19937_64 gen(1234 + n);
    s->hull = randomHull(n, gen);
    std::uniform_real_distribution<double> u(-1.1, 1.1);
    std::normal_distribution<double> normal;
    const gq::Geometry<double> hull = gq::ConvexMeshGeometry<double>(s->hull);
    while (s->hull && int(s->pose0.size()) < kPairs) {
      const auto rot = [&] { return gq::Quat<double>(normal(gen), normal(gen), normal(gen), normal(gen)).normalized(); };
      const gq::Transform<double> p0(gq::Vec3<double>(u(gen), u(gen), u(gen)), rot());
      const gq::Transform<double> p1(gq::Vec3<double>(u(gen), u(gen), u(gen)), rot());
      gq::DistanceResult<double> r;
      if (!gq::distance(r, hull, p0, hull, p1).ok() || !(r.distance < 0)) continue;
      s->pose0.push_back(p0);
      s->pose1.push_back(p1);
    }
    cache[n] = std::move(s);
  }
  return *cache[n];
}

// ---- runners: one pass over the 64 pairs, noinline so that callgrind reports each one's instruction count ------
// (`bench_convex_distance --once` runs every runner once per size and exits: for callgrind, see the results CSV).
using Caches = std::vector<gq::GjkCache<double>>;

[[gnu::noinline]] int runGqDistance(const Scene& s, const gq::Geometry<double>& g0, const gq::Geometry<double>& g1,
                                    Caches* caches) {
  int overlapping = 0;
  for (int i = 0; i < kPairs; ++i) {
    gq::DistanceResult<double> r;
    (void)gq::distance(r, g0, s.pose0[i], g1, s.pose1[i], caches ? &(*caches)[i] : nullptr);  // valid input: timed
    overlapping += r.distance <= 0;
    benchmark::DoNotOptimize(r);
  }
  return overlapping;
}

// Boolean GJK (stops at the first separating axis), the kernel behind gq's custom-shape and mesh overlaps.
[[gnu::noinline]] int runGqGjkOverlap(const Scene& s, const gq::Geometry<double>& g0, const gq::Geometry<double>& g1) {
  int overlapping = 0;
  for (int i = 0; i < kPairs; ++i)
    overlapping += gq::detail::gjkOverlap(gq::detail::makeConvexShape(g0, s.pose0[i]), gq::detail::makeConvexShape(g1, s.pose1[i]));
  return overlapping;
}

// Public gq::overlap (convex-convex is SAT there; primitives use closed forms).
[[gnu::noinline]] int runGqOverlap(const Scene& s, const gq::Geometry<double>& g0, const gq::Geometry<double>& g1) {
  int overlapping = 0;
  for (int i = 0; i < kPairs; ++i) {
    bool hit = false;
    (void)gq::overlap(g0, s.pose0[i], g1, s.pose1[i], hit);  // valid input: timed
    overlapping += hit;
  }
  return overlapping;
}

[[gnu::noinline]] int runGqPenetration(const Scene& s, const gq::Geometry<double>& g0, const gq::Geometry<double>& g1) {
  int overlapping = 0;
  for (int i = 0; i < kPairs; ++i) {
    gq::PenetrationResult<double> r;
    (void)gq::computePenetration(r, g0, s.pose0[i], g1, s.pose1[i]);  // valid input: timed
    overlapping += r.penetrating;
    benchmark::DoNotOptimize(r);
  }
  return overlapping;
}

// ---- libccd -------------------------------------------------------------------------------------------------
// libccd gets an exhaustive support function over the hull vertices (as its users usually write it) and closed
// forms for boxes and capsules.
struct CcdShape {
  const gq::Geometry<double>* geom;
  gq::Transform<double> pose;
};

gq::Vec3<double> ccdLocalSupport(const gq::Geometry<double>& g, const gq::Vec3<double>& d) {
  if (const auto* h = g.getIf<gq::ConvexMeshGeometry<double>>()) {
    const gq::Vec3<double>* best = &h->mesh->vertices[0];
    double bestDot = best->dot(d);
    for (const auto& v : h->mesh->vertices)
      if (v.dot(d) > bestDot) { bestDot = v.dot(d); best = &v; }
    return *best;
  }
  if (const auto* c = g.getIf<gq::CustomGeometry<double>>()) return c->callbacks->support(d);
  if (const auto* b = g.getIf<gq::BoxGeometry<double>>())
    return gq::Vec3<double>(d.x() < 0 ? -b->halfExtents.x() : b->halfExtents.x(), d.y() < 0 ? -b->halfExtents.y() : b->halfExtents.y(),
                            d.z() < 0 ? -b->halfExtents.z() : b->halfExtents.z());
  const auto& c = g.get<gq::CapsuleGeometry<double>>();
  const double n = d.norm();
  const gq::Vec3<double> tip(d.x() < 0 ? -c.halfHeight : c.halfHeight, 0, 0);
  return n > 0 ? gq::Vec3<double>(tip + c.radius * d / n) : tip;
}

void ccdSupport(const void* obj, const ccd_vec3_t* dir, ccd_vec3_t* out) {
  const auto* h = static_cast<const CcdShape*>(obj);
  const gq::Vec3<double> d = h->pose.rotateInv(gq::Vec3<double>(dir->v[0], dir->v[1], dir->v[2]));
  const gq::Vec3<double> p = h->pose.transform(ccdLocalSupport(*h->geom, d));
  ccdVec3Set(out, p.x(), p.y(), p.z());
}

void ccdCenter(const void* obj, ccd_vec3_t* out) {
  const auto* h = static_cast<const CcdShape*>(obj);
  const auto* hull = h->geom->getIf<gq::ConvexMeshGeometry<double>>();
  const gq::Vec3<double> c = h->pose.transform(hull ? hull->mesh->center : gq::Vec3<double>::Zero());
  ccdVec3Set(out, c.x(), c.y(), c.z());
}

ccd_t makeCcd() {
  ccd_t ccd;
  CCD_INIT(&ccd);
  ccd.support1 = ccdSupport;
  ccd.support2 = ccdSupport;
  ccd.center1 = ccdCenter;
  ccd.center2 = ccdCenter;
  ccd.max_iterations = 128;
  ccd.epa_tolerance = 1e-12;
  ccd.dist_tolerance = 1e-12;
  return ccd;
}

[[gnu::noinline]] int runCcdIntersect(const Scene& s, const gq::Geometry<double>& g0, const gq::Geometry<double>& g1) {
  const ccd_t ccd = makeCcd();
  int overlapping = 0;
  for (int i = 0; i < kPairs; ++i) {
    const CcdShape a{&g0, s.pose0[i]}, b{&g1, s.pose1[i]};
    overlapping += ccdGJKIntersect(&a, &b, &ccd);
  }
  return overlapping;
}

// libccd's penetration solvers share one signature: GJK+EPA (ccdGJKPenetration) and MPR (ccdMPRPenetration).
using CcdPenetrationSolver = int (*)(const void*, const void*, const ccd_t*, ccd_real_t*, ccd_vec3_t*, ccd_vec3_t*);

[[gnu::noinline]] int runCcdPenetrationWith(CcdPenetrationSolver solve, const Scene& s, const gq::Geometry<double>& g0,
                                            const gq::Geometry<double>& g1) {
  const ccd_t ccd = makeCcd();
  int overlapping = 0;
  for (int i = 0; i < kPairs; ++i) {
    const CcdShape a{&g0, s.pose0[i]}, b{&g1, s.pose1[i]};
    ccd_real_t depth;
    ccd_vec3_t dir, pos;
    overlapping += solve(&a, &b, &ccd, &depth, &dir, &pos) == 0;
    benchmark::DoNotOptimize(depth);
  }
  return overlapping;
}
int runCcdPenetration(const Scene& s, const gq::Geometry<double>& g0, const gq::Geometry<double>& g1) {
  return runCcdPenetrationWith(ccdGJKPenetration, s, g0, g1);
}
int runCcdMprPenetration(const Scene& s, const gq::Geometry<double>& g0, const gq::Geometry<double>& g1) {
  return runCcdPenetrationWith(ccdMPRPenetration, s, g0, g1);
}

// ---- FCL (GST_INDEP) ------------------------------------------------------------------------------------------
struct FclScene {
  std::vector<std::unique_ptr<fcl::CollisionObjectd>> o0, o1;
};

std::shared_ptr<fcl::Convexd> fclHull(const gq::ConvexMesh<double>& hull) {
  auto vertices = std::make_shared<std::vector<fcl::Vector3d>>(hull.vertices.begin(), hull.vertices.end());
  auto faces = std::make_shared<std::vector<int>>();
  for (const auto& poly : hull.polygons) {
    faces->push_back(int(poly.indexCount));
    for (std::uint32_t k = 0; k < poly.indexCount; ++k) faces->push_back(int(hull.polygonVertices[poly.indexBase + k]));
  }
  return std::make_shared<fcl::Convexd>(vertices, int(hull.polygons.size()), faces);
}

const FclScene& fclScene(const Scene& s) {
  static std::map<const Scene*, FclScene> cache;
  FclScene& f = cache[&s];
  if (f.o0.empty()) {
    const std::shared_ptr<fcl::Convexd> hull = fclHull(*s.hull);
    for (int i = 0; i < kPairs; ++i) {
      f.o0.push_back(std::make_unique<fcl::CollisionObjectd>(hull, s.pose0[i].toIsometry()));
      f.o1.push_back(std::make_unique<fcl::CollisionObjectd>(hull, s.pose1[i].toIsometry()));
    }
  }
  return f;
}

[[gnu::noinline]] int runFclDistance(const FclScene& f) {
  // Unsigned: with enable_signed_distance, FCL 0.7 answers an overlapping Convex pair by collide() with contacts,
  // which under GST_INDEP returns none, and then trips its own assertion (distance-inl.h: index != -1).
  fcl::DistanceRequestd request;
  request.gjk_solver_type = fcl::GST_INDEP;
  request.enable_nearest_points = true;
  int overlapping = 0;
  for (int i = 0; i < kPairs; ++i) {
    fcl::DistanceResultd r;
    fcl::distance(f.o0[i].get(), f.o1[i].get(), request, r);
    overlapping += r.min_distance <= 0;
    benchmark::DoNotOptimize(r);
  }
  return overlapping;
}

[[gnu::noinline]] int runFclCollide(const FclScene& f) {
  fcl::CollisionRequestd request;
  request.gjk_solver_type = fcl::GST_INDEP;
  int overlapping = 0;
  for (int i = 0; i < kPairs; ++i) {
    fcl::CollisionResultd r;
    fcl::collide(f.o0[i].get(), f.o1[i].get(), request, r);
    overlapping += r.isCollision();
  }
  return overlapping;
}

// Penetration depth through collide() with one contact; GST_LIBCCD (GST_INDEP returns no contact for Convex pairs).
[[gnu::noinline]] int runFclPenetration(const FclScene& f) {
  fcl::CollisionRequestd request;
  request.gjk_solver_type = fcl::GST_LIBCCD;
  request.enable_contact = true;
  request.num_max_contacts = 1;
  int overlapping = 0;
  for (int i = 0; i < kPairs; ++i) {
    fcl::CollisionResultd r;
    fcl::collide(f.o0[i].get(), f.o1[i].get(), request, r);
    overlapping += r.numContacts() > 0;
    benchmark::DoNotOptimize(r);
  }
  return overlapping;
}

// ---- Bullet (float64) ----------------------------------------------------------------------------------------
btTransform bulletPose(const gq::Transform<double>& p) {
  return btTransform(btQuaternion(p.q.x(), p.q.y(), p.q.z(), p.q.w()), btVector3(p.p.x(), p.p.y(), p.p.z()));
}

std::unique_ptr<btConvexHullShape> bulletHull(const gq::ConvexMesh<double>& hull) {
  auto shape = std::make_unique<btConvexHullShape>();
  for (const auto& v : hull.vertices) shape->addPoint(btVector3(v.x(), v.y(), v.z()), false);
  shape->recalcLocalAabb();
  shape->setMargin(0);  // margin-free: the exact hull, as gq and libccd see it
  return shape;
}

// One pair through Bullet's GJK, with EPA when the hulls overlap (as btConvexConvexAlgorithm uses them).
inline btPointCollector bulletClosestPoints(const btConvexHullShape& hull, btVoronoiSimplexSolver& simplex,
                                            btGjkEpaPenetrationDepthSolver& epa, const gq::Transform<double>& p0,
                                            const gq::Transform<double>& p1) {
  btGjkPairDetector gjk(&hull, &hull, &simplex, &epa);
  btGjkPairDetector::ClosestPointInput input;
  input.m_transformA = bulletPose(p0);
  input.m_transformB = bulletPose(p1);
  btPointCollector out;
  gjk.getClosestPoints(input, out, nullptr);
  return out;
}

[[gnu::noinline]] int runBulletDistance(const Scene& s, const btConvexHullShape& hull) {
  btVoronoiSimplexSolver simplex;
  btGjkEpaPenetrationDepthSolver epa;
  int overlapping = 0;
  for (int i = 0; i < kPairs; ++i) {
    const btPointCollector out = bulletClosestPoints(hull, simplex, epa, s.pose0[i], s.pose1[i]);
    overlapping += out.m_hasResult && out.m_distance <= 0;
    benchmark::DoNotOptimize(out);
  }
  return overlapping;
}

// ---- penetration rows: the overlapping scene, hull vs hull ------------------------------------------------------
template <class Run> void benchOverlapping(benchmark::State& state, Run run) {
  const Scene& s = overlappingScene(int(state.range(0)));
  if (!s.hull) return state.SkipWithError("convex cooking failed");
  const gq::Geometry<double> hull = gq::ConvexMeshGeometry<double>(s.hull);
  int overlapping = 0;
  for (auto _ : state) overlapping = run(s, hull);
  state.counters["overlapping"] = overlapping;
  state.SetItemsProcessed(state.iterations() * kPairs);
}

void BM_PenGqPenetration(benchmark::State& state) {
  benchOverlapping(state, [](const Scene& s, const gq::Geometry<double>& h) { return runGqPenetration(s, h, h); });
}
void BM_PenGqDistance(benchmark::State& state) {
  benchOverlapping(state, [](const Scene& s, const gq::Geometry<double>& h) { return runGqDistance(s, h, h, nullptr); });
}
void BM_PenCcdGJKPenetration(benchmark::State& state) {
  benchOverlapping(state, [](const Scene& s, const gq::Geometry<double>& h) { return runCcdPenetration(s, h, h); });
}
void BM_PenCcdMPRPenetration(benchmark::State& state) {
  benchOverlapping(state, [](const Scene& s, const gq::Geometry<double>& h) { return runCcdMprPenetration(s, h, h); });
}
void BM_PenFclCollideContact(benchmark::State& state) {
  benchOverlapping(state, [](const Scene& s, const gq::Geometry<double>&) { return runFclPenetration(fclScene(s)); });
}
void BM_PenBulletGjkEpa(benchmark::State& state) {
  const Scene& s = overlappingScene(int(state.range(0)));
  if (!s.hull) return state.SkipWithError("convex cooking failed");
  const std::unique_ptr<btConvexHullShape> hull = bulletHull(*s.hull);
  benchOverlapping(state, [&](const Scene& sc, const gq::Geometry<double>&) { return runBulletDistance(sc, *hull); });
}

// ---- shape pairs --------------------------------------------------------------------------------------------
// Arg: 30/100/300 = hull vs hull with that many points; 1 = box vs box; 2 = capsule vs box; 3 = cylinder vs box.
struct Pair {
  gq::Geometry<double> g0, g1;
};

Pair pairFor(int arg, const Scene& s) {
  const gq::Geometry<double> box = gq::BoxGeometry<double>(gq::Vec3<double>(0.9, 0.6, 0.4));
  if (arg == 1) return {box, box};
  if (arg == 2) return {gq::CapsuleGeometry<double>(0.3, 0.7), box};
  if (arg == 3) return {gq::CustomGeometry<double>(std::make_shared<gq::CylinderCallbacks<double>>(0.4, 0.6)), box};
  const gq::Geometry<double> hull = gq::ConvexMeshGeometry<double>(s.hull);
  return {hull, hull};
}

const Scene& sceneFor(int arg) { return scene(arg < 4 ? 30 : arg); }

template <class Run> void benchPairs(benchmark::State& state, Run run) {
  const Scene& s = sceneFor(int(state.range(0)));
  if (!s.hull) return state.SkipWithError("convex cooking failed");
  const Pair p = pairFor(int(state.range(0)), s);
  int overlapping = 0;
  for (auto _ : state) overlapping = run(s, p);
  state.counters["overlapping"] = overlapping;
  state.SetItemsProcessed(state.iterations() * kPairs);
}

void BM_GqDistance(benchmark::State& state) {
  benchPairs(state, [](const Scene& s, const Pair& p) { return runGqDistance(s, p.g0, p.g1, nullptr); });
}

// Same poses, second call per pair with the GJK cache of the first (frame-to-frame coherence at zero motion).
void BM_GqDistanceWarm(benchmark::State& state) {
  Caches caches(kPairs);
  bool primed = false;
  benchPairs(state, [&](const Scene& s, const Pair& p) {
    if (!primed) runGqDistance(s, p.g0, p.g1, &caches);
    primed = true;
    return runGqDistance(s, p.g0, p.g1, &caches);
  });
}

void BM_GqGjkOverlap(benchmark::State& state) {
  benchPairs(state, [](const Scene& s, const Pair& p) { return runGqGjkOverlap(s, p.g0, p.g1); });
}
void BM_GqOverlap(benchmark::State& state) {
  benchPairs(state, [](const Scene& s, const Pair& p) { return runGqOverlap(s, p.g0, p.g1); });
}
void BM_CcdGJKIntersect(benchmark::State& state) {
  benchPairs(state, [](const Scene& s, const Pair& p) { return runCcdIntersect(s, p.g0, p.g1); });
}
void BM_CcdGJKPenetration(benchmark::State& state) {
  benchPairs(state, [](const Scene& s, const Pair& p) { return runCcdPenetration(s, p.g0, p.g1); });
}

void BM_FclIndepDistance(benchmark::State& state) {
  benchPairs(state, [](const Scene& s, const Pair&) { return runFclDistance(fclScene(s)); });
}
void BM_FclIndepCollide(benchmark::State& state) {
  benchPairs(state, [](const Scene& s, const Pair&) { return runFclCollide(fclScene(s)); });
}
void BM_BulletGjkEpaDistance(benchmark::State& state) {
  const Scene& s = sceneFor(int(state.range(0)));
  if (!s.hull) return state.SkipWithError("convex cooking failed");
  const std::unique_ptr<btConvexHullShape> hull = bulletHull(*s.hull);
  benchPairs(state, [&](const Scene& sc, const Pair&) { return runBulletDistance(sc, *hull); });
}

// Second pass with the caches of a first (primed outside so that callgrind counts only the warm calls here).
[[gnu::noinline]] int runGqDistanceWarm(const Scene& s, const gq::Geometry<double>& g0, const gq::Geometry<double>& g1,
                                        Caches& caches) {
  return runGqDistance(s, g0, g1, &caches);
}

// One pass of every runner for one shape pair (`--once ARG`) or all of them (`--once`), for
// `valgrind --tool=callgrind` instruction counts (inclusive cost of each run* function / 64 = per query).
// The overlapping scene in float: the same hull points cooked in float, the same poses.
struct FloatScene {
  std::shared_ptr<const gq::ConvexMesh<float>> hull;
  std::vector<gq::Transform<float>> pose0, pose1;
};

FloatScene floatScene(const Scene& s) {
  FloatScene f;
  std::vector<gq::Vec3<float>> pts;
  for (const gq::Vec3<double>& v : s.hull->vertices) pts.push_back(v.cast<float>());
  if (!gq::cookConvexMesh(pts, f.hull).ok()) f.hull = nullptr;
  const auto cast = [](const gq::Transform<double>& p) {
    return gq::Transform<float>(p.p.cast<float>(), p.q.cast<float>().normalized());
  };
  for (const gq::Transform<double>& p : s.pose0) f.pose0.push_back(cast(p));
  for (const gq::Transform<double>& p : s.pose1) f.pose1.push_back(cast(p));
  return f;
}

[[gnu::noinline]] int runGqPenetrationFloat(const FloatScene& s, const gq::Geometry<float>& g0,
                                            const gq::Geometry<float>& g1) {
  int overlapping = 0;
  for (std::size_t i = 0; i < s.pose0.size(); ++i) {
    gq::PenetrationResult<float> r;
    (void)gq::computePenetration(r, g0, s.pose0[i], g1, s.pose1[i]);  // valid input: timed
    overlapping += r.penetrating;
    benchmark::DoNotOptimize(r);
  }
  return overlapping;
}

[[gnu::noinline]] int runGqDistanceFloat(const FloatScene& s, const gq::Geometry<float>& g0,
                                         const gq::Geometry<float>& g1) {
  int overlapping = 0;
  for (std::size_t i = 0; i < s.pose0.size(); ++i) {
    gq::DistanceResult<float> r;
    (void)gq::distance(r, g0, s.pose0[i], g1, s.pose1[i]);  // valid input: timed
    overlapping += r.distance <= 0;
    benchmark::DoNotOptimize(r);
  }
  return overlapping;
}

// `--once-penetration N`: the penetration rows' runners once on the overlapping scene of N-point hulls, then gq's
// computePenetration and distance on the same scene in float (the hull's per-mesh caches built first).
void runOncePenetration(int n) {
  const Scene& s = overlappingScene(n);
  const gq::Geometry<double> hull = gq::ConvexMeshGeometry<double>(s.hull);
  gq::PenetrationResult<double> warm;
  (void)gq::computePenetration(warm, hull, s.pose0[0], hull, s.pose1[0]);
  runGqPenetration(s, hull, hull);
  runGqDistance(s, hull, hull, nullptr);
  runCcdPenetration(s, hull, hull);
  runCcdMprPenetration(s, hull, hull);
  runFclPenetration(fclScene(s));
  runBulletDistance(s, *bulletHull(*s.hull));
  const FloatScene f = floatScene(s);
  if (!f.hull) return;
  const gq::Geometry<float> hullF = gq::ConvexMeshGeometry<float>(f.hull);
  gq::PenetrationResult<float> warmF;
  (void)gq::computePenetration(warmF, hullF, f.pose0[0], hullF, f.pose1[0]);
  const int penetratingF = runGqPenetrationFloat(f, hullF, hullF);
  const int overlappingF = runGqDistanceFloat(f, hullF, hullF);
  std::printf("float: %d of %d penetrating (distance: %d)\n", penetratingF, kPairs, overlappingF);
}

// `--once-penetration-shapes N`: a sphere, a capsule and a box (geom0 at pose0) against the N-point hull (at pose1)
// on the overlapping scene's poses, computePenetration and distance, each through its own runner (each makes its
// own shape, so that the linker cannot fold them into one); then the same in float (the hull's points cooked in
// float, the poses cast).
int penetrationPass(const Scene& s, const gq::Geometry<double>& g0, const gq::Geometry<double>& g1) {
  return runGqPenetration(s, g0, g1);
}
int penetrationPass(const FloatScene& s, const gq::Geometry<float>& g0, const gq::Geometry<float>& g1) {
  return runGqPenetrationFloat(s, g0, g1);
}
int distancePass(const Scene& s, const gq::Geometry<double>& g0, const gq::Geometry<double>& g1) {
  return runGqDistance(s, g0, g1, nullptr);
}
int distancePass(const FloatScene& s, const gq::Geometry<float>& g0, const gq::Geometry<float>& g1) {
  return runGqDistanceFloat(s, g0, g1);
}

template <class T> gq::Geometry<T> sphereShape() { return gq::SphereGeometry<T>(T(0.5)); }
template <class T> gq::Geometry<T> capsuleShape() { return gq::CapsuleGeometry<T>(T(0.3), T(0.7)); }
template <class T> gq::Geometry<T> boxShape() { return gq::BoxGeometry<T>(gq::Vec3<T>(T(0.9), T(0.6), T(0.4))); }

template <class S, class T> [[gnu::noinline]] int runSphereHullPenetration(const S& s, const gq::Geometry<T>& hull) {
  return penetrationPass(s, sphereShape<T>(), hull);
}
template <class S, class T> [[gnu::noinline]] int runSphereHullDistance(const S& s, const gq::Geometry<T>& hull) {
  return distancePass(s, sphereShape<T>(), hull);
}
template <class S, class T> [[gnu::noinline]] int runCapsuleHullPenetration(const S& s, const gq::Geometry<T>& hull) {
  return penetrationPass(s, capsuleShape<T>(), hull);
}
template <class S, class T> [[gnu::noinline]] int runCapsuleHullDistance(const S& s, const gq::Geometry<T>& hull) {
  return distancePass(s, capsuleShape<T>(), hull);
}
template <class S, class T> [[gnu::noinline]] int runBoxHullPenetration(const S& s, const gq::Geometry<T>& hull) {
  return penetrationPass(s, boxShape<T>(), hull);
}
template <class S, class T> [[gnu::noinline]] int runBoxHullDistance(const S& s, const gq::Geometry<T>& hull) {
  return distancePass(s, boxShape<T>(), hull);
}

// The six runners on one scene (S: Scene or FloatScene, with its cooked hull); `label` prefixes the printed counts.
template <class S, class T> void runShapesAgainstHull(const S& s, const std::shared_ptr<const gq::ConvexMesh<T>>& mesh,
                                                      const char* label) {
  const gq::Geometry<T> hull = gq::ConvexMeshGeometry<T>(mesh);
  // The hull's per-mesh caches (support start table, topology, Gauss tree) are built here, outside the counted runners.
  gq::PenetrationResult<T> pr;
  gq::DistanceResult<T> dr;
  (void)gq::computePenetration(pr, capsuleShape<T>(), s.pose0[0], hull, s.pose1[0]);
  (void)gq::computePenetration(pr, hull, s.pose0[0], hull, s.pose1[0]);
  (void)gq::distance(dr, sphereShape<T>(), s.pose0[0], hull, s.pose1[0]);
  int counts[6];
  counts[0] = runSphereHullPenetration(s, hull);
  counts[1] = runSphereHullDistance(s, hull);
  counts[2] = runCapsuleHullPenetration(s, hull);
  counts[3] = runCapsuleHullDistance(s, hull);
  counts[4] = runBoxHullPenetration(s, hull);
  counts[5] = runBoxHullDistance(s, hull);
  std::printf("%soverlapping of %d: sphere %d (distance %d), capsule %d (%d), box %d (%d)\n", label, kPairs, counts[0],
              counts[1], counts[2], counts[3], counts[4], counts[5]);
}

void runOncePenetrationShapes(int n) {
  const Scene& s = overlappingScene(n);
  runShapesAgainstHull(s, s.hull, "");
  const FloatScene f = floatScene(s);
  if (f.hull) runShapesAgainstHull(f, f.hull, "float: ");
}

#if GQ_BENCH_PENETRATION_ERRORS
// ---- penetration errors against the exact MTD ----------------------------------------------------------------
// One backend's answer for one pair, in computePenetration's convention: translating geom0 by dir * depth separates.
struct PenAnswer {
  bool hit = false;
  double depth = 0;
  gq::Vec3<double> dir = gq::Vec3<double>::Zero();
};
using PenAnswers = std::vector<PenAnswer>;

PenAnswers gqPenetrationAnswers(const Scene& s, const gq::Geometry<double>& h) {
  PenAnswers out(kPairs);
  for (int i = 0; i < kPairs; ++i) {
    gq::PenetrationResult<double> r;
    if (gq::computePenetration(r, h, s.pose0[i], h, s.pose1[i]).ok() && r.penetrating) out[i] = {true, r.depth, r.direction};
  }
  return out;
}

// distance's normal points from geom0 towards geom1: geom0 leaves along -normal.
PenAnswers gqDistanceAnswers(const Scene& s, const gq::Geometry<double>& h) {
  PenAnswers out(kPairs);
  for (int i = 0; i < kPairs; ++i) {
    gq::DistanceResult<double> r;
    if (gq::distance(r, h, s.pose0[i], h, s.pose1[i]).ok() && r.distance < 0) out[i] = {true, -r.distance, -r.normal};
  }
  return out;
}

// libccd's dir is the direction in which obj2 moves out: geom0 leaves along -dir.
PenAnswers ccdAnswers(CcdPenetrationSolver solve, const Scene& s, const gq::Geometry<double>& h) {
  const ccd_t ccd = makeCcd();
  PenAnswers out(kPairs);
  for (int i = 0; i < kPairs; ++i) {
    const CcdShape a{&h, s.pose0[i]}, b{&h, s.pose1[i]};
    ccd_real_t depth;
    ccd_vec3_t dir, pos;
    if (solve(&a, &b, &ccd, &depth, &dir, &pos) == 0)
      out[i] = {true, depth, -gq::Vec3<double>(dir.v[0], dir.v[1], dir.v[2]).normalized()};
  }
  return out;
}

// Bullet's normal on B points from B towards A: A (geom0) leaves along it.
PenAnswers bulletAnswers(const Scene& s, const btConvexHullShape& hull) {
  btVoronoiSimplexSolver simplex;
  btGjkEpaPenetrationDepthSolver epa;
  PenAnswers out(kPairs);
  for (int i = 0; i < kPairs; ++i) {
    const btPointCollector r = bulletClosestPoints(hull, simplex, epa, s.pose0[i], s.pose1[i]);
    const btVector3& n = r.m_normalOnBInWorld;
    if (r.m_hasResult && r.m_distance < 0) out[i] = {true, -r.m_distance, gq::Vec3<double>(n.x(), n.y(), n.z())};
  }
  return out;
}

// FCL's contact normal points from o1 towards o2: o1 (geom0) leaves along -normal.
PenAnswers fclAnswers(const FclScene& f) {
  fcl::CollisionRequestd request;
  request.gjk_solver_type = fcl::GST_LIBCCD;
  request.enable_contact = true;
  request.num_max_contacts = 1;
  PenAnswers out(kPairs);
  for (int i = 0; i < kPairs; ++i) {
    fcl::CollisionResultd r;
    fcl::collide(f.o0[i].get(), f.o1[i].get(), request, r);
    if (r.numContacts() > 0) out[i] = {true, r.getContact(0).penetration_depth, -r.getContact(0).normal};
  }
  return out;
}

// A posed hull as the referee's polytope (long double vertices, face normals, edge directions).
gq::urdf::test::Polytope refereePolytope(const gq::Geometry<double>& hull, const gq::Transform<double>& pose) {
  gq::urdf::Shape<double> shape;
  shape.geometry = hull;
  gq::urdf::test::Polytope p;
  gq::urdf::test::worldPolytope(shape, pose, p);
  return p;
}

struct PenErrors {
  double maxDepth = 0;      // max |depth - exact| / exact; a missed pair (no contact reported) counts 1
  double maxDirection = 0;  // max (push-out along the backend's direction, by every vertex) / exact - 1
  int missed = 0;
};

// The push-out along `dir` is hi1(dir) - lo0(dir): it equals the exact depth exactly when dir is an MTD direction.
PenErrors penetrationErrors(const PenAnswers& answers, const std::vector<gq::urdf::test::Polytope>& p0,
                            const std::vector<gq::urdf::test::Polytope>& p1, const std::vector<long double>& exact) {
  using LD = long double;
  PenErrors e;
  for (int i = 0; i < kPairs; ++i) {
    const PenAnswer& a = answers[i];
    if (!a.hit || !std::isfinite(a.depth) || !a.dir.allFinite()) {
      e.maxDepth = std::max(e.maxDepth, 1.0);
      ++e.missed;
      continue;
    }
    e.maxDepth = std::max(e.maxDepth, double(std::abs(LD(a.depth) - exact[i]) / exact[i]));
    LD lo0, hi0, lo1, hi1;
    const Eigen::Matrix<LD, 3, 1> d = a.dir.cast<LD>().normalized();
    gq::urdf::test::project(p0[i], d, lo0, hi0);
    gq::urdf::test::project(p1[i], d, lo1, hi1);
    e.maxDirection = std::max(e.maxDirection, double((hi1 - lo0) / exact[i] - 1));
  }
  return e;
}

// `--once-penetration-errors N`: for the penetration rows' 64 overlapping pairs of N-point hulls, each backend's
// errors against the exact MTD, one CSV-ready line per backend:
// `errors,penetration_hullN,<backend>,<max_rel_depth_error>,<max_rel_direction_excess>,<missed>`.
int runOncePenetrationErrors(int n) {
  const Scene& s = overlappingScene(n);
  if (!s.hull) return 1;
  const gq::Geometry<double> hull = gq::ConvexMeshGeometry<double>(s.hull);
  std::vector<gq::urdf::test::Polytope> p0, p1;
  std::vector<long double> exact;
  for (int i = 0; i < kPairs; ++i) {
    p0.push_back(refereePolytope(hull, s.pose0[i]));
    p1.push_back(refereePolytope(hull, s.pose1[i]));
    exact.push_back(-gq::urdf::test::satGap(p0[i], p1[i]));
  }
  const std::unique_ptr<btConvexHullShape> bullet = bulletHull(*s.hull);
  const std::pair<const char*, PenAnswers> rows[] = {
      {"gq", gqPenetrationAnswers(s, hull)},
      {"gq_distance", gqDistanceAnswers(s, hull)},
      {"libccd_gjk_epa", ccdAnswers(ccdGJKPenetration, s, hull)},
      {"libccd_mpr", ccdAnswers(ccdMPRPenetration, s, hull)},
      {"bullet64_gjk_epa", bulletAnswers(s, *bullet)},
      {"fcl_libccd_contact", fclAnswers(fclScene(s))},
  };
  for (const auto& [backend, answers] : rows) {
    const PenErrors e = penetrationErrors(answers, p0, p1, exact);
    std::printf("errors,penetration_hull%d,%s,%.3e,%.3e,%d\n", n, backend, e.maxDepth, e.maxDirection, e.missed);
  }
  return 0;
}
#else
int runOncePenetrationErrors(int) {
  std::fprintf(stderr, "built without the URDF plugin: no exact referee for --once-penetration-errors\n");
  return 1;
}
#endif

void runOnce(const std::vector<int>& args) {
  for (int arg : args) {
    const Scene& s = sceneFor(arg);
    const Pair p = pairFor(arg, s);
    Caches caches(kPairs);
    for (int i = 0; i < kPairs; ++i) {
      gq::DistanceResult<double> r;
      (void)gq::distance(r, p.g0, s.pose0[i], p.g1, s.pose1[i], &caches[i]);  // valid input: timed
    }
    runGqDistanceWarm(s, p.g0, p.g1, caches);
    runGqDistance(s, p.g0, p.g1, nullptr);
    runGqGjkOverlap(s, p.g0, p.g1);
    runGqOverlap(s, p.g0, p.g1);
    runCcdIntersect(s, p.g0, p.g1);
    runCcdPenetration(s, p.g0, p.g1);
    if (arg >= 30) {
      runFclDistance(fclScene(s));
      runFclCollide(fclScene(s));
      runBulletDistance(s, *bulletHull(*s.hull));
    }
  }
}

}  // namespace

BENCHMARK(BM_GqDistance)->Arg(30)->Arg(100)->Arg(300)->Arg(1)->Arg(2)->Arg(3);
BENCHMARK(BM_GqDistanceWarm)->Arg(30)->Arg(100)->Arg(300);
BENCHMARK(BM_GqGjkOverlap)->Arg(30)->Arg(100)->Arg(300)->Arg(1)->Arg(2)->Arg(3);
BENCHMARK(BM_GqOverlap)->Arg(30)->Arg(100)->Arg(300)->Arg(1)->Arg(2)->Arg(3);
BENCHMARK(BM_CcdGJKIntersect)->Arg(30)->Arg(100)->Arg(300)->Arg(1)->Arg(2)->Arg(3);
BENCHMARK(BM_CcdGJKPenetration)->Arg(30)->Arg(100)->Arg(300)->Arg(1)->Arg(2)->Arg(3);
BENCHMARK(BM_FclIndepDistance)->Arg(30)->Arg(100)->Arg(300);
BENCHMARK(BM_FclIndepCollide)->Arg(30)->Arg(100)->Arg(300);
BENCHMARK(BM_BulletGjkEpaDistance)->Arg(30)->Arg(100)->Arg(300);
BENCHMARK(BM_PenGqPenetration)->Arg(30)->Arg(100)->Arg(300);
BENCHMARK(BM_PenGqDistance)->Arg(30)->Arg(100)->Arg(300);
BENCHMARK(BM_PenCcdGJKPenetration)->Arg(30)->Arg(100)->Arg(300);
BENCHMARK(BM_PenCcdMPRPenetration)->Arg(30)->Arg(100)->Arg(300);
BENCHMARK(BM_PenFclCollideContact)->Arg(30)->Arg(100)->Arg(300);
BENCHMARK(BM_PenBulletGjkEpa)->Arg(30)->Arg(100)->Arg(300);

int main(int argc, char** argv) {
  if (argc > 2 && std::string(argv[1]) == "--once-penetration") {
    runOncePenetration(std::stoi(argv[2]));
    return 0;
  }
  if (argc > 2 && std::string(argv[1]) == "--once-penetration-shapes") {
    runOncePenetrationShapes(std::stoi(argv[2]));
    return 0;
  }
  if (argc > 2 && std::string(argv[1]) == "--once-penetration-errors") {
    return runOncePenetrationErrors(std::stoi(argv[2]));
  }
  if (argc > 1 && std::string(argv[1]) == "--once") {
    runOnce(argc > 2 ? std::vector<int>{std::stoi(argv[2])} : std::vector<int>{30, 100, 300, 1, 2, 3});
    return 0;
  }
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
