// Approximate convex decomposition by hierarchical splitting on concavity (in the spirit of V-HACD and CoACD):
// start from the whole mesh as one piece; while there are fewer than maxParts pieces and the most concave piece's
// concavity exceeds half the tolerance, split it by the candidate plane whose two halves have the least concavity.
// Candidates: the plane of the mesh face nearest the piece's deepest concavity (a cut along a concave edge: an L of
// two boxes splits into the two boxes), the axis planes through that point, and each axis (mesh frame, principal)
// at a quarter, half and three quarters of the piece's extent. Each part is the convex hull of its piece. A piece's
// concavity is the larger of the largest distance from its hull's surface to the mesh surface (branch and bound
// over the hull faces) and the largest depth of its own surface below its hull's faces (at up to 2000 of its
// points), faces on the piece's own cut planes excepted both ways: an estimate from below that steers the
// splitting; the union's bound is certified afterwards like any fit's.
// Halves overlap in a slab 2e-6 of the mesh size thick across the cut, so the union has no crack along it; the
// bound drops a patch of a cut face whose ball lies half in each hull.
// Every mesh vertex lies in a piece and so in its hull: the union contains the mesh.
#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>

#include "fit/fit_internal.h"
#include "gq/query.h"

namespace gq::fit {
namespace {

struct Plane {
  Vec3d normal;
  double offset;  // the piece keeps normal . x <= offset
};

struct Piece {
  std::vector<Vec3d> triangles;  // 3 per triangle
  std::vector<Plane> cuts;
  Solid hull;
  double concavity = 0;
  // Where the concavity estimate peaks: the mesh point nearest the worst hull sample and its triangle's plane.
  Vec3d deepest = Vec3d::Zero();
  Plane deepestPlane{Vec3d::UnitX(), 0.0};
};

// What counts as on a plane (rounding of clipped points and of coplanar mesh faces), and how far a piece's hull
// reaches across each of its cuts, relative to the mesh size.
constexpr double kOnPlane = 1e-9;
constexpr double kOverlap = 1e-6;

// Sutherland-Hodgman clipping of every triangle to normal . x <= offset, fanned back to triangles. A triangle lying
// in the plane bounds the solid on the side opposite its outward normal: it stays with the half on that side.
std::vector<Vec3d> clip(const std::vector<Vec3d>& tris, const Plane& plane, double size) {
  std::vector<Vec3d> out;
  std::vector<Vec3d> poly;
  const double eps = kOnPlane * size;
  for (std::size_t t = 0; t + 2 < tris.size(); t += 3) {
    double d[3];
    for (int i = 0; i < 3; ++i) d[i] = plane.normal.dot(tris[t + i]) - plane.offset;
    if (std::abs(d[0]) <= eps && std::abs(d[1]) <= eps && std::abs(d[2]) <= eps) {
      const Vec3d n = (tris[t + 1] - tris[t]).cross(tris[t + 2] - tris[t]);
      if (n.dot(plane.normal) > 0) out.insert(out.end(), tris.begin() + std::ptrdiff_t(t), tris.begin() + std::ptrdiff_t(t + 3));
      continue;
    }
    poly.clear();
    for (int i = 0; i < 3; ++i) {
      const Vec3d& a = tris[t + i];
      const Vec3d& b = tris[t + (i + 1) % 3];
      const double da = d[i], db = d[(i + 1) % 3];
      if (da <= 0) poly.push_back(a);
      if ((da < 0 && db > 0) || (da > 0 && db < 0)) poly.push_back(a + (da / (da - db)) * (b - a));
    }
    for (std::size_t k = 1; k + 1 < poly.size(); ++k) {
      out.push_back(poly[0]);
      out.push_back(poly[k]);
      out.push_back(poly[k + 1]);
    }
  }
  return out;
}

bool onCut(const Face& f, const std::vector<Plane>& cuts, double size) {
  for (const Plane& c : cuts)
    if (f.normal.dot(c.normal) > 1 - 1e-9 && std::abs(-f.d - c.offset - kOverlap * size) <= 1e-8 * size) return true;
  return false;
}

// The concavity: the largest distance from the piece's hull surface (faces on the piece's cuts excepted) to the
// mesh surface, and where it peaks. Branch and bound over the hull's fan triangles: the distance to the mesh is
// 1-Lipschitz, so a triangle's value is at most its centroid's distance plus the centroid's distance to its farthest
// corner; the triangle of largest such bound is split in four until that bound is within 10 % (or 1e-3 of the mesh
// size) of the largest distance attained, or kConcavityRefinements splits are spent. A centroid alone misses the
// middle of a large face bridging a hollow (the hole of a torus), which is where the concavity peaks.
constexpr std::size_t kConcavityRefinements = 250;
constexpr std::size_t kDepthSamples = 2000;

struct HullPatch {
  Vec3d a, b, c, centre;
  double upper;
  bool operator<(const HullPatch& o) const { return upper < o.upper; }
};

// `cutoff`: the measure stops (false) as soon as the concavity reaches it, the value only growing as it goes: a
// trial half that reaches the best score so far cannot win. `locate`: also find where it peaks (kept pieces).
bool measureConcavity(const Surface& surface, Piece& piece, double cutoff, bool locate) {
  piece.concavity = 0;
  Vec3d worst = Vec3d::Zero();
  bool any = false;
  std::priority_queue<HullPatch> heap;
  const auto push = [&](const Vec3d& a, const Vec3d& b, const Vec3d& c) {
    const Vec3d q = (a + b + c) / 3.0;
    const double d = surface.distance(q);
    if (d > piece.concavity || !any) {
      piece.concavity = d;
      worst = q;
      any = true;
    }
    heap.push({a, b, c, q, d + std::max({(a - q).norm(), (b - q).norm(), (c - q).norm()})});
    return piece.concavity < cutoff;
  };
  const auto& v = piece.hull.vertices;
  std::vector<const Face*> outer;  // the hull's faces not on a cut
  for (const Face& f : piece.hull.faces)
    if (!onCut(f, piece.cuts, surface.size)) outer.push_back(&f);
  for (const Face* face : outer) {
    const Face& f = *face;
    for (std::size_t k = 1; k + 1 < f.vertices.size(); ++k)
      if (!push(v[f.vertices[0]], v[f.vertices[k]], v[f.vertices[k + 1]])) return false;
  }
  for (std::size_t split = 0; split < kConcavityRefinements && !heap.empty(); ++split) {
    const HullPatch t = heap.top();
    if (t.upper <= std::max(1.1 * piece.concavity, piece.concavity + 1e-3 * surface.size)) break;
    heap.pop();
    const Vec3d ab = (t.a + t.b) / 2, bc = (t.b + t.c) / 2, ca = (t.c + t.a) / 2;
    // All four pushed before the cutoff is read, as the measure without one does.
    const bool below = push(t.a, ab, ca) & push(ab, t.b, bc) & push(ca, bc, t.c) & push(ab, bc, ca);
    if (!below) return false;
  }
  // The other way: how deep the piece's own surface lies below its hull's faces (cut faces excepted), at up to
  // kDepthSamples of its points; inside a convex solid the distance to the boundary is the least face-plane distance.
  const std::size_t stride = std::max<std::size_t>(1, piece.triangles.size() / kDepthSamples);
  for (std::size_t i = 0; i < piece.triangles.size(); i += stride) {
    const Vec3d& p = piece.triangles[i];
    double depth = std::numeric_limits<double>::infinity();
    for (const Face* f : outer) depth = std::min(depth, -(f->normal.dot(p) + f->d));
    if (std::isfinite(depth) && (depth > piece.concavity || !any)) {
      piece.concavity = depth;
      worst = p;
      any = true;
      if (piece.concavity >= cutoff) return false;
    }
  }
  if (!any || !locate) return true;
  PointDistanceResult<double> r;
  if (!pointDistance<double>(worst, TriangleMeshGeometry<double>(surface.cooked), Transform<double>(), r).ok()) return true;
  piece.deepest = r.closestPoint;
  const TriangleMesh<double>& m = *surface.cooked;
  if (r.closestIndex >= m.cookedIndex.size() || m.cookedIndex[r.closestIndex] >= m.triangles.size()) return true;
  const TriangleIndices& t = m.triangles[m.cookedIndex[r.closestIndex]];
  const Vec3d n = (m.vertices[t[1]] - m.vertices[t[0]]).cross(m.vertices[t[2]] - m.vertices[t[0]]);
  if (n.norm() > 0) piece.deepestPlane = {n.normalized(), n.normalized().dot(m.vertices[t[0]])};
  return true;
}

// Each point once (a mesh vertex is a corner of about six triangles): qhull's work is in the points.
void keepUnique(std::vector<Vec3d>& pts) {
  const auto less = [](const Vec3d& a, const Vec3d& b) {
    return a.x() != b.x() ? a.x() < b.x() : a.y() != b.y() ? a.y() < b.y() : a.z() < b.z();
  };
  std::sort(pts.begin(), pts.end(), less);
  pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
}

// The piece's hull holds its triangles and each of their points on a cut pushed across it by kOverlap of the mesh
// size: the two halves of a cut overlap in a thin slab, so their union has no crack along it. A trial piece (one
// half of a candidate cut, only scored) takes qhull's hull as it is; a kept piece's hull is grown to hold every point
// (enclosingHull), which costs a pass over the points per face. False also when a trial piece's concavity reaches
// `cutoff` (it cannot be the better split).
bool makePiece(std::vector<Vec3d> tris, std::vector<Plane> cuts, const Surface& surface, bool kept, double cutoff,
               Piece& out) {
  if (tris.size() < 12) return false;
  // The points themselves stay too: pushing a corner where a cut meets a slanted face can leave it just outside.
  std::vector<Vec3d> points = tris;
  const double eps = kOnPlane * surface.size, overlap = kOverlap * surface.size;
  for (const Vec3d& p : tris) {
    Vec3d pushed = p;
    for (const Plane& c : cuts)
      if (std::abs(c.normal.dot(p) - c.offset) <= eps) pushed += overlap * c.normal;
    if (pushed != p) points.push_back(pushed);
  }
  keepUnique(points);
  out.triangles = std::move(tris);
  out.cuts = std::move(cuts);
  if (kept) {
    if (!hullOf(points, out.hull).ok()) return false;
  } else {
    std::shared_ptr<const ConvexMesh<double>> hull;
    if (!cookConvexMesh(points, hull).ok()) return false;
    out.hull = polytopeOf(*hull);
  }
  return measureConcavity(surface, out, kept ? std::numeric_limits<double>::infinity() : cutoff, kept);
}

// Candidate planes: first through the deepest concavity (the plane of the mesh face there, which cuts along a
// concave edge, and the axis planes through the point), then each axis at a quarter, half and three quarters of
// the piece's extent. Axes: the mesh frame's and the piece's principal axes.
std::vector<Plane> candidatePlanes(const Piece& piece) {
  const Mat3d pca = principalAxes(piece.triangles);
  std::vector<Plane> out{piece.deepestPlane};
  for (int i = 0; i < 6; ++i) {
    const Vec3d n = i < 3 ? Vec3d(Mat3d::Identity().col(i)) : Vec3d(pca.col(i - 3));
    out.push_back({n, n.dot(piece.deepest)});
  }
  for (int i = 0; i < 6; ++i) {
    const Vec3d n = i < 3 ? Vec3d(Mat3d::Identity().col(i)) : Vec3d(pca.col(i - 3));
    double lo = std::numeric_limits<double>::max(), hi = -lo;
    for (const Vec3d& p : piece.triangles) {
      lo = std::min(lo, n.dot(p));
      hi = std::max(hi, n.dot(p));
    }
    for (double f : {0.5, 0.25, 0.75}) out.push_back({n, lo + f * (hi - lo)});
  }
  return out;
}

// The candidate plane whose two halves have the least concavity (the larger of the two); a plane that leaves
// (nearly) nothing on one side is skipped. A trial half is measured only until it reaches the best score so far
// (its plane cannot win then): the choice is the one measuring every half in full would make.
bool splitPiece(const Piece& piece, const Surface& surface, Piece& a, Piece& b) {
  constexpr double kNoCutoff = std::numeric_limits<double>::infinity();
  double best = kNoCutoff;
  const Plane* chosen = nullptr;
  const std::vector<Plane> candidates = candidatePlanes(piece);
  const auto half = [&](const Plane& plane, bool kept, double cutoff, Piece& out) {
    std::vector<Plane> cuts = piece.cuts;
    cuts.push_back(plane);
    return makePiece(clip(piece.triangles, plane, surface.size), cuts, surface, kept, cutoff, out);
  };
  const auto opposite = [](const Plane& p) { return Plane{-p.normal, -p.offset}; };
  for (const Plane& plane : candidates) {
    Piece pa, pb;
    if (!half(plane, false, best, pa) || !half(opposite(plane), false, best, pb)) continue;
    const double score = std::max(pa.concavity, pb.concavity);
    if (score < best) {
      best = score;
      chosen = &plane;
    }
  }
  return chosen != nullptr && half(*chosen, true, kNoCutoff, a) && half(opposite(*chosen), true, kNoCutoff, b);
}

}  // namespace

Status decompose(const Surface& surface, double tolerance, std::uint32_t maxParts, std::uint32_t,
                 std::vector<Solid>& parts) {
  std::vector<Vec3d> tris;
  tris.reserve(surface.triangles.size() * 3);
  for (const auto& t : surface.triangles)
    for (std::uint32_t i : t) tris.push_back(surface.vertices[i]);
  std::vector<Piece> pieces(1);
  if (!makePiece(std::move(tris), {}, surface, true, std::numeric_limits<double>::infinity(), pieces[0])) return Status::degenerate("mesh has no convex hull");
  while (pieces.size() < maxParts) {
    std::size_t worst = 0;
    for (std::size_t i = 1; i < pieces.size(); ++i)
      if (pieces[i].concavity > pieces[worst].concavity) worst = i;
    if (pieces[worst].concavity <= 0.5 * tolerance) break;
    Piece a, b;
    if (!splitPiece(pieces[worst], surface, a, b)) {
      pieces[worst].concavity = 0;  // cannot be split further: leave it
      continue;
    }
    pieces[worst] = std::move(a);
    pieces.push_back(std::move(b));
  }
  parts.clear();
  for (Piece& p : pieces) parts.push_back(std::move(p.hull));
  return {};
}

}  // namespace gq::fit
