// Reference faces and incident features of a contact set (contact_features.h).
#include <cmath>

#include "contacts/contact_features.h"
#include "gq/cooking.h"
#include "gq/custom_shapes.h"

namespace gq::detail {
namespace {

// Box face with outward normal sign * axis k, corners counter-clockwise seen from outside: the face centre plus or
// minus the two other half axes, from the pose's rotation matrix (a quaternion product per corner costs ~4x more).
template <class T>
void boxFace(const Vec3<T>& h, const Mat3<T>& r, const Vec3<T>& p, int k, T sign, Feature<T>& f) {
  const int i = (k + 1) % 3, j = (k + 2) % 3;
  const Vec3<T> centre = p + r.col(k) * (sign * h[k]), u = r.col(i) * h[i], w = r.col(j) * h[j];
  const Vec3<T> corners[4] = {centre - u - w, centre + u - w, centre + u + w, centre - u + w};
  f.count = 4;
  for (int c = 0; c < 4; ++c) f.points[c] = corners[sign > 0 ? c : 3 - c];
  f.normal = r.col(k) * sign;
  f.origin = f.points[0];
  f.unbounded = false;
  f.rectangle = true;
  f.centre = centre;
  f.u = r.col(i);
  f.w = r.col(j);
  f.hu = h[i];
  f.hw = h[j];
}

// Box face most aligned with `dir`; returns its alignment (cosine).
template <class T> T alignedBoxFace(const BoxGeometry<T>& box, const Transform<T>& pose, const Vec3<T>& dir, Feature<T>& f) {
  const Mat3<T> r = pose.q.toRotationMatrix();
  const Vec3<T> local = r.transpose() * dir;
  int k = 0;
  local.cwiseAbs().maxCoeff(&k);
  const T sign = local[k] >= 0 ? T(1) : T(-1);
  boxFace(box.halfExtents, r, pose.p, k, sign, f);
  return std::abs(local[k]);
}

// Hull polygon most aligned with `dir` under the instance scale (normals map by the inverse scale matrix).
template <class T>
T alignedHullFace(const ConvexMeshGeometry<T>& hull, const Transform<T>& pose, const Vec3<T>& dir, Feature<T>& f) {
  const Mat3<T> m = hull.scale.toMatrix();
  const Mat3<T> normalMap = m.inverse().transpose();
  const Vec3<T> local = pose.rotateInv(dir);
  T best = -2;
  const HullPolygon<T>* bestPolygon = nullptr;
  Vec3<T> bestNormal = Vec3<T>::Zero();
  for (const HullPolygon<T>& p : hull.mesh->polygons) {
    Vec3<T> n = normalMap * p.normal;
    if (hull.scale.flipsWinding()) n = -n;
    n.normalize();
    const T c = n.dot(local);
    if (c > best) best = c, bestPolygon = &p, bestNormal = n;
  }
  if (!bestPolygon || bestPolygon->indexCount > std::uint32_t(kMaxFeaturePoints)) return -1;
  f.count = int(bestPolygon->indexCount);
  for (std::uint32_t c = 0; c < bestPolygon->indexCount; ++c) {
    const Vec3<T>& v = hull.mesh->vertices[hull.mesh->polygonVertices[bestPolygon->indexBase + c]];
    f.points[c] = pose.transform(m * v);
  }
  f.normal = pose.rotate(bestNormal);
  f.origin = f.points[0];
  f.unbounded = false;
  f.rectangle = false;
  return best;
}

template <class T> T alignedFace(const Geometry<T>& g, const Transform<T>& pose, const Vec3<T>& dir, Feature<T>& f) {
  if (const auto* box = g.template getIf<BoxGeometry<T>>()) return alignedBoxFace(*box, pose, dir, f);
  if (const auto* hull = g.template getIf<ConvexMeshGeometry<T>>()) return alignedHullFace(*hull, pose, dir, f);
  return -1;
}

// Any unit vector perpendicular to unit `a`.
template <class T> Vec3<T> perpendicular(const Vec3<T>& a) {
  const Vec3<T> helper = std::abs(a.x()) < T(0.6) ? Vec3<T>::UnitX() : Vec3<T>::UnitY();
  return a.cross(helper).normalized();
}

// Cylinder (axis = pose X): its cap rim when the axis is along `dir`, its side line when perpendicular to it.
template <class T>
bool cylinderFeature(const CylinderCallbacks<T>& cyl, const Transform<T>& pose, const Vec3<T>& dir, Feature<T>& f) {
  const Vec3<T> axis = pose.rotate(Vec3<T>::UnitX());
  const T along = axis.dot(dir);
  if (std::abs(along) >= T(kFaceAlignmentCos)) {
    const Vec3<T> cap = pose.p + axis * (along > 0 ? cyl.halfHeight() : -cyl.halfHeight());
    const Vec3<T> u = perpendicular(axis), w = axis.cross(u);
    f.count = kCapRimPoints;
    for (int k = 0; k < kCapRimPoints; ++k) {
      const T angle = T(2 * EIGEN_PI) * T(k) / T(kCapRimPoints);
      f.points[k] = cap + cyl.radius() * (std::cos(angle) * u + std::sin(angle) * w);
    }
    return true;
  }
  if (std::abs(along) > T(1) - T(kFaceAlignmentCos)) return false;
  const Vec3<T> side = (dir - axis * along).normalized() * cyl.radius();
  f.count = 2;
  f.points[0] = pose.p + side - axis * cyl.halfHeight();
  f.points[1] = pose.p + side + axis * cyl.halfHeight();
  return true;
}

// Capsule lying along the face: the two points of its end spheres farthest along `dir`.
template <class T>
bool capsuleFeature(const CapsuleGeometry<T>& cap, const Transform<T>& pose, const Vec3<T>& dir, Feature<T>& f) {
  const Vec3<T> axis = pose.rotate(Vec3<T>::UnitX());
  if (std::abs(axis.dot(dir)) > T(1) - T(kFaceAlignmentCos) || cap.halfHeight <= T(0)) return false;
  f.count = 2;
  f.points[0] = pose.p - axis * cap.halfHeight + dir * cap.radius;
  f.points[1] = pose.p + axis * cap.halfHeight + dir * cap.radius;
  return true;
}

}  // namespace

template <class T>
bool referenceFace(const Geometry<T>& g, const Transform<T>& pose, const Vec3<T>& dir, Feature<T>& face, T* alignment) {
  T c;
  if (g.type() == GeometryType::Plane) {
    face.normal = pose.rotate(Vec3<T>::UnitX());
    face.origin = pose.p;
    face.unbounded = true;
    face.rectangle = false;
    face.count = 0;
    c = face.normal.dot(dir);
  } else {
    c = alignedFace(g, pose, dir, face);
  }
  if (alignment) *alignment = c;
  return c >= T(kFaceAlignmentCos);
}

template <class T>
bool incidentFeature(const Geometry<T>& g, const Transform<T>& pose, const Vec3<T>& dir, Feature<T>& feature) {
  if (isPolytope(g)) return alignedFace(g, pose, dir, feature) >= T(kFaceAlignmentCos);
  if (const auto* cap = g.template getIf<CapsuleGeometry<T>>()) return capsuleFeature(*cap, pose, dir, feature);
  if (const auto* custom = g.template getIf<CustomGeometry<T>>()) {
    if (const auto* cyl = dynamic_cast<const CylinderCallbacks<T>*>(custom->callbacks.get()))
      return cylinderFeature(*cyl, pose, dir, feature);
  }
  return false;
}

#define GQ_INSTANTIATE(T)                                                                                         \
  template bool referenceFace<T>(const Geometry<T>&, const Transform<T>&, const Vec3<T>&, Feature<T>&, T*);       \
  template bool incidentFeature<T>(const Geometry<T>&, const Transform<T>&, const Vec3<T>&, Feature<T>&);
GQ_INSTANTIATE(float)
GQ_INSTANTIATE(double)
#undef GQ_INSTANTIATE

}  // namespace gq::detail
