#include "gq_fcl_backend.h"

#include <exception>
#include <map>

#include "gq/fcl/fcl.h"
#include "fcl_distance_out.h"
#include "native_shapes.h"
#include "timing.h"

namespace gq::cases {
namespace {

template <class S> using FclGeometry = std::shared_ptr<::fcl::CollisionGeometry<S>>;

// FCL geometries of a case side; convex hulls and meshes are built once per (cooked data, scale) and kept alive, so
// the adapter's per-geometry cache converts each once.
template <class S> class Shapes {
 public:
  FclGeometry<S> build(const ShapeDesc& d, bool& alongZ, std::string& error) {
    alongZ = false;
    switch (d.kind) {
      case ShapeKind::Sphere: return std::make_shared<::fcl::Sphere<S>>(S(d.radius));
      case ShapeKind::Box: return std::make_shared<::fcl::Box<S>>(2 * d.halfExtents.cast<S>());
      // FCL's capsule, cylinder and cone lie along Z with full length lz = 2 * halfHeight.
      case ShapeKind::Capsule: alongZ = true; return std::make_shared<::fcl::Capsule<S>>(S(d.radius), S(2 * d.halfHeight));
      case ShapeKind::Cylinder: alongZ = true; return std::make_shared<::fcl::Cylinder<S>>(S(d.radius), S(2 * d.halfHeight));
      case ShapeKind::Cone: alongZ = true; return std::make_shared<::fcl::Cone<S>>(S(d.radius), S(2 * d.halfHeight));
      case ShapeKind::Plane: return std::make_shared<::fcl::Halfspace<S>>(::fcl::Vector3<S>::UnitX(), S(0));
      case ShapeKind::Convex: return cached(d, [&] { return convex(d, error); });
      case ShapeKind::Mesh: return cached(d, [&] { return mesh(d); });
      case ShapeKind::HeightField: error = "unsupported: FCL 0.7 has no heightfield"; return nullptr;
    }
    error = "unknown shape";
    return nullptr;
  }

 private:
  template <class Make> FclGeometry<S> cached(const ShapeDesc& d, Make make) {
    const std::string key = native::scaledKey(d);
    if (auto it = cache_.find(key); it != cache_.end()) return it->second;
    FclGeometry<S> g = make();
    if (g) cache_.emplace(key, g);
    return g;
  }
  FclGeometry<S> convex(const ShapeDesc& d, std::string& error) {
    native::HullPolygons hull;
    if (!native::cookHullPolygons(native::scaledPoints(d), hull, error)) return nullptr;
    auto vertices = std::make_shared<std::vector<::fcl::Vector3<S>>>();
    for (const Vec3d& v : hull.vertices) vertices->push_back(v.cast<S>());
    auto faces = std::make_shared<std::vector<int>>();
    for (const auto& poly : hull.polygons) {
      faces->push_back(int(poly.size()));
      for (std::uint32_t i : poly) faces->push_back(int(i));
    }
    return std::make_shared<::fcl::Convex<S>>(vertices, int(hull.polygons.size()), faces);
  }
  FclGeometry<S> mesh(const ShapeDesc& d) {
    std::vector<::fcl::Vector3<S>> vertices;
    for (const Vec3d& v : native::scaledPoints(d)) vertices.push_back(v.cast<S>());
    std::vector<::fcl::Triangle> triangles;
    for (const auto& t : native::scaledTriangles(d)) triangles.emplace_back(t[0], t[1], t[2]);
    auto model = std::make_shared<::fcl::BVHModel<::fcl::OBBRSS<S>>>();
    model->beginModel(int(triangles.size()), int(vertices.size()));
    model->addSubModel(vertices, triangles);
    model->endModel();
    return model;
  }
  std::map<std::string, FclGeometry<S>> cache_;
};

template <class S> ::fcl::Transform3<S> toFcl(const PoseDesc& p) {
  ::fcl::Transform3<S> tf = ::fcl::Transform3<S>::Identity();
  tf.linear() = p.q.toRotationMatrix().cast<S>();
  tf.translation() = p.p.cast<S>();
  return tf;
}

template <class S> Result success(double ns, ResultFields fields) {
  Result r;
  r.ok = true;
  r.ns = ns;
  r.fields = std::move(fields);
  return r;
}

template <class S> Result runPair(Shapes<S>& shapes, QueryKind kind, const PairCase& q, int repeat) {
  std::string error;
  bool z0 = false, z1 = false;
  const FclGeometry<S> g0 = shapes.build(q.geom0, z0, error);
  const FclGeometry<S> g1 = g0 ? shapes.build(q.geom1, z1, error) : nullptr;
  if (!g0 || !g1) return Result::failure(error);
  PoseDesc p0 = q.pose0, p1 = q.pose1;
  if (z0) p0.q = p0.q * native::zAxisToX();  // FCL's Z axis onto gq's X axis
  if (z1) p1.q = p1.q * native::zAxisToX();
  const ::fcl::Transform3<S> tf0 = toFcl<S>(p0), tf1 = toFcl<S>(p1);
  gq::fcl::Options options;
  options.minimumTranslation = true;
  options.exactContainedBoxDepth = true;
  if (kind == QueryKind::Overlap || kind == QueryKind::Penetration) {
    const bool contacts = kind == QueryKind::Penetration;
    const ::fcl::CollisionRequest<S> request(contacts ? 64 : 1, contacts);
    ::fcl::CollisionResult<S> result;
    const double ns = medianNanoseconds(repeat, [&] {
      result.clear();
      gq::fcl::collide<S>(g0.get(), tf0, g1.get(), tf1, request, result, options);
    });
    if (!contacts) return success<S>(ns, OverlapOut{result.isCollision()});
    PenetrationOut out;
    // The contact normal points from o1 to o2: geom0 moves along -normal by the depth to separate.
    for (std::size_t i = 0; i < result.numContacts(); ++i) {
      const ::fcl::Contact<S>& c = result.getContact(i);
      if (!out.penetrating || double(c.penetration_depth) > out.depth) {
        out.penetrating = true;
        out.depth = double(c.penetration_depth);
        out.direction = -c.normal.template cast<double>();
      }
    }
    return success<S>(ns, out);
  }
  ::fcl::DistanceRequest<S> request(true);
  request.enable_signed_distance = true;
  request.distance_tolerance = 0;  // gq's own GJK tolerance, as the `gq` backend (FCL's 1e-6 default: docs/fcl.md)
  ::fcl::DistanceResult<S> result;
  const double ns = medianNanoseconds(repeat, [&] {
    result.clear();
    gq::fcl::distance<S>(g0.get(), tf0, g1.get(), tf1, request, result);
  });
  return success<S>(ns, distanceOutOf(result));
}

}  // namespace

struct GqFclBackend::Impl {
  Shapes<float> floatShapes;
  Shapes<double> doubleShapes;
  template <class S> Result runIn(Shapes<S>& shapes, const Case& c, int repeat) {
    switch (c.query) {
      case QueryKind::Overlap:
      case QueryKind::Penetration:
      case QueryKind::Distance: return runPair<S>(shapes, c.query, std::get<PairCase>(c.input), repeat);
      default: return native::unsupportedQuery("gq-fcl", c.query, "any geometry (it answers overlap, penetration, distance)");
    }
  }
};

GqFclBackend::GqFclBackend() : impl_(new Impl()) {}
GqFclBackend::~GqFclBackend() = default;

Result GqFclBackend::run(const Case& c, int repeat) {
  try {  // the adapter never throws; building FCL objects may (allocation)
    return c.precision == Precision::Float ? impl_->runIn<float>(impl_->floatShapes, c, repeat)
                                           : impl_->runIn<double>(impl_->doubleShapes, c, repeat);
  } catch (const std::exception& e) {
    return Result::failure(std::string("gq-fcl error: ") + e.what());
  }
}

}  // namespace gq::cases
