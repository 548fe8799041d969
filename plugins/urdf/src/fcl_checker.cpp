// FCL reference checker. FCL's capsule and cylinder run along Z, gq's capsule along X: a quarter turn about Y maps
// FCL's Z onto gq's X.
#include "gq/urdf/fcl_checker.h"

#include <fcl/fcl.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "gq/cooking.h"
#include "gq/custom_shapes.h"
#include "kinematic_chain.h"
#include "pair_order.h"

namespace gq::urdf {

struct FclSelfCollisionChecker::Impl {
  std::shared_ptr<const RobotModel<double>> model;
  std::unique_ptr<internal::KinematicChain<double>> chain;        // the same compiled kinematics as gq's checker
  std::vector<std::unique_ptr<fcl::CollisionObjectd>> objects;  // one per shape
  std::vector<std::uint32_t> shapeBody;                         // rigid body carrying each shape
  std::vector<fcl::Transform3d> inBody;                         // FCL geometry frame in its body's frame
  std::vector<Mat3<double>> bodyRotations;
  std::vector<Vec3<double>> bodyPositions;
  std::vector<fcl::AABBd> linkBounds;
  std::vector<LinkPair> checkedPairs;  // not allowed, both with shapes; most often touching first (pair_order.h)
};

namespace {

std::shared_ptr<fcl::CollisionGeometryd> convexToFcl(const ConvexMesh<double>& hull) {
  auto vertices = std::make_shared<std::vector<fcl::Vector3d>>(hull.vertices.begin(), hull.vertices.end());
  auto faces = std::make_shared<std::vector<int>>();
  for (const auto& poly : hull.polygons) {
    faces->push_back(int(poly.indexCount));
    for (std::uint32_t k = 0; k < poly.indexCount; ++k) faces->push_back(int(hull.polygonVertices[poly.indexBase + k]));
  }
  return std::make_shared<fcl::Convexd>(vertices, int(hull.polygons.size()), faces);
}

std::shared_ptr<fcl::CollisionGeometryd> meshToFcl(const TriangleMesh<double>& mesh) {
  auto model = std::make_shared<fcl::BVHModel<fcl::OBBRSSd>>();
  model->beginModel();
  for (const auto& t : mesh.triangles) model->addTriangle(mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]);
  model->endModel();
  return model;
}

const CylinderCallbacks<double>* cylinderOf(const Geometry<double>& g) {
  const auto* custom = g.getIf<CustomGeometry<double>>();
  return custom ? dynamic_cast<const CylinderCallbacks<double>*>(custom->callbacks.get()) : nullptr;
}

Status toFcl(const Shape<double>& shape, std::shared_ptr<fcl::CollisionGeometryd>& out, fcl::Transform3d& offset) {
  offset = fcl::Transform3d::Identity();
  const Geometry<double>& g = shape.geometry;
  if (auto* s = g.getIf<SphereGeometry<double>>()) out = std::make_shared<fcl::Sphered>(s->radius);
  else if (auto* b = g.getIf<BoxGeometry<double>>()) out = std::make_shared<fcl::Boxd>(2.0 * b->halfExtents);
  else if (auto* c = g.getIf<CapsuleGeometry<double>>()) {
    out = std::make_shared<fcl::Capsuled>(c->radius, 2.0 * c->halfHeight);
    offset.linear() = Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitY()).toRotationMatrix();
  } else if (auto* cyl = cylinderOf(g)) {
    out = std::make_shared<fcl::Cylinderd>(cyl->radius(), 2.0 * cyl->halfHeight());
    offset.linear() = Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitY()).toRotationMatrix();
  } else if (auto* h = g.getIf<ConvexMeshGeometry<double>>()) out = convexToFcl(*h->mesh);
  else if (auto* m = g.getIf<TriangleMeshGeometry<double>>()) out = meshToFcl(*m->mesh);
  else return Status::owned(StatusCode::Unsupported, std::string("FCL checker: ") + toString(g.type()));
  return {};
}

fcl::Transform3d toIsometry(const Transform<double>& t) {
  fcl::Transform3d iso = fcl::Transform3d::Identity();
  iso.linear() = t.q.toRotationMatrix();
  iso.translation() = t.p;
  return iso;
}

}  // namespace

