#pragma once
// Test helpers: DART frames, bodies and worlds built in code.
#include <assimp/scene.h>

#include <memory>
#include <random>
#include <string>
#include <vector>

#include <dart/collision/CollisionDetector.hpp>
#include <dart/collision/CollisionGroup.hpp>
#include <dart/constraint/ConstraintSolver.hpp>
#include <dart/dynamics/BoxShape.hpp>
#include <dart/dynamics/CapsuleShape.hpp>
#include <dart/dynamics/FreeJoint.hpp>
#include <dart/dynamics/HeightmapShape.hpp>
#include <dart/dynamics/MeshShape.hpp>
#include <dart/dynamics/SimpleFrame.hpp>
#include <dart/dynamics/Skeleton.hpp>
#include <dart/dynamics/SphereShape.hpp>
#include <dart/dynamics/WeldJoint.hpp>
#include <dart/simulation/World.hpp>

namespace gqtest {

namespace dd = ::dart::dynamics;
namespace dc = ::dart::collision;

inline Eigen::Isometry3d at(const Eigen::Vector3d& p, const Eigen::Quaterniond& q = Eigen::Quaterniond::Identity()) {
  Eigen::Isometry3d tf = Eigen::Isometry3d::Identity();
  tf.linear() = q.toRotationMatrix();
  tf.translation() = p;
  return tf;
}

inline std::shared_ptr<dd::SimpleFrame> frame(const dd::ShapePtr& shape, const Eigen::Isometry3d& tf,
                                              const std::string& name = "frame") {
  auto f = std::make_shared<dd::SimpleFrame>(dd::Frame::World(), name, tf);
  f->setShape(shape);
  return f;
}

inline std::shared_ptr<dc::CollisionDetector> detector(const std::string& name) {
  return dc::CollisionDetector::getFactory()->create(name);
}

// An assimp scene of one mesh (owned by the MeshShape that receives it).
inline aiScene* meshScene(const std::vector<Eigen::Vector3d>& vertices, const std::vector<std::array<unsigned, 3>>& tris) {
  auto* scene = new aiScene();
  scene->mNumMeshes = 1;
  scene->mMeshes = new aiMesh*[1];
  auto* mesh = new aiMesh();
  scene->mMeshes[0] = mesh;
  scene->mRootNode = new aiNode();
  mesh->mNumVertices = unsigned(vertices.size());
  mesh->mVertices = new aiVector3D[vertices.size()];
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    mesh->mVertices[i] = aiVector3D(ai_real(vertices[i].x()), ai_real(vertices[i].y()), ai_real(vertices[i].z()));
  }
  mesh->mNumFaces = unsigned(tris.size());
  mesh->mFaces = new aiFace[tris.size()];
  for (std::size_t i = 0; i < tris.size(); ++i) {
    mesh->mFaces[i].mNumIndices = 3;
    mesh->mFaces[i].mIndices = new unsigned[3]{tris[i][0], tris[i][1], tris[i][2]};
  }
  mesh->mPrimitiveTypes = aiPrimitiveType_TRIANGLE;
  return scene;
}

// A flat square ground of n x n cells, 2 * half wide, at z = 0, normals +z.
inline std::shared_ptr<dd::MeshShape> groundMesh(double half, int n, const Eigen::Vector3d& scale = Eigen::Vector3d::Ones()) {
  std::vector<Eigen::Vector3d> v;
  std::vector<std::array<unsigned, 3>> t;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) v.emplace_back(-half + 2 * half * i / n, -half + 2 * half * j / n, 0.0);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const unsigned a = unsigned(i * (n + 1) + j), b = a + unsigned(n + 1), c = b + 1, d = a + 1;
      t.push_back({a, b, c});
      t.push_back({a, c, d});
    }
  return std::make_shared<dd::MeshShape>(scale, std::shared_ptr<const aiScene>(meshScene(v, t), [](const aiScene*) {}).get());
}

// A flat heightmap of n x n samples at height h, `spacing` apart (float: DART's Bullet detector takes only those).
inline std::shared_ptr<dd::HeightmapShapef> flatHeightmap(std::size_t n, float spacing, float h) {
  auto shape = std::make_shared<dd::HeightmapShapef>();
  shape->setHeightField(n, n, std::vector<float>(n * n, h));
  shape->setScale(Eigen::Vector3f(spacing, spacing, 1.0f));
  return shape;
}

// A skeleton of one body: free (dynamic, mass 1) or welded to the world.
inline dd::SkeletonPtr body(const std::string& name, const dd::ShapePtr& shape, const Eigen::Isometry3d& tf,
                            bool fixed) {
  auto skeleton = dd::Skeleton::create(name);
  dd::BodyNode* node = nullptr;
  if (fixed) {
    node = skeleton->createJointAndBodyNodePair<dd::WeldJoint>().second;
    node->getParentJoint()->setTransformFromParentBodyNode(tf);
  } else {
    node = skeleton->createJointAndBodyNodePair<dd::FreeJoint>().second;
    dd::FreeJoint::setTransformOf(node, tf);
  }
  node->createShapeNodeWith<dd::CollisionAspect, dd::DynamicsAspect>(shape);
  dd::Inertia inertia;
  inertia.setMass(1.0);
  inertia.setMoment(shape->computeInertia(1.0));
  node->setInertia(inertia);
  return skeleton;
}

}  // namespace gqtest
