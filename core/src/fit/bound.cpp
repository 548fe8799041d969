// The certified bound: the two-sided Hausdorff distance between the mesh surface M and the boundary of the union U
// of convex parts, from above.
//  - M to the boundary of U, one part: the signed distance s to a convex solid is convex, so over a triangle its
//    positive part peaks at a vertex, and -s (the depth) lies below its tangent plane at the centroid: the depth's
//    maximum over the triangle is at most the largest tangent value at the vertices. Several parts: the distance to
//    the boundary of U is 1-Lipschitz, so its value at the centroid (exact outside U, a ray walked out of U inside)
//    plus the centroid's distance to the farthest vertex bounds it over the triangle.
//  - the boundary of U to M: the parts' surfaces are covered by patches (flat triangles, spherical triangles,
//    cylinder rectangles, disk sectors), each inside a ball of radius r about a surface point c. The distance to M is
//    1-Lipschitz, so dist(c, M) + r bounds it over the patch; a patch inside another part's solid (the ball of
//    radius r about c inside it) is not on the boundary of U and is dropped.
// A piece whose bound exceeds max(target, 1.02 x the largest distance attained) is split in four and bounded again,
// until the patch budget is spent; the bound is then the largest over the pieces, and stays an upper bound.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <queue>
#include <unordered_map>
#include <cstdio>
#include <cstdlib>

#include "fit/fit_internal.h"
#include "gq/query.h"
#include "mesh/triangle.h"

namespace gq::fit {

double Surface::distance(const Vec3d& p) const {
  std::uint32_t ignored = 0;
  return distance(p, ignored);
}

double Surface::distance(const Vec3d& p, std::uint32_t& triangle) const {
  PointDistanceResult<double> r;
  const Status s = pointDistance<double>(p, TriangleMeshGeometry<double>(cooked), Transform<double>(), r);
  triangle = r.closestIndex;
  return s.ok() ? r.distance : std::numeric_limits<double>::infinity();
}

Status makeSurface(const std::vector<Vec3d>& vertices, const std::vector<TriangleIndices>& triangles, Surface& out) {
  MeshCookReport report;
  Status s = cookTriangleMesh(vertices, triangles, out.cooked, &report);
  if (!s.ok()) return s;
  out.vertices = vertices;
  out.triangles.clear();
  for (const TriangleIndices& t : out.cooked->triangles) out.triangles.push_back(t);
  out.neighbours.assign(out.triangles.size(), {Surface::kNoNeighbour, Surface::kNoNeighbour, Surface::kNoNeighbour});
  std::unordered_map<std::uint64_t, std::pair<std::uint32_t, int>> open;  // undirected edge -> (triangle, edge)
  for (std::uint32_t t = 0; t < out.triangles.size(); ++t)
    for (int e = 0; e < 3; ++e) {
      const std::uint32_t i = out.triangles[t][e], j = out.triangles[t][(e + 1) % 3];
      const std::uint64_t key = (std::uint64_t(std::min(i, j)) << 32) | std::max(i, j);
      const auto [it, inserted] = open.try_emplace(key, t, e);
      if (inserted) continue;
      const auto [u, f] = it->second;
      if (out.neighbours[u][f] == Surface::kNoNeighbour) {  // on an edge of more than two triangles, the first two
        out.neighbours[u][f] = t;
        out.neighbours[t][e] = u;
      }
    }
  Bounds3<double> b;
  for (const auto& t : out.triangles)
    for (std::uint32_t i : t) b.include(vertices[i]);
  out.size = (b.max - b.min).norm();
  return {};
}

namespace {

constexpr int kMaxDepth = 14;

struct Budget {
  std::uint64_t left;
  bool take(std::uint64_t n) {
    if (left < n) return false;
    left -= n;
    return true;
  }
};

bool acceptable(double upper, double target, double lower) { return upper <= std::max(target, 1.02 * lower); }

// The parts with a ball about each that holds it: a point at distance e from a ball's centre is at least e - R from
// the part, so most parts are skipped without their exact signed distance.
struct Union {
  struct Ball {
    Vec3d centre;
    double radius;
  };
  const std::vector<Solid>& solids;
  std::vector<Ball> balls;

