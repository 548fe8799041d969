// A mesh collision element in the requested representation: the mesh itself, its bounding box in the element frame
// (box-aabb), or what gq::fitShape (gq/fit.h) fits enclosing it, with the fit's certified error bound. Also the
// point-cloud frames and the enclosing capsule the culling volumes use: the capsule's segment ends are as short as
// every point allows (a point at axial t and radial r is covered when t lies within sqrt(R^2 - r^2) of the segment).
#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>

#include "gq/custom_shapes.h"
#include "gq/fit.h"
#include "gq/tolerances.h"
#include "internal.h"

namespace gq::urdf::internal {

// Principal axes of the vertex cloud as a proper rotation (columns sorted by decreasing variance), and the mean.
template <class T> Mat3<double> principalAxes(const std::vector<Vec3<T>>& v, Vec3<double>& mean) {
  mean.setZero();
  for (const auto& p : v) mean += p.template cast<double>();
  mean /= double(v.size());
  Mat3<double> cov = Mat3<double>::Zero();
  for (const auto& p : v) {
    const Vec3<double> d = p.template cast<double>() - mean;
    cov += d * d.transpose();
  }
  Eigen::SelfAdjointEigenSolver<Mat3<double>> eig(cov);
  Mat3<double> r;
  for (int i = 0; i < 3; ++i) r.col(i) = eig.eigenvectors().col(2 - i);  // eigenvalues come in increasing order
  if (r.determinant() < 0) r.col(2) = -r.col(2);
  return r;
}

template <class T> void extentsIn(const std::vector<Vec3<T>>& v, const Mat3<double>& r, Vec3<double>& lo, Vec3<double>& hi) {
  lo.setConstant(std::numeric_limits<double>::max());
  hi.setConstant(-std::numeric_limits<double>::max());
  for (const auto& p : v) {
    const Vec3<double> l = r.transpose() * p.template cast<double>();
    lo = lo.cwiseMin(l);
    hi = hi.cwiseMax(l);
  }
}

template <class T>
EnclosingCapsule enclosingCapsule(const std::vector<Vec3<T>>& v, const Mat3<double>& r, double minRadius,
                                  const std::vector<double>* radii) {
  Vec3<double> lo, hi;
  extentsIn(v, r, lo, hi);
  const Vec3<double> c = (lo + hi) * 0.5;  // the axis runs along local x through (c.y, c.z)
  const auto ball = [&](std::size_t i) { return radii ? (*radii)[i] : 0.0; };
  double radius = minRadius;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const Vec3<double> l = r.transpose() * v[i].template cast<double>() - c;
    radius = std::max(radius, std::hypot(l.y(), l.z()) + ball(i));
  }
  double a = std::numeric_limits<double>::max(), b = -std::numeric_limits<double>::max();
  for (std::size_t i = 0; i < v.size(); ++i) {
    const Vec3<double> l = r.transpose() * v[i].template cast<double>() - c;
    const double room = radius - ball(i);  // the ball fits when its centre is this close to the segment
    const double reach = std::sqrt(std::max(0.0, room * room - l.y() * l.y() - l.z() * l.z()));
    a = std::min(a, l.x() + reach);  // the segment must start at or before t + reach
    b = std::max(b, l.x() - reach);  // and end at or after t - reach
  }
  if (b < a) a = b = 0.5 * (a + b);  // a sphere of `radius` around the middle covers everything
  EnclosingCapsule out;
  out.centre = r * Vec3<double>(c.x() + 0.5 * (a + b), c.y(), c.z());
  out.axis = r.col(0);
  out.halfHeight = 0.5 * (b - a);
  out.radius = radius;
  return out;
}

template EnclosingCapsule enclosingCapsule<float>(const std::vector<Vec3<float>>&, const Mat3<double>&, double,
                                                  const std::vector<double>*);
template EnclosingCapsule enclosingCapsule<double>(const std::vector<Vec3<double>>&, const Mat3<double>&, double,
                                                   const std::vector<double>*);

