// loadMeshFile: OBJ and STL by gq's own readers (exact coordinates), every other format through assimp (32-bit
// float coordinates): triangulated, identical vertices joined, and all meshes merged into one vertex/triangle list
// in the frame of the file's root, applying every node's transform.
#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>

#include "common/validate.h"
#include "gq/io.h"
#include "io/mesh_readers.h"
#include "io/mesh_text.h"

namespace gq {
namespace {

Mat3<double> linearPart(const aiMatrix4x4& m) {
  Mat3<double> r;
  r << m.a1, m.a2, m.a3, m.b1, m.b2, m.b3, m.c1, m.c2, m.c3;
  return r;
}

// Appends the triangles of every mesh referenced by `node` and its descendants; `parent` maps the node's parent
// frame to the output frame. `applyOwn` = false drops this node's own transform (the root, on request).
template <class T> void appendNode(const aiScene& scene, const aiNode& node, const aiMatrix4x4& parent,
                                   bool applyOwn, MeshData<T>& out) {
  const aiMatrix4x4 world = applyOwn ? parent * node.mTransformation : parent;
  const Mat3<double> linear = linearPart(world);
  const Vec3<double> offset(world.a4, world.b4, world.c4);
  for (unsigned k = 0; k < node.mNumMeshes; ++k) {
    const aiMesh& mesh = *scene.mMeshes[node.mMeshes[k]];
    const auto base = std::uint32_t(out.vertices.size());
    for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
      const aiVector3D& p = mesh.mVertices[v];
      out.vertices.push_back((linear * Vec3<double>(p.x, p.y, p.z) + offset).template cast<T>());
    }
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
      const aiFace& face = mesh.mFaces[f];
      if (face.mNumIndices != 3) continue;  // points and lines left by triangulation
      out.triangles.push_back({base + face.mIndices[0], base + face.mIndices[1], base + face.mIndices[2]});
    }
  }
  for (unsigned c = 0; c < node.mNumChildren; ++c) appendNode(scene, *node.mChildren[c], world, true, out);
}

template <class T> Status loadWithAssimp(const std::string& path, MeshData<T>& out, bool ignoreRootTransform) {
  if (!std::ifstream(path).good()) return Status::owned(StatusCode::FileError, "cannot open mesh file '" + path + "'");
  Assimp::Importer importer;
  const aiScene* scene = importer.ReadFile(path, aiProcess_Triangulate | aiProcess_JoinIdenticalVertices);
  if (scene == nullptr || scene->mRootNode == nullptr || (scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE))
    return Status::owned(StatusCode::ParseError, "cannot parse mesh file '" + path + "': " + importer.GetErrorString());
  MeshData<T> data;
  // The root's own transform (e.g. a DAE up-axis conversion) is dropped on request; children keep theirs.
  appendNode(*scene, *scene->mRootNode, aiMatrix4x4(), !ignoreRootTransform, data);
  if (data.triangles.empty()) return Status::owned(StatusCode::ParseError, "mesh file '" + path + "' contains no triangles");
  out = std::move(data);
  return Status();
}

std::string lowerExtension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}

}  // namespace

template <class T> Status loadMeshFile(const std::string& path, MeshData<T>& out, bool ignoreRootTransform) {
  return detail::guarded([&]() -> Status {
    const std::string ext = lowerExtension(path);
    if (ext != ".obj" && ext != ".stl") return loadWithAssimp(path, out, ignoreRootTransform);
    // OBJ and STL have no node hierarchy: ignoreRootTransform changes nothing.
    std::string text;
    if (Status s = io::readFileText(path, text); !s.ok()) return s;
    return ext == ".obj" ? io::readObj(path, text, out) : io::readStl(path, text, out);
  });
}

template Status loadMeshFile<float>(const std::string&, MeshData<float>&, bool);
template Status loadMeshFile<double>(const std::string&, MeshData<double>&, bool);

}  // namespace gq