  explicit Union(const std::vector<Solid>& s) : solids(s) {
    for (const Solid& p : s) balls.push_back({p.centre, reach(p)});
  }
  static double reach(const Solid& p) {
    switch (p.kind) {
      case Solid::Kind::Sphere: return p.radius;
      case Solid::Kind::Capsule: return p.halfHeight + p.radius;
      case Solid::Kind::Box: return p.halfExtents.norm();
      case Solid::Kind::Cylinder: return std::hypot(p.halfHeight, p.radius);
      case Solid::Kind::Polytope: break;
    }
    double r = 0;
    for (const Vec3d& v : p.vertices) r = std::max(r, (v - p.centre).norm());
    return r;
  }
  std::size_t size() const { return solids.size(); }
  const Solid& operator[](std::size_t i) const { return solids[i]; }
  // A lower bound of part i's signed distance at x.
  double below(std::size_t i, const Vec3d& x) const { return (x - balls[i].centre).norm() - balls[i].radius; }
};

// ---- mesh surface to the boundary of the union -------------------------------------------------------------

// Distance from p to the boundary of the union, from above: exact outside; inside, a walk along +-dir out of the
// union (each step to the exit of a part containing the point) and the distance from there.
double exitAlong(const Solid& s, const Vec3d& p, const Vec3d& dir) {
  if (s.kind == Solid::Kind::Polytope) {
    double t = std::numeric_limits<double>::infinity();
    for (const Face& f : s.faces) {
      const double nd = f.normal.dot(dir);
      if (nd > 0) t = std::min(t, -(f.normal.dot(p) + f.d) / nd);
    }
    return std::max(t, 0.0);
  }
  double t = 0;  // sphere tracing: a step of the depth never leaves the solid
  Vec3d g;
  for (int i = 0; i < 200; ++i) {
    const double sd = signedDistance(s, p + t * dir, g);
    if (sd >= 0) break;
    t += std::max(-sd, 1e-12);
  }
  return t;
}

// Each step goes to the farthest exit of the parts holding the point; once none holds it, the point is outside the
// union and its exact distance to it is added. (Only a part whose ball holds the point can hold it.)
double walkOut(const Union& parts, const Vec3d& p, const Vec3d& dir, double size) {
  double t = 0;
  for (std::size_t step = 0; step < parts.size() + 8; ++step) {
    const Vec3d x = p + t * dir;
    bool inside = false;
    double next = t, out = std::numeric_limits<double>::infinity();
    Vec3d g;
    for (std::size_t i = 0; i < parts.size(); ++i) {
      if (parts.below(i, x) >= 0) continue;
      const double sd = signedDistance(parts[i], x, g);
      out = std::min(out, sd);
      if (sd < 0) {
        inside = true;
        next = std::max(next, t + exitAlong(parts[i], x, dir));
      }
    }
    if (!inside) {  // the parts not yet measured are at least their ball's distance away
      for (std::size_t i = 0; i < parts.size(); ++i)
        if (parts.below(i, x) >= 0 && parts.below(i, x) < out) out = std::min(out, signedDistance(parts[i], x, g));
      return t + out;
    }
    t = next + 1e-9 * size;
  }
  return std::numeric_limits<double>::infinity();
}

// Inside, along +-normal; `thorough`, also along the six axis directions and out through the nearest face of each
// polytope holding p (the normal can run along a buried sheet of the mesh while the boundary is near the other way).
// `out`: outsideDistance at p.
double unionBoundaryDistance(const Union& parts, const Vec3d& p, double out, const Vec3d& normal, double size,
                             bool thorough) {
  if (out >= 0) return out;
  double best = std::min(walkOut(parts, p, normal, size), walkOut(parts, p, -normal, size));
  if (!thorough) return best;
  for (int axis = 0; axis < 3; ++axis)
    for (double sign : {-1.0, 1.0}) best = std::min(best, walkOut(parts, p, sign * Vec3d::Unit(axis), size));
  for (std::size_t i = 0; i < parts.size(); ++i) {
    if (parts[i].kind != Solid::Kind::Polytope || parts.below(i, p) >= 0) continue;
    const Face* nearest = nullptr;
    double depth = std::numeric_limits<double>::infinity();
    for (const Face& f : parts[i].faces)
      if (-(f.normal.dot(p) + f.d) < depth) {
        depth = -(f.normal.dot(p) + f.d);
        nearest = &f;
      }
    if (nearest && depth > 0) best = std::min(best, walkOut(parts, p, nearest->normal, size));
  }
  return best;
}

struct Tri {
  Vec3d a, b, c;
  int depth;
  double upper;
  bool thorough = false;  // walked out of the union in every direction tried, not only along the normal
  bool walked = false;    // the bound is a walk's: the thorough walks may lower it
  // The mesh vertices at the corners (a mesh triangle's), or kNoVertex (a piece of one): the corners' signed
  // distances are then shared by the triangles around each vertex.
  std::array<std::uint32_t, 3> vertex{kNoVertex, kNoVertex, kNoVertex};
  static constexpr std::uint32_t kNoVertex = 0xffffffffu;
  bool operator<(const Tri& o) const { return upper < o.upper; }
};

// What the tests of one triangle share: each part's signed distance (and gradient) at the centroid, computed once,
// and each mesh vertex's signed distance to the last part asked about it.
struct Scratch {
  std::vector<double> sd;    // at the centroid; NaN where not computed
  std::vector<Vec3d> grad;
  std::vector<std::pair<std::uint32_t, double>> vertexSd;  // (part, signed distance); part kNoVertex: none yet
  explicit Scratch(std::size_t parts, std::size_t vertices)
      : sd(parts), grad(parts), vertexSd(vertices, {Tri::kNoVertex, 0.0}) {}
  double at(const Union& parts, std::size_t i, const Vec3d& q) {
    if (std::isnan(sd[i])) sd[i] = signedDistance(parts[i], q, grad[i]);
    return sd[i];
  }
  double corner(const Solid& part, std::uint32_t partIndex, std::uint32_t vertex, const Vec3d& p) {
    Vec3d g;
    if (vertex == Tri::kNoVertex) return signedDistance(part, p, g);
    auto& slot = vertexSd[vertex];
    if (slot.first != partIndex) slot = {partIndex, signedDistance(part, p, g)};
    return slot.second;
  }
};

// Whether one face plane of polytope q has every point of `corners` on or outside it (within `slack`) and its
// normal not against `dir`: then no point of their triangle, nor any point beyond it along dir, is inside q.
bool beyondAFace(const Solid& q, const Vec3d (&corners)[3], const Vec3d& dir, double slack) {
  for (const Face& g : q.faces) {
    if (g.normal.dot(dir) < 0) continue;
    if (g.normal.dot(corners[0]) + g.d >= -slack && g.normal.dot(corners[1]) + g.d >= -slack &&
        g.normal.dot(corners[2]) + g.d >= -slack)
      return true;
  }
  return false;
}

// A mesh triangle on (or just inside) a flat face of the union, from above, far below its size. Along the
// outward normal u, each point p reaches the plane of the face F through which the centroid leaves its part P at
// beta(p) = -(n_F . p + d_F) / (n_F . u), linear in p. When each other part lies beyond one of its own face planes
// from the image triangle (corners p + beta(p) u) with a normal not against u, points just past the image are
// outside every part, so the distance from p to the union's boundary is at most beta(p): at most the largest beta
// at a corner. Polytopes only (a decomposition's parts); infinity when the test does not apply.
double exitThroughFace(const Union& parts, const Tri& t, const Vec3d& q, const Vec3d& u, double size,
                       Scratch& scratch) {
  const double inf = std::numeric_limits<double>::infinity();
  const double slack = 1e-9 * size;
  for (const Solid& s : parts.solids)
    if (s.kind != Solid::Kind::Polytope) return inf;
  for (std::size_t k = 0; k < parts.size(); ++k) {
    const Solid& p = parts[k];
    if (parts.below(k, q) > slack || scratch.at(parts, k, q) > slack) continue;
    const Face* exit = nullptr;
    double nearest = inf;
    for (const Face& f : p.faces) {
      const double nu = f.normal.dot(u);
      if (nu <= 1e-6) continue;
      const double at = -(f.normal.dot(q) + f.d) / nu;
      if (at < nearest) {
        nearest = at;
        exit = &f;
      }
    }
    if (!exit) continue;
    const double nu = exit->normal.dot(u);
    const Vec3d v[3] = {t.a, t.b, t.c};
    Vec3d image[3];
    double worst = 0;
    bool behind = false;
    for (int i = 0; i < 3; ++i) {
      const double beta = -(exit->normal.dot(v[i]) + exit->d) / nu;
      if (beta < -slack) behind = true;
      worst = std::max(worst, beta);
      image[i] = v[i] + beta * u;
    }
    if (behind) continue;
    bool clear = true;
    for (std::size_t j = 0; j < parts.size() && clear; ++j)
      if (j != k) clear = beyondAFace(parts[j], image, u, slack);
    if (clear) return worst + slack;
  }
  return inf;
}

// Bounds a mesh triangle's distance to the boundary of the union from above; `lower` gets a distance attained.
// The distance from the triangle to the boundary of one convex part, from above, and one attained.
double boundToPart(const Union& parts, std::uint32_t i, const Tri& t, const Vec3d& q, Scratch& scratch,
                   double& lower) {
  const Solid& part = parts[i];
  const double sq = scratch.at(parts, i, q);
  const Vec3d& g = scratch.grad[i];
  const double sa = scratch.corner(part, i, t.vertex[0], t.a), sb = scratch.corner(part, i, t.vertex[1], t.b),
               sc = scratch.corner(part, i, t.vertex[2], t.c);
  const double outside = std::max({sa, sb, sc});
  const double depth = std::max({-sq - g.dot(t.a - q), -sq - g.dot(t.b - q), -sq - g.dot(t.c - q)});
  lower = std::max({std::abs(sa), std::abs(sb), std::abs(sc), std::abs(sq)});
  return std::max({outside, depth, 0.0});
}

double boundTriangle(const Union& parts, Tri& t, double size, double target, Scratch& scratch, double& lower) {
  t.walked = false;
  const Vec3d q = (t.a + t.b + t.c) / 3.0;
  std::fill(scratch.sd.begin(), scratch.sd.end(), std::numeric_limits<double>::quiet_NaN());
  if (parts.size() == 1) return boundToPart(parts, 0, t, q, scratch, lower);
  const double r = std::max({(t.a - q).norm(), (t.b - q).norm(), (t.c - q).norm()});
  // One part P alone: with B its bound, each point x of the triangle has a point y of P's boundary within B, and
  // when every other part is farther than r + B from the centroid, y is outside them all, so on the union's
  // boundary (and x, outside the union, is at most sd_P(x) <= B from it): B bounds the union too. P is the part
  // nearest the centroid. Inside it, the centroid's depth is at most its distance to the union's boundary: a
  // distance attained, from below. A part skipped here has a signed distance of at least the nearest's absolute
  // value, so the least signed distance computed is the least of all: the union's outside distance.
  std::uint32_t nearest = 0;
  double nearestDistance = std::numeric_limits<double>::infinity(), nearestSigned = 0;
  double out = std::numeric_limits<double>::infinity();
  for (std::uint32_t i = 0; i < parts.size(); ++i) {
    if (std::abs(parts.below(i, q)) >= nearestDistance && parts.below(i, q) > 0) continue;
    const double sd = scratch.at(parts, i, q);
    out = std::min(out, sd);
    if (std::abs(sd) < nearestDistance) {
      nearestDistance = std::abs(sd);
      nearestSigned = sd;
      nearest = i;
    }
  }
  {
    double single = 0;
    const double bound = boundToPart(parts, nearest, t, q, scratch, single);
    bool alone = true;
    for (std::uint32_t i = 0; i < parts.size() && alone; ++i)
      if (i != nearest && parts.below(i, q) <= r + bound) alone = scratch.at(parts, i, q) > r + bound;
    if (alone) {
      lower = nearestSigned < 0 ? -nearestSigned : std::max(0.0, out);
      return bound;
    }
  }
  const Vec3d n = (t.b - t.a).cross(t.c - t.a);
  const Vec3d normal = n.norm() > 0 ? Vec3d(n.normalized()) : Vec3d::UnitX();
  lower = out >= 0 ? out : std::max(0.0, -nearestSigned);
  // A triangle on a flat face of the union is proven by the exit through that face; the walks only where not.
  const double exit = out < 0 && n.norm() > 0 ? exitThroughFace(parts, t, q, normal, size, scratch)
                                              : std::numeric_limits<double>::infinity();
  if (exit <= target) return exit;
  const double walk = unionBoundaryDistance(parts, q, out, normal, size, t.thorough) + r;
  t.walked = out < 0;
  return std::min(exit, walk);
}

// Best first: the triangle of largest bound is split until it is acceptable or the budget is spent; the bound is
// then the largest left.
void meshToFit(const Surface& surface, const Union& parts, double target, Budget& budget, Bound& out) {
  std::priority_queue<Tri> heap;
  double lower = 0;
  Scratch scratch(parts.size(), surface.vertices.size());
  const auto push = [&](Tri t) {
    double l = 0;
    t.upper = boundTriangle(parts, t, surface.size, target, scratch, l);
    lower = std::max(lower, l);
    heap.push(t);
  };
  for (const auto& tri : surface.triangles) {
    Tri t{surface.vertices[tri[0]], surface.vertices[tri[1]], surface.vertices[tri[2]], 0, 0};
    t.vertex = tri;
    push(t);
  }
  while (!heap.empty()) {
    const Tri t = heap.top();
    if (acceptable(t.upper, target, lower)) break;
    heap.pop();
    if (!t.thorough && t.walked) {  // the other walks first, for the few triangles that decide the bound
      Tri again = t;
      again.thorough = true;
      push(again);
      continue;
    }
    if (t.depth >= kMaxDepth || !budget.take(4)) {
      heap.push(t);
      break;
    }
    const Vec3d ab = (t.a + t.b) / 2, bc = (t.b + t.c) / 2, ca = (t.c + t.a) / 2;
    const int d = t.depth + 1;
    push({t.a, ab, ca, d, 0});
    push({ab, t.b, bc, d, 0});
    push({ca, bc, t.c, d, 0});
    push({ab, bc, ca, d, 0});
  }
  out.lower = std::max(out.lower, lower);
  if (!heap.empty()) out.upper = std::max(out.upper, heap.top().upper);
}

// ---- boundary of the union to the mesh surface -------------------------------------------------------------

struct Patch {
  enum class Kind : std::uint8_t { Flat, Spherical, Side, Disk } kind = Kind::Flat;
  std::uint32_t part = 0;
  int depth = 0;
  // Flat: corners; Spherical: unit directions (frame of the part's rotation).
  Vec3d a = Vec3d::Zero(), b = Vec3d::Zero(), c = Vec3d::Zero();
  double u0 = 0, u1 = 0, v0 = 0, v1 = 0;  // Side: axial [u0,u1] x angle [v0,v1]; Disk: radius [u0,u1] x angle
  double offset = 0;              // Spherical: centre offset along the axis; Disk: the cap's axial position
  Vec3d normal = Vec3d::Zero();   // Flat: the outward normal of the face it lies on
};

// The patch's centre on the part's surface and a radius of a ball about it holding the whole patch.
void centreOf(const Patch& p, const Solid& s, Vec3d& centre, double& radius) {
  const Vec3d axisCentre = s.centre + p.offset * s.rotation.col(0);
  switch (p.kind) {
    case Patch::Kind::Flat:
      centre = (p.a + p.b + p.c) / 3.0;
      radius = std::max({(p.a - centre).norm(), (p.b - centre).norm(), (p.c - centre).norm()});
      return;
    case Patch::Kind::Spherical: {
      const Vec3d m = (p.a + p.b + p.c).normalized();
      centre = axisCentre + s.radius * (s.rotation * m);
      radius = s.radius * std::max({(m - p.a).norm(), (m - p.b).norm(), (m - p.c).norm()});
      return;
    }
    case Patch::Kind::Side: {
      const double t = 0.5 * (p.u0 + p.u1), phi = 0.5 * (p.v0 + p.v1);
      centre = s.centre + s.rotation * Vec3d(t, s.radius * std::cos(phi), s.radius * std::sin(phi));
      radius = std::hypot(0.5 * (p.u1 - p.u0), 2 * s.radius * std::sin(0.25 * (p.v1 - p.v0)));
      return;
    }
    case Patch::Kind::Disk: {
      const double rho = 0.5 * (p.u0 + p.u1), phi = 0.5 * (p.v0 + p.v1);
      centre = s.centre + s.rotation * Vec3d(p.offset, rho * std::cos(phi), rho * std::sin(phi));
      radius = 0.5 * (p.u1 - p.u0) + 2 * rho * std::sin(0.25 * (p.v1 - p.v0));
      return;
    }
  }
}

void split(const Patch& p, std::vector<Patch>& out) {
  Patch q = p;
  q.depth = p.depth + 1;
  if (p.kind == Patch::Kind::Flat || p.kind == Patch::Kind::Spherical) {
    Vec3d ab = (p.a + p.b) / 2, bc = (p.b + p.c) / 2, ca = (p.c + p.a) / 2;
    if (p.kind == Patch::Kind::Spherical) {
      ab.normalize();
      bc.normalize();
      ca.normalize();
    }
    const Vec3d tris[4][3] = {{p.a, ab, ca}, {ab, p.b, bc}, {ca, bc, p.c}, {ab, bc, ca}};
    for (const auto& t : tris) {
      q.a = t[0];
      q.b = t[1];
      q.c = t[2];
      out.push_back(q);
    }
    return;
  }
  const double um = 0.5 * (p.u0 + p.u1), vm = 0.5 * (p.v0 + p.v1);
  const double us[2][2] = {{p.u0, um}, {um, p.u1}}, vs[2][2] = {{p.v0, vm}, {vm, p.v1}};
  for (const auto& u : us)
    for (const auto& v : vs) {
      q.u0 = u[0];
      q.u1 = u[1];
      q.v0 = v[0];
      q.v1 = v[1];
      out.push_back(q);
    }
}

void flat(std::uint32_t part, const Vec3d& a, const Vec3d& b, const Vec3d& c, const Vec3d& normal,
          std::vector<Patch>& out) {
  Patch p;
  p.normal = normal;
  p.part = part;
  p.a = a;
  p.b = b;
  p.c = c;
  out.push_back(p);
}

// The octahedron's faces, the half with x >= 0 (sign +1) or x <= 0 (sign -1), or all of them (sign 0).
void hemisphere(std::uint32_t part, int sign, double offset, std::vector<Patch>& out) {
  const Vec3d x(1, 0, 0), y(0, 1, 0), z(0, 0, 1);
  for (int sx : {1, -1}) {
    if (sign != 0 && sx != sign) continue;
    for (int sy : {1, -1})
      for (int sz : {1, -1}) {
        Patch p;
        p.kind = Patch::Kind::Spherical;
        p.part = part;
        p.offset = offset;
        p.a = sx * x;
        p.b = sy * y;
        p.c = sz * z;
        out.push_back(p);
      }
  }
}

void sides(std::uint32_t part, double halfHeight, std::vector<Patch>& out) {
  for (int k = 0; k < 8; ++k) {
    Patch p;
    p.kind = Patch::Kind::Side;
    p.part = part;
    p.u0 = -halfHeight;
    p.u1 = halfHeight;
    p.v0 = k * M_PI / 4;
    p.v1 = (k + 1) * M_PI / 4;
    out.push_back(p);
  }
}

void initialPatches(const Solid& s, std::uint32_t part, std::vector<Patch>& out) {
  switch (s.kind) {
    case Solid::Kind::Sphere: hemisphere(part, 0, 0, out); return;
    case Solid::Kind::Capsule:
      hemisphere(part, 1, s.halfHeight, out);
      hemisphere(part, -1, -s.halfHeight, out);
      if (s.halfHeight > 0) sides(part, s.halfHeight, out);
      return;
    case Solid::Kind::Cylinder:
      sides(part, s.halfHeight, out);
      for (double x : {-s.halfHeight, s.halfHeight})
        for (int k = 0; k < 8; ++k) {
          Patch p;
          p.kind = Patch::Kind::Disk;
          p.part = part;
          p.offset = x;
          p.u0 = 0;
          p.u1 = s.radius;
          p.v0 = k * M_PI / 4;
          p.v1 = (k + 1) * M_PI / 4;
          out.push_back(p);
        }
      return;
    case Solid::Kind::Box: {
      const Vec3d& h = s.halfExtents;
      for (int axis = 0; axis < 3; ++axis)
        for (double sgn : {-1.0, 1.0}) {
          const int i = (axis + 1) % 3, j = (axis + 2) % 3;
          Vec3d corner[4];
          for (int k = 0; k < 4; ++k) {
            Vec3d l;
            l[axis] = sgn * h[axis];
            l[i] = (k == 1 || k == 2) ? h[i] : -h[i];
            l[j] = (k >= 2) ? h[j] : -h[j];
            corner[k] = s.centre + s.rotation * l;
          }
          const Vec3d normal = s.rotation.col(axis) * sgn;
          flat(part, corner[0], corner[1], corner[2], normal, out);
          flat(part, corner[0], corner[2], corner[3], normal, out);
        }
      return;
    }
    case Solid::Kind::Polytope:
      for (const Face& f : s.faces)
        for (std::size_t k = 1; k + 1 < f.vertices.size(); ++k)
          flat(part, s.vertices[f.vertices[0]], s.vertices[f.vertices[k]], s.vertices[f.vertices[k + 1]], f.normal,
               out);
      return;
  }
}

// Whether the half of the ball B(c, r) on one side of the plane through c with normal n (side -1: n . (x - c) <= 0,
// +1: >= 0) lies inside the polytope: for each face, the largest value of its plane function over the half ball is
// at most 0 (over the half ball, m . (x - c) peaks at r when m points into the half, else at r times the length of
// m's part in the plane).
bool halfBallInside(const Solid& s, const Vec3d& c, double r, const Vec3d& n, int side) {
  if (s.kind != Solid::Kind::Polytope) return false;
  for (const Face& f : s.faces) {
    const double cosine = f.normal.dot(n);
    const bool intoHalf = side < 0 ? cosine <= 0 : cosine >= 0;
    const double reach = intoHalf ? r : r * std::sqrt(std::max(0.0, 1 - cosine * cosine));
    // c lies on one of the faces: its own plane's value is 0 up to rounding (covered by the final allowance).
    if (f.normal.dot(c) + f.d + reach > 1e-12 * (std::abs(f.d) + c.norm() + r)) return false;
  }
  return true;
}

// Whether p is deeper than `margin` inside the part (a polytope stops at the first face plane it is not behind).
bool insideBy(const Solid& s, const Vec3d& p, double margin) {
  if (s.kind == Solid::Kind::Polytope) {
    for (const Face& f : s.faces)
      if (f.normal.dot(p) + f.d >= -margin) return false;
    return true;
  }
  Vec3d g;
  return signedDistance(s, p, g) < -margin;
}

// A flat patch of one part whose ball is covered by the union: the inner half ball inside its own part and the
// outer half inside another (a cut face shared by two parts of a decomposition), the whole ball inside another, or
// (flat) its corners inside another.
// `depth[j]`: part j's signed distance at c where its ball holds c, else +infinity (c not inside it).
bool buried(const Union& parts, const Patch& p, const Vec3d& c, double r, double size, const std::vector<double>& depth) {
  for (std::uint32_t j = 0; j < parts.size(); ++j)
    if (j != p.part && depth[j] <= -r) return true;
  // A flat patch is the convex hull of its corners: with the corners in the interior of a convex part, all of it is.
  const double margin = 1e-9 * size;
  if (p.kind == Patch::Kind::Flat)
    for (std::uint32_t j = 0; j < parts.size(); ++j)
      if (j != p.part && depth[j] < -margin && insideBy(parts[j], p.a, margin) && insideBy(parts[j], p.b, margin) &&
          insideBy(parts[j], p.c, margin))
        return true;
  if (p.kind != Patch::Kind::Flat || !halfBallInside(parts[p.part], c, r, p.normal, -1)) return false;
  for (std::uint32_t j = 0; j < parts.size(); ++j)
    if (j != p.part && depth[j] <= 0 && halfBallInside(parts[j], c, r, p.normal, 1)) return true;
  return false;
}

// A second bound over a flat or spherical patch: the distance to one mesh triangle T (the one nearest the patch's
// centre) is convex, so over the flat triangle through the patch's corners it peaks at a corner; a spherical patch is
// within R - h of that flat triangle (h: the sphere centre's distance to its plane), along the rays from the centre.
// Where the fit and the mesh share a face this proves a bound far below the patch's size.
double nearTriangleBound(const Surface& surface, const Solid& s, const Patch& p, std::uint32_t nearest) {
  if (p.kind != Patch::Kind::Flat && p.kind != Patch::Kind::Spherical) return std::numeric_limits<double>::infinity();
  if (nearest >= surface.cooked->cookedIndex.size()) return std::numeric_limits<double>::infinity();
  const std::uint32_t cooked = surface.cooked->cookedIndex[nearest];
  if (cooked == kRemovedTriangle) return std::numeric_limits<double>::infinity();
  const TriangleIndices& t = surface.cooked->triangles[cooked];
  const Vec3d& ta = surface.vertices[t[0]];
  const Vec3d& tb = surface.vertices[t[1]];
  const Vec3d& tc = surface.vertices[t[2]];
  Vec3d corner[3] = {p.a, p.b, p.c};
  double bulge = 0;
  if (p.kind == Patch::Kind::Spherical) {
    const Vec3d centre = s.centre + p.offset * s.rotation.col(0);
    for (int i = 0; i < 3; ++i) corner[i] = centre + s.radius * (s.rotation * corner[i]);
    const Vec3d n = (corner[1] - corner[0]).cross(corner[2] - corner[0]);
    if (!(n.norm() > 0)) return std::numeric_limits<double>::infinity();
    bulge = s.radius - std::abs(n.normalized().dot(corner[0] - centre));
  }
  const auto farthest = [&](const Vec3d& a, const Vec3d& b, const Vec3d& c) {
    double worst = 0;
    for (const Vec3d& v : corner) worst = std::max(worst, (v - detail::closestPointOnTriangle(v, a, b, c)).norm());
    return worst;
  };
  double best = farthest(ta, tb, tc);
  // T and a coplanar neighbour N whose union is a convex quadrilateral Q: min(d(x, T), d(x, N)) = d(x, Q) is convex
  // too, so over the flat triangle it peaks at a corner. A patch straddling the diagonal of a flat quad (a box face,
  // a hull face of two mesh triangles) is then proven to round-off instead of refined along the whole diagonal.
  const Vec3d normal = (tb - ta).cross(tc - ta);
  const double area2 = normal.norm();
  for (int e = 0; e < 3 && best > 0 && area2 > 0; ++e) {
    const std::uint32_t n = surface.neighbours[cooked][e];
    if (n == Surface::kNoNeighbour) continue;
    const Vec3d& p = surface.vertices[t[e]];
    const Vec3d& q = surface.vertices[t[(e + 1) % 3]];
    const Vec3d& r = surface.vertices[t[(e + 2) % 3]];
    const TriangleIndices& u = surface.cooked->triangles[n];
    const std::uint32_t far = u[0] != t[e] && u[0] != t[(e + 1) % 3] ? u[0] : u[1] != t[e] && u[1] != t[(e + 1) % 3] ? u[1] : u[2];
    const Vec3d& s = surface.vertices[far];
    const Vec3d un = normal / area2;
    if (std::abs(un.dot(s - p)) > 1e-12 * surface.size) continue;  // not coplanar
    // Convex: r and s on opposite sides of the line pq, and p and q not on the same side of the line rs.
    const double sideR = un.dot((q - p).cross(r - p)), sideS = un.dot((q - p).cross(s - p));
    const double sideP = un.dot((s - r).cross(p - r)), sideQ = un.dot((s - r).cross(q - r));
    if (!(sideR * sideS < 0) || sideP * sideQ > 0) continue;
    double worst = 0;
    for (const Vec3d& v : corner)
      worst = std::max(worst, std::min((v - detail::closestPointOnTriangle(v, ta, tb, tc)).norm(),
                                       (v - detail::closestPointOnTriangle(v, p, q, s)).norm()));
    best = std::min(best, worst);
  }
  return best + bulge;
}

struct Scored {
  Patch patch;
  double upper;
  bool operator<(const Scored& o) const { return upper < o.upper; }
};

// `out` holds the other direction's bound: refining this one below it would not lower the maximum.
void fitToMesh(const Surface& surface, const Union& parts, double target, Budget& budget, Bound& out) {
  target = std::max(target, out.upper);
  std::priority_queue<Scored> heap;
  double lower = 0;
  std::vector<double> depth(parts.size());
  const auto push = [&](const Patch& p) {
    Vec3d c = Vec3d::Zero();
    double r = 0;
    centreOf(p, parts[p.part], c, r);
    bool onBoundary = true;
    if (parts.size() > 1) {
      Vec3d g;
      for (std::uint32_t j = 0; j < parts.size(); ++j) {
        depth[j] = j != p.part && parts.below(j, c) < 0 ? signedDistance(parts[j], c, g)
                                                        : std::numeric_limits<double>::infinity();
        if (depth[j] < 0) onBoundary = false;
      }
      if (buried(parts, p, c, r, surface.size, depth)) return;  // not on the union's boundary
    }
    std::uint32_t nearest = 0;
    const double d = surface.distance(c, nearest);
    if (onBoundary) lower = std::max(lower, d);
    heap.push({p, std::min(d + r, nearTriangleBound(surface, parts[p.part], p, nearest))});
  };
  std::vector<Patch> initial;
  for (std::uint32_t i = 0; i < parts.size(); ++i) initialPatches(parts[i], i, initial);
  for (const Patch& p : initial) push(p);
  std::vector<Patch> children;
  while (!heap.empty()) {
    const Scored top = heap.top();
    if (acceptable(top.upper, target, lower) || top.patch.depth >= 2 * kMaxDepth || !budget.take(4)) break;
    heap.pop();
    children.clear();
    split(top.patch, children);
    for (const Patch& c : children) push(c);
  }
  out.lower = std::max(out.lower, lower);
  if (!heap.empty()) out.upper = std::max(out.upper, heap.top().upper);
}

}  // namespace

Bound certifiedBound(const Surface& surface, const std::vector<Solid>& parts, double target, std::uint32_t maxPatches) {
  Bound b;
  if (parts.empty()) {
    b.upper = b.lower = std::numeric_limits<double>::infinity();
    return b;
  }
  Budget first{maxPatches};
  const Union solids(parts);
  meshToFit(surface, solids, target, first, b);
  Budget second{maxPatches};
  fitToMesh(surface, solids, target, second, b);

  // Rounding: hull faces merged by qhull are planar within 1e-9 of the hull size, distances are computed in double.
  b.upper += 1e-8 * surface.size;
  return b;
}

}  // namespace gq::fit
