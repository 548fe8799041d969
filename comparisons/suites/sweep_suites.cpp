// sweep suite: sphere, capsule, box and convex swept against sphere, capsule, box, convex and plane targets:
// well-aimed random sweeps, starts in initial overlap, maxDist short of the impact, and poses 1e3 from the origin.
// The exact time of impact (TOI) is the first t in [0, maxDist] at which the swept solid A moved by t*dir meets B,
// i.e. where the ray t*dir enters the Minkowski difference M = B - A:
//  - polytopes (box, convex): the ray clipped by the half-spaces n.x <= h(n) = max_B n.b - min_A n.a over every
//    face normal of both hulls (all point triples) and every edge-pair cross product. Those include every facet
//    of M and the rest only support it, so the clipped interval is exact.
//  - rounded cores (sphere, capsule on either side): d(t), the signed distance of the moved core to the target,
//    is convex in t (the signed distance to a convex set is convex); golden-section search finds its minimum and
//    bisection its first root.
//  - plane targets: closed form from the lowest point of A along the normal.
// "margin" (how far the hit boolean is from flipping) is the depth of the path inside M for hits (or the distance
// to maxDist), the exact distance from the swept segment to M for misses. "spread" is the first-order change of
// the TOI when the start moves sideways by the tolerance: tol * tan(angle between the contact normal and -dir).
#include <algorithm>
#include <cmath>

#include "suite.h"

