// Convex hull cooking with qhull's reentrant C API (libqhull_r). qhull builds the hull with premerged facets
// ("C-n": facets whose centrums lie within n of a neighbour's plane merge, n = planeTolerance * hull size;
// "Qx": exact pre-merges), so coplanar hull points form one facet; qh_facet3vertex gives each facet's vertices in boundary order, which we orient counter-clockwise seen
// from outside. Only hull vertices are kept; planes are recomputed in double with Newell's method.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <string>

#include "gq/cooking.h"

extern "C" {
#include <libqhull_r/qhull_ra.h>
}

namespace gq {
namespace {

using Vec3d = Vec3<double>;

// Captures qhull's messages in memory: qhull prints to the FILEs it is given, and a library must not write to
// the user's stdout/stderr.
class MessageSink {
 public:
  MessageSink() { file_ = open_memstream(&buffer_, &size_); }
  ~MessageSink() {
    if (file_) std::fclose(file_);
    std::free(buffer_);
  }
  MessageSink(const MessageSink&) = delete;
  MessageSink& operator=(const MessageSink&) = delete;
  FILE* file() const { return file_; }
  // The first line of what qhull printed (its error code and reason).
  std::string firstLine() {
    if (!file_) return "";
    std::fflush(file_);
    std::string text(buffer_ ? buffer_ : "", size_);
    const auto end = text.find('\n');
    return text.substr(0, end);
  }

