#pragma once
// Independent long-double references for the mesh / heightfield pair tests: exact primitive-triangle predicates and
// distances written from scratch (projection + barycentric coordinates, critical points of the segment-segment
// distance, SAT), a test-side mesh instance (vertices through scale and pose), heightfield triangles from the
// documented layout, and the random scenes.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "gq/cooking.h"
#include "gq/geometry.h"
#include "test_util.h"

namespace gq::meshpairs {

using test::LD;
using test::Mat3L;
using test::Vec3L;
using TriL = std::array<Vec3L, 3>;

inline LD pointSegmentDistSq(const Vec3L& x, const Vec3L& a, const Vec3L& b) {
  const Vec3L d = b - a;
  const LD len2 = d.squaredNorm();
  LD t = len2 > 0 ? (x - a).dot(d) / len2 : 0;
  t = std::min<LD>(1, std::max<LD>(0, t));
  return (a + t * d - x).squaredNorm();
}

// Barycentric coordinates of the projection of x on the triangle's plane; inside when all are >= 0.
inline bool projectsInside(const Vec3L& x, const TriL& t, Vec3L& projected) {
  const Vec3L n = (t[1] - t[0]).cross(t[2] - t[0]);
  const LD n2 = n.squaredNorm();
  projected = x - n * (n.dot(x - t[0]) / n2);
  for (int i = 0; i < 3; ++i)
    if (n.dot((t[(i + 1) % 3] - t[i]).cross(projected - t[i])) < 0) return false;
  return true;
}

inline LD pointTriangleDistSq(const Vec3L& x, const TriL& t) {
  Vec3L p;
  if (projectsInside(x, t, p)) return (p - x).squaredNorm();
  return std::min({pointSegmentDistSq(x, t[0], t[1]), pointSegmentDistSq(x, t[1], t[2]), pointSegmentDistSq(x, t[2], t[0])});
}

// Minimum of |a0 + s(a1-a0) - b0 - u(b1-b0)|^2 over [0,1]^2: the interior critical point if inside, else the best
// of the four boundary point-segment distances.
inline LD segmentSegmentDistSq(const Vec3L& a0, const Vec3L& a1, const Vec3L& b0, const Vec3L& b1) {
  LD best = std::min({pointSegmentDistSq(a0, b0, b1), pointSegmentDistSq(a1, b0, b1), pointSegmentDistSq(b0, a0, a1),
                      pointSegmentDistSq(b1, a0, a1)});
  const Vec3L d0 = a1 - a0, d1 = b1 - b0, r = a0 - b0;
  const LD A = d0.dot(d0), B = d0.dot(d1), C = d1.dot(d1), D = d0.dot(r), E = d1.dot(r);
  const LD det = A * C - B * B;
  if (det > 1e-30L * A * C) {
    const LD s = (B * E - C * D) / det, u = (A * E - B * D) / det;
    if (s > 0 && s < 1 && u > 0 && u < 1) best = std::min(best, (a0 + s * d0 - b0 - u * d1).squaredNorm());
  }
  return best;
}

// Whether segment [p, q] crosses the triangle (meets it at a point strictly between the planes' sides).
inline bool segmentCrossesTriangle(const Vec3L& p, const Vec3L& q, const TriL& t) {
  const Vec3L n = (t[1] - t[0]).cross(t[2] - t[0]);
  const LD dp = n.dot(p - t[0]), dq = n.dot(q - t[0]);
  if ((dp > 0 && dq > 0) || (dp < 0 && dq < 0) || dp == dq) return false;
  const Vec3L x = p + (dp / (dp - dq)) * (q - p);
  for (int i = 0; i < 3; ++i)
    if (n.dot((t[(i + 1) % 3] - t[i]).cross(x - t[i])) < 0) return false;
  return true;
}

inline LD segmentTriangleDistSq(const Vec3L& p, const Vec3L& q, const TriL& t) {
  if (segmentCrossesTriangle(p, q, t)) return 0;
  LD best = std::min(pointTriangleDistSq(p, t), pointTriangleDistSq(q, t));
  for (int i = 0; i < 3; ++i) best = std::min(best, segmentSegmentDistSq(p, q, t[i], t[(i + 1) % 3]));
  return best;
}

// Triangles in general position intersect iff an edge of one crosses the other.
inline bool trianglesIntersect(const TriL& a, const TriL& b) {
  for (int i = 0; i < 3; ++i) {
    if (segmentCrossesTriangle(a[i], a[(i + 1) % 3], b)) return true;
    if (segmentCrossesTriangle(b[i], b[(i + 1) % 3], a)) return true;
  }
  return false;
}

inline LD triangleTriangleDistSq(const TriL& a, const TriL& b) {
  if (trianglesIntersect(a, b)) return 0;
  LD best = std::numeric_limits<LD>::infinity();
  for (int i = 0; i < 3; ++i) {
    best = std::min(best, segmentTriangleDistSq(a[i], a[(i + 1) % 3], b));
    best = std::min(best, segmentTriangleDistSq(b[i], b[(i + 1) % 3], a));
  }
  return best;
}

// Oriented box: centre, rotation (columns = axes), half extents.
struct BoxL {
  Vec3L c;
  Mat3L r;
  Vec3L h;
  Vec3L corner(int k) const {
    return c + r * Vec3L((k & 1) ? h.x() : -h.x(), (k & 2) ? h.y() : -h.y(), (k & 4) ? h.z() : -h.z());
  }
};

// SAT over the box's 3 axes, the triangle normal and the 9 axis x edge crosses, in world coordinates.
inline bool boxTriangleIntersect(const BoxL& b, const TriL& t) {
  std::vector<Vec3L> axes;
  for (int k = 0; k < 3; ++k) axes.push_back(b.r.col(k));
  axes.push_back((t[1] - t[0]).cross(t[2] - t[0]));
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 3; ++j) axes.push_back(Vec3L(b.r.col(k)).cross(t[(j + 1) % 3] - t[j]));
  for (const Vec3L& a : axes) {
    LD lo = std::numeric_limits<LD>::infinity(), hi = -lo;
    for (const auto& v : t) {
      lo = std::min(lo, a.dot(v));
      hi = std::max(hi, a.dot(v));
    }
    LD radius = 0;
    for (int k = 0; k < 3; ++k) radius += b.h[k] * std::abs(a.dot(b.r.col(k)));
    const LD c = a.dot(b.c);
    if (lo > c + radius || hi < c - radius) return false;
  }
  return true;
}