namespace gq::suites {
namespace {

constexpr Ld kInfinity = std::numeric_limits<Ld>::infinity();

bool isPolytope(Kind k) { return k == Kind::Box || k == Kind::Convex; }

// ---- polytope pairs: slab clipping over the SAT axes of the Minkowski difference ------------------------------

SweepToi polytopeToi(const Core& a, const Core& b, const V3& dir, Ld maxDist) {
  std::vector<V3> axes;
  addTriangleNormals(a.points, axes);
  addTriangleNormals(b.points, axes);
  addEdgePairAxes(a.points, b.points, axes);
  // Facets of the swept segment against M: M's facets and dir x (edges of M), which are edges of A or B; the
  // segment {0, dir} has dir as its one edge.
  const std::vector<V3> path = {V3::Zero(), dir};
  addEdgePairAxes(path, a.points, axes);
  addEdgePairAxes(path, b.points, axes);
  Ld enter = 0, exit = maxDist, gap = -kInfinity, depthAtStart = kInfinity, cosine = 1;
  for (const V3& axis : axes)
    for (const V3& n : {axis, V3(-axis)}) {
      Ld hiB = -kInfinity, loA = kInfinity;
      for (const V3& p : b.points) hiB = std::max(hiB, n.dot(p));
      for (const V3& p : a.points) loA = std::min(loA, n.dot(p));
      const Ld h = hiB - loA, rate = n.dot(dir);
      depthAtStart = std::min(depthAtStart, h);
      gap = std::max(gap, std::min(Ld(0), rate * maxDist) - h);  // separation of the segment along n
      if (rate > 0) {
        exit = std::min(exit, h / rate);
      } else if (rate < 0 && h / rate > enter) {
        enter = h / rate;
        cosine = -rate;
      } else if (rate == 0 && h < 0) {
        exit = -kInfinity;
      }
    }
  SweepToi t;
  t.hit = enter <= exit;
  if (!t.hit) {
    t.margin = std::max(gap, Ld(0));
    return t;
  }
  t.distance = enter;
  t.cosine = enter > 0 ? cosine : Ld(1);
  t.margin = enter > 0 ? std::min(exit - enter, maxDist - enter) : depthAtStart;
  return t;
}

// ---- rounded cores: convex d(t) ---------------------------------------------------------------------------------

SweepToi roundedToi(const Core& a, const Core& b, const V3& dir, Ld maxDist) {
  const auto d = [&](Ld t) {
    Core moved = a;
    for (V3& p : moved.points) p += t * dir;
    return signedDistance(moved, b);
  };
  SweepToi out;
  const Ld d0 = d(0);
  if (d0 <= 0) {
    out.hit = true;
    out.margin = -d0;
    return out;
  }
  // Golden-section search for the minimum of the convex d on [0, maxDist].
  const Ld ratio = (std::sqrt(Ld(5)) - 1) / 2;
  Ld lo = 0, hi = maxDist;
  Ld x1 = hi - ratio * (hi - lo), x2 = lo + ratio * (hi - lo), f1 = d(x1), f2 = d(x2);
  for (int i = 0; i < 160 && hi - lo > 1e-19L * maxDist; ++i) {
    if (f1 <= f2) {
      hi = x2, x2 = x1, f2 = f1;
      x1 = hi - ratio * (hi - lo), f1 = d(x1);
    } else {
      lo = x1, x1 = x2, f1 = f2;
      x2 = lo + ratio * (hi - lo), f2 = d(x2);
    }
  }
  const Ld tMin = (lo + hi) / 2, dMin = std::min({d(tMin), d(maxDist)});
  if (dMin > 0) {
    out.margin = dMin;
    return out;
  }
  // d decreases on [0, tMin]: bisection for its root.
  Ld r0 = 0, r1 = d(maxDist) <= 0 && d(maxDist) < d(tMin) ? maxDist : tMin;
  for (int i = 0; i < 200 && r1 - r0 > 1e-20L * maxDist; ++i) {
    const Ld mid = (r0 + r1) / 2;
    (d(mid) > 0 ? r0 : r1) = mid;
  }
  out.hit = true;
  out.distance = r1;
  out.margin = std::min(-dMin, maxDist - r1);
  const Ld step = 1e-7L * maxDist;  // d'(t) just before contact = -|n . dir|
  out.cosine = std::clamp((d(std::max(Ld(0), r1 - step)) - d(r1)) / std::min(step, r1 > 0 ? r1 : step), Ld(1e-30),
                          Ld(1));
  return out;
}

SweepToi planeToi(const Core& a, const HalfSpace& plane, const V3& dir, Ld maxDist) {
  const Ld height = signedDistance(a, plane), rate = plane.normal.dot(dir);
  SweepToi t;
  if (height <= 0) {
    t.hit = true;
    t.margin = -height;
    return t;
  }
  const Ld toi = rate < 0 ? height / -rate : kInfinity;
  t.hit = toi <= maxDist;
  t.distance = t.hit ? toi : 0;
  t.margin = t.hit ? maxDist - toi : (rate < 0 ? (toi - maxDist) * -rate : height);
  t.cosine = -rate;
  return t;
}

class SweepSuiteBuilder {
 public:
  SweepSuiteBuilder(const SuiteOptions& o, std::vector<nlohmann::json>& out) : options_(o), rng_(o.seed + 5), out_(out) {}

  void add(const std::string& group, const std::string& name, const Placed& a, const Placed& b, const V3d& dir,
           double maxDist) {
    const SweepToi toi = exactSweepToi(a, b, dir, maxDist);
    const double scale = std::max({sizeOf(a.shape), b.shape.kind == Kind::Plane ? 0.0 : sizeOf(b.shape),
                                   a.pose.p.norm(), b.pose.p.norm(), maxDist});
    nlohmann::json j = {{"query", "sweep"}, {"geom0", toJson(a.shape)}, {"pose0", toJson(a.pose)},
                        {"dir", {dir.x(), dir.y(), dir.z()}},  {"maxDist", maxDist},
                        {"geom1", toJson(b.shape)}, {"pose1", toJson(b.pose)}, {"flags", {"position", "normal"}}};
    j["expect"] = {{"group", group}, {"class", "iterative"}, {"scale", scale}, {"margin", double(toi.margin)},
                   {"hit", toi.hit}};
    if (toi.hit) {
      j["expect"]["distance"] = double(toi.distance);
      const Ld slope = std::sqrt(std::max(Ld(0), 1 - toi.cosine * toi.cosine)) / toi.cosine;
      j["expect"]["spread"] = {{"1e-07", double(1e-7L * slope)}, {"1e-04", double(1e-4L * slope)}};
    }
    emitBothPrecisions(j, group + "/" + name + "#" + std::to_string(count_++), out_);
  }

