// Minimum-volume oriented box, approximately: O'Rourke's exact algorithm (cubic in the hull size) is replaced by
// the boxes with a face flush with a hull face, each the minimum-area rectangle of the hull projected on that face
// (rotating calipers: the optimal rectangle has a side flush with an edge of the projected 2-D hull), plus the
// principal-axis and mesh-frame boxes. The optimum may have no face flush with a hull face (only two edges on
// adjacent faces), so the result is not guaranteed optimal; docs/fit.md states the measured gap.
#include <algorithm>
#include <cmath>
#include <limits>

#include "fit/fit_internal.h"

namespace gq::fit {
namespace {

using V2 = Eigen::Vector2d;

double cross(const V2& o, const V2& a, const V2& b) {
  return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
}

// Andrew's monotone chain.
std::vector<V2> hull2d(std::vector<V2> p) {
  std::sort(p.begin(), p.end(), [](const V2& a, const V2& b) { return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y()); });
  std::vector<V2> h(2 * p.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    while (k >= 2 && cross(h[k - 2], h[k - 1], p[i]) <= 0) --k;
    h[k++] = p[i];
  }
  for (std::size_t i = p.size() - 1, t = k + 1; i-- > 0;) {
    while (k >= t && cross(h[k - 2], h[k - 1], p[i]) <= 0) --k;
    h[k++] = p[i];
  }
  h.resize(k > 1 ? k - 1 : k);
  return h;
}

struct Box {
  Mat3d frame;
  Vec3d lo, hi;
  double volume() const { return (hi - lo).prod(); }
};

Box boxIn(const std::vector<Vec3d>& pts, const Mat3d& frame) {
  Box b{frame, Vec3d::Constant(std::numeric_limits<double>::max()), Vec3d::Constant(-std::numeric_limits<double>::max())};
  for (const Vec3d& p : pts) {
    const Vec3d l = frame.transpose() * p;
    b.lo = b.lo.cwiseMin(l);
    b.hi = b.hi.cwiseMax(l);
  }
  return b;
}

// The frame whose first axis is `normal` and whose other two span the minimum-area rectangle of the projection.
Mat3d flushFrame(const std::vector<Vec3d>& pts, const Vec3d& normal) {
  Mat3d f;
  f.col(0) = normal;
  const Vec3d helper = std::abs(normal.x()) < 0.9 ? Vec3d::UnitX() : Vec3d::UnitY();
  const Vec3d u = normal.cross(helper).normalized(), w = normal.cross(u);
  std::vector<V2> proj;
  proj.reserve(pts.size());
  for (const Vec3d& p : pts) proj.emplace_back(p.dot(u), p.dot(w));
  const std::vector<V2> h = hull2d(proj);
  double bestArea = std::numeric_limits<double>::infinity();
  V2 bestDir(1, 0);
  for (std::size_t i = 0; i < h.size(); ++i) {
    V2 e = h[(i + 1) % h.size()] - h[i];
    if (e.norm() == 0) continue;
    e.normalize();
    const V2 n(-e.y(), e.x());
    double a0 = std::numeric_limits<double>::max(), a1 = -a0, b0 = a0, b1 = -a0;
    for (const V2& q : h) {
      a0 = std::min(a0, q.dot(e));
      a1 = std::max(a1, q.dot(e));
      b0 = std::min(b0, q.dot(n));
      b1 = std::max(b1, q.dot(n));
    }
    const double area = (a1 - a0) * (b1 - b0);
    if (area < bestArea) {
      bestArea = area;
      bestDir = e;
    }
  }
  f.col(1) = (bestDir.x() * u + bestDir.y() * w).normalized();
  f.col(2) = f.col(0).cross(f.col(1));
  return f;
}

}  // namespace

Solid fitBox(const ConvexMesh<double>& hull, std::vector<Mat3d>& axes) {
  const std::vector<Vec3d>& pts = hull.vertices;
  std::vector<Mat3d> frames = {principalAxes(pts), Mat3d::Identity()};
  std::vector<Vec3d> normals;
  for (const auto& poly : hull.polygons) {
    bool seen = false;  // parallel faces give the same frame
    for (const Vec3d& n : normals)
      if (std::abs(n.dot(poly.normal)) > 1 - 1e-9) seen = true;
    if (!seen) normals.push_back(poly.normal);
    if (normals.size() >= 512) break;
  }
  for (const Vec3d& n : normals) frames.push_back(flushFrame(pts, n));
  Box best = boxIn(pts, frames[0]);
  for (std::size_t i = 1; i < frames.size(); ++i) {
    const Box b = boxIn(pts, frames[i]);
    if (b.volume() < best.volume()) best = b;
  }
  axes = {best.frame, frames[0], frames[1]};
  Solid s;
  s.kind = Solid::Kind::Box;
  s.rotation = best.frame;
  s.centre = best.frame * ((best.lo + best.hi) * 0.5);
  s.halfExtents = (best.hi - best.lo) * 0.5;
  return s;
}

}  // namespace gq::fit
