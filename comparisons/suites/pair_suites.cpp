// Overlap, penetration and distance suites. Each scenario is a placed pair with its exact signed distance
// (exact.h); it becomes one case per query family and precision.
#include <algorithm>
#include <cmath>
#include <functional>

#include "suite.h"

namespace gq::suites {
namespace {

struct Scenario {
  std::string group, name;
  Placed a, b;
};

bool isRound(Kind k) { return k == Kind::Sphere || k == Kind::Plane; }

// Which tolerance applies: closed forms and SAT for the primitive pairs; GJK/EPA when a hull or custom shape
// is involved, and for distance between boxes and capsules (no closed form for the witness pair).
std::string pairClass(Kind a, Kind b, const std::string& query) {
  const auto iterative = [](Kind k) { return k == Kind::Convex || k == Kind::Cylinder || k == Kind::Mesh; };
  if (iterative(a) || iterative(b)) return "iterative";
  if (query != "distance") return "analytic";
  if (isRound(a) || isRound(b) || (a == Kind::Capsule && b == Kind::Capsule)) return "analytic";
  return "iterative";
}

// Coaxial cylinders: they overlap along the axis and radially, the smaller of the two overlaps is the depth.
Ld coaxialCylinderSignedDistance(const Placed& a, const Placed& b) {
  const V3 axis = rotationOf(a.pose) * V3::UnitX();
  const Ld offset = std::abs(axis.dot(b.pose.p.cast<Ld>() - a.pose.p.cast<Ld>()));
  const Ld axial = offset - Ld(a.shape.halfHeight) - Ld(b.shape.halfHeight);
  const Ld radial = -(Ld(a.shape.radius) + Ld(b.shape.radius));
  return std::max(axial, radial);
}

Ld exactSignedDistance(const Placed& a, const Placed& b) {
  if (a.shape.kind == Kind::Cylinder) return coaxialCylinderSignedDistance(a, b);
  if (a.shape.kind == Kind::Plane) return signedDistance(coreOf(b), halfSpaceOf(a));
  if (b.shape.kind == Kind::Plane) return signedDistance(coreOf(a), halfSpaceOf(b));
  return signedDistance(coreOf(a), coreOf(b));
}

double scaleOf(const Placed& a, const Placed& b) {
  return std::max({sizeOf(a.shape), sizeOf(b.shape), a.pose.p.norm(), b.pose.p.norm()});
}

// Moves b along u (from a's origin) until the exact signed distance is `target` (bisection in long double),
// then writes the position in double; the expect is recomputed from the written numbers.
void placeAtGap(const Placed& a, Placed& b, const V3d& u, double target) {
  if (a.shape.kind == Kind::Plane) {
    const V3 n = halfSpaceOf(a).normal;
    b.pose.p += (n * (Ld(target) - exactSignedDistance(a, b))).cast<double>();
    return;
  }
  const V3 origin = a.pose.p.cast<Ld>(), dir = u.normalized().cast<Ld>();
  const auto at = [&](Ld t) {
    Placed moved = b;
    moved.pose.p = (origin + t * dir).cast<double>();
    return moved;
  };
  Ld lo = 0, hi = Ld(sizeOf(a.shape) + sizeOf(b.shape)) * 2 + std::abs(target) + 1;
  for (int i = 0; i < 200 && hi - lo > 1e-19L * hi; ++i) {
    const Ld mid = (lo + hi) / 2;
    (exactSignedDistance(a, at(mid)) < target ? lo : hi) = mid;
  }
  b = at((lo + hi) / 2);
}

Placed randomPlaced(Random& rng, Kind k) {
  Placed p;
  p.shape = rng.shape(k);
  if (k == Kind::Plane) p.shape.kind = Kind::Plane;
  p.pose.p = rng.inBox(1.5);
  p.pose.q = rng.rotation();
  return p;
}

void emit(const Scenario& s, std::size_t index, std::vector<nlohmann::json>& overlap,
          std::vector<nlohmann::json>& penetration, std::vector<nlohmann::json>& distance) {
  const Ld sd = exactSignedDistance(s.a, s.b);
  const double scale = scaleOf(s.a, s.b);
  nlohmann::json base = {{"geom0", toJson(s.a.shape)}, {"pose0", toJson(s.a.pose)},
                         {"geom1", toJson(s.b.shape)}, {"pose1", toJson(s.b.pose)}};
  const std::string id = s.group + "/" + s.name + "#" + std::to_string(index);
  const auto expect = [&](const std::string& query) {
    return nlohmann::json{{"group", s.group}, {"class", pairClass(s.a.shape.kind, s.b.shape.kind, query)},
                          {"scale", scale}, {"margin", double(sd)}};
  };
  nlohmann::json o = base;
  o["query"] = "overlap";
  o["expect"] = expect("overlap");
  o["expect"]["overlap"] = sd <= 0;  // touching counts as overlapping
  emitBothPrecisions(o, id, overlap);
  nlohmann::json p = base;
  p["query"] = "penetration";
  p["expect"] = expect("penetration");
  p["expect"]["penetrating"] = sd <= 0;
  p["expect"]["depth"] = double(std::max(Ld(0), -sd));
  emitBothPrecisions(p, id, penetration);
  nlohmann::json d = base;
  d["query"] = "distance";
  d["expect"] = expect("distance");
  d["expect"]["distance"] = double(sd);
  emitBothPrecisions(d, id, distance);
}


std::string pairName(Kind a, Kind b) { return std::string(kindName(a)) + "_" + kindName(b); }

std::string gapName(double g) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%+.0e", g);
  return buf;
}

using Pair = std::pair<Kind, Kind>;
const Kind S = Kind::Sphere, C = Kind::Capsule, B = Kind::Box, X = Kind::Convex, P = Kind::Plane;

class PairSuiteBuilder {
 public:
  PairSuiteBuilder(const SuiteOptions& o, std::vector<nlohmann::json>& overlap, std::vector<nlohmann::json>& pen,
                   std::vector<nlohmann::json>& dist)
      : options_(o), rng_(o.seed), overlap_(overlap), pen_(pen), dist_(dist) {}

