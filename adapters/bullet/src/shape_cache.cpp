#include "shape_cache.h"

#include <cmath>
#include <cstring>
#include <mutex>
#include <unordered_map>

#include "gq/bullet/collision_configuration.h"
#include "gq/tolerances.h"
#include "mesh_fitting.h"

namespace gq::bullet {
namespace {

// A 64-bit FNV-1a hash of the values a shape's data was cooked from, compared on every lookup (no allocation
// per frame).
class Fingerprint {
 public:
  Fingerprint& add(double v) {
    unsigned char bytes[sizeof v];
    std::memcpy(bytes, &v, sizeof v);
    for (unsigned char b : bytes) hash_ = (hash_ ^ b) * 1099511628211ull;
    return *this;
  }
  std::uint64_t value() const { return hash_; }

 private:
  std::uint64_t hash_ = 14695981039346656037ull;
};

// One cache entry: the fingerprint and the cooked data (null when cooking failed, so a refused shape is not
// re-cooked every frame).
struct Entry {
  std::uint64_t fingerprint = 0;
  std::shared_ptr<const void> data;
};

class ShapeCache {
 public:
  template <class Cook>
  std::shared_ptr<const void> get(const void* key, std::uint64_t fingerprint, Cook&& cook) {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      auto it = entries_.find(key);
      if (it != entries_.end() && it->second.fingerprint == fingerprint) return it->second.data;
    }
    std::shared_ptr<const void> data = cook();  // outside the lock: cooking may take milliseconds
    std::lock_guard<std::mutex> lock(mutex_);
    entries_[key] = Entry{fingerprint, data};
    return data;
  }
  void put(const void* key, std::uint64_t fingerprint, std::shared_ptr<const void> data) {
    std::lock_guard<std::mutex> lock(mutex_);
    entries_[key] = Entry{fingerprint, std::move(data)};
  }
  void clear() {
    std::lock_guard<std::mutex> lock(mutex_);
    entries_.clear();
  }