 private:
  char* buffer_ = nullptr;
  std::size_t size_ = 0;
  FILE* file_ = nullptr;
};

struct QhullPolygon {
  std::vector<int> inputIds;  // boundary order, counter-clockwise from outside
};

// Newell's method: the area-weighted normal of a (possibly non-planar) polygon, robust for near-collinear runs.
Vec3d newellNormal(const std::vector<Vec3d>& pts) {
  Vec3d n = Vec3d::Zero();
  for (std::size_t i = 0; i < pts.size(); ++i) n += pts[i].cross(pts[(i + 1) % pts.size()]);
  return n;
}

// Runs qhull on `coords` (x,y,z triples) and returns its facets as ordered vertex loops of input indices.
Status runQhull(std::vector<double>& coords, double premergeRadius, std::vector<QhullPolygon>& out) {
  MessageSink sink;
  FILE* err = sink.file() ? sink.file() : stderr;
  qhT qhData;
  qhT* qh = &qhData;
  qh_zero(qh, err);
  std::ostringstream cmd;
  cmd.precision(17);
  cmd << "qhull Qx C-" << premergeRadius;
  std::string command = cmd.str();
  const int numPoints = static_cast<int>(coords.size() / 3);
  const int exitCode = qh_new_qhull(qh, 3, numPoints, coords.data(), False, command.data(), nullptr, err);
  Status status;
  if (exitCode != 0) {
    status = Status::owned(StatusCode::DegenerateMesh, "convex hull failed (points coplanar, collinear or coincident?): qhull: " +
                                sink.firstLine());
  } else {
    facetT* facet;
    FORALLfacets {
      setT* loop = qh_facet3vertex(qh, facet);
      QhullPolygon poly;
      std::vector<Vec3d> pts;
      vertexT *vertex, **vertexp;
      FOREACHvertex_(loop) {
        const int id = qh_pointid(qh, vertex->point);
        poly.inputIds.push_back(id);
        pts.emplace_back(coords[3 * id], coords[3 * id + 1], coords[3 * id + 2]);
      }
      qh_settempfree(qh, &loop);
      const Vec3d outward(facet->normal[0], facet->normal[1], facet->normal[2]);
      if (newellNormal(pts).dot(outward) < 0) std::reverse(poly.inputIds.begin(), poly.inputIds.end());
      if (poly.inputIds.size() >= 3) out.push_back(std::move(poly));
    }
    if (out.size() < 4) status = Status::degenerate("convex hull has fewer than 4 faces");
  }
  qh_freeqhull(qh, !qh_ALL);
  int curlong = 0, totlong = 0;
  qh_memfreeshort(qh, &curlong, &totlong);
  return status;
}

// Vertex adjacency along polygon edges, in CSR form.
template <class T> void buildAdjacency(ConvexMesh<T>& hull) {
  std::vector<std::set<std::uint32_t>> neighbours(hull.vertices.size());
  for (const HullPolygon<T>& poly : hull.polygons) {
    for (std::uint32_t k = 0; k < poly.indexCount; ++k) {
      const std::uint32_t a = hull.polygonVertices[poly.indexBase + k];
      const std::uint32_t b = hull.polygonVertices[poly.indexBase + (k + 1) % poly.indexCount];
      neighbours[a].insert(b);
      neighbours[b].insert(a);
    }
  }
  hull.adjacencyOffsets.assign(1, 0);
  hull.adjacency.clear();
  for (const auto& set : neighbours) {
    hull.adjacency.insert(hull.adjacency.end(), set.begin(), set.end());
    hull.adjacencyOffsets.push_back(static_cast<std::uint32_t>(hull.adjacency.size()));
  }
}

// A double radius as a T no smaller (outer balls) or no larger (inner balls).
template <class T> T roundedUp(double r) {
  const T t = T(r);
  return double(t) < r ? std::nextafter(t, std::numeric_limits<T>::infinity()) : t;
}
template <class T> T roundedDown(double r) {
  const T t = T(r);
  return double(t) > r ? std::nextafter(t, T(0)) : t;
}

// The balls about the stored centre, from the stored (rounded) vertices and planes, in double. The inner one keeps
// clear of each polygon's plane by 4x its vertices' deviation from it (the facets qhull merged into the polygon
// tilt by about that much) and by T's rounding of the plane.
template <class T> void setBalls(ConvexMesh<T>& hull) {
  const Vec3d c = hull.center.template cast<double>();
  const double eps = std::numeric_limits<T>::epsilon();
  double inner = std::numeric_limits<double>::infinity(), outer = 0;
  for (const HullPolygon<T>& poly : hull.polygons) {
    const Vec3d n = poly.normal.template cast<double>();
    const double d = double(poly.d);
    double deviation = 0;
    for (std::uint32_t k = 0; k < poly.indexCount; ++k) {
      const Vec3d v = hull.vertices[hull.polygonVertices[poly.indexBase + k]].template cast<double>();
      deviation = std::max(deviation, std::abs(n.dot(v) + d));
    }
    const double rounding = 8 * eps * (std::abs(d) + c.cwiseAbs().sum());
    inner = std::min(inner, -(n.dot(c) + d) - 4 * deviation - rounding);
  }
  for (const Vec3<T>& v : hull.vertices) outer = std::max(outer, (v.template cast<double>() - c).norm());
  hull.innerRadius = roundedDown<T>(std::max(0.0, inner));
  hull.outerRadius = roundedUp<T>(outer * (1 + 1e-15));
}

template <class T>
Status buildHull(const std::vector<Vec3d>& input, const std::vector<QhullPolygon>& polys, ConvexMesh<T>& hull) {
  std::map<int, std::uint32_t> compact;  // input index -> hull vertex index
  std::vector<Vec3d> verts;
  for (const QhullPolygon& poly : polys) {
    for (int id : poly.inputIds) {
      if (compact.emplace(id, static_cast<std::uint32_t>(verts.size())).second) verts.push_back(input[id]);
    }
  }
  for (const Vec3d& v : verts) {
    hull.vertices.push_back(v.cast<T>());
    hull.localBounds.include(v.cast<T>());
  }
  Vec3d centroid = Vec3d::Zero();
  for (const Vec3d& v : verts) centroid += v;
  centroid /= double(verts.size());
  hull.center = centroid.cast<T>();
  for (const QhullPolygon& poly : polys) {
    std::vector<Vec3d> pts;
    HullPolygon<T> out;
    out.indexBase = static_cast<std::uint32_t>(hull.polygonVertices.size());
    out.indexCount = static_cast<std::uint32_t>(poly.inputIds.size());
    for (int id : poly.inputIds) {
      hull.polygonVertices.push_back(compact[id]);
      pts.push_back(input[id]);
    }
    const Vec3d n = newellNormal(pts);
    if (!(n.norm() > 0)) return Status::degenerate("convex hull has a zero-area face");
    const Vec3d unit = n.normalized();
    double d = 0;
    for (const Vec3d& p : pts) d -= unit.dot(p);
    d /= double(pts.size());
    if (!(unit.dot(centroid) + d < 0)) return Status::degenerate("convex hull is flat (centroid on a face plane)");
    out.normal = unit.cast<T>();
    out.d = T(d);
    hull.polygons.push_back(out);
  }
  setBalls(hull);
  buildAdjacency(hull);
  return {};
}

}  // namespace

// qhull's determinants multiply up to six coordinate differences: beyond this magnitude they overflow double and
// qhull dereferences a null facet (found by fuzz_point_queries with coordinates near 1e290).
constexpr double kMaxHullCoordinate = 1e50;

template <class T>
Status cookConvexMesh(const std::vector<Vec3<T>>& points, std::shared_ptr<const ConvexMesh<T>>& out,
                      const ConvexCookParams& params) {
  try {
    if (points.size() < 4)
      return Status::owned(StatusCode::DegenerateMesh, "convex hull needs at least 4 points (got " + std::to_string(points.size()) + ")");
    if (!(params.planeTolerance >= 0) || !std::isfinite(params.planeTolerance))
      return Status::invalid("planeTolerance must be finite and >= 0");
    std::vector<Vec3d> input;
    input.reserve(points.size());
    Bounds3<double> box;
    for (std::size_t i = 0; i < points.size(); ++i) {
      if (!isFinite(points[i])) return Status::owned(StatusCode::InvalidArgument, "convex point " + std::to_string(i) + " is not finite");
      if (points[i].template cast<double>().cwiseAbs().maxCoeff() > kMaxHullCoordinate)
        return Status::owned(StatusCode::InvalidArgument, "convex point " + std::to_string(i) + " has a coordinate beyond 1e50");
      input.push_back(points[i].template cast<double>());
      box.include(input.back());
    }
    const double size = (box.max - box.min).norm();
    if (!(size > 0)) return Status::degenerate("convex hull points are all coincident");
    std::vector<double> coords;
    coords.reserve(3 * input.size());
    for (const Vec3d& p : input) coords.insert(coords.end(), {p.x(), p.y(), p.z()});
    std::vector<QhullPolygon> polys;
    if (Status s = runQhull(coords, params.planeTolerance * size, polys); !s.ok()) return s;
    auto hull = std::make_shared<ConvexMesh<T>>();
    if (Status s = buildHull(input, polys, *hull); !s.ok()) return s;
    out = std::move(hull);
    return {};
  } catch (const std::exception& e) {
    return Status::owned(StatusCode::InternalError, std::string("convex cooking: ") + e.what());
  }
}

template Status cookConvexMesh<float>(const std::vector<Vec3<float>>&, std::shared_ptr<const ConvexMesh<float>>&, const ConvexCookParams&);
template Status cookConvexMesh<double>(const std::vector<Vec3<double>>&, std::shared_ptr<const ConvexMesh<double>>&, const ConvexCookParams&);

}  // namespace gq