  void add(const std::string& group, const std::string& name, const Placed& a, const Placed& b) {
    emit(Scenario{group, name, a, b}, count_++, overlap_, pen_, dist_);
  }

  // Well-conditioned: random poses, rejected when closer than 2% of the scale to touching.
  void random() {
    const std::vector<Pair> pairs = {{S, S}, {S, C}, {S, B}, {S, X}, {C, C}, {C, B}, {C, X},
                                     {B, B}, {B, X}, {X, X}, {P, S}, {P, C}, {P, B}, {P, X}};
    for (const Pair& pr : pairs)
      for (int i = 0; i < options_.randomPerPair; ++i) {
        Placed a, b;
        do {
          a = randomPlaced(rng_, pr.first);
          b = randomPlaced(rng_, pr.second);
        } while (std::abs(double(exactSignedDistance(a, b))) < 0.02 * scaleOf(a, b));
        add("random", pairName(pr.first, pr.second), a, b);
      }
  }

  // Touching at +-1e-12 .. 1e-3 of the scale.
  void touching() {
    const std::vector<Pair> pairs = {{S, S}, {S, B}, {C, C}, {C, B}, {B, B}, {B, X}, {X, X}, {P, B}, {P, X}};
    for (const Pair& pr : pairs)
      for (int o = 0; o < options_.orientations; ++o) {
        const Placed a = randomPlaced(rng_, pr.first);
        const Placed b0 = randomPlaced(rng_, pr.second);
        const V3d u = rng_.unitVector();
        for (double rel : {1e-12, 1e-9, 1e-6, 1e-3})
          for (double sign : {-1.0, 1.0}) {
            Placed b = b0;
            placeAtGap(a, b, u, sign * rel * std::max(sizeOf(a.shape), sizeOf(b.shape)));
            add("touching", pairName(pr.first, pr.second) + "@" + gapName(sign * rel), a, b);
          }
      }
  }

