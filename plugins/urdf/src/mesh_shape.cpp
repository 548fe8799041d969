// A mesh collision element in the requested representation. Primitive fits enclose every vertex:
//  - box: the bounding box in the principal-axis (PCA) frame of the vertices, or in the link frame (box-aabb);
//  - capsule: axis = first principal axis through the centre of the PCA box's cross-section, radius = largest
//    distance of a vertex from that axis, segment ends as short as every vertex allows: a vertex at axial t and
//    radial r is covered when t lies within sqrt(R^2 - r^2) of the segment;
//  - sphere: centred at the AABB centre or the vertex centroid (the smaller radius wins);
//  - best primitive: the enclosing box, capsule or sphere of least volume.
#include <Eigen/Eigenvalues>

#include <cmath>

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

template <class T> struct Fit {
  Geometry<T> geometry;
  Transform<T> pose;  // in the mesh frame
  double volume = 0;
  Representation representation = Representation::Box;
};

template <class T> double sizeOf(const std::vector<Vec3<T>>& v) {
  Bounds3<double> b;
  for (const auto& p : v) b.include(p.template cast<double>());
  return (b.max - b.min).norm();
}

template <class T> Transform<T> poseOf(const Vec3<double>& centre, const Mat3<double>& r) {
  return Transform<T>(centre.cast<T>(), Quat<T>(Quat<double>(r).normalized().template cast<T>()));
}

template <class T> Fit<T> fitBox(const std::vector<Vec3<T>>& v, const Mat3<double>& r, double minHalf, Representation rep) {
  Vec3<double> lo, hi;
  extentsIn(v, r, lo, hi);
  const Vec3<double> half = ((hi - lo) * 0.5).cwiseMax(Vec3<double>::Constant(minHalf));
  Fit<T> f;
  f.geometry = BoxGeometry<T>(half.cast<T>());
  f.pose = poseOf<T>(r * ((lo + hi) * 0.5), r);
  f.volume = 8.0 * half.prod();
  f.representation = rep;
  return f;
}

template <class T> Fit<T> fitCapsule(const std::vector<Vec3<T>>& v, const Mat3<double>& r, double minHalf) {
  const EnclosingCapsule c = enclosingCapsule(v, r, minHalf);
  Fit<T> f;
  f.geometry = CapsuleGeometry<T>(T(c.radius), T(c.halfHeight));
  f.pose = poseOf<T>(c.centre, r);
  f.volume = M_PI * c.radius * c.radius * (2.0 * c.halfHeight + 4.0 / 3.0 * c.radius);
  f.representation = Representation::Capsule;
  return f;
}

template <class T> double radiusAbout(const std::vector<Vec3<T>>& v, const Vec3<double>& c) {
  double r = 0;
  for (const auto& p : v) r = std::max(r, (p.template cast<double>() - c).norm());
  return r;
}

template <class T> Fit<T> fitSphere(const std::vector<Vec3<T>>& v, const Vec3<double>& mean, double minHalf) {
  Vec3<double> lo, hi;
  extentsIn(v, Mat3<double>::Identity(), lo, hi);
  Vec3<double> c = (lo + hi) * 0.5;
  double radius = radiusAbout(v, c);
  if (const double rm = radiusAbout(v, mean); rm < radius) {
    radius = rm;
    c = mean;
  }
  radius = std::max(radius, minHalf);
  Fit<T> f;
  f.geometry = SphereGeometry<T>(T(radius));
  f.pose = Transform<T>(c.cast<T>());
  f.volume = 4.0 / 3.0 * M_PI * radius * radius * radius;
  f.representation = Representation::Sphere;
  return f;
}

