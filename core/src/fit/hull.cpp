// The convex hull, and the simplified hull: farthest-point insertion (the hull's vertices added, those farthest
// outside the current hull first, until every vertex is within the slack of it; a vertex is added per face per
// round when it is at least half as far out as the farthest). With `contain`, every face plane is pushed out past
// the farthest vertex and the polytope is rebuilt from the planes (their intersection, by polar duality about an
// interior point: the dual hull's facets are the polytope's vertices); a polytope's vertices can move farther than
// its planes, so the bound is certified afterwards like any fit's.
#include <algorithm>
#include <limits>

#include "fit/fit_internal.h"

namespace gq::fit {
namespace {

Status planesToPolytope(const std::vector<Face>& planes, const Vec3d& inside, Solid& out) {
  std::vector<Vec3d> dual;
  dual.reserve(planes.size());
  for (const Face& f : planes) {
    const double k = -(f.d + f.normal.dot(inside));
    if (!(k > 0)) return Status::internal("interior point on a face plane");
    dual.push_back(f.normal / k);
  }
  std::shared_ptr<const ConvexMesh<double>> dualHull;
  Status s = cookConvexMesh(dual, dualHull);
  if (!s.ok()) return s;
  std::vector<Vec3d> vertices;
  for (const auto& poly : dualHull->polygons) vertices.push_back(inside + poly.normal / -poly.d);
  return hullOf(vertices, out);
}

double excess(const Face& f, const std::vector<Vec3d>& pts) {
  double e = -std::numeric_limits<double>::infinity();
  for (const Vec3d& p : pts) e = std::max(e, f.normal.dot(p) + f.d);
  return e;
}

}  // namespace

// Cooking merges facets whose planes agree within 1e-9 of the hull's size, so a point can lie that far outside a
// merged face. The hull is then cooked again from its vertices scaled about its centre: a factor 1 + 2 e / r (e the
// largest excess, r the inner ball's radius) moves every face plane out by at least 2 e.
Status enclosingHull(const std::vector<Vec3d>& pts, std::shared_ptr<const ConvexMesh<double>>& out) {
  std::shared_ptr<const ConvexMesh<double>> hull;
  Status s = cookConvexMesh(pts, hull);
  if (!s.ok()) return s;
  double worst = 0;
  for (const auto& poly : hull->polygons)
    for (const Vec3d& p : pts) worst = std::max(worst, poly.normal.dot(p) + poly.d);
  if (worst > 0 && hull->innerRadius > 0) {
    const double k = 1 + 2 * worst / hull->innerRadius;
    std::vector<Vec3d> grown;
    grown.reserve(hull->vertices.size());
    for (const Vec3d& v : hull->vertices) grown.push_back(hull->center + k * (v - hull->center));
    std::shared_ptr<const ConvexMesh<double>> outer;
    if (cookConvexMesh(grown, outer).ok()) hull = outer;
  }
  out = std::move(hull);
  return {};
}

Status hullOf(const std::vector<Vec3d>& pts, Solid& out) {
  std::shared_ptr<const ConvexMesh<double>> hull;
  if (Status s = enclosingHull(pts, hull); !s.ok()) return s;
  out = polytopeOf(*hull);
  return {};
}

Status simplifiedHull(const ConvexMesh<double>& hull, double slack, bool contain, Solid& out) {
  const std::vector<Vec3d>& v = hull.vertices;
  const std::size_t n = v.size();
  // A first tetrahedron of extreme vertices.
  std::vector<std::uint32_t> chosen;
  std::vector<char> used(n, 0);
  const auto take = [&](std::uint32_t i) {
    if (!used[i]) chosen.push_back(i);
    used[i] = 1;
  };
  std::uint32_t i0 = 0;
  for (std::uint32_t i = 1; i < n; ++i)
    if (v[i].x() < v[i0].x()) i0 = i;
  std::uint32_t i1 = i0, i2 = i0, i3 = i0;
  for (std::uint32_t i = 0; i < n; ++i)
    if ((v[i] - v[i0]).squaredNorm() > (v[i1] - v[i0]).squaredNorm()) i1 = i;
  const Vec3d axis = (v[i1] - v[i0]).normalized();
  const auto offLine = [&](std::uint32_t i) { return (v[i] - v[i0] - (v[i] - v[i0]).dot(axis) * axis).norm(); };
  for (std::uint32_t i = 0; i < n; ++i)
    if (offLine(i) > offLine(i2)) i2 = i;
  const Vec3d normal = axis.cross(v[i2] - v[i0]).normalized();
  for (std::uint32_t i = 0; i < n; ++i)
    if (std::abs((v[i] - v[i0]).dot(normal)) > std::abs((v[i3] - v[i0]).dot(normal))) i3 = i;
  for (std::uint32_t i : {i0, i1, i2, i3}) take(i);
  Solid current;
  for (;;) {
    std::vector<Vec3d> pts;
    for (std::uint32_t i : chosen) pts.push_back(v[i]);
    Status s = hullOf(pts, current);
    if (!s.ok()) return s;
    // The farthest vertex above each face, and the farthest overall.
    std::vector<std::pair<double, std::uint32_t>> above(current.faces.size(), {0.0, 0});
    double farthest = 0;
    for (std::uint32_t i = 0; i < n; ++i) {
      if (used[i]) continue;
      for (std::size_t f = 0; f < current.faces.size(); ++f) {
        const double e = current.faces[f].normal.dot(v[i]) + current.faces[f].d;
        if (e > above[f].first) above[f] = {e, i};
      }
    }
    for (const auto& a : above) farthest = std::max(farthest, a.first);
    if (farthest <= slack || chosen.size() >= n) break;
    for (const auto& a : above)
      if (a.first > slack && a.first >= 0.5 * farthest) take(a.second);
  }
  if (contain) {
    for (int round = 0; round < 4; ++round) {
      bool outside = false;
      std::vector<Face> planes = current.faces;
      for (Face& f : planes) {
        const double e = excess(f, v);
        if (e > 0) {
          f.d -= e;
          outside = true;
        }
      }
      if (!outside) break;
      Solid pushed;
      Status s = planesToPolytope(planes, hull.center, pushed);
      if (!s.ok()) return s;
      current = std::move(pushed);
    }
  }
  out = std::move(current);
  return {};
}

}  // namespace gq::fit
