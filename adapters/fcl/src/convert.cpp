// Conversion of FCL geometries for one call: primitives here (a few stores, no allocation), Convex and BVHModel
// through the cache (geometry_cache.cpp).
#include "convert.h"

#include <fcl/geometry/shape/box.h>
#include <fcl/geometry/shape/capsule.h>
#include <fcl/geometry/shape/cone.h>
#include <fcl/geometry/shape/cylinder.h>
#include <fcl/geometry/shape/ellipsoid.h>
#include <fcl/geometry/shape/halfspace.h>
#include <fcl/geometry/shape/plane.h>
#include <fcl/geometry/shape/sphere.h>
#include <fcl/geometry/shape/triangle_p.h>

#include <cmath>

#include "geometry_cache.h"

namespace gq::fcl::internal {
namespace {

template <class T> bool positive(T v) { return std::isfinite(v) && v > T(0); }

// +X onto the unit vector n (shortest arc; the antiparallel case turns about Y).
template <class T> Quat<T> xOnto(const Vec3<T>& n) {
  if (n.x() < T(-1) + T(1e-12)) return Quat<T>(Eigen::AngleAxis<T>(T(M_PI), Vec3<T>::UnitY()));
  return Quat<T>::FromTwoVectors(Vec3<T>::UnitX(), n);
}

// FCL's Halfspace/Plane n.x = d (n of any non-zero length; FCL normalises it too) as gq's plane frame.
template <class T> Conversion planeFrame(FclShape shape, const Vec3<T>& normal, T d, Converted<T>& out) {
  const T len = normal.norm();
  if (!positive(len) || !std::isfinite(d)) return Conversion::Invalid;
  const Vec3<T> n = normal / len;
  out.shape = shape;
  out.setLocal(PlaneGeometry<T>());
  out.frame = Frame::Offset;
  out.offset = Transform<T>(n * (d / len), xOnto<T>(n));
  return Conversion::Ok;
}

// Cylinder and cone: radius and full length lz along FCL's Z; gq's callbacks take the half height along X.
template <class T, class Callbacks> Conversion roundShape(FclShape shape, T radius, T lz, Converted<T>& out) {
  if (!positive(radius) || !positive(lz)) return Conversion::Invalid;
  out.shape = shape;
  out.template setCallbacks<Callbacks>(radius, lz / T(2));
  out.frame = Frame::XOntoZ;
  return Conversion::Ok;
}

template <class T> Conversion sphere(const ::fcl::Sphere<T>& s, Converted<T>& out) {
  if (!positive(s.radius)) return Conversion::Invalid;
  out.shape = FclShape::Sphere;
  out.setLocal(SphereGeometry<T>(s.radius));
  out.frame = Frame::TranslationOnly;
  return Conversion::Ok;
}

template <class T> Conversion box(const ::fcl::Box<T>& b, Converted<T>& out) {
  if (!positive(b.side.minCoeff()) || !isFinite(Vec3<T>(b.side))) return Conversion::Invalid;
  out.shape = FclShape::Box;
  out.setLocal(BoxGeometry<T>(b.side / T(2)));
  return Conversion::Ok;
}

template <class T> Conversion capsule(const ::fcl::Capsule<T>& c, Converted<T>& out) {
  if (!positive(c.radius) || !std::isfinite(c.lz) || !(c.lz >= T(0))) return Conversion::Invalid;
  out.shape = FclShape::Capsule;
  out.setLocal(CapsuleGeometry<T>(c.radius, c.lz / T(2)));
  out.frame = Frame::XOntoZ;
  return Conversion::Ok;
}

template <class T> Conversion ellipsoid(const ::fcl::Ellipsoid<T>& e, Converted<T>& out) {
  const Vec3<T> radii = e.radii;
  if (!positive(radii.minCoeff()) || !isFinite(radii)) return Conversion::Invalid;
  out.shape = FclShape::Ellipsoid;
  out.template setCallbacks<EllipsoidCallbacks<T>>(radii);
  return Conversion::Ok;
}

template <class T> Conversion triangle(const ::fcl::TriangleP<T>& t, Converted<T>& out) {
  const Vec3<T> a = t.a, b = t.b, c = t.c;
  if (!isFinite(a) || !isFinite(b) || !isFinite(c)) return Conversion::Invalid;
  out.shape = FclShape::TriangleP;
  out.template setCallbacks<TriangleCallbacks<T>>(a, b, c);
  return Conversion::Ok;
}

template <class T>
Conversion cached(const ::fcl::CollisionGeometry<T>* g, ::fcl::NODE_TYPE type, MeshUse use, Converted<T>& out) {
  Cooked<T> cooked;
  const Conversion conversion = cachedGeometry(g, type, cooked, use);
  if (conversion == Conversion::Ok) out.setCached(cooked);
  return conversion;
}

}  // namespace

template <class T> Conversion convert(const ::fcl::CollisionGeometry<T>* g, Converted<T>& out, MeshUse use) {
  if (!g) return Conversion::Invalid;
  const ::fcl::NODE_TYPE type = g->getNodeType();
  switch (type) {
    case ::fcl::GEOM_SPHERE: return sphere(*static_cast<const ::fcl::Sphere<T>*>(g), out);
    case ::fcl::GEOM_BOX: return box(*static_cast<const ::fcl::Box<T>*>(g), out);
    case ::fcl::GEOM_CAPSULE: return capsule(*static_cast<const ::fcl::Capsule<T>*>(g), out);
    case ::fcl::GEOM_CYLINDER: {
      const auto* c = static_cast<const ::fcl::Cylinder<T>*>(g);
      return roundShape<T, CylinderCallbacks<T>>(FclShape::Cylinder, c->radius, c->lz, out);
    }
    case ::fcl::GEOM_CONE: {
      const auto* c = static_cast<const ::fcl::Cone<T>*>(g);
      return roundShape<T, ConeCallbacks<T>>(FclShape::Cone, c->radius, c->lz, out);
    }
    case ::fcl::GEOM_ELLIPSOID: return ellipsoid(*static_cast<const ::fcl::Ellipsoid<T>*>(g), out);
    case ::fcl::GEOM_TRIANGLE: return triangle(*static_cast<const ::fcl::TriangleP<T>*>(g), out);
    case ::fcl::GEOM_HALFSPACE: {
      const auto* h = static_cast<const ::fcl::Halfspace<T>*>(g);
      return planeFrame<T>(FclShape::Halfspace, h->n, h->d, out);
    }
    case ::fcl::GEOM_PLANE: {
      const auto* p = static_cast<const ::fcl::Plane<T>*>(g);
      return planeFrame<T>(FclShape::Plane, p->n, p->d, out);
    }
    case ::fcl::GEOM_OCTREE: return Conversion::NotModelled;
    default: return cached(g, type, use, out);  // Convex and BVHModels
  }
}

template <class T> void forget(const ::fcl::CollisionGeometry<T>* g) { forgetCached(g); }
void clearCache() { clearCached(); }

template Conversion convert<float>(const ::fcl::CollisionGeometry<float>*, Converted<float>&, MeshUse);
template Conversion convert<double>(const ::fcl::CollisionGeometry<double>*, Converted<double>&, MeshUse);
template void forget<float>(const ::fcl::CollisionGeometry<float>*);
template void forget<double>(const ::fcl::CollisionGeometry<double>*);

}  // namespace gq::fcl::internal