  // Swept from a start `gap` beyond contact, aimed at the target's centre within `aimError` (relative to size).
  void aimed(const std::string& group, double far, double aimError, double maxDistFactor) {
    for (Kind ka : kSwept)
      for (Kind kb : kTargets)
        for (int i = 0; i < options_.randomSweeps; ++i) {
          Placed b = target(kb, far);
          Placed a;
          a.shape = rng_.shape(ka);
          a.pose.q = rng_.rotation();
          const double reach = sizeOf(a.shape) + (kb == Kind::Plane ? 0.0 : sizeOf(b.shape));
          const V3d toward = kb == Kind::Plane ? V3d(-planeNormal(b)) : rng_.unitVector();
          a.pose.p = b.pose.p - toward * (reach + rng_.uniform(0.2, 1.5));
          const V3d dir = (toward + rng_.unitVector() * aimError).normalized();
          const double maxDist = maxDistFactor * (a.pose.p - b.pose.p).norm();
          add(group, std::string(kindName(ka)) + "_" + kindName(kb), a, b, dir, maxDist);
        }
  }

  // Starts overlapping the target: a hit at distance 0.
  void initialOverlap() {
    for (Kind ka : kSwept)
      for (Kind kb : kTargets) {
        Placed b = target(kb, 0);
        Placed a;
        a.shape = rng_.shape(ka);
        a.pose.q = rng_.rotation();
        a.pose.p = b.pose.p + (kb == Kind::Plane ? V3d(-0.2 * planeNormal(b)) : V3d(rng_.inBox(0.2)));
        add("initialOverlap", std::string(kindName(ka)) + "_" + kindName(kb), a, b, rng_.unitVector(), 2.0);
      }
  }

 private:
  Placed target(Kind k, double far) {
    Placed t;
    t.shape = k == Kind::Plane ? Shape{} : rng_.shape(k);
    t.shape.kind = k;
    t.pose.p = rng_.inBox(1.0) + V3d(far, -far, far);
    t.pose.q = rng_.rotation();
    return t;
  }
  static V3d planeNormal(const Placed& p) { return halfSpaceOf(p).normal.cast<double>(); }

  static constexpr Kind kSwept[] = {Kind::Sphere, Kind::Capsule, Kind::Box, Kind::Convex};
  static constexpr Kind kTargets[] = {Kind::Sphere, Kind::Capsule, Kind::Box, Kind::Convex, Kind::Plane};
  const SuiteOptions& options_;
  Random rng_;
  std::vector<nlohmann::json>& out_;
  int count_ = 0;
};

}  // namespace

SweepToi exactSweepToi(const Placed& a, const Placed& b, const V3d& dir, double maxDist) {
  const V3 u = dir.cast<Ld>().normalized();
  if (b.shape.kind == Kind::Plane) return planeToi(coreOf(a), halfSpaceOf(b), u, Ld(maxDist));
  if (isPolytope(a.shape.kind) && isPolytope(b.shape.kind)) return polytopeToi(coreOf(a), coreOf(b), u, Ld(maxDist));
  return roundedToi(coreOf(a), coreOf(b), u, Ld(maxDist));
}

void addSweepSuite(const SuiteOptions& options, std::vector<nlohmann::json>& out) {
  SweepSuiteBuilder b(options, out);
  b.aimed("random", 0, 0.15, 2.0);
  b.aimed("wideAim", 0, 0.8, 2.0);       // hits and misses, some grazing
  b.aimed("shortMaxDist", 0, 0.1, 0.5);  // maxDist ends before the impact
  b.aimed("far", 1e3, 0.15, 2.0);        // poses 1e3 from the origin
  b.initialOverlap();
}

}  // namespace gq::suites