 private:
  std::mutex mutex_;
  std::unordered_map<const void*, Entry> entries_;
};

ShapeCache& cache() {
  static ShapeCache instance;
  return instance;
}

// Reads the protected layout fields of btHeightfieldTerrainShape through member pointers (no copy of its code).
struct HeightFieldFields : btHeightfieldTerrainShape {
  static int width(const btHeightfieldTerrainShape& s) { return s.*(&HeightFieldFields::m_heightStickWidth); }
  static int length(const btHeightfieldTerrainShape& s) { return s.*(&HeightFieldFields::m_heightStickLength); }
  static bool plainQuads(const btHeightfieldTerrainShape& s) {
    return !(s.*(&HeightFieldFields::m_flipQuadEdges)) && !(s.*(&HeightFieldFields::m_useDiamondSubdivision)) &&
           !(s.*(&HeightFieldFields::m_useZigzagSubdivision));
  }
  static const void* data(const btHeightfieldTerrainShape& s) {
    return s.*(&HeightFieldFields::m_heightfieldDataUnknown);
  }
};

// Dimensions and axis gq can build a grid from, checked before a single sample is read (Bullet trusts them and
// reads outside the caller's buffer for absurd sizes).
bool sizedSensibly(const btHeightfieldTerrainShape& s) {
  const int width = HeightFieldFields::width(s), length = HeightFieldFields::length(s), u = s.getUpAxis();
  if (u < 0 || u > 2 || width < 2 || length < 2 || !HeightFieldFields::data(s)) return false;
  return std::uint64_t(width) * std::uint64_t(length) <= tol::kMaxHeightFieldSamples;
}

struct MeshPart {
  const unsigned char* vertexBase = nullptr;
  int vertexCount = 0, vertexStride = 0, indexStride = 0, triangleCount = 0;
  const unsigned char* indexBase = nullptr;
  PHY_ScalarType vertexType = PHY_FLOAT, indexType = PHY_INTEGER;
};

MeshPart lockPart(const btStridingMeshInterface& mi, int part) {
  MeshPart p;
  mi.getLockedReadOnlyVertexIndexBase(&p.vertexBase, p.vertexCount, p.vertexType, p.vertexStride, &p.indexBase,
                                      p.indexStride, p.triangleCount, p.indexType, part);
  return p;
}

// Counts, buffers and types Bullet's mesh interfaces can describe; anything else would be read out of bounds.
bool wellFormed(const MeshPart& p) {
  const bool knownVertex = p.vertexType == PHY_FLOAT || p.vertexType == PHY_DOUBLE;
  const int vertexSize = 3 * (p.vertexType == PHY_DOUBLE ? int(sizeof(double)) : int(sizeof(float)));
  const int indexSize = 3 * (p.indexType == PHY_SHORT ? int(sizeof(short)) : p.indexType == PHY_UCHAR ? 1 : int(sizeof(int)));
  const bool knownIndex = p.indexType == PHY_SHORT || p.indexType == PHY_UCHAR || p.indexType == PHY_INTEGER;
  if (!knownVertex || !knownIndex || p.vertexCount < 0 || p.triangleCount < 0) return false;
  if (p.vertexCount > 0 && (!p.vertexBase || p.vertexStride < vertexSize)) return false;
  if (p.triangleCount > 0 && (!p.indexBase || p.indexStride < indexSize)) return false;
  return true;
}

V3 partVertex(const MeshPart& p, std::uint32_t i) {
  const unsigned char* v = p.vertexBase + std::size_t(i) * p.vertexStride;
  if (p.vertexType == PHY_DOUBLE) {
    const double* d = reinterpret_cast<const double*>(v);
    return V3(Real(d[0]), Real(d[1]), Real(d[2]));
  }
  const float* f = reinterpret_cast<const float*>(v);
  return V3(Real(f[0]), Real(f[1]), Real(f[2]));
}

std::uint32_t partIndex(const MeshPart& p, int triangle, int corner) {
  const unsigned char* t = p.indexBase + std::size_t(triangle) * p.indexStride;
  switch (p.indexType) {
    case PHY_SHORT: return reinterpret_cast<const unsigned short*>(t)[corner];
    case PHY_UCHAR: return t[corner];
    default: return reinterpret_cast<const unsigned int*>(t)[corner];
  }
}

std::shared_ptr<const void> cookMesh(const btStridingMeshInterface& mi) {
  std::vector<V3> vertices;
  std::vector<TriangleIndices> triangles;
  auto starts = std::make_shared<std::vector<std::uint32_t>>();
  for (int part = 0; part < mi.getNumSubParts(); ++part) {
    const MeshPart p = lockPart(mi, part);
    const auto base = static_cast<std::uint32_t>(vertices.size());
    starts->push_back(static_cast<std::uint32_t>(triangles.size()));
    for (int i = 0; i < p.vertexCount; ++i) vertices.push_back(partVertex(p, std::uint32_t(i)));
    for (int t = 0; t < p.triangleCount; ++t)
      triangles.push_back({base + partIndex(p, t, 0), base + partIndex(p, t, 1), base + partIndex(p, t, 2)});
    mi.unLockReadOnlyVertexBase(part);
  }
  auto cooked = std::make_shared<CookedMesh>();
  if (!cookTriangleMesh(vertices, triangles, cooked->mesh)) return nullptr;
  cooked->partStarts = std::move(starts);
  return cooked;
}

// gq's heightfield grid has rows along local X, columns along Z and heights along Y. Bullet's up axis u takes Y;
// the remaining axes follow cyclically (X -> axis (u+2)%3, Z -> axis (u+1)%3) so the frame stays right-handed.
// Bullet splits each quad along the diagonal (x, j+1)-(x+1, j), as gq does along (r, c+1)-(r+1, c), and that
// diagonal is the same whichever grid index becomes the row.
std::shared_ptr<const void> cookHeightFieldShape(const btHeightfieldTerrainShape& shape) {
  const int u = shape.getUpAxis();
  const int rowAxis = (u + 2) % 3, columnAxis = (u + 1) % 3;
  const bool rowsAreX = (u == 1);
  const int width = HeightFieldFields::width(shape), length = HeightFieldFields::length(shape);
  auto out = std::make_shared<CookedHeightField>();
  HeightFieldDesc<Real> desc;
  desc.rows = std::uint32_t(rowsAreX ? width : length);
  desc.columns = std::uint32_t(rowsAreX ? length : width);
  desc.heights.resize(std::size_t(desc.rows) * desc.columns);
  for (std::uint32_t r = 0; r < desc.rows; ++r) {
    for (std::uint32_t c = 0; c < desc.columns; ++c) {
      btVector3 v;
      shape.getVertex(int(rowsAreX ? r : c), int(rowsAreX ? c : r), v);
      desc.heights[std::size_t(r) * desc.columns + c] = v[u];
    }
  }
  if (!cookHeightField(desc, out->heightField)) return nullptr;
  btVector3 origin;
  shape.getVertex(0, 0, origin);
  Mat3<Real> axes = Mat3<Real>::Zero();
  axes(rowAxis, 0) = axes(u, 1) = axes(columnAxis, 2) = Real(1);
  V3 offset = V3::Zero();
  offset[rowAxis] = origin[rowAxis];
  offset[columnAxis] = origin[columnAxis];
  out->localPose = Pose(offset, Quat<Real>(axes));
  out->rowScale = shape.getLocalScaling()[rowAxis];
  out->columnScale = shape.getLocalScaling()[columnAxis];
  out->rowsAreX = rowsAreX;
  return out;
}

}  // namespace