FclSelfCollisionChecker::FclSelfCollisionChecker(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
FclSelfCollisionChecker::~FclSelfCollisionChecker() = default;

Status FclSelfCollisionChecker::create(std::shared_ptr<const RobotModel<double>> model,
                                       std::unique_ptr<FclSelfCollisionChecker>& out) {
  if (!model) return Status::invalid("FCL checker needs a model");
  auto impl = std::make_unique<Impl>();
  impl->model = model;
  impl->chain = std::make_unique<internal::KinematicChain<double>>(*model);
  for (const auto& shape : model->shapes) {
    std::shared_ptr<fcl::CollisionGeometryd> geom;
    fcl::Transform3d offset;
    Status s = toFcl(shape, geom, offset);
    if (!s.ok()) return s;
    impl->objects.push_back(std::make_unique<fcl::CollisionObjectd>(geom));
    impl->shapeBody.push_back(impl->chain->bodyOf(shape.link));
    impl->inBody.push_back(toIsometry(impl->chain->linkInBody(shape.link) * shape.origin) * offset);
  }
  impl->linkBounds.resize(model->links.size());
  for (std::uint32_t a = 0; a < model->links.size(); ++a)
    for (std::uint32_t b = a + 1; b < model->links.size(); ++b)
      if (!model->isAllowed(a, b) && !model->links[a].shapes.empty() && !model->links[b].shapes.empty())
        impl->checkedPairs.push_back({a, b});
  out.reset(new FclSelfCollisionChecker(std::move(impl)));
  internal::orderByContactFrequency(
      *model, out->impl_->checkedPairs, [](const LinkPair& p) { return p; },
      [&](const std::vector<double>& q, CollisionResult& r) { return out->checkSelfCollision(q, r); });
  return {};
}

// Places every shape's FCL object and its link's AABB at configuration q.
Status FclSelfCollisionChecker::place(const std::vector<double>& q) {
  Impl& m = *impl_;
  const RobotModel<double>& model = *m.model;
  Status s = m.chain->place(q, m.bodyRotations, m.bodyPositions);
  if (!s.ok()) return s;
  for (std::uint32_t l = 0; l < model.links.size(); ++l) {
    bool first = true;
    for (std::uint32_t i : model.links[l].shapes) {
      fcl::Transform3d pose = fcl::Transform3d::Identity();
      const std::uint32_t b = m.shapeBody[i];
      pose.linear().noalias() = m.bodyRotations[b] * m.inBody[i].linear();
      pose.translation().noalias() = m.bodyRotations[b] * m.inBody[i].translation();
      pose.translation() += m.bodyPositions[b];
      m.objects[i]->setTransform(pose);
      m.objects[i]->computeAABB();
      if (first) m.linkBounds[l] = m.objects[i]->getAABB();
      else m.linkBounds[l] += m.objects[i]->getAABB();
      first = false;
    }
  }
  return {};
}

Status FclSelfCollisionChecker::checkSelfCollision(const std::vector<double>& q, CollisionResult& result,
                                                   const CollisionRequest& request) {
  Status s = place(q);
  if (!s.ok()) return s;
  Impl& m = *impl_;
  const RobotModel<double>& model = *m.model;
  CollisionResult out;
  fcl::CollisionRequestd fclRequest;  // one contact, boolean answer
  for (const LinkPair& p : m.checkedPairs) {
    const std::uint32_t a = p.a, b = p.b;
    if (!m.linkBounds[a].overlap(m.linkBounds[b])) continue;
    bool hit = false;
    for (std::uint32_t sa : model.links[a].shapes) {
      for (std::uint32_t sb : model.links[b].shapes) {
        if (!m.objects[sa]->getAABB().overlap(m.objects[sb]->getAABB())) continue;
        fcl::CollisionResultd fclResult;
        if (fcl::collide(m.objects[sa].get(), m.objects[sb].get(), fclRequest, fclResult) > 0) {
          hit = true;
          break;
        }
      }
      if (hit) break;
    }
    if (!hit) continue;
    out.colliding = true;
    out.pairs.push_back(p);
    if (!request.allPairs) break;
  }
  std::sort(out.pairs.begin(), out.pairs.end());  // the pair order is by contact frequency, the result is sorted
  result = std::move(out);
  return {};
}

Status FclSelfCollisionChecker::selfDistance(const std::vector<double>& q, SelfDistanceResult<double>& result) {
  Status s = place(q);
  if (!s.ok()) return s;
  Impl& m = *impl_;
  const RobotModel<double>& model = *m.model;
  fcl::DistanceRequestd request(true);
  request.enable_signed_distance = true;
  fcl::DistanceResultd fclResult;  // min_distance starts at the largest double: every pair lowers it in turn
  SelfDistanceResult<double> out;
  out.distance = std::numeric_limits<double>::infinity();
  for (const LinkPair& p : m.checkedPairs)
    for (std::uint32_t sa : model.links[p.a].shapes)
      for (std::uint32_t sb : model.links[p.b].shapes) {
        const double before = fclResult.min_distance;
        fcl::distance(m.objects[sa].get(), m.objects[sb].get(), request, fclResult);
        if (!(fclResult.min_distance < before)) continue;
        out.distance = fclResult.min_distance;
        out.pair = p;
        out.point0 = fclResult.nearest_points[0];
        out.point1 = fclResult.nearest_points[1];
      }
  result = out;
  return {};
}

}  // namespace gq::urdf
