// Conversion of FCL geometries and the per-CollisionGeometry* cache.
// Cached: Convex, BVHModel, Cylinder, Cone, Ellipsoid, TriangleP (cooking or a shared callback object); spheres,
// boxes, capsules and planes are rebuilt per call (a few stores). An entry is reused while its fingerprint matches:
// the node type, the sizes, the addresses of the vertex/triangle arrays and up to kFingerprintSamples
// vertices and triangles sampled evenly (shape parameters for primitives). The samples also catch a new geometry
// allocated at a destroyed one's address (pointer reuse), unless it agrees on all of them. Anything else changed in place is invisible: call
// gq::fcl::forgetGeometry() after editing a BVHModel or Convex without changing those.
#include "convert.h"

#include <fcl/geometry/bvh/BVH_model.h>
#include <fcl/geometry/shape/box.h>
#include <fcl/geometry/shape/capsule.h>
#include <fcl/geometry/shape/cone.h>
#include <fcl/geometry/shape/convex.h>
#include <fcl/geometry/shape/cylinder.h>
#include <fcl/geometry/shape/ellipsoid.h>
#include <fcl/geometry/shape/halfspace.h>
#include <fcl/geometry/shape/plane.h>
#include <fcl/geometry/shape/sphere.h>
#include <fcl/geometry/shape/triangle_p.h>
#include <fcl/math/bv/AABB.h>
#include <fcl/math/bv/OBB.h>
#include <fcl/math/bv/OBBRSS.h>
#include <fcl/math/bv/RSS.h>
#include <fcl/math/bv/kDOP.h>
#include <fcl/math/bv/kIOS.h>

#include <algorithm>
#include <cstring>
#include <mutex>
#include <shared_mutex>
#include <unordered_map>
#include <vector>

#include "gq/cooking.h"
#include "gq/custom_shapes.h"
#include "support_shapes.h"

namespace gq::fcl::detail {
namespace {

constexpr int kFingerprintSamples = 16;

// FNV-1a over 64-bit words (bytes of a trailing partial word zero-padded): equal inputs give equal fingerprints; a
// change is caught unless it collides. Word-wise, one multiply per 8 bytes (it runs on every cached lookup).
struct Fingerprint {
  std::uint64_t h = 1469598103934665603ull;
  void add(const void* data, std::size_t n) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < n; i += 8) {
      std::uint64_t word = 0;
      std::memcpy(&word, p + i, std::min<std::size_t>(8, n - i));
      h = (h ^ word) * 1099511628211ull;
    }
  }
  template <class V> void addValue(const V& v) { add(&v, sizeof(V)); }
};

template <class T> struct CacheEntry {
  std::uint64_t fingerprint = 0;
  Converted<T> converted;
};

template <class T> struct Cache {
  std::shared_mutex mutex;
  std::unordered_map<const void*, CacheEntry<T>> entries;
};
template <class T> Cache<T>& cache() {
  static Cache<T> c;
  return c;
}

// X onto Z: a quarter turn about -Y (R_y(-pi/2) x = z).
template <class T> Quat<T> xOntoZ() { return Quat<T>(Eigen::AngleAxis<T>(T(-M_PI / 2), Vec3<T>::UnitY())); }
// +X onto the unit vector n (shortest arc; the antiparallel case turns about Y).
template <class T> Quat<T> xOnto(const Vec3<T>& n) {
  if (n.x() < T(-1) + T(1e-12)) return Quat<T>(Eigen::AngleAxis<T>(T(M_PI), Vec3<T>::UnitY()));
  return Quat<T>::FromTwoVectors(Vec3<T>::UnitX(), n);
}

template <class T> bool positive(T v) { return std::isfinite(v) && v > T(0); }

template <class T> bool planeFrame(const Vec3<T>& normal, T d, Converted<T>& out) {
  const T len = normal.norm();
  if (!positive(len) || !std::isfinite(d)) return false;
  const Vec3<T> n = normal / len;  // FCL normalises too (Halfspace/Plane unitNormalTest)
  out.geom = PlaneGeometry<T>();
  out.offset = Transform<T>(n * (d / len), xOnto<T>(n));
  out.hasOffset = true;
  return true;
}

