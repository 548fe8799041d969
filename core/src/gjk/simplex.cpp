// Signed-volume closest point on a simplex (see simplex.h).
#include "gjk/simplex.h"

#include "gjk/wide.h"

#include <cmath>

namespace gq::detail {
namespace {

// A sub-simplex candidate (simplex.h).
template <class T> using Candidate = SimplexChoice<T>;

template <class T> constexpr T kDegenerate = T(16) * std::numeric_limits<T>::epsilon();

template <class T> Candidate<T> vertexCandidate(const GjkSimplex<T>& s, std::uint32_t i) {
  Candidate<T> c;
  c.index[0] = i;
  c.v = s.points[i].w;
  return c;
}

template <class T> const Candidate<T>& closer(const Candidate<T>& x, const Candidate<T>& y) {
  return y.v.squaredNorm() < x.v.squaredNorm() ? y : x;
}

// p + t e cancels to |v| from |p|: rounding of eps |p| in v. Once that exceeds 1e-3 of |v| while |v| is above GJK's
// tolerance (float support points ~1e6 from the origin around a distance of a few units: v's direction, GJK's next
// search direction, was off by 4 % and GJK stalled), v is recomputed from the widened points.
template <class T> bool segmentNeedsWider(T farSq, T vSq) {
  constexpr T eps = std::numeric_limits<T>::epsilon(), rel = gjkRelativeTolerance<T>();
  if constexpr (eps <= T(1e-3) * rel) return false;  // both conditions at once need eps > 1e-3 rel (float only)
  else return eps * eps * farSq > T(1e-6) * vSq && vSq > rel * rel * farSq;
}
template <class T> [[gnu::noinline]] void widenSegment(const Vec3<T>& p, const Vec3<T>& q, Candidate<T>& c) {
  using W = typename Wider<T>::type;
  const WideVec<W> wp = p.template cast<W>(), we = q.template cast<W>() - wp;
  const W t = -wp.dot(we) / we.squaredNorm();
  c.lambda = {T(W(1) - t), T(t), T(0), T(0)};
  c.v = (wp + t * we).template cast<T>();
}

// Segment i-j: t = -p_i.(p_j - p_i) / |p_j - p_i|^2, clamped to the end points.
template <class T> [[gnu::always_inline]] inline Candidate<T> segmentCandidate(const GjkSimplex<T>& s, std::uint32_t i, std::uint32_t j) {
  const Vec3<T>& p = s.points[i].w;
  const Vec3<T> e = s.points[j].w - p;
  const T ee = e.squaredNorm();
  if (!(ee > T(0))) return vertexCandidate(s, i);
  const T t = -p.dot(e) / ee;
  if (t <= T(0)) return vertexCandidate(s, i);
  if (t >= T(1)) return vertexCandidate(s, j);
  Candidate<T> c;
  c.index = {i, j, 0, 0};
  c.count = 2;
  c.lambda = {T(1) - t, t, T(0), T(0)};
  c.v = p + t * e;
  if (segmentNeedsWider(p.squaredNorm(), c.v.squaredNorm())) widenSegment(p, s.points[j].w, c);
  return c;
}

template <class T>
Candidate<T> bestEdge(const GjkSimplex<T>& s, std::uint32_t i, std::uint32_t j, std::uint32_t k) {
  const Candidate<T> a = segmentCandidate(s, i, j), b = segmentCandidate(s, j, k), c = segmentCandidate(s, k, i);
  return closer(closer(a, b), c);
}

// Origin projecting outside triangle (i, j, k) with weights l: the closest point lies on an edge whose line
// separates the projection from the triangle, i.e. an edge opposite a vertex of weight <= 0 (the difference
// vector lies in the normal cone of the closest point, spanned by such edges' outward normals). Only those
// edges are tried (Montanari et al. 2017's sign test).
template <class T>
Candidate<T> closestEdge(const GjkSimplex<T>& s, const std::array<std::uint32_t, 3>& v, const std::array<T, 3>& l) {
  Candidate<T> best;
  bool any = false;
  for (int m = 0; m < 3; ++m) {
    if (l[m] > T(0)) continue;
    const Candidate<T> c = segmentCandidate(s, v[(m + 1) % 3], v[(m + 2) % 3]);
    if (!any || c.v.squaredNorm() < best.v.squaredNorm()) best = c;
    any = true;
  }
  return any ? best : bestEdge(s, v[0], v[1], v[2]);  // unreachable (some weight is <= 0 or NaN); kept total
}

// The origin's projection p on the plane of (p0, p1, p2) with normal n = (p1 - p0) x (p2 - p0), and its weights: the
// signed areas of the sub-triangles (dotted with n) over |n|^2.
template <class W> struct PlaneProjection {
  Eigen::Matrix<W, 3, 1> p;
  W l0, l1;
};
template <class W>
[[gnu::always_inline]] inline PlaneProjection<W> projectOrigin(const Eigen::Matrix<W, 3, 1>& p0, const Eigen::Matrix<W, 3, 1>& p1,
                                 const Eigen::Matrix<W, 3, 1>& p2, const Eigen::Matrix<W, 3, 1>& n, W nn) {
  const Eigen::Matrix<W, 3, 1> p = n * (n.dot(p0) / nn);
  return {p, n.dot((p1 - p).cross(p2 - p)) / nn, n.dot((p2 - p).cross(p0 - p)) / nn};
}

// The projection from the widened points (out of line: the wide arithmetic would enlarge the hot function's frame).
template <class T>
[[gnu::noinline]] PlaneProjection<T> wideProjection(const Vec3<T>& p0, const Vec3<T>& p1, const Vec3<T>& p2) {
  using W = typename Wider<T>::type;
  const WideVec<W> w0 = p0.template cast<W>(), w1 = p1.template cast<W>(), w2 = p2.template cast<W>();
  const WideVec<W> wn = (w1 - w0).cross(w2 - w0);
  const PlaneProjection<W> wide = projectOrigin(w0, w1, w2, wn, wn.squaredNorm());
  return {wide.p.template cast<T>(), T(wide.l0), T(wide.l1)};
}

// Triangle i-j-k: project the origin on the plane. Outside the triangle (or degenerate) the closest point is on an
// edge.
template <class T>
Candidate<T> triangleCandidate(const GjkSimplex<T>& s, std::uint32_t i, std::uint32_t j, std::uint32_t k) {
  const Vec3<T>&p0 = s.points[i].w, &p1 = s.points[j].w, &p2 = s.points[k].w;
  const Vec3<T> e1 = p1 - p0, e2 = p2 - p0;  // |p0 - p2| = |e2| exactly
  const Vec3<T> n = e1.cross(e2);
  const T nn = n.squaredNorm();
  const T edge2 = std::max({e1.squaredNorm(), (p2 - p1).squaredNorm(), e2.squaredNorm()});
  if (!(nn > kDegenerate<T> * edge2 * edge2 * kDegenerate<T>)) return bestEdge(s, i, j, k);
  PlaneProjection<T> pr = projectOrigin(p0, p1, p2, n, nn);
  // Past GJK's relative tolerance and past |p| itself (gjk/wide.h): recomputed from the widened points.
  if (planeNeedsWider(nn, edge2, gjkRelativeTolerance<T>(), [&] { return p0.squaredNorm(); },
                      [&] { return pr.p.squaredNorm(); }))
    pr = wideProjection(p0, p1, p2);
  const T l0 = pr.l0, l1 = pr.l1, l2 = T(1) - l0 - l1;
  if (!(l0 > T(0) && l1 > T(0) && l2 > T(0))) return closestEdge(s, {i, j, k}, {l0, l1, l2});
  Candidate<T> c;
  c.index = {i, j, k, 0};
  c.count = 3;
  c.lambda = {l0, l1, l2, T(0)};
  // The plane projection, not sum(l_i p_i): near the origin the sum cancels and its direction (the next search
  // direction) would be noise, while n is accurate to rounding of the edges.
  c.v = pr.p;
  return c;
}

template <class T> Candidate<T> bestFace(const GjkSimplex<T>& s) {
  const Candidate<T> a = triangleCandidate(s, 0, 1, 2), b = triangleCandidate(s, 0, 1, 3);
  const Candidate<T> c = triangleCandidate(s, 0, 2, 3), d = triangleCandidate(s, 1, 2, 3);
  return closer(closer(a, b), closer(c, d));
}

// Origin outside the tetrahedron: the closest point lies on a face the origin sees, i.e. a face opposite a vertex
// of signed-volume weight <= 0 (same normal-cone argument as closestEdge); only those faces are tried.
template <class T> Candidate<T> closestFace(const GjkSimplex<T>& s, const std::array<T, 4>& l) {
  static constexpr std::array<std::array<std::uint32_t, 3>, 4> kOpposite = {{{1, 2, 3}, {0, 2, 3}, {0, 1, 3}, {0, 1, 2}}};
  Candidate<T> best;
  bool any = false;
  for (int m = 0; m < 4; ++m) {
    if (l[m] > T(0)) continue;
    const auto& f = kOpposite[m];
    const Candidate<T> c = triangleCandidate(s, f[0], f[1], f[2]);
    if (!any || c.v.squaredNorm() < best.v.squaredNorm()) best = c;
    any = true;
  }
  return any ? best : bestFace(s);  // unreachable (some weight is <= 0 or NaN); kept total
}

// a . (b x c) in scalars: Eigen's cross product, stored a component at a time and read back as packed pairs by the
// dot product, waited on failed store forwarding (perf; in scalars convex30/convex100 distance is ~3 % faster). The
// plane projection's triple products (projectOrigin) stay Eigen's: in scalars they made convex30 distance ~8 % slower.
template <class T> T tripleProduct(const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& c) {
  return a.x() * (b.y() * c.z() - b.z() * c.y()) + a.y() * (b.z() * c.x() - b.x() * c.z()) +
         a.z() * (b.x() * c.y() - b.y() * c.x());
}

// The origin's barycentric weights in the tetrahedron: signed volumes with the origin replacing one vertex, over det.
template <class W>
std::array<W, 4> originWeights(const Vec3<W>& p0, const Vec3<W>& p1, const Vec3<W>& p2, const Vec3<W>& p3, W det) {
  return {tripleProduct<W>(p1, p2, p3) / det, tripleProduct<W>(p0, p3, p2) / det, tripleProduct<W>(p0, p1, p3) / det,
          tripleProduct<W>(p0, p2, p1) / det};
}

// Origin at barycentric weights l of the tetrahedron: inside when all are positive, else on a face it sees.
template <class T> Candidate<T> tetrahedronFromWeights(const GjkSimplex<T>& s, const std::array<T, 4>& l) {
  if (!(l[0] > T(0) && l[1] > T(0) && l[2] > T(0) && l[3] > T(0))) return closestFace(s, l);
  Candidate<T> c;
  c.index = {0, 1, 2, 3};
  c.count = 4;
  c.lambda = l;
  c.v = Vec3<T>::Zero();
  c.containsOrigin = true;
  return c;
}

// A long thin tetrahedron (support points of a shape 1e8+ times longer than wide): its volume is below double's
// rounding of the triple products (error ~ eps |e|^3 with e the long edges), though the points themselves resolve the
// origin's side of every face. Each rounding in the wider type is ~eps_W / eps_T smaller, so the volumes are
// recomputed there from the exact (widened) points; still degenerate there, the closest face as before.
template <class T> [[gnu::noinline]] Candidate<T> wideTetrahedron(const GjkSimplex<T>& s, T edge) {
  using W = typename Wider<T>::type;
  std::array<Vec3<W>, 4> p;
  for (int k = 0; k < 4; ++k) p[k] = s.points[k].w.template cast<W>();
  const W det = tripleProduct<W>(p[1] - p[0], p[2] - p[0], p[3] - p[0]);
  const W e = W(edge), bound = W(16) * wideEpsilon<W>() * e * e * e;
  if (!(det > bound || det < -bound)) return bestFace(s);
  const std::array<W, 4> wide = originWeights<W>(p[0], p[1], p[2], p[3], det);
  return tetrahedronFromWeights(s, {T(wide[0]), T(wide[1]), T(wide[2]), T(wide[3])});
}

// Tetrahedron: the origin's barycentric weights are signed volumes with the origin replacing one vertex.
template <class T> Candidate<T> tetrahedronCandidate(const GjkSimplex<T>& s) {
  const Vec3<T>&p0 = s.points[0].w, &p1 = s.points[1].w, &p2 = s.points[2].w, &p3 = s.points[3].w;
  const T det = tripleProduct<T>(p1 - p0, p2 - p0, p3 - p0);
  T edge = T(0);
  for (const auto& q : {p1, p2, p3}) edge = std::max(edge, (q - p0).norm());
  if (!(std::abs(det) > kDegenerate<T> * edge * edge * edge)) return wideTetrahedron(s, edge);
  return tetrahedronFromWeights(s, originWeights<T>(p0, p1, p2, p3, det));
}

}  // namespace

template <class T> SimplexChoice<T> chooseOnSimplex(const GjkSimplex<T>& s) {
  Candidate<T> c;
  switch (s.size) {
    case 1: c = vertexCandidate(s, 0); break;
    case 2: c = segmentCandidate(s, 0, 1); break;
    case 3: c = triangleCandidate(s, 0, 1, 2); break;
    default: c = tetrahedronCandidate(s); break;
  }
  return c;
}

// Increasing indices (all but one edge order of the solver) move in place: index[k] >= k, so slot k is filled from a
// slot not yet overwritten, and slots already in place are not copied.
template <class T> void reduceSimplex(GjkSimplex<T>& s, const SimplexChoice<T>& choice) {
  bool increasing = true;
  for (std::uint32_t k = 1; k < choice.count; ++k) increasing = increasing && choice.index[k] > choice.index[k - 1];
  if (increasing) {
    for (std::uint32_t k = 0; k < choice.count; ++k)
      if (choice.index[k] != k) s.points[k] = s.points[choice.index[k]];
  } else {
    std::array<SupportPoint<T>, 4> kept;
    for (std::uint32_t k = 0; k < choice.count; ++k) kept[k] = s.points[choice.index[k]];
    for (std::uint32_t k = 0; k < choice.count; ++k) s.points[k] = kept[k];
  }
  s.size = choice.count;
}

template <class T> SimplexClosest<T> closestOnSimplex(GjkSimplex<T>& s) {
  const SimplexChoice<T> c = chooseOnSimplex(s);
  reduceSimplex(s, c);
  return SimplexClosest<T>{c.v, c.lambda, c.containsOrigin};
}

template <class T> void simplexWitnesses(const GjkSimplex<T>& s, const std::array<T, 4>& lambda, Vec3<T>& a, Vec3<T>& b) {
  a.setZero();
  b.setZero();
  for (std::uint32_t k = 0; k < s.size; ++k) {
    a += lambda[k] * s.points[k].a;
    b += lambda[k] * s.points[k].b;
  }
}

template SimplexChoice<float> chooseOnSimplex<float>(const GjkSimplex<float>&);
template SimplexChoice<double> chooseOnSimplex<double>(const GjkSimplex<double>&);
template void reduceSimplex<float>(GjkSimplex<float>&, const SimplexChoice<float>&);
template void reduceSimplex<double>(GjkSimplex<double>&, const SimplexChoice<double>&);
template SimplexClosest<float> closestOnSimplex<float>(GjkSimplex<float>&);
template SimplexClosest<double> closestOnSimplex<double>(GjkSimplex<double>&);
template void simplexWitnesses<float>(const GjkSimplex<float>&, const std::array<float, 4>&, Vec3<float>&, Vec3<float>&);
template void simplexWitnesses<double>(const GjkSimplex<double>&, const std::array<double, 4>&, Vec3<double>&, Vec3<double>&);

}  // namespace gq::detail