inline LD pointBoxDistSq(const Vec3L& x, const BoxL& b) {
  const Vec3L local = b.r.transpose() * (x - b.c);
  const Vec3L outside = (local.cwiseAbs() - b.h).cwiseMax(Vec3L::Zero());
  return outside.squaredNorm();
}

// Separated box and triangle: the closest pair is vertex-face, face-vertex or edge-edge.
inline LD boxTriangleDistSq(const BoxL& b, const TriL& t) {
  if (boxTriangleIntersect(b, t)) return 0;
  LD best = std::numeric_limits<LD>::infinity();
  for (int k = 0; k < 8; ++k) best = std::min(best, pointTriangleDistSq(b.corner(k), t));
  for (const auto& v : t) best = std::min(best, pointBoxDistSq(v, b));
  for (int k = 0; k < 8; ++k)
    for (int bit = 1; bit < 8; bit <<= 1) {
      if (k & bit) continue;
      for (int j = 0; j < 3; ++j)
        best = std::min(best, segmentSegmentDistSq(b.corner(k), b.corner(k | bit), t[j], t[(j + 1) % 3]));
    }
  return best;
}

// A test-side mesh instance: every input triangle in world coordinates (x = R S v + p, S = Rs diag(s) Rs^T).
template <class T> std::vector<TriL> worldTriangles(const MeshData<T>& data, const MeshScale<T>& scale, const Transform<T>& pose) {
  const Mat3L rs = test::rotationLD(scale.rotation);
  const Mat3L s = rs * scale.scale.template cast<LD>().asDiagonal() * rs.transpose();
  const Mat3L m = test::rotationLD(pose.q) * s;
  std::vector<TriL> out;
  for (const auto& idx : data.triangles) {
    TriL t;
    for (int k = 0; k < 3; ++k) t[k] = m * data.vertices[idx[k]].template cast<LD>() + test::toLD(pose.p);
    out.push_back(t);
  }
  return out;
}

// Heightfield triangles from the documented layout: sample (r, c) at (r rowScale, h heightScale, c columnScale);
// triangle 2*cell = (v00, v01, v10), 2*cell+1 = (v01, v11, v10); hole cells yield no triangle (marked invalid).
template <class T>
std::vector<TriL> heightFieldTriangles(const HeightFieldDesc<T>& d, T hs, T rs, T cs, const Transform<T>& pose,
                                       std::vector<bool>& valid) {
  const Mat3L r = test::rotationLD(pose.q);
  auto sample = [&](std::uint32_t row, std::uint32_t col) {
    const Vec3L local(LD(row) * LD(rs), LD(d.heights[row * d.columns + col]) * LD(hs), LD(col) * LD(cs));
    return Vec3L(r * local + test::toLD(pose.p));
  };
  std::vector<TriL> out;
  valid.clear();
  for (std::uint32_t row = 0; row + 1 < d.rows; ++row)
    for (std::uint32_t col = 0; col + 1 < d.columns; ++col) {
      const std::uint32_t cell = row * (d.columns - 1) + col;
      const bool hole = std::find(d.holes.begin(), d.holes.end(), cell) != d.holes.end();
      out.push_back({sample(row, col), sample(row, col + 1), sample(row + 1, col)});
      out.push_back({sample(row, col + 1), sample(row + 1, col + 1), sample(row + 1, col)});
      valid.push_back(!hole);
      valid.push_back(!hole);
    }
  return out;
}

inline bool boxesOverlap(const TriL& t, const Vec3L& lo, const Vec3L& hi) {
  for (int k = 0; k < 3; ++k) {
    const LD a = std::min({t[0][k], t[1][k], t[2][k]}), b = std::max({t[0][k], t[1][k], t[2][k]});
    if (a > hi[k] || b < lo[k]) return false;
  }
  return true;
}

}  // namespace gq::meshpairs