template <class V> void sampleArray(Fingerprint& f, const V* data, int count) {
  if (count <= 0 || !data) return;
  const int step = std::max(1, count / kFingerprintSamples);
  for (int i = 0; i < count; i += step) f.addValue(data[i]);
  f.addValue(data[count - 1]);
}

template <class BV> const ::fcl::BVHModel<BV>* asModel(const ::fcl::CollisionGeometry<typename BV::S>* g) {
  return static_cast<const ::fcl::BVHModel<BV>*>(g);
}

// The vertex and triangle arrays of a BVHModel of any BV type.
template <class T> struct MeshView {
  const ::fcl::Vector3<T>* vertices = nullptr;
  const ::fcl::Triangle* triangles = nullptr;
  int vertexCount = 0, triangleCount = 0;
  bool triangleModel = false, built = false;
};
template <class BV> MeshView<typename BV::S> viewOf(const ::fcl::CollisionGeometry<typename BV::S>* g) {
  const auto* m = asModel<BV>(g);
  MeshView<typename BV::S> v;
  v.vertices = m->vertices;
  v.triangles = m->tri_indices;
  v.vertexCount = m->num_vertices;
  v.triangleCount = m->num_tris;
  v.triangleModel = m->getModelType() == ::fcl::BVH_MODEL_TRIANGLES;
  v.built = m->build_state == ::fcl::BVH_BUILD_STATE_PROCESSED || m->build_state == ::fcl::BVH_BUILD_STATE_UPDATED;
  return v;
}
template <class T> bool meshView(const ::fcl::CollisionGeometry<T>* g, MeshView<T>& v) {
  switch (g->getNodeType()) {
    case ::fcl::BV_AABB: v = viewOf<::fcl::AABB<T>>(g); return true;
    case ::fcl::BV_OBB: v = viewOf<::fcl::OBB<T>>(g); return true;
    case ::fcl::BV_RSS: v = viewOf<::fcl::RSS<T>>(g); return true;
    case ::fcl::BV_kIOS: v = viewOf<::fcl::kIOS<T>>(g); return true;
    case ::fcl::BV_OBBRSS: v = viewOf<::fcl::OBBRSS<T>>(g); return true;
    case ::fcl::BV_KDOP16: v = viewOf<::fcl::KDOP<T, 16>>(g); return true;
    case ::fcl::BV_KDOP18: v = viewOf<::fcl::KDOP<T, 18>>(g); return true;
    case ::fcl::BV_KDOP24: v = viewOf<::fcl::KDOP<T, 24>>(g); return true;
    default: return false;
  }
}

// Fingerprint of a geometry that is worth caching; false for geometries gq cannot take.
template <class T> bool fingerprintOf(const ::fcl::CollisionGeometry<T>* g, std::uint64_t& out) {
  Fingerprint f;
  const ::fcl::NODE_TYPE type = g->getNodeType();
  f.addValue(type);
  switch (type) {
    case ::fcl::GEOM_CYLINDER: {
      const auto* s = static_cast<const ::fcl::Cylinder<T>*>(g);
      f.addValue(s->radius), f.addValue(s->lz);
      break;
    }
    case ::fcl::GEOM_CONE: {
      const auto* s = static_cast<const ::fcl::Cone<T>*>(g);
      f.addValue(s->radius), f.addValue(s->lz);
      break;
    }
    case ::fcl::GEOM_ELLIPSOID: f.addValue(static_cast<const ::fcl::Ellipsoid<T>*>(g)->radii); break;
    case ::fcl::GEOM_TRIANGLE: {
      const auto* s = static_cast<const ::fcl::TriangleP<T>*>(g);
      f.addValue(s->a), f.addValue(s->b), f.addValue(s->c);
      break;
    }
    case ::fcl::GEOM_CONVEX: {  // sampled too: a new Convex may reuse a freed one's addresses
      const auto& vertices = static_cast<const ::fcl::Convex<T>*>(g)->getVertices();
      f.addValue(vertices.size()), f.addValue(vertices.data());
      sampleArray(f, vertices.data(), int(vertices.size()));
      break;
    }
    default: {
      MeshView<T> v;
      if (!meshView(g, v) || !v.triangleModel || !v.built || v.triangleCount <= 0) return false;
      f.addValue(v.vertexCount), f.addValue(v.triangleCount), f.addValue(v.vertices), f.addValue(v.triangles);
      sampleArray(f, v.vertices, v.vertexCount);
      sampleArray(f, v.triangles, v.triangleCount);
    }
  }
  out = f.h;
  return true;
}

