// Options::meshFitting: a triangle BVHModel answered by its gq::fitShape fit (see gq/fcl/fit.h).
#include <iterator>
#include <map>
#include <mutex>
#include <tuple>

#include <fcl/geometry/bvh/BVH_model.h>
#include <fcl/geometry/shape/box.h>
#include <fcl/geometry/shape/capsule.h>
#include <fcl/geometry/shape/convex.h>
#include <fcl/geometry/shape/cylinder.h>
#include <fcl/geometry/shape/sphere.h>
#include <fcl/math/bv/OBBRSS.h>

#include "gq/custom_shapes.h"
#include "gq/fcl/collision.h"
#include "gq/fcl/fit.h"
#include "mesh_fitting.h"

namespace gq::fcl {
namespace {

// gq's capsule and cylinder axis is local X, FCL's is Z: the FCL shape sits rotated by R_y(+90 deg) (Z onto X).
template <class S> ::fcl::Transform3<S> zOntoX() {
  ::fcl::Transform3<S> r = ::fcl::Transform3<S>::Identity();
  r.linear() = Eigen::AngleAxis<S>(S(EIGEN_PI / 2), ::fcl::Vector3<S>::UnitY()).toRotationMatrix();
  return r;
}

// A hull as an FCL Convex: its vertices (scaled) and polygons (count, then vertex indices, counter-clockwise).
template <class S> std::shared_ptr<::fcl::Convex<S>> fclConvex(const ConvexMeshGeometry<S>& g) {
  const ConvexMesh<S>& hull = *g.mesh;
  const Mat3<S> scale = g.scale.toMatrix();
  auto vertices = std::make_shared<std::vector<::fcl::Vector3<S>>>();
  for (const Vec3<S>& v : hull.vertices) vertices->push_back(scale * v);
  auto faces = std::make_shared<std::vector<int>>();
  for (const HullPolygon<S>& p : hull.polygons) {
    faces->push_back(int(p.indexCount));
    for (std::uint32_t k = 0; k < p.indexCount; ++k) faces->push_back(int(hull.polygonVertices[p.indexBase + k]));
  }
  return std::make_shared<::fcl::Convex<S>>(vertices, int(hull.polygons.size()), faces);
}

// One fitted part as an FCL shape at its pose in the model's frame; false for a part FCL has no shape for.
template <class S> bool fclPart(const Geometry<S>& g, const Transform<S>& pose, FittedPart<S>& out) {
  out.pose = ::fcl::Transform3<S>::Identity();
  out.pose.linear() = pose.q.toRotationMatrix();
  out.pose.translation() = pose.p;
  std::shared_ptr<::fcl::CollisionGeometry<S>> shape;
  if (const auto* s = g.template getIf<SphereGeometry<S>>()) {
    shape = std::make_shared<::fcl::Sphere<S>>(s->radius);
  } else if (const auto* c = g.template getIf<CapsuleGeometry<S>>()) {
    shape = std::make_shared<::fcl::Capsule<S>>(c->radius, 2 * c->halfHeight);
    out.pose = out.pose * zOntoX<S>();
  } else if (const auto* b = g.template getIf<BoxGeometry<S>>()) {
    shape = std::make_shared<::fcl::Box<S>>(2 * b->halfExtents);
  } else if (const auto* h = g.template getIf<ConvexMeshGeometry<S>>()) {
    shape = fclConvex(*h);
  } else if (const auto* u = g.template getIf<CustomGeometry<S>>()) {
    const auto* cylinder = dynamic_cast<const CylinderCallbacks<S>*>(u->callbacks.get());
    if (!cylinder) return false;
    shape = std::make_shared<::fcl::Cylinder<S>>(cylinder->radius(), 2 * cylinder->halfHeight());
    out.pose = out.pose * zOntoX<S>();
  } else {
    return false;
  }
  shape->computeLocalAABB();
  out.geometry = std::move(shape);
  return true;
}

template <class S> using Model = ::fcl::BVHModel<::fcl::OBBRSS<S>>;

template <class S> bool isFittable(const ::fcl::CollisionGeometry<S>* g) {
  if (!g || g->getObjectType() != ::fcl::OT_BVH || g->getNodeType() != ::fcl::BV_OBBRSS) return false;
  const auto* m = static_cast<const Model<S>*>(g);
  return m->getModelType() == ::fcl::BVH_MODEL_TRIANGLES && m->num_tris > 0 && m->num_vertices > 0 &&
         (m->build_state == ::fcl::BVH_BUILD_STATE_PROCESSED || m->build_state == ::fcl::BVH_BUILD_STATE_UPDATED);
}

template <class S> MeshFit<S> cookFit(const ::fcl::CollisionGeometry<S>* g, const MeshFitting& fitting) {
  MeshFit<S> fit;
  if (!isFittable(g)) {
    fit.status = Status::invalid("meshFit: not a finished triangle BVHModel<OBBRSS>");
    return fit;
  }
  const auto* m = static_cast<const Model<S>*>(g);
  MeshData<S> mesh;
  mesh.vertices.assign(m->vertices, m->vertices + m->num_vertices);
  for (int t = 0; t < m->num_tris; ++t) {
    const ::fcl::Triangle& tri = m->tri_indices[t];
    mesh.triangles.push_back({std::uint32_t(tri[0]), std::uint32_t(tri[1]), std::uint32_t(tri[2])});
  }
  FitOptions<S> options;
  options.tolerance = S(fitting.tolerance);
  options.allowed = fitting.allowed;
  options.maxParts = fitting.maxParts;
  options.contain = fitting.contain;
  options.measureCost = false;
  FitResult<S> result;
  fit.status = fitShape(mesh, options, result);
  if (!fit.status.ok()) return fit;
  fit.representation = result.representation;
  fit.errorBound = result.errorBound;
  if (result.representation == FitRepresentation::Mesh) return fit;  // the model itself: no parts
  for (const auto& [geometry, pose] : result.parts) {
    FittedPart<S> part;
    if (!fclPart(geometry, pose, part)) {
      fit.status = Status::unsupported("meshFit: a fitted part has no FCL shape");
      fit.parts.clear();
      return fit;
    }
    fit.parts.push_back(std::move(part));
  }
  return fit;
}

using FitKey = std::tuple<const void*, double, FitRepresentationSet, std::uint32_t, bool>;

template <class S> struct FitCache {
  std::mutex mutex;
  std::map<FitKey, std::unique_ptr<MeshFit<S>>> fits;  // node-based: references stay valid while the entry lives
};
template <class S> FitCache<S>& fitCache() {
  static FitCache<S> cache;
  return cache;
}

// The shapes that stand for one side: its fitted parts placed by the side's pose, or the side itself.
template <class S> struct Side {
  const ::fcl::CollisionGeometry<S>* geometry;
  ::fcl::Transform3<S> pose;
};
template <class S>
bool sidesOf(const ::fcl::CollisionGeometry<S>* g, const ::fcl::Transform3<S>& tf, const MeshFitting& fitting,
             std::vector<Side<S>>& sides) {
  if (isFittable(g)) {
    const MeshFit<S>& fit = meshFit(g, fitting);
    if (fit.status.code == StatusCode::Ok && !fit.parts.empty()) {
      for (const FittedPart<S>& p : fit.parts) sides.push_back({p.geometry.get(), tf * p.pose});
      return true;
    }
  }
  sides.push_back({g, tf});
  return false;
}

}  // namespace

template <typename S> const MeshFit<S>& meshFit(const ::fcl::CollisionGeometry<S>* geometry, const MeshFitting& fitting) {
  FitCache<S>& cache = fitCache<S>();
  const FitKey key{geometry, fitting.tolerance, fitting.allowed, fitting.maxParts, fitting.contain};
  std::lock_guard<std::mutex> lock(cache.mutex);
  std::unique_ptr<MeshFit<S>>& entry = cache.fits[key];
  if (!entry) entry = std::make_unique<MeshFit<S>>(cookFit(geometry, fitting));  // fitting under the lock: once
  return *entry;
}
template const MeshFit<float>& meshFit<float>(const ::fcl::CollisionGeometry<float>*, const MeshFitting&);
template const MeshFit<double>& meshFit<double>(const ::fcl::CollisionGeometry<double>*, const MeshFitting&);

namespace internal {

template <class S>
std::size_t collideFitted(const ::fcl::CollisionGeometry<S>* o1, const ::fcl::Transform3<S>& tf1,
                          const ::fcl::CollisionGeometry<S>* o2, const ::fcl::Transform3<S>& tf2,
                          const ::fcl::CollisionRequest<S>& request, ::fcl::CollisionResult<S>& result,
                          const Options& options) {
  Options plain = options;
  plain.meshFitting = nullptr;
  std::vector<Side<S>> a, b;
  const bool fitted1 = sidesOf(o1, tf1, *options.meshFitting, a), fitted2 = sidesOf(o2, tf2, *options.meshFitting, b);
  if (!fitted1 && !fitted2) return gq::fcl::collide(o1, tf1, o2, tf2, request, result, plain);
  for (const Side<S>& x : a)
    for (const Side<S>& y : b) {
      if (result.numContacts() >= request.num_max_contacts) return result.numContacts();
      ::fcl::CollisionResult<S> part;
      gq::fcl::collide(x.geometry, x.pose, y.geometry, y.pose, request, part, plain);
      for (std::size_t i = 0; i < part.numContacts() && result.numContacts() < request.num_max_contacts; ++i) {
        ::fcl::Contact<S> c = part.getContact(i);
        c.o1 = o1;
        c.o2 = o2;
        if (fitted1) c.b1 = ::fcl::Contact<S>::NONE;
        if (fitted2) c.b2 = ::fcl::Contact<S>::NONE;
        result.addContact(c);
      }
    }
  return result.numContacts();
}

template <class S>
S distanceFitted(const ::fcl::CollisionGeometry<S>* o1, const ::fcl::Transform3<S>& tf1,
                 const ::fcl::CollisionGeometry<S>* o2, const ::fcl::Transform3<S>& tf2,
                 const ::fcl::DistanceRequest<S>& request, ::fcl::DistanceResult<S>& result, const Options& options) {
  std::vector<Side<S>> a, b;
  const bool fitted1 = sidesOf(o1, tf1, *options.meshFitting, a), fitted2 = sidesOf(o2, tf2, *options.meshFitting, b);
  if (!fitted1 && !fitted2) return gq::fcl::distance(o1, tf1, o2, tf2, request, result);
  for (const Side<S>& x : a)
    for (const Side<S>& y : b) {
      ::fcl::DistanceResult<S> part;
      gq::fcl::distance(x.geometry, x.pose, y.geometry, y.pose, request, part);
      result.update(part.min_distance, o1, o2, fitted1 ? ::fcl::DistanceResult<S>::NONE : part.b1,
                    fitted2 ? ::fcl::DistanceResult<S>::NONE : part.b2, part.nearest_points[0],
                    part.nearest_points[1]);
    }
  return result.min_distance;
}

template <class S> void forgetFits(const ::fcl::CollisionGeometry<S>* geometry) {
  FitCache<S>& cache = fitCache<S>();
  std::lock_guard<std::mutex> lock(cache.mutex);
  for (auto it = cache.fits.begin(); it != cache.fits.end();)
    it = std::get<0>(it->first) == geometry ? cache.fits.erase(it) : std::next(it);
}

void clearFits() {
  for (auto* lock : {&fitCache<float>().mutex, &fitCache<double>().mutex}) lock->lock();
  fitCache<float>().fits.clear();
  fitCache<double>().fits.clear();
  fitCache<double>().mutex.unlock();
  fitCache<float>().mutex.unlock();
}

#define GQ_FCL_FITTED(S)                                                                                               \
  template std::size_t collideFitted<S>(const ::fcl::CollisionGeometry<S>*, const ::fcl::Transform3<S>&,              \
                                        const ::fcl::CollisionGeometry<S>*, const ::fcl::Transform3<S>&,              \
                                        const ::fcl::CollisionRequest<S>&, ::fcl::CollisionResult<S>&,                \
                                        const Options&);                                                              \
  template S distanceFitted<S>(const ::fcl::CollisionGeometry<S>*, const ::fcl::Transform3<S>&,                       \
                               const ::fcl::CollisionGeometry<S>*, const ::fcl::Transform3<S>&,                       \
                               const ::fcl::DistanceRequest<S>&, ::fcl::DistanceResult<S>&, const Options&);          \
  template void forgetFits<S>(const ::fcl::CollisionGeometry<S>*);
GQ_FCL_FITTED(float)
GQ_FCL_FITTED(double)
#undef GQ_FCL_FITTED

}  // namespace internal
}  // namespace gq::fcl