namespace {

// The fingerprint of a hull shape's unscaled points; false for no points or a non-finite one.
bool hullFingerprint(const btConvexHullShape& shape, std::uint64_t& out) {
  const int n = shape.getNumPoints();
  if (n <= 0) return false;  // stock Bullet's GJK reads the empty point array (segfault)
  Fingerprint fingerprint;
  fingerprint.add(n);
  const btVector3* points = shape.getUnscaledPoints();
  bool finite = true;
  for (int i = 0; i < n; ++i)
    for (int k = 0; k < 3; ++k) {
      finite = finite && std::isfinite(points[i][k]);
      fingerprint.add(points[i][k]);
    }
  out = fingerprint.value();
  return finite;
}

}  // namespace

bool shareHull(const btConvexHullShape& shape, std::shared_ptr<const ConvexMesh<Real>> hull) {
  std::uint64_t fingerprint;
  if (!hull || !hullFingerprint(shape, fingerprint)) return false;
  cache().put(&shape, fingerprint, std::move(hull));
  return true;
}

Support cachedHull(const btConvexHullShape& shape, std::shared_ptr<const ConvexMesh<Real>>& out) {
  std::uint64_t fingerprint;
  if (!hullFingerprint(shape, fingerprint)) return Support::Invalid;
  const int n = shape.getNumPoints();
  const btVector3* points = shape.getUnscaledPoints();
  auto data = cache().get(&shape, fingerprint, [&]() -> std::shared_ptr<const void> {
    std::vector<V3> pts;
    for (int i = 0; i < n; ++i) pts.push_back(toGq(points[i]));
    std::shared_ptr<const ConvexMesh<Real>> hull;
    if (!cookConvexMesh(pts, hull)) return nullptr;
    return hull;
  });
  if (!data) return Support::Bullet;
  out = std::static_pointer_cast<const ConvexMesh<Real>>(data);
  return Support::Gq;
}