template <class T> bool cookMesh(const ::fcl::CollisionGeometry<T>* g, Converted<T>& out) {
  MeshView<T> v;
  if (!meshView(g, v)) return false;
  std::vector<Vec3<T>> vertices(v.vertices, v.vertices + v.vertexCount);
  std::vector<TriangleIndices> triangles(std::size_t(v.triangleCount));
  for (int i = 0; i < v.triangleCount; ++i)
    triangles[std::size_t(i)] = {std::uint32_t(v.triangles[i][0]), std::uint32_t(v.triangles[i][1]),
                                 std::uint32_t(v.triangles[i][2])};
  std::shared_ptr<const TriangleMesh<T>> mesh;
  if (!cookTriangleMesh(vertices, triangles, mesh).ok()) return false;
  out.shape = FclShape::Mesh;
  out.geom = TriangleMeshGeometry<T>(mesh);
  return true;
}

// The conversions that cost an allocation or cooking (the cached ones).
template <class T> bool convertHeavy(const ::fcl::CollisionGeometry<T>* g, Converted<T>& out) {
  switch (g->getNodeType()) {
    case ::fcl::GEOM_CYLINDER:
    case ::fcl::GEOM_CONE: {
      const bool cylinder = g->getNodeType() == ::fcl::GEOM_CYLINDER;
      const T radius = cylinder ? static_cast<const ::fcl::Cylinder<T>*>(g)->radius
                                : static_cast<const ::fcl::Cone<T>*>(g)->radius;
      const T lz = cylinder ? static_cast<const ::fcl::Cylinder<T>*>(g)->lz : static_cast<const ::fcl::Cone<T>*>(g)->lz;
      CustomGeometry<T> custom;
      const Status s = cylinder ? makeCylinder(radius, lz / 2, custom) : makeCone(radius, lz / 2, custom);
      if (!s.ok()) return false;
      out.shape = cylinder ? FclShape::Cylinder : FclShape::Cone;
      out.geom = custom;
      out.offset = Transform<T>(Vec3<T>::Zero(), xOntoZ<T>());
      out.hasOffset = true;
      return true;
    }
    case ::fcl::GEOM_ELLIPSOID: {
      const Vec3<T> radii = static_cast<const ::fcl::Ellipsoid<T>*>(g)->radii;
      if (!positive(radii.minCoeff()) || !isFinite(radii)) return false;
      out.shape = FclShape::Ellipsoid;
      out.geom = CustomGeometry<T>(std::make_shared<EllipsoidCallbacks<T>>(radii));
      return true;
    }
    case ::fcl::GEOM_TRIANGLE: {
      const auto* t = static_cast<const ::fcl::TriangleP<T>*>(g);
      if (!isFinite(Vec3<T>(t->a)) || !isFinite(Vec3<T>(t->b)) || !isFinite(Vec3<T>(t->c))) return false;
      out.shape = FclShape::TriangleP;
      out.geom = CustomGeometry<T>(std::make_shared<TriangleCallbacks<T>>(t->a, t->b, t->c));
      return true;
    }
    case ::fcl::GEOM_CONVEX: {
      const auto& vertices = static_cast<const ::fcl::Convex<T>*>(g)->getVertices();
      std::shared_ptr<const ConvexMesh<T>> hull;
      if (!cookConvexMesh(std::vector<Vec3<T>>(vertices.begin(), vertices.end()), hull).ok()) return false;
      out.shape = FclShape::Convex;
      out.geom = ConvexMeshGeometry<T>(hull);
      return true;
    }
    default: return cookMesh(g, out);
  }
}