  // Contained shapes and coincident centres.
  void contained() {
    for (int o = 0; o < options_.orientations; ++o) {
      const Eigen::Vector4d q = rng_.rotation();
      const V3d c = rng_.inBox(1.0);
      Placed big{box(1, 0.8, 0.6), {c, q}};
      add("contained", "sphere_in_box_centre", big, Placed{sphere(0.2), {c, rng_.rotation()}});
      add("contained", "sphere_in_box_offset", big, Placed{sphere(0.2), {c + V3d(0.5, -0.3, 0.1), q}});
      Placed hull{rng_.shape(X), {c, rng_.rotation()}};
      add("contained", "convex_convex_same_centre", hull, Placed{rng_.shape(X), {c, rng_.rotation()}});
      add("contained", "sphere_sphere_same_centre", Placed{sphere(0.7), {c, q}}, Placed{sphere(0.4), {c, q}});
      add("contained", "capsule_capsule_same_centre", Placed{capsule(0.3, 0.8), {c, q}},
          Placed{capsule(0.2, 0.5), {c, rng_.rotation()}});
      add("contained", "box_box_same_centre", big, Placed{box(0.5, 0.4, 0.3), {c, rng_.rotation()}});
      add("contained", "small_convex_in_box", big, Placed{scaled(rng_.shape(X), 0.2), {c, rng_.rotation()}});
    }
  }

  // Reported upstream against FCL (flexible-collision-library/fcl#545): boxes offset along their diagonal, a sphere
  // near a box corner.
  void diagonal() {
    const Eigen::Vector4d id(0, 0, 0, 1);
    for (double d : {1.5, 1.99, 2.01, 2.5}) {
      add("diagonal", "box_box_d" + std::to_string(d).substr(0, 4), Placed{box(1, 1, 1), {V3d::Zero(), id}},
          Placed{box(1, 1, 1), {V3d(d, d, d), id}});
      add("diagonal", "box_box45_d" + std::to_string(d).substr(0, 4), Placed{box(1, 1, 1), {V3d::Zero(), id}},
          Placed{box(1, 1, 1), {V3d(d, d, 0), axisAngle(V3d::UnitZ(), M_PI / 4)}});
    }
    for (double a : {-0.2, -0.01, 0.01, 0.2}) {
      // Sphere centre k(1,1,1) beyond the corner (1,1,1): signed distance sqrt(3) (k - 1) - r = a.
      const double r = 0.5, k = 1 + (r + a) / std::sqrt(3.0);
      add("diagonal", "sphere_corner" + gapName(a), Placed{box(1, 1, 1), {V3d::Zero(), id}},
          Placed{sphere(r), {V3d(k, k, k), id}});
    }
  }

  // Reported upstream against FCL (flexible-collision-library/fcl#628): a box inside a box, centred, off-centre,
  // touching a wall from inside, rotated.
  void boxInBox() {
    const Eigen::Vector4d id(0, 0, 0, 1);
    const Placed outer{box(1, 1, 1), {V3d::Zero(), id}};
    for (const V3d& off : {V3d(0, 0, 0), V3d(0.2, 0.1, 0), V3d(0.5, 0, 0), V3d(0.3, 0.3, 0.3)}) {
      add("boxInBox", "aligned", outer, Placed{box(0.5, 0.5, 0.5), {off, id}});
      add("boxInBox", "rotated", outer, Placed{box(0.5, 0.3, 0.2), {off, axisAngle(V3d(1, 2, 3), 0.7)}});
    }
  }

  // The libccd cylinder pair (its golden file says 0.75; exact depth 0.45), along the shared axis z.
  void cylinders() {
    const Eigen::Vector4d xToZ = axisAngle(V3d::UnitY(), -M_PI / 2);
    Shape c0, c1;
    c0.kind = c1.kind = Kind::Cylinder;
    c0.radius = 0.35, c0.halfHeight = 0.25;
    c1.radius = 0.5, c1.halfHeight = 0.5;
    add("cylinders", "libccd_pair", Placed{c0, {V3d::Zero(), xToZ}}, Placed{c1, {V3d(0, 0, 0.3), xToZ}});
  }

  // R versus R * Rz(pi): the same shape turned half a turn about its local z.
  void halfTurn() {
    for (Kind k : {B, X, C})
      for (int o = 0; o < options_.orientations; ++o) {
        const Shape s = rng_.shape(k);
        const Eigen::Vector4d r = rng_.rotation();
        const V3d u = rng_.unitVector();
        for (double dist : {0.3, 1.0, 2.5}) {
          Placed a{s, {V3d::Zero(), r}};
          Placed b{s, {u * dist * sizeOf(s), compose(r, axisAngle(V3d::UnitZ(), M_PI))}};
          add("halfTurn", std::string(kindName(k)) + "_d" + std::to_string(dist).substr(0, 3), a, b);
        }
      }
  }

