#pragma once
// Test shapes and poses in either scalar: the FCL geometry of a TestShape in float or double, and the rounding of a
// shape and a pose to float (the exact references then run on exactly the float values).
#include <memory>
#include <type_traits>
#include <vector>

#include "fcl_scenes.h"

namespace gq::fcltest {

inline double toFloatAndBack(double x) { return double(float(x)); }
inline ::fcl::Vector3d toFloatAndBack(const ::fcl::Vector3d& v) { return v.cast<float>().cast<double>(); }

// The FCL geometry of a test shape in scalar S, from its recorded parameters.
template <class S> std::shared_ptr<::fcl::CollisionGeometry<S>> fclGeometry(const TestShape& s) {
  using V = ::fcl::Vector3<S>;
  const auto vec = [](const ::fcl::Vector3d& v) { return V(v.cast<S>()); };
  std::shared_ptr<::fcl::CollisionGeometry<S>> g;
  switch (s.kind) {
    case Kind::Sphere: g = std::make_shared<::fcl::Sphere<S>>(S(s.size.x())); break;
    case Kind::Box: g = std::make_shared<::fcl::Box<S>>(vec(s.size)); break;
    case Kind::Capsule: g = std::make_shared<::fcl::Capsule<S>>(S(s.size.x()), S(s.size.y())); break;
    case Kind::Cylinder: g = std::make_shared<::fcl::Cylinder<S>>(S(s.size.x()), S(s.size.y())); break;
    case Kind::Cone: g = std::make_shared<::fcl::Cone<S>>(S(s.size.x()), S(s.size.y())); break;
    case Kind::Ellipsoid: g = std::make_shared<::fcl::Ellipsoid<S>>(vec(s.size)); break;
    case Kind::Convex: {
      auto vertices = std::make_shared<std::vector<V>>();
      for (const auto& v : s.vertices) vertices->push_back(vec(v));
      auto faces = std::make_shared<std::vector<int>>();
      for (const auto& f : s.faces) {
        faces->push_back(int(f.size()));
        faces->insert(faces->end(), f.begin(), f.end());
      }
      g = std::make_shared<::fcl::Convex<S>>(vertices, int(s.faces.size()), faces);
      break;
    }
    case Kind::TriangleP:
      g = std::make_shared<::fcl::TriangleP<S>>(vec(s.vertices[0]), vec(s.vertices[1]), vec(s.vertices[2]));
      break;
    case Kind::Halfspace: g = std::make_shared<::fcl::Halfspace<S>>(vec(s.planeNormal), S(s.planeOffset)); break;
    case Kind::Plane: g = std::make_shared<::fcl::Plane<S>>(vec(s.planeNormal), S(s.planeOffset)); break;
    case Kind::Mesh: {
      auto model = std::make_shared<::fcl::BVHModel<::fcl::OBBRSS<S>>>();
      model->beginModel();
      for (const auto& f : s.faces) model->addTriangle(vec(s.vertices[f[0]]), vec(s.vertices[f[1]]), vec(s.vertices[f[2]]));
      model->endModel();
      g = model;
      break;
    }
  }
  g->computeLocalAABB();
  return g;
}

// A test shape whose every parameter is a float, with its double geometry rebuilt from those values. FCL normalises
// plane normals in the geometry's own scalar: the reference takes the normal FCL's float Halfspace/Plane holds.
inline TestShape roundedToFloat(const TestShape& s) {
  TestShape r = s;
  r.size = toFloatAndBack(s.size);
  for (auto& v : r.vertices) v = toFloatAndBack(v);
  r.planeNormal = toFloatAndBack(s.planeNormal);
  r.planeOffset = toFloatAndBack(s.planeOffset);
  if (isPlaneLike(s.kind)) {
    const auto f = fclGeometry<float>(r);
    const auto* h = dynamic_cast<const ::fcl::Halfspacef*>(f.get());
    const auto* p = dynamic_cast<const ::fcl::Planef*>(f.get());
    r.planeNormal = (h ? h->n : p->n).cast<double>();
    r.planeOffset = double(h ? h->d : p->d);
  }
  r.geometry = fclGeometry<double>(r);
  return r;
}

// A shape whose parameters are representable in S (float: rounded; double: as made).
template <class S> TestShape roundedTo(const TestShape& s) {
  if constexpr (std::is_same_v<S, float>) return roundedToFloat(s);
  else return s;
}
// A pose in S, and the double pose of exactly its values.
template <class S> ::fcl::Transform3<S> poseIn(const ::fcl::Transform3d& tf) {
  ::fcl::Transform3<S> p = ::fcl::Transform3<S>::Identity();
  p.linear() = tf.linear().cast<S>();
  p.translation() = tf.translation().cast<S>();
  return p;
}
template <class S> ::fcl::Transform3d poseInDouble(const ::fcl::Transform3<S>& tf) {
  ::fcl::Transform3d p = ::fcl::Transform3d::Identity();
  p.linear() = tf.linear().template cast<double>();
  p.translation() = tf.translation().template cast<double>();
  return p;
}

}  // namespace gq::fcltest
