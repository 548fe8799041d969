#include "contact_features.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "gq/cooking.h"
#include "gq/custom_shapes.h"

namespace gq::bullet {
namespace {

// Box face with outward normal sign * axis k, corners counter-clockwise seen from outside: the face centre plus or
// minus the two other half axes, from the pose's rotation matrix (a quaternion product per corner cost ~4x more).
void boxFace(const V3& h, const Mat3<Real>& r, const V3& p, int k, Real sign, Feature& f) {
  const int i = (k + 1) % 3, j = (k + 2) % 3;
  const V3 centre = p + r.col(k) * (sign * h[k]), u = r.col(i) * h[i], w = r.col(j) * h[j];
  const V3 corners[4] = {centre - u - w, centre + u - w, centre + u + w, centre - u + w};
  f.count = 4;
  for (int c = 0; c < 4; ++c) f.points[c] = corners[sign > 0 ? c : 3 - c];
  f.normal = r.col(k) * sign;
  f.origin = f.points[0];
  f.rectangle = true;
  f.centre = centre;
  f.u = r.col(i);
  f.w = r.col(j);
  f.hu = h[i];
  f.hw = h[j];
}

// Box face most aligned with `dir`; returns its alignment (cosine).
Real alignedBoxFace(const BoxGeometry<Real>& box, const Pose& pose, const V3& dir, Feature& f) {
  const Mat3<Real> r = pose.q.toRotationMatrix();
  const V3 local = r.transpose() * dir;
  int k = 0;
  local.cwiseAbs().maxCoeff(&k);
  const Real sign = local[k] >= 0 ? Real(1) : Real(-1);
  boxFace(box.halfExtents, r, pose.p, k, sign, f);
  return std::abs(local[k]);
}

// Hull polygon most aligned with `dir` under the instance scale (normals map by the inverse scale matrix).
Real alignedHullFace(const ConvexMeshGeometry<Real>& hull, const Pose& pose, const V3& dir, Feature& f) {
  const Mat3<Real> m = hull.scale.toMatrix();
  const Mat3<Real> normalMap = m.inverse().transpose();
  const V3 local = pose.rotateInv(dir);
  Real best = -2;
  const HullPolygon<Real>* bestPolygon = nullptr;
  V3 bestNormal = V3::Zero();
  for (const HullPolygon<Real>& p : hull.mesh->polygons) {
    V3 n = normalMap * p.normal;
    if (hull.scale.flipsWinding()) n = -n;
    n.normalize();
    const Real c = n.dot(local);
    if (c > best) best = c, bestPolygon = &p, bestNormal = n;
  }
  if (!bestPolygon || bestPolygon->indexCount > std::uint32_t(kMaxFeaturePoints)) return -1;
  f.count = int(bestPolygon->indexCount);
  for (std::uint32_t c = 0; c < bestPolygon->indexCount; ++c) {
    const V3& v = hull.mesh->vertices[hull.mesh->polygonVertices[bestPolygon->indexBase + c]];
    f.points[c] = pose.transform(m * v);
  }
  f.normal = pose.rotate(bestNormal);
  f.origin = f.points[0];
  f.rectangle = false;
  return best;
}

Real alignedFace(const PlacedShape& s, const V3& dir, Feature& f) {
  const Geometry<Real>& g = s.view->geom;
  if (const auto* box = g.getIf<BoxGeometry<Real>>()) return alignedBoxFace(*box, s.pose, dir, f);
  if (const auto* hull = g.getIf<ConvexMeshGeometry<Real>>()) return alignedHullFace(*hull, s.pose, dir, f);
  return -1;
}

// Any unit vector perpendicular to unit `a`.
V3 perpendicular(const V3& a) {
  const V3 helper = std::abs(a.x()) < Real(0.6) ? V3::UnitX() : V3::UnitY();
  return a.cross(helper).normalized();
}

// Cylinder (axis = pose X): its cap rim when the axis is along `dir`, its side line when perpendicular to it.
bool cylinderFeature(const CylinderCallbacks<Real>& cyl, const Pose& pose, const V3& dir, Feature& f) {
  const V3 axis = pose.rotate(V3::UnitX());
  const Real along = axis.dot(dir);
  if (std::abs(along) >= kFaceAlignmentCos) {
    const V3 cap = pose.p + axis * (along > 0 ? cyl.halfHeight() : -cyl.halfHeight());
    const V3 u = perpendicular(axis), w = axis.cross(u);
    f.count = kCapRimPoints;
    for (int k = 0; k < kCapRimPoints; ++k) {
      const Real angle = Real(2 * EIGEN_PI) * Real(k) / Real(kCapRimPoints);
      f.points[k] = cap + cyl.radius() * (std::cos(angle) * u + std::sin(angle) * w);
    }
    return true;
  }
  if (std::abs(along) > Real(1) - kFaceAlignmentCos) return false;
  const V3 side = (dir - axis * along).normalized() * cyl.radius();
  f.count = 2;
  f.points[0] = pose.p + side - axis * cyl.halfHeight();
  f.points[1] = pose.p + side + axis * cyl.halfHeight();
  return true;
}

// Capsule lying along the face: the two points of its end spheres farthest along `dir`.
bool capsuleFeature(const CapsuleGeometry<Real>& cap, const Pose& pose, const V3& dir, Feature& f) {
  const V3 axis = pose.rotate(V3::UnitX());
  if (std::abs(axis.dot(dir)) > Real(1) - kFaceAlignmentCos || cap.halfHeight <= Real(0)) return false;
  f.count = 2;
  f.points[0] = pose.p - axis * cap.halfHeight + dir * cap.radius;
  f.points[1] = pose.p + axis * cap.halfHeight + dir * cap.radius;
  return true;
}

}  // namespace

bool referenceFace(const PlacedShape& s, const V3& dir, Feature& face) {
  if (s.view->kind == ShapeKind::Plane) {
    face.normal = s.pose.rotate(V3::UnitX());
    face.origin = s.pose.p;
    face.unbounded = true;
    face.rectangle = false;
    face.count = 0;
    return face.normal.dot(dir) >= kFaceAlignmentCos;
  }
  return alignedFace(s, dir, face) >= kFaceAlignmentCos;
}

bool incidentFeature(const PlacedShape& s, const V3& dir, Feature& feature) {
  const Geometry<Real>& g = s.view->geom;
  if (s.view->isPolytope()) return alignedFace(s, dir, feature) >= kFaceAlignmentCos;
  if (const auto* cap = g.getIf<CapsuleGeometry<Real>>()) return capsuleFeature(*cap, s.pose, dir, feature);
  if (const auto* custom = g.getIf<CustomGeometry<Real>>()) {
    if (const auto* cyl = dynamic_cast<const CylinderCallbacks<Real>*>(custom->callbacks.get()))
      return cylinderFeature(*cyl, s.pose, dir, feature);
  }
  return false;
}

namespace {

// Clipping to a rectangle in its own frame: each point as (x, y, height over the face), four axis-aligned half
// planes (a quarter of the work of the general polygon's cross products and dot products per edge).
int clipToRectangle(const Feature& reference, Feature& incident) {
  struct P {
    Real c[3];
  };
  std::array<P, kMaxFeaturePoints> bufferA, bufferB;
  int count = incident.count;
  for (int i = 0; i < count; ++i) {
    const V3 d = incident.points[i] - reference.centre;
    bufferA[i] = P{{d.dot(reference.u), d.dot(reference.w), d.dot(reference.normal)}};
  }
  P* in = bufferA.data();
  P* out = bufferB.data();
  const Real limits[2] = {reference.hu, reference.hw};
  for (int e = 0; e < 4 && count > 0; ++e) {
    const int axis = e >> 1;
    const Real sign = (e & 1) ? Real(-1) : Real(1), limit = limits[axis];
    int n = 0;
    for (int i = 0; i < count; ++i) {
      const int next = i + 1 == count ? 0 : i + 1;
      const Real da = sign * in[i].c[axis] - limit, db = sign * in[next].c[axis] - limit;
      if (da <= 0 && n < kMaxFeaturePoints) out[n++] = in[i];
      const bool crosses = (da < 0 && db > 0) || (da > 0 && db < 0);
      if (crosses && n < kMaxFeaturePoints && (count > 2 || i == 0)) {
        const Real t = da / (da - db);
        P q;
        for (int k = 0; k < 3; ++k) q.c[k] = in[i].c[k] + (in[next].c[k] - in[i].c[k]) * t;
        out[n++] = q;
      }
    }
    std::swap(in, out);
    count = n;
  }
  for (int i = 0; i < count; ++i)
    incident.points[i] = reference.centre + reference.u * in[i].c[0] + reference.w * in[i].c[1] +
                         reference.normal * in[i].c[2];
  incident.count = count;
  return count;
}

}  // namespace

int clipToFace(const Feature& reference, Feature& incident) {
  if (reference.unbounded) return incident.count;
  if (reference.rectangle) return clipToRectangle(reference, incident);
  V3 centroid = V3::Zero();
  for (int i = 0; i < reference.count; ++i) centroid += reference.points[i];
  centroid /= Real(reference.count);
  // Two buffers swapped per edge and each point's side distance taken once (copying the clipped polygon back and
  // measuring every point twice cost more than the clipping).
  std::array<V3, kMaxFeaturePoints> buffer;
  std::array<Real, kMaxFeaturePoints> d;
  V3* in = incident.points.data();
  V3* out = buffer.data();
  int count = incident.count;
  for (int e = 0; e < reference.count && count > 0; ++e) {
    const V3& p0 = reference.points[e];
    const V3& p1 = reference.points[e + 1 == reference.count ? 0 : e + 1];
    V3 side = (p1 - p0).cross(reference.normal);
    if (side.dot(centroid - p0) > 0) side = -side;  // outward, whatever the winding
    // Keep the part of the incident polygon with side . (x - p0) <= 0.
    for (int i = 0; i < count; ++i) d[i] = side.dot(in[i] - p0);
    int n = 0;
    for (int i = 0; i < count; ++i) {
      const int next = i + 1 == count ? 0 : i + 1;
      const V3& a = in[i];
      const Real da = d[i], db = d[next];
      if (da <= 0 && n < kMaxFeaturePoints) out[n++] = a;
      const bool crosses = (da < 0 && db > 0) || (da > 0 && db < 0);
      if (crosses && n < kMaxFeaturePoints && (count > 2 || i == 0)) out[n++] = a + (in[next] - a) * (da / (da - db));
    }
    std::swap(in, out);
    count = n;
  }
  if (in != incident.points.data()) std::copy(in, in + count, incident.points.data());
  incident.count = count;
  return count;
}

}  // namespace gq::bullet
