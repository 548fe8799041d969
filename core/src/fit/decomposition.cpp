// Approximate convex decomposition by hierarchical splitting on concavity (in the spirit of V-HACD and CoACD):
// start from the whole mesh as one piece; while there are fewer than maxParts pieces and the most concave piece's
// concavity exceeds half the tolerance, split it by the best of nine planes (its three principal axes at a quarter,
// half and three quarters of its extent), the one whose two halves have the least concavity. Each part is the convex
// hull of its piece. A piece's concavity is the largest distance from the centroids of its hull's faces (faces on
// the piece's own cut planes excepted) to the mesh surface: a fast estimate that steers the splitting; the union's
// bound is certified afterwards like any fit's.
// Halves overlap in a slab 2e-6 of the mesh size thick across the cut, so the union has no crack along it; the
// bound drops a patch of a cut face whose ball lies half in each hull.
// Every mesh vertex lies in a piece and so in its hull: the union contains the mesh.
#include <algorithm>
#include <limits>

#include "fit/fit_internal.h"

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
};

// Sutherland-Hodgman clipping of every triangle to normal . x <= offset, fanned back to triangles.
std::vector<Vec3d> clip(const std::vector<Vec3d>& tris, const Plane& plane) {
  std::vector<Vec3d> out;
  std::vector<Vec3d> poly;
  for (std::size_t t = 0; t + 2 < tris.size(); t += 3) {
    poly.clear();
    for (int i = 0; i < 3; ++i) {
      const Vec3d& a = tris[t + i];
      const Vec3d& b = tris[t + (i + 1) % 3];
      const double da = plane.normal.dot(a) - plane.offset, db = plane.normal.dot(b) - plane.offset;
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
    if (f.normal.dot(c.normal) > 1 - 1e-9 && std::abs(-f.d - c.offset) <= 1e-9 * size) return true;
  return false;
}

double concavityOf(const Solid& hull, const std::vector<Plane>& cuts, const Surface& surface) {
  double worst = 0;
  for (const Face& f : hull.faces) {
    if (onCut(f, cuts, surface.size)) continue;
    for (std::size_t k = 1; k + 1 < f.vertices.size(); ++k) {
      const Vec3d c = (hull.vertices[f.vertices[0]] + hull.vertices[f.vertices[k]] + hull.vertices[f.vertices[k + 1]]) / 3.0;
      worst = std::max(worst, surface.distance(c));
    }
  }
  return worst;
}

bool makePiece(std::vector<Vec3d> tris, std::vector<Plane> cuts, const Surface& surface, Piece& out) {
  if (tris.size() < 12) return false;
  out.triangles = std::move(tris);
  out.cuts = std::move(cuts);
  if (!hullOf(out.triangles, out.hull).ok()) return false;
  out.concavity = concavityOf(out.hull, out.cuts, surface);
  return true;
}

bool splitPiece(const Piece& piece, const Surface& surface, Piece& a, Piece& b) {
  const Mat3d pca = principalAxes(piece.triangles);
  double best = std::numeric_limits<double>::infinity();
  bool found = false;
  for (int i = 0; i < 6; ++i) {
    const Vec3d n = i < 3 ? Vec3d(Mat3d::Identity().col(i)) : Vec3d(pca.col(i - 3));
    double lo = std::numeric_limits<double>::max(), hi = -lo;
    for (const Vec3d& p : piece.triangles) {
      lo = std::min(lo, n.dot(p));
      hi = std::max(hi, n.dot(p));
    }
    const double overlap = 1e-6 * surface.size;
    for (double f : {0.5, 0.25, 0.75}) {
      const double at = lo + f * (hi - lo);
      std::vector<Plane> cutsA = piece.cuts, cutsB = piece.cuts;
      cutsA.push_back({n, at + overlap});
      cutsB.push_back({-n, -(at - overlap)});
      Piece pa, pb;
      if (!makePiece(clip(piece.triangles, cutsA.back()), cutsA, surface, pa)) continue;
      if (!makePiece(clip(piece.triangles, cutsB.back()), cutsB, surface, pb)) continue;
      const double score = std::max(pa.concavity, pb.concavity);
      if (score < best) {
        best = score;
        a = std::move(pa);
        b = std::move(pb);
        found = true;
      }
    }
  }
  return found;
}

}  // namespace

Status decompose(const Surface& surface, double tolerance, std::uint32_t maxParts, std::uint32_t,
                 std::vector<Solid>& parts) {
  std::vector<Vec3d> tris;
  tris.reserve(surface.triangles.size() * 3);
  for (const auto& t : surface.triangles)
    for (std::uint32_t i : t) tris.push_back(surface.vertices[i]);
  std::vector<Piece> pieces(1);
  if (!makePiece(std::move(tris), {}, surface, pieces[0])) return Status::degenerate("mesh has no convex hull");
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