namespace {

template <class T> std::size_t meshBytes(const TriangleMesh<T>& m, std::size_t bvhBytes) {
  return m.vertices.size() * sizeof(Vec3<T>) + m.triangles.size() * sizeof(TriangleIndices) +
         (m.inputIndex.size() + m.cookedIndex.size() + m.hullVertices.size()) * sizeof(std::uint32_t) +
         m.leafVertices.size() * sizeof(T) + bvhBytes;
}

template <class T> Shape<T> meshSourceShape(const MeshData<T>& mesh, Representation rep) {
  Shape<T> shape;
  shape.source = ShapeSource::Mesh;
  shape.sourceTriangles = std::uint32_t(mesh.triangles.size());
  shape.representation = rep;
  return shape;
}

// The triangle mesh itself, with its convex hull as the checker's culling volume (none for a flat mesh, which has
// no hull): error 0.
template <class T> Status wholeMesh(const MeshData<T>& mesh, Representation rep, MeshParts<T>& out) {
  std::shared_ptr<const TriangleMesh<T>> cooked;
  MeshCookReport report;
  Status s = cookTriangleMesh(mesh.vertices, mesh.triangles, cooked, &report);
  if (!s.ok()) return s;
  std::shared_ptr<const ConvexMesh<T>> hull;
  if (!cookConvexMesh(mesh.vertices, hull).ok()) hull.reset();
  Shape<T> shape = meshSourceShape(mesh, rep);
  shape.geometry = TriangleMeshGeometry<T>(cooked);
  shape.boundingHull = hull;
  shape.fitted = FitRepresentation::Mesh;
  shape.modelTriangles = report.cookedTriangles;
  shape.bytes = meshBytes(*cooked, report.bvhBytes) + (hull ? hullBytes(*hull) : 0);
  out.shapes = {std::move(shape)};
  out.fits = {Transform<T>()};
  return {};
}

// The certified bound's refinement target: LoadOptions::errorBoundTarget, but at least 1e-4 of the mesh's size, so a
// huge mesh (a large scale) is not refined to an absolute target far below what its size resolves.
template <class T> T boundTarget(const MeshData<T>& mesh, const LoadOptions& options) {
  Vec3<double> lo, hi;
  extentsIn(mesh.vertices, Mat3<double>::Identity(), lo, hi);
  return T(std::max(options.errorBoundTarget, 1e-4 * (hi - lo).norm()));
}

// The bounding box in the mesh frame (flat meshes get a box of a few ulps of their size across), and its bound.
template <class T> Status meshFrameBox(const MeshData<T>& mesh, const LoadOptions& options, MeshParts<T>& out) {
  Vec3<double> lo, hi;
  extentsIn(mesh.vertices, Mat3<double>::Identity(), lo, hi);
  const double minHalf = double(tol::Rel<T>::kEpsilon) * (hi - lo).norm();
  const Vec3<double> half = ((hi - lo) * 0.5).cwiseMax(Vec3<double>::Constant(minHalf));
  Shape<T> shape = meshSourceShape(mesh, Representation::BoxAabb);
  shape.geometry = BoxGeometry<T>(half.cast<T>());
  shape.fitted = FitRepresentation::Box;
  shape.bytes = sizeof(Geometry<T>);
  const Transform<T> pose(((lo + hi) * 0.5).cast<T>());
  Status s = certifyFit(mesh, {{shape.geometry, pose}}, boundTarget(mesh, options), FitOptions<T>().maxBoundPatches,
                        shape.errorBound);
  if (!s.ok()) return s;
  out.shapes = {std::move(shape)};
  out.fits = {pose};
  return {};
}

FitRepresentationSet allowedFor(Representation rep) {
  switch (rep) {
    case Representation::Hull: return fitBit(FitRepresentation::ConvexHull);
    case Representation::Box: return fitBit(FitRepresentation::Box);
    case Representation::Capsule: return fitBit(FitRepresentation::Capsule);
    case Representation::Sphere: return fitBit(FitRepresentation::Sphere);
    case Representation::BestPrimitive: return kFitPrimitives;
    default: return kAllFitRepresentations;
  }
}

template <class T> std::uint32_t polygonCount(const Geometry<T>& g) {
  const auto* hull = g.template getIf<ConvexMeshGeometry<T>>();
  return hull ? std::uint32_t(hull->mesh->polygons.size()) : 0u;
}

template <class T> std::size_t geometryBytes(const Geometry<T>& g) {
  if (const auto* hull = g.template getIf<ConvexMeshGeometry<T>>()) return hullBytes(*hull->mesh);
  if (g.template getIf<CustomGeometry<T>>()) return sizeof(Geometry<T>) + sizeof(CylinderCallbacks<T>);
  return sizeof(Geometry<T>);
}

}  // namespace

template <class T>
Status meshShapes(const MeshData<T>& mesh, Representation rep, const LoadOptions& options, MeshParts<T>& out) {
  if (rep == Representation::Mesh) return wholeMesh(mesh, rep, out);
  if (rep == Representation::BoxAabb) return meshFrameBox(mesh, options, out);
  FitOptions<T> fit;
  fit.tolerance = rep == Representation::Fit ? T(options.fitTolerance) : boundTarget(mesh, options);
  fit.allowed = allowedFor(rep);
  fit.maxParts = options.fitMaxParts;
  fit.contain = true;
  fit.measureCost = false;
  FitResult<T> result;
  // A Warning only says that no allowed representation is within the tolerance: the modes other than Fit allow
  // one and report its bound whatever it is.
  Status s = fitShape(mesh, fit, result);
  if (!s.ok() && s.code != StatusCode::Warning) return s;
  if (result.representation == FitRepresentation::Mesh) return wholeMesh(mesh, rep, out);
  out.shapes.clear();
  out.fits.clear();
  for (const auto& [geometry, pose] : result.parts) {
    Shape<T> shape = meshSourceShape(mesh, rep);
    shape.geometry = geometry;
    shape.fitted = result.representation;
    shape.fitParts = std::uint32_t(result.parts.size());
    shape.modelTriangles = polygonCount(geometry);
    shape.bytes = geometryBytes(geometry);
    shape.errorBound = result.errorBound;
    out.shapes.push_back(std::move(shape));
    out.fits.push_back(pose);
  }
  return {};
}

template Mat3<double> principalAxes<float>(const std::vector<Vec3<float>>&, Vec3<double>&);
template Mat3<double> principalAxes<double>(const std::vector<Vec3<double>>&, Vec3<double>&);
template void extentsIn<float>(const std::vector<Vec3<float>>&, const Mat3<double>&, Vec3<double>&, Vec3<double>&);
template void extentsIn<double>(const std::vector<Vec3<double>>&, const Mat3<double>&, Vec3<double>&, Vec3<double>&);
template Status meshShapes<float>(const MeshData<float>&, Representation, const LoadOptions&, MeshParts<float>&);
template Status meshShapes<double>(const MeshData<double>&, Representation, const LoadOptions&, MeshParts<double>&);

}  // namespace gq::urdf::internal
