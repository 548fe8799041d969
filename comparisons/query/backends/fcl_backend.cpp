#include "fcl_backend.h"

#include <exception>
#include <map>

#include <fcl/fcl.h>

#include "fcl_distance_out.h"
#include "native_shapes.h"
#include "timing.h"

namespace gq::cases {
namespace {

template <class S> using Vec3S = fcl::Vector3<S>;

// One side of a pair query: the FCL geometry and its world pose.
template <class S> struct FclSide {
  std::shared_ptr<fcl::CollisionGeometry<S>> geom;
  fcl::Transform3<S> pose = fcl::Transform3<S>::Identity();
};

template <class S> fcl::Transform3<S> toFcl(const PoseDesc& p) {
  fcl::Transform3<S> tf = fcl::Transform3<S>::Identity();
  tf.linear() = p.q.toRotationMatrix().cast<S>();
  tf.translation() = p.p.cast<S>();
  return tf;
}

// Builds FCL shapes; convex hulls and meshes are built once per (cooked data, scale).
template <class S> class FclShapes {
 public:
  // Empty `error` and a geometry, or an "unsupported: ..." / cooking message.
  std::shared_ptr<fcl::CollisionGeometry<S>> build(const ShapeDesc& d, bool& alongZ, std::string& error) {
    alongZ = false;
    switch (d.kind) {
      case ShapeKind::Sphere: return std::make_shared<fcl::Sphere<S>>(S(d.radius));
      case ShapeKind::Box: return std::make_shared<fcl::Box<S>>(2 * d.halfExtents.cast<S>());
      // FCL's capsule, cylinder and cone lie along Z with full length lz = 2 * halfHeight.
      case ShapeKind::Capsule: alongZ = true; return std::make_shared<fcl::Capsule<S>>(S(d.radius), S(2 * d.halfHeight));
      case ShapeKind::Cylinder: alongZ = true; return std::make_shared<fcl::Cylinder<S>>(S(d.radius), S(2 * d.halfHeight));
      case ShapeKind::Cone: alongZ = true; return std::make_shared<fcl::Cone<S>>(S(d.radius), S(2 * d.halfHeight));
      // gq's plane: solid x <= 0, i.e. the halfspace n.x <= d with n = +X, d = 0.
      case ShapeKind::Plane: return std::make_shared<fcl::Halfspace<S>>(Vec3S<S>::UnitX(), S(0));
      case ShapeKind::Convex: return convex(d, error);
      case ShapeKind::Mesh: return mesh(d);
      case ShapeKind::HeightField: error = "unsupported: FCL 0.7 has no heightfield"; return nullptr;
    }
    error = "unknown shape";
    return nullptr;
  }

 private:
  std::shared_ptr<fcl::CollisionGeometry<S>> convex(const ShapeDesc& d, std::string& error) {
    const std::string key = native::scaledKey(d);
    if (auto it = cache_.find(key); it != cache_.end()) return it->second;
    native::HullPolygons hull;
    if (!native::cookHullPolygons(native::scaledPoints(d), hull, error)) return nullptr;
    auto vertices = std::make_shared<std::vector<Vec3S<S>>>();
    for (const Vec3d& v : hull.vertices) vertices->push_back(v.cast<S>());
    // FCL's face list: for each face its vertex count, then the indices, counter-clockwise from outside.
    auto faces = std::make_shared<std::vector<int>>();
    for (const auto& poly : hull.polygons) {
      faces->push_back(int(poly.size()));
      for (std::uint32_t i : poly) faces->push_back(int(i));
    }
    auto shape = std::make_shared<fcl::Convex<S>>(vertices, int(hull.polygons.size()), faces);
    cache_.emplace(key, shape);
    return shape;
  }

  std::shared_ptr<fcl::CollisionGeometry<S>> mesh(const ShapeDesc& d) {
    const std::string key = native::scaledKey(d);
    if (auto it = cache_.find(key); it != cache_.end()) return it->second;
    std::vector<Vec3S<S>> vertices;
    for (const Vec3d& v : native::scaledPoints(d)) vertices.push_back(v.cast<S>());
    std::vector<fcl::Triangle> triangles;
    for (const auto& t : native::scaledTriangles(d)) triangles.emplace_back(t[0], t[1], t[2]);
    auto model = std::make_shared<fcl::BVHModel<fcl::OBBRSS<S>>>();
    model->beginModel(int(triangles.size()), int(vertices.size()));
    model->addSubModel(vertices, triangles);
    model->endModel();
    cache_.emplace(key, model);
    return model;
  }

  std::map<std::string, std::shared_ptr<fcl::CollisionGeometry<S>>> cache_;
};

template <class S> bool place(FclShapes<S>& shapes, const ShapeDesc& d, const PoseDesc& p, FclSide<S>& out,
                              std::string& error) {
  bool alongZ = false;
  out.geom = shapes.build(d, alongZ, error);
  if (!out.geom) return false;
  PoseDesc pose = p;
  if (alongZ) pose.q = p.q * native::zAxisToX();  // FCL's Z axis onto gq's X axis
  out.pose = toFcl<S>(pose);
  return true;
}

template <class S> Result success(double ns, ResultFields fields) {
  Result r;
  r.ok = true;
  r.ns = ns;
  r.fields = std::move(fields);
  return r;
}

template <class S>
Result runPair(FclShapes<S>& shapes, fcl::GJKSolverType solver, QueryKind kind, const PairCase& q, int repeat) {
  FclSide<S> a, b;
  std::string error;
  if (!place(shapes, q.geom0, q.pose0, a, error) || !place(shapes, q.geom1, q.pose1, b, error))
    return Result::failure(error);
  const fcl::CollisionObject<S> o0(a.geom, a.pose), o1(b.geom, b.pose);
  if (kind == QueryKind::Overlap || kind == QueryKind::Penetration) {
    const bool contacts = kind == QueryKind::Penetration;
    fcl::CollisionRequest<S> request(contacts ? 64 : 1, contacts);
    request.gjk_solver_type = solver;
    fcl::CollisionResult<S> result;
    const double ns = medianNanoseconds(repeat, [&] {
      result.clear();
      fcl::collide(&o0, &o1, request, result);
    });
    if (!contacts) return success<S>(ns, OverlapOut{result.isCollision()});
    PenetrationOut out;
    // FCL's contact normal points from o1 to o2: moving geom0 along -normal by the depth separates them.
    for (std::size_t i = 0; i < result.numContacts(); ++i) {
      const fcl::Contact<S>& c = result.getContact(i);
      if (!out.penetrating || double(c.penetration_depth) > out.depth) {
        out.penetrating = true;
        out.depth = double(c.penetration_depth);
        out.direction = -c.normal.template cast<double>();
      }
    }
    return success<S>(ns, out);
  }
  fcl::DistanceRequest<S> request(true);  // nearest points
  request.enable_signed_distance = true;
  request.gjk_solver_type = solver;
  fcl::DistanceResult<S> result;
  // FCL's signed distance re-runs collide when the distance is <= 0 and aborts (assert in libfcl) when GST_INDEP's
  // collide then finds no contact. For GST_INDEP the same two steps run here without the abort: contacts decide
  // penetration (depth of the deepest, witness = its position), otherwise the unsigned distance.
  const bool guardIndep = solver == fcl::GST_INDEP;
  fcl::CollisionRequest<S> contactRequest(64, true);
  contactRequest.gjk_solver_type = solver;
  fcl::CollisionResult<S> contacts;
  const double ns = medianNanoseconds(repeat, [&] {
    result.clear();
    if (!guardIndep) {
      fcl::distance(&o0, &o1, request, result);
      return;
    }
    contacts.clear();
    fcl::collide(&o0, &o1, contactRequest, contacts);
    if (contacts.numContacts() > 0) return;
    fcl::DistanceRequest<S> unsignedRequest = request;
    unsignedRequest.enable_signed_distance = false;
    fcl::distance(&o0, &o1, unsignedRequest, result);
  });
  if (guardIndep && contacts.numContacts() > 0) {
    std::size_t deepest = 0;
    for (std::size_t i = 1; i < contacts.numContacts(); ++i)
      if (contacts.getContact(i).penetration_depth > contacts.getContact(deepest).penetration_depth) deepest = i;
    const fcl::Contact<S>& c = contacts.getContact(deepest);
    result.min_distance = -c.penetration_depth;
    result.nearest_points[0] = result.nearest_points[1] = c.pos;
  }
  return success<S>(ns, distanceOutOf(result));
}

}  // namespace

struct FclBackend::Impl {
  FclSolver solver;
  FclShapes<float> floatShapes;
  FclShapes<double> doubleShapes;