// Primitives rebuilt per call; false when the geometry needs the cache.
template <class T> bool convertLight(const ::fcl::CollisionGeometry<T>* g, Converted<T>& out, bool& valid) {
  valid = true;
  switch (g->getNodeType()) {
    case ::fcl::GEOM_SPHERE: {
      const T r = static_cast<const ::fcl::Sphere<T>*>(g)->radius;
      valid = positive(r);
      out.shape = FclShape::Sphere;
      out.geom = SphereGeometry<T>(r);
      out.rotationFree = true;
      return true;
    }
    case ::fcl::GEOM_BOX: {
      const Vec3<T> side = static_cast<const ::fcl::Box<T>*>(g)->side;
      valid = positive(side.minCoeff()) && isFinite(side);
      out.shape = FclShape::Box;
      out.geom = BoxGeometry<T>(side / T(2));
      return true;
    }
    case ::fcl::GEOM_CAPSULE: {
      const auto* c = static_cast<const ::fcl::Capsule<T>*>(g);
      valid = positive(c->radius) && std::isfinite(c->lz) && c->lz >= T(0);
      out.shape = FclShape::Capsule;
      out.geom = CapsuleGeometry<T>(c->radius, c->lz / T(2));
      out.offset = Transform<T>(Vec3<T>::Zero(), xOntoZ<T>());
      out.hasOffset = true;
      return true;
    }
    case ::fcl::GEOM_HALFSPACE: {
      const auto* h = static_cast<const ::fcl::Halfspace<T>*>(g);
      out.shape = FclShape::Halfspace;
      valid = planeFrame<T>(h->n, h->d, out);
      return true;
    }
    case ::fcl::GEOM_PLANE: {
      const auto* p = static_cast<const ::fcl::Plane<T>*>(g);
      out.shape = FclShape::Plane;
      valid = planeFrame<T>(p->n, p->d, out);
      return true;
    }
    default: return false;
  }
}

}  // namespace

template <class T> bool convert(const ::fcl::CollisionGeometry<T>* g, Converted<T>& out) {
  if (!g) return false;
  bool valid = true;
  if (convertLight(g, out, valid)) return valid;
  std::uint64_t fingerprint = 0;
  if (!fingerprintOf(g, fingerprint)) return false;
  Cache<T>& c = cache<T>();
  {
    std::shared_lock<std::shared_mutex> lock(c.mutex);
    auto it = c.entries.find(g);
    if (it != c.entries.end() && it->second.fingerprint == fingerprint) {
      out = it->second.converted;
      return out.shape != FclShape::Unsupported;
    }
  }
  // Convert outside the lock (cooking may take milliseconds); a failed conversion is cached as Unsupported.
  Converted<T> fresh;
  if (!convertHeavy(g, fresh)) fresh = Converted<T>();
  {
    std::unique_lock<std::shared_mutex> lock(c.mutex);
    c.entries[g] = CacheEntry<T>{fingerprint, fresh};
  }
  out = fresh;
  return out.shape != FclShape::Unsupported;
}

template <class T> void forget(const ::fcl::CollisionGeometry<T>* g) {
  Cache<T>& c = cache<T>();
  std::unique_lock<std::shared_mutex> lock(c.mutex);
  c.entries.erase(g);
}

void clearCache() {
  {
    std::unique_lock<std::shared_mutex> lock(cache<float>().mutex);
    cache<float>().entries.clear();
  }
  std::unique_lock<std::shared_mutex> lock(cache<double>().mutex);
  cache<double>().entries.clear();
}

template bool convert<float>(const ::fcl::CollisionGeometry<float>*, Converted<float>&);
template bool convert<double>(const ::fcl::CollisionGeometry<double>*, Converted<double>&);
template void forget<float>(const ::fcl::CollisionGeometry<float>*);
template void forget<double>(const ::fcl::CollisionGeometry<double>*);

}  // namespace gq::fcl::detail