template <class T> Fit<T> fitPrimitive(const std::vector<Vec3<T>>& v, Representation rep) {
  const double minHalf = double(tol::Rel<T>::kEpsilon) * sizeOf(v);  // flat meshes still get a valid solid
  Vec3<double> mean;
  const Mat3<double> axes = principalAxes(v, mean);
  switch (rep) {
    case Representation::Box: return fitBox(v, axes, minHalf, rep);
    case Representation::BoxAabb: return fitBox(v, Mat3<double>::Identity(), minHalf, rep);
    case Representation::Capsule: return fitCapsule(v, axes, minHalf);
    case Representation::Sphere: return fitSphere(v, mean, minHalf);
    default: break;
  }
  Fit<T> best = fitBox(v, axes, minHalf, Representation::Box);
  for (const Fit<T>& f : {fitBox(v, Mat3<double>::Identity(), minHalf, Representation::BoxAabb),
                          fitCapsule(v, axes, minHalf), fitSphere(v, mean, minHalf)})
    if (f.volume < best.volume) best = f;
  return best;
}

template <class T> std::size_t meshBytes(const TriangleMesh<T>& m, std::size_t bvhBytes) {
  return m.vertices.size() * sizeof(Vec3<T>) + m.triangles.size() * sizeof(TriangleIndices) +
         (m.inputIndex.size() + m.cookedIndex.size() + m.hullVertices.size()) * sizeof(std::uint32_t) + bvhBytes;
}

}  // namespace

template <class T>
Status meshShape(const MeshData<T>& mesh, Representation rep, const LoadOptions&, Shape<T>& shape, Transform<T>& fit) {
  shape.source = ShapeSource::Mesh;
  shape.sourceTriangles = std::uint32_t(mesh.triangles.size());
  fit = Transform<T>();
  if (rep == Representation::Mesh) {
    std::shared_ptr<const TriangleMesh<T>> cooked;
    MeshCookReport report;
    Status s = cookTriangleMesh(mesh.vertices, mesh.triangles, cooked, &report);
    if (!s.ok()) return s;
    std::shared_ptr<const ConvexMesh<T>> hull;
    s = cookConvexMesh(mesh.vertices, hull);
    if (!s.ok()) return s;
    shape.geometry = TriangleMeshGeometry<T>(cooked);
    shape.boundingHull = hull;
    shape.representation = rep;
    shape.modelTriangles = report.cookedTriangles;
    shape.bytes = meshBytes(*cooked, report.bvhBytes) + hullBytes(*hull);
    return {};
  }
  if (rep == Representation::Hull) {
    std::shared_ptr<const ConvexMesh<T>> hull;
    Status s = cookConvexMesh(mesh.vertices, hull);
    if (!s.ok()) return s;
    shape.geometry = ConvexMeshGeometry<T>(hull);
    shape.representation = rep;
    shape.modelTriangles = std::uint32_t(hull->polygons.size());
    shape.bytes = hullBytes(*hull);
    return {};
  }
  if (mesh.vertices.empty()) return Status::degenerate("mesh has no vertices");
  Fit<T> f = fitPrimitive(mesh.vertices, rep);
  shape.geometry = f.geometry;
  shape.representation = f.representation;
  shape.modelTriangles = 0;
  shape.bytes = sizeof(Geometry<T>);
  fit = f.pose;
  return {};
}

template Mat3<double> principalAxes<float>(const std::vector<Vec3<float>>&, Vec3<double>&);
template Mat3<double> principalAxes<double>(const std::vector<Vec3<double>>&, Vec3<double>&);
template void extentsIn<float>(const std::vector<Vec3<float>>&, const Mat3<double>&, Vec3<double>&, Vec3<double>&);
template void extentsIn<double>(const std::vector<Vec3<double>>&, const Mat3<double>&, Vec3<double>&, Vec3<double>&);
template Status meshShape<float>(const MeshData<float>&, Representation, const LoadOptions&, Shape<float>&,
                                 Transform<float>&);
template Status meshShape<double>(const MeshData<double>&, Representation, const LoadOptions&, Shape<double>&,
                                  Transform<double>&);

}  // namespace gq::urdf::internal