  // Size ratios 1e-4 .. 1e4 against a unit box, 10% of the smaller size apart or overlapping.
  void sizeRatio() {
    for (double k : {1e-4, 1e-2, 1e2, 1e4})
      for (Kind kind : {S, X, B})
        for (double sign : {-1.0, 1.0}) {
          Placed a{box(1, 1, 1), {V3d::Zero(), rng_.rotation()}};
          Placed b{scaled(rng_.shape(kind), k / 0.8), {V3d::Zero(), rng_.rotation()}};
          placeAtGap(a, b, rng_.unitVector(), sign * 0.1 * std::min(sizeOf(a.shape), sizeOf(b.shape)));
          add("sizeRatio", std::string(kindName(kind)) + "_x" + gapName(k) + (sign < 0 ? "_in" : "_out"), a, b);
        }
  }

  // Poses 1e3 .. 1e6 from the origin: a pair 10% apart (or overlapping) translated far away.
  void farPose() {
    const std::vector<Pair> pairs = {{S, B}, {B, B}, {C, X}, {X, X}};
    for (double far : {1e3, 1e4, 1e5, 1e6})
      for (const Pair& pr : pairs)
        for (double sign : {-1.0, 1.0}) {
          Placed a = randomPlaced(rng_, pr.first), b = randomPlaced(rng_, pr.second);
          placeAtGap(a, b, rng_.unitVector(), sign * 0.1);
          const V3d shift = rng_.unitVector() * far;
          a.pose.p += shift, b.pose.p += shift;
          add("farPose", pairName(pr.first, pr.second) + "@" + gapName(far) + (sign < 0 ? "_in" : "_out"), a, b);
        }
  }

  // Quaternions written with lengths 1e-3 .. 1e3 (the runner normalizes them).
  void quaternionScale() {
    for (double f : {1e-3, 0.5, 3.0, 1e3})
      for (const Pair& pr : std::vector<Pair>{{B, B}, {C, X}}) {
        Placed a, b;
        do {
          a = randomPlaced(rng_, pr.first);
          b = randomPlaced(rng_, pr.second);
        } while (std::abs(double(exactSignedDistance(a, b))) < 0.02 * scaleOf(a, b));
        a.pose.q *= f, b.pose.q *= 1 / f;
        add("quaternionScale", pairName(pr.first, pr.second) + "_x" + gapName(f), a, b);
      }
  }

  // Parallel capsules (side by side, end to end) and zero-length capsules.
  void capsules() {
    const Eigen::Vector4d q = rng_.rotation();
    const Eigen::Quaterniond rot(q.w(), q.x(), q.y(), q.z());
    for (double gap : {-0.1, -1e-6, 1e-6, 0.1}) {
      const double lateral = 0.3 + 0.2 + gap;
      add("capsules", "parallel_side" + gapName(gap), Placed{capsule(0.3, 1.0), {V3d::Zero(), q}},
          Placed{capsule(0.2, 0.7), {rot * V3d(0.4, lateral, 0), q}});
      add("capsules", "parallel_end" + gapName(gap), Placed{capsule(0.3, 1.0), {V3d::Zero(), q}},
          Placed{capsule(0.2, 0.7), {rot * V3d(1.0 + 0.3 + 0.7 + 0.2 + gap, 0, 0), q}});
      add("capsules", "zero_length_capsule" + gapName(gap), Placed{capsule(0.3, 1.0), {V3d::Zero(), q}},
          Placed{capsule(0.25, 0.0), {rot * V3d(0.2, 0.55 + gap, 0), rng_.rotation()}});
      add("capsules", "zero_length_box" + gapName(gap), Placed{box(0.5, 0.5, 0.5), {V3d::Zero(), q}},
          Placed{capsule(0.25, 0.0), {rot * V3d(0.1, 0.2, 0.75 + gap), rng_.rotation()}});
    }
  }

