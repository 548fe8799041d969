#pragma once
// Geometry value types. A Geometry<T> holds any of them by value (std::variant): no slicing, cheap to copy
// (cooked data is shared through std::shared_ptr<const ...>).
#include <cstdint>
#include <memory>
#include <variant>

#include "gq/math.h"
#include "gq/status.h"

namespace gq {

// The order is fixed: dispatch tables are indexed by it, and pair files are named a_b with a <= b.
enum class GeometryType : std::uint8_t { Sphere, Plane, Capsule, Box, ConvexMesh, TriangleMesh, HeightField, Custom };
inline constexpr std::size_t kGeometryTypeCount = 8;
const char* toString(GeometryType type);

template <class T> struct ConvexMesh;
template <class T> struct TriangleMesh;
template <class T> struct HeightField;
template <class T> class CustomGeometryCallbacks;

// Non-uniform scale along the axes of `rotation`: x_shape = R * diag(scale) * R^T * x_mesh.
template <class T> struct MeshScale {
  Vec3<T> scale = Vec3<T>::Ones();
  Quat<T> rotation = Quat<T>::Identity();

  MeshScale() = default;
  explicit MeshScale(T s) : scale(Vec3<T>::Constant(s)) {}
  explicit MeshScale(const Vec3<T>& s, const Quat<T>& r = Quat<T>::Identity()) : scale(s), rotation(r) {}

  Mat3<T> toMatrix() const {
    const Mat3<T> r = rotation.toRotationMatrix();
    return r * scale.asDiagonal() * r.transpose();
  }
  bool isIdentity() const { return (scale.array() == T(1)).all(); }
  // A mirrored scale (odd number of negative factors) flips triangle winding.
  bool flipsWinding() const { return scale.x() * scale.y() * scale.z() < T(0); }
};

// PxMeshGeometryFlag::eDOUBLE_SIDED
enum class MeshGeometryFlag : std::uint8_t { None = 0, DoubleSided = 1 };

template <class T> struct SphereGeometry {
  T radius = T(0);
  SphereGeometry() = default;
  explicit SphereGeometry(T r) : radius(r) {}
};

// The plane x = 0 in its local frame, normal +X; solid half-space x <= 0 for overlaps and sweeps.
template <class T> struct PlaneGeometry {};

// Capsule along local X: segment from (-halfHeight,0,0) to (+halfHeight,0,0), swept by a sphere of radius.
template <class T> struct CapsuleGeometry {
  T radius = T(0);
  T halfHeight = T(0);
  CapsuleGeometry() = default;
  CapsuleGeometry(T r, T hh) : radius(r), halfHeight(hh) {}
};

template <class T> struct BoxGeometry {
  Vec3<T> halfExtents = Vec3<T>::Zero();
  BoxGeometry() = default;
  explicit BoxGeometry(const Vec3<T>& he) : halfExtents(he) {}
  BoxGeometry(T hx, T hy, T hz) : halfExtents(hx, hy, hz) {}
};

template <class T> struct ConvexMeshGeometry {
  std::shared_ptr<const ConvexMesh<T>> mesh;
  MeshScale<T> scale;
  ConvexMeshGeometry() = default;
  explicit ConvexMeshGeometry(std::shared_ptr<const ConvexMesh<T>> m, const MeshScale<T>& s = MeshScale<T>())
      : mesh(std::move(m)), scale(s) {}
};

template <class T> struct TriangleMeshGeometry {
  std::shared_ptr<const TriangleMesh<T>> mesh;
  MeshScale<T> scale;
  MeshGeometryFlag flags = MeshGeometryFlag::None;
  TriangleMeshGeometry() = default;
  explicit TriangleMeshGeometry(std::shared_ptr<const TriangleMesh<T>> m, const MeshScale<T>& s = MeshScale<T>(),
                                MeshGeometryFlag f = MeshGeometryFlag::None)
      : mesh(std::move(m)), scale(s), flags(f) {}
  bool doubleSided() const { return flags == MeshGeometryFlag::DoubleSided; }
};

// Sample (row r, column c) sits at local (r * rowScale, height * heightScale, c * columnScale); normals face +Y.
template <class T> struct HeightFieldGeometry {
  std::shared_ptr<const HeightField<T>> heightField;
  T heightScale = T(1);
  T rowScale = T(1);
  T columnScale = T(1);
  MeshGeometryFlag flags = MeshGeometryFlag::None;
  HeightFieldGeometry() = default;
  HeightFieldGeometry(std::shared_ptr<const HeightField<T>> hf, T hs, T rs, T cs,
                      MeshGeometryFlag f = MeshGeometryFlag::None)
      : heightField(std::move(hf)), heightScale(hs), rowScale(rs), columnScale(cs), flags(f) {}
  bool doubleSided() const { return flags == MeshGeometryFlag::DoubleSided; }
};

// A user shape defined by callbacks (see gq/custom.h); Cylinder and Cone ship ready-made.
template <class T> struct CustomGeometry {
  std::shared_ptr<const CustomGeometryCallbacks<T>> callbacks;
  CustomGeometry() = default;
  explicit CustomGeometry(std::shared_ptr<const CustomGeometryCallbacks<T>> cb) : callbacks(std::move(cb)) {}
};

template <class T> class Geometry {
 public:
  using Variant = std::variant<SphereGeometry<T>, PlaneGeometry<T>, CapsuleGeometry<T>, BoxGeometry<T>,
                               ConvexMeshGeometry<T>, TriangleMeshGeometry<T>, HeightFieldGeometry<T>,
                               CustomGeometry<T>>;
  static_assert(std::variant_size_v<Variant> == kGeometryTypeCount, "one alternative per GeometryType");

  Geometry() = default;  // an empty sphere: fails validation
  template <class G, class = std::enable_if_t<!std::is_same_v<std::decay_t<G>, Geometry>>>
  Geometry(G&& g) : v_(std::forward<G>(g)) {}  // NOLINT: implicit on purpose, like PxGeometry references

  GeometryType type() const { return static_cast<GeometryType>(v_.index()); }
  template <class G> const G& get() const { return *std::get_if<G>(&v_); }
  template <class G> const G* getIf() const { return std::get_if<G>(&v_); }
  const Variant& variant() const { return v_; }

 private:
  Variant v_;
};

// Checks sizes (> 0 and finite; capsule halfHeight >= 0), cooked data present, scales finite and non-zero.
template <class T> Status validateGeometry(const Geometry<T>& geom) noexcept;

}  // namespace gq