Support cachedMultiSphere(const btMultiSphereShape& shape, std::shared_ptr<const MultiSphereShape>& out) {
  const int n = shape.getSphereCount();
  if (n <= 0) return Support::Invalid;
  const btVector3& s = shape.getLocalScaling();
  Fingerprint fingerprint;
  fingerprint.add(n).add(s.x());
  for (int i = 0; i < n; ++i) {
    const btScalar r = shape.getSphereRadius(i);
    if (!isFinite(shape.getSpherePosition(i)) || !(r > 0) || !std::isfinite(r)) return Support::Invalid;
    for (int k = 0; k < 3; ++k) fingerprint.add(shape.getSpherePosition(i)[k]);
    fingerprint.add(r);
  }
  if (!(s.x() > 0 && s.x() == s.y() && s.y() == s.z())) return Support::Bullet;  // Bullet scales radii per axis
  auto data = cache().get(&shape, fingerprint.value(), [&]() -> std::shared_ptr<const void> {
    std::vector<V3> centres;
    std::vector<Real> radii;
    for (int i = 0; i < n; ++i) {
      centres.push_back(toGq(shape.getSpherePosition(i) * s.x()));
      radii.push_back(shape.getSphereRadius(i) * s.x());
    }
    return std::make_shared<MultiSphereShape>(std::move(centres), std::move(radii));
  });
  out = std::static_pointer_cast<const MultiSphereShape>(data);
  return Support::Gq;
}

bool meshFingerprint(const btStridingMeshInterface& mi, std::uint64_t& out) {
  Fingerprint fingerprint;
  fingerprint.add(mi.getNumSubParts());
  bool wellFormedParts = mi.getNumSubParts() > 0;
  for (int part = 0; part < mi.getNumSubParts(); ++part) {
    const MeshPart p = lockPart(mi, part);
    wellFormedParts = wellFormedParts && wellFormed(p);
    fingerprint.add(double(reinterpret_cast<std::uintptr_t>(p.vertexBase)))
        .add(double(reinterpret_cast<std::uintptr_t>(p.indexBase)))
        .add(p.vertexCount)
        .add(p.triangleCount)
        .add(p.vertexStride)
        .add(p.indexStride)
        .add(int(p.vertexType))
        .add(int(p.indexType));
    mi.unLockReadOnlyVertexBase(part);
  }
  out = fingerprint.value();
  return wellFormedParts;
}

Support cachedMesh(const btStridingMeshInterface& mi, CookedMesh& out) {
  std::uint64_t fingerprint;
  if (!meshFingerprint(mi, fingerprint)) return Support::Invalid;
  auto data = cache().get(&mi, fingerprint, [&] { return cookMesh(mi); });
  if (!data) return Support::Invalid;
  out = *static_cast<const CookedMesh*>(data.get());
  return Support::Gq;
}

bool heightFieldFingerprint(const btHeightfieldTerrainShape& shape, std::uint64_t& out) {
  if (!sizedSensibly(shape)) return false;
  const btVector3& s = shape.getLocalScaling();
  Fingerprint fingerprint;
  fingerprint.add(double(reinterpret_cast<std::uintptr_t>(HeightFieldFields::data(shape))))
      .add(HeightFieldFields::width(shape))
      .add(HeightFieldFields::length(shape))
      .add(shape.getUpAxis())
      .add(s.x())
      .add(s.y())
      .add(s.z())
      .add(HeightFieldFields::plainQuads(shape) ? 1 : 0);
  out = fingerprint.value();
  return true;
}

Support cachedHeightField(const btHeightfieldTerrainShape& shape, CookedHeightField& out) {
  const btVector3& s = shape.getLocalScaling();
  std::uint64_t fingerprint;
  if (!heightFieldFingerprint(shape, fingerprint) || !isUsableScaling(s)) return Support::Invalid;
  if (!HeightFieldFields::plainQuads(shape) || !(s.x() > 0 && s.y() > 0 && s.z() > 0)) return Support::Bullet;
  auto data = cache().get(&shape, fingerprint, [&] { return cookHeightFieldShape(shape); });
  if (!data) return Support::Invalid;  // a non-finite height (cooking checks every sample)
  out = *static_cast<const CookedHeightField*>(data.get());
  return Support::Gq;
}

void clearShapeCache() {
  cache().clear();
  clearFittedMeshes();
}

}  // namespace gq::bullet