  // Thin boxes (1e-4 thick) near and through other shapes.
  void thinBoxes() {
    const Eigen::Vector4d id(0, 0, 0, 1);
    const Placed plate{box(1, 1, 1e-4), {V3d::Zero(), id}};
    for (double gap : {-5e-5, -1e-6, 1e-6, 1e-3}) {
      add("thinBox", "sphere" + gapName(gap), plate, Placed{sphere(0.3), {V3d(0.2, 0.1, 1e-4 + 0.3 + gap), id}});
      add("thinBox", "box" + gapName(gap), plate,
          Placed{box(0.2, 0.2, 1e-4), {V3d(0.5, -0.3, 2e-4 + gap), axisAngle(V3d::UnitZ(), 0.3)}});
    }
    add("thinBox", "capsule_through", plate, Placed{capsule(0.1, 0.5), {V3d(0.3, 0, 0.1), axisAngle(V3d::UnitY(), 1.2)}});
    add("thinBox", "plate_cross", plate, Placed{box(1, 1, 1e-4), {V3d(0, 0, 0), axisAngle(V3d::UnitX(), M_PI / 2)}});
  }

  // Degenerate hull point sets: coplanar, collinear, duplicated points, nearly flat.
  void degenerate() {
    Shape coplanar;
    coplanar.kind = X;
    coplanar.points = {V3d(-0.5, -0.5, 0), V3d(0.5, -0.5, 0), V3d(0.5, 0.5, 0), V3d(-0.5, 0.5, 0), V3d(0.1, 0.2, 0)};
    Shape collinear;
    collinear.kind = X;
    collinear.points = {V3d(-0.6, 0, 0), V3d(0.1, 0, 0), V3d(0.6, 0, 0)};
    Shape duplicated = rng_.shape(X);
    const std::size_t n = duplicated.points.size();
    for (std::size_t i = 0; i < n; ++i) duplicated.points.push_back(duplicated.points[i]);
    Shape nearlyFlat = coplanar;
    nearlyFlat.points.push_back(V3d(0, 0, 1e-9));
    const std::vector<std::pair<std::string, Shape>> sets = {
        {"coplanar", coplanar}, {"collinear", collinear}, {"duplicated", duplicated}, {"nearly_flat", nearlyFlat}};
    for (const auto& [name, shape] : sets)
      for (double gap : {-0.05, 0.05}) {
        Placed a{box(0.5, 0.5, 0.5), {V3d::Zero(), rng_.rotation()}};
        Placed b{shape, {V3d::Zero(), rng_.rotation()}};
        placeAtGap(a, b, rng_.unitVector(), gap);
        add("degenerate", name + "_box" + gapName(gap), a, b);
        Placed s{sphere(0.4), {V3d::Zero(), rng_.rotation()}};
        Placed c{shape, {V3d::Zero(), rng_.rotation()}};
        placeAtGap(s, c, rng_.unitVector(), gap);
        add("degenerate", name + "_sphere" + gapName(gap), s, c);
      }
  }

 private:
  static Shape sphere(double r) { Shape s; s.kind = S; s.radius = r; return s; }
  static Shape capsule(double r, double hh) { Shape s; s.kind = C; s.radius = r; s.halfHeight = hh; return s; }
  static Shape box(double x, double y, double z) { Shape s; s.kind = B; s.halfExtents = V3d(x, y, z); return s; }
  static Shape scaled(Shape s, double k) {
    s.radius *= k, s.halfHeight *= k, s.halfExtents *= k;
    for (V3d& p : s.points) p *= k;
    return s;
  }

  const SuiteOptions& options_;
  Random rng_;
  std::vector<nlohmann::json>& overlap_;
  std::vector<nlohmann::json>& pen_;
  std::vector<nlohmann::json>& dist_;
  std::size_t count_ = 0;
};

}  // namespace

void addPairSuites(const SuiteOptions& options, std::vector<nlohmann::json>& overlap,
                   std::vector<nlohmann::json>& penetration, std::vector<nlohmann::json>& distance) {
  PairSuiteBuilder b(options, overlap, penetration, distance);
  b.random();
  b.touching();
  b.contained();
  b.diagonal();
  b.boxInBox();
  b.cylinders();
  b.halfTurn();
  b.sizeRatio();
  b.farPose();
  b.quaternionScale();
  b.capsules();
  b.thinBoxes();
  b.degenerate();
}

}  // namespace gq::suites