  template <class S> Result runIn(FclShapes<S>& shapes, const Case& c, int repeat) {
    const fcl::GJKSolverType type = solver == FclSolver::Indep ? fcl::GST_INDEP : fcl::GST_LIBCCD;
    switch (c.query) {
      case QueryKind::Overlap:
      case QueryKind::Penetration:
      case QueryKind::Distance: return runPair<S>(shapes, type, c.query, std::get<PairCase>(c.input), repeat);
      default: return native::unsupportedQuery("fcl", c.query, "any geometry (it answers overlap, penetration, distance)");
    }
  }
};

FclBackend::FclBackend(FclSolver solver) : impl_(new Impl{solver, {}, {}}) {}
FclBackend::~FclBackend() = default;

const char* FclBackend::name() const { return impl_->solver == FclSolver::Indep ? "fcl-indep" : "fcl"; }

Result FclBackend::run(const Case& c, int repeat) {
  try {
    return c.precision == Precision::Float ? impl_->runIn<float>(impl_->floatShapes, c, repeat)
                                           : impl_->runIn<double>(impl_->doubleShapes, c, repeat);
  } catch (const std::exception& e) {  // FCL throws on some invalid inputs
    return Result::failure(std::string("fcl error: ") + e.what());
  }
}

}  // namespace gq::cases
