#pragma once
// FCL geometry -> gq geometry for one call. FCL's capsule, cylinder and cone lie along local Z with full length lz;
// gq's along local X with halfHeight, so their gq frame is the FCL frame turned by a quarter turn that takes X onto Z.
// Halfspace n.x <= d and Plane n.x = d become gq's plane (x = 0, solid x <= 0) in a frame taking +X onto n.
// Primitives (sphere, box, capsule, cylinder, cone, ellipsoid, triangle, planes) are built in the Converted object
// itself, without allocating: the support callbacks of the custom shapes live inside it and the gq geometry borrows
// them. Convex (-> cookConvexMesh of its vertices) and triangle BVHModels (-> cookTriangleMesh, faceIndex = FCL's
// triangle id) come from the cache (geometry_cache.h). Octrees and point clouds are not converted.
#include <cstdint>
#include <vector>
#include <variant>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "gq/custom_shapes.h"
#include "gq/geometry.h"
#include "gq/tolerances.h"
#include "gq/transform.h"

namespace fcl {
template <typename S> class CollisionGeometry;
}
namespace gq::kernels {
template <class T> struct ConvexShape;  // gq/kernels/gjk.h
}

namespace gq::fcl::internal {

enum class FclShape : std::uint8_t {
  Sphere, Box, Capsule, Cylinder, Cone, Ellipsoid, Convex, TriangleP, Halfspace, Plane, Mesh, Unsupported
};

// What a conversion found: a gq geometry, input gq (and FCL) cannot answer (null, NaN or non-positive sizes, an
// empty or unfinished BVHModel: the call writes nothing), or a type gq does not model (FCL answers it).
enum class Conversion : std::uint8_t { Ok, Invalid, NotModelled };

// How the gq shape frame sits in the FCL geometry's frame.
enum class Frame : std::uint8_t {
  Same,             // box, convex, mesh, ellipsoid, triangle
  TranslationOnly,  // sphere: the rotation does not matter
  XOntoZ,           // capsule, cylinder, cone: gq's axis X along FCL's Z (R_y(-90 deg))
  Offset,           // planes: `offset`
};

// The stand-in that findOverlapTriangleMesh takes for a shape it does not take itself (pair_kernels.h), in the
// shape's local frame: a box or sphere `volume` centred at `centre`.
template <class T> struct CandidateVolume {
  Geometry<T> volume;
  Vec3<T> centre = Vec3<T>::Zero();
};

// What the cache (geometry_cache.h) cooked once for a Convex or a BVHModel: the gq geometry and, for a Convex, its
// candidate volume and its GJK support mapping at the identity pose (the table of start vertices found).
// A hull's face planes packed two at a time (nx0 nx1 ny0 ny1 nz0 nz1 d0 d1; an odd count repeats the last plane):
// the point-in-hull test of the Convex pairs reads them with packed loads.
template <class T> struct HullPlanes {
  std::vector<T> packed;
  std::uint32_t pairs = 0;
};

// A triangle BVHModel the cache has not cooked yet: queried on FCL's own BV tree (fcl_tree.h), its work charged to
// the cache's entry, until the queries have cost about as much as cooking it.
template <class T> struct MeshTree {
  const ::fcl::CollisionGeometry<T>* model;
  int type;           // the model's ::fcl::NODE_TYPE (its BV type)
  const void* entry;  // the cache's entry (geometry_cache.cpp)
};

// Whether a conversion may answer a triangle BVHModel with its FCL tree (the pairs fcl_tree.h answers) or needs
// the cooked mesh.
enum class MeshUse : std::uint8_t { Cooked, TreeAllowed };

// No initialisers on purpose: cachedGeometry / cachedHulls write every field before a caller may read one (on Ok),
// and the Convex pairs' two a call cost them as much as their last certificate saved.
template <class T> struct Cooked {
  FclShape shape;
  const Geometry<T>* geometry;
  const CandidateVolume<T>* candidate;
  const gq::kernels::ConvexShape<T>* support;
  const HullPlanes<T>* planes;  // Convex: its face planes, packed for the point-in-hull test
  const MeshTree<T>* tree;      // a BVHModel not cooked yet (geometry then unset); else null
};

template <class T> class Converted {
 public:
  Converted() = default;
  Converted(const Converted&) = delete;  // the geometry may borrow this object's callbacks
  Converted& operator=(const Converted&) = delete;

  FclShape shape = FclShape::Unsupported;
  Frame frame = Frame::Same;
  Transform<T> offset;  // Frame::Offset: the gq shape frame expressed in the FCL geometry's local frame

  const Geometry<T>& geometry() const { return *geometry_; }
  bool isPlaneLike() const { return shape == FclShape::Halfspace || shape == FclShape::Plane; }
  bool isMesh() const { return shape == FclShape::Mesh; }
  // A BVHModel answered on FCL's tree: geometry() is not a gq mesh, tree() is set.
  bool isTree() const { return tree_ != nullptr; }
  const MeshTree<T>& tree() const { return *tree_; }
  // A closed convex solid (or a half-space): gq's pair kernels answer it directly.
  bool isSolid() const { return shape != FclShape::Mesh && shape != FclShape::Plane && shape != FclShape::Unsupported; }

  void setLocal(const Geometry<T>& g) {
    local_ = g;
    geometry_ = &local_;
  }
  // Custom shape whose callbacks live here (no allocation); the geometry holds a non-owning pointer to them.
  template <class Callbacks, class... Args> void setCallbacks(const Args&... args) {
    const Callbacks& c = callbacks_.template emplace<Callbacks>(args...);
    local_ = CustomGeometry<T>(std::shared_ptr<const CustomGeometryCallbacks<T>>(std::shared_ptr<const void>(), &c));
    geometry_ = &local_;
  }
  // Cached geometry, kept alive by the cache for the duration of the call (see geometry_cache.h).
  void setCached(const Cooked<T>& cooked) {
    shape = cooked.shape;
    geometry_ = cooked.geometry;
    candidate_ = cooked.candidate;
    support_ = cooked.support;
    tree_ = cooked.tree;
  }
  const CandidateVolume<T>* cachedCandidate() const { return candidate_; }
  const gq::kernels::ConvexShape<T>* cachedSupport() const { return support_; }

 private:
  Geometry<T> local_;
  const Geometry<T>* geometry_ = &local_;
  const CandidateVolume<T>* candidate_ = nullptr;
  const gq::kernels::ConvexShape<T>* support_ = nullptr;
  const MeshTree<T>* tree_ = nullptr;
  std::variant<std::monostate, CylinderCallbacks<T>, ConeCallbacks<T>, EllipsoidCallbacks<T>, TriangleCallbacks<T>>
      callbacks_;
};

template <class T>
Conversion convert(const ::fcl::CollisionGeometry<T>* geometry, Converted<T>& out, MeshUse use = MeshUse::Cooked);
template <class T> void forget(const ::fcl::CollisionGeometry<T>* geometry);
void clearCache();

// FCL's Transform3 as a gq pose (its linear part a rotation: rotationUsable).
template <class T> Transform<T> toGq(const Eigen::Transform<T, 3, Eigen::Isometry>& tf) {
  return Transform<T>(tf.translation(), Quat<T>(tf.linear()));
}

// Every entry of both transforms finite. The plain sum of the entries is finite only if every entry is (an inf or a
// NaN reaches it: inf - inf is NaN), so a finite sum answers at once (~20 instructions: Eigen adds the contiguous 4x4
// arrays in SIMD packets); a non-finite sum is a non-finite entry or an overflow of finite ones (entries near the
// largest finite value), which the exact test tells apart: x * 0 is 0 for a finite x, NaN otherwise (~50 instructions
// on its own). Forced inline: as a call it cost the sphere pairs ~10 more.
template <class T> [[gnu::noinline, gnu::cold]] bool everyEntryFinite(const Eigen::Transform<T, 3, Eigen::Isometry>& a) {
  return (a.matrix().array() * T(0)).sum() == T(0);
}
template <class T>
[[gnu::always_inline]] inline bool isFiniteTransforms(const Eigen::Transform<T, 3, Eigen::Isometry>& a,
                                                      const Eigen::Transform<T, 3, Eigen::Isometry>& b) {
  if ((a.matrix().array() + b.matrix().array()).sum() * T(0) == T(0)) [[likely]] return true;
  return everyEntryFinite(a) && everyEntryFinite(b);
}

// The same test on one transform.
template <class T> [[gnu::always_inline]] inline bool isFiniteTransform(const Eigen::Transform<T, 3, Eigen::Isometry>& a) {
  if (a.matrix().sum() * T(0) == T(0)) [[likely]] return true;
  return everyEntryFinite(a);
}

// The world pose of the converted gq shape.
template <class T> Transform<T> shapePose(const Converted<T>& c, const Eigen::Transform<T, 3, Eigen::Isometry>& tf) {
  switch (c.frame) {
    case Frame::TranslationOnly: return Transform<T>(Vec3<T>(tf.translation()));
    case Frame::XOntoZ: {  // R R_y(-90 deg) = [R e_z, R e_y, -R e_x]
      Mat3<T> r;
      r << tf.linear().col(2), tf.linear().col(1), -tf.linear().col(0);
      return Transform<T>(tf.translation(), Quat<T>(r));
    }
    case Frame::Offset: return toGq(tf) * c.offset;
    case Frame::Same: break;
  }
  return toGq(tf);
}

// The linear part's columns are orthonormal: the Gram matrix R^T R = I within the façade's unit-quaternion tolerance
// carried over to the matrix. A rotation scaled by 1 + e has Gram (1 + e)^2 I, about 2e on each diagonal entry, so
// the Frobenius norm of R^T R - I may reach 2 sqrt(3) kUnitQuaternion. A reflection passes: sphere, box and capsule
// are symmetric under flips of their local axes, so R and R diag(1, 1, -1) place the same set (no determinant here:
// rotationUsable and the hulls' entries add positiveDeterminant). A non-finite entry fails the test.
constexpr double kGramDeviationSq = 12 * tol::kUnitQuaternion * tol::kUnitQuaternion;

// x * 0 is 0 for a finite x and NaN otherwise.
template <class S> bool finiteTranslation(const Eigen::Transform<S, 3, Eigen::Isometry>& tf) {
  const S* m = tf.data();  // column-major 4x4: the translation starts at 12
  return m[12] * S(0) + m[13] * S(0) + m[14] * S(0) == S(0);
}

template <class S> bool isOrthonormal(const Eigen::Transform<S, 3, Eigen::Isometry>& tf) {
  const S* m = tf.data();  // column-major 4x4: the columns start at 0, 4, 8
  const S xx = m[0] * m[0] + m[1] * m[1] + m[2] * m[2] - S(1);
  const S yy = m[4] * m[4] + m[5] * m[5] + m[6] * m[6] - S(1);
  const S zz = m[8] * m[8] + m[9] * m[9] + m[10] * m[10] - S(1);
  const S xy = m[0] * m[4] + m[1] * m[5] + m[2] * m[6];
  const S xz = m[0] * m[8] + m[1] * m[9] + m[2] * m[10];
  const S yz = m[4] * m[8] + m[5] * m[9] + m[6] * m[10];
  return xx * xx + yy * yy + zz * zz + S(2) * (xy * xy + xz * xz + yz * yz) <= S(kGramDeviationSq);
}

#if defined(__SSE2__)
// The same test for double on SSE2 pairs, by rows: R R^T and R^T R have the same eigenvalues (the squared singular
// values), so |R R^T - I|_F = |R^T R - I|_F exactly, and the rows' Gram matrix packs better: the first two rows'
// x, y and z entries are the columns' first pairs (one load each), the third row's entries are scalars. ~35
// instructions where the column form took ~60 (every validated box and capsule pose).
inline bool isOrthonormal(const Eigen::Transform<double, 3, Eigen::Isometry>& tf) {
  const double* m = tf.data();  // column-major 4x4: the columns start at 0, 4, 8
  const __m128d x = _mm_loadu_pd(m), y = _mm_loadu_pd(m + 4), z = _mm_loadu_pd(m + 8);  // (row0, row1) entries
  const auto swap = [](__m128d v) { return _mm_shuffle_pd(v, v, 1); };
  // (|r0|^2, |r1|^2), (r0.r1, r1.r0), (r0.r2, r1.r2), and |r2|^2.
  const __m128d norms = _mm_add_pd(_mm_add_pd(_mm_mul_pd(x, x), _mm_mul_pd(y, y)), _mm_mul_pd(z, z));
  const __m128d cross = _mm_add_pd(_mm_add_pd(_mm_mul_pd(x, swap(x)), _mm_mul_pd(y, swap(y))), _mm_mul_pd(z, swap(z)));
  const __m128d third = _mm_add_pd(_mm_add_pd(_mm_mul_pd(x, _mm_set1_pd(m[2])), _mm_mul_pd(y, _mm_set1_pd(m[6]))),
                                   _mm_mul_pd(z, _mm_set1_pd(m[10])));
  const double last = m[2] * m[2] + m[6] * m[6] + m[10] * m[10] - 1.0;
  const __m128d d = _mm_sub_pd(norms, _mm_set1_pd(1.0));
  // |R R^T - I|_F^2: the diagonal deviations once, the off-diagonal entries twice (r0.r1 appears in both lanes).
  const __m128d sum = _mm_add_pd(_mm_add_pd(_mm_mul_pd(d, d), _mm_mul_pd(cross, cross)),
                                 _mm_mul_pd(_mm_mul_pd(third, third), _mm_set1_pd(2.0)));
  return _mm_cvtsd_f64(_mm_add_sd(sum, _mm_unpackhi_pd(sum, sum))) + last * last <= kGramDeviationSq;
}
#endif

// det = x . (y x z) > 0 on the linear part's columns: not a reflection (Eigen's determinant of the 4x4's block cost
// ~40 more instructions).
template <class T> bool positiveDeterminant(const Eigen::Transform<T, 3, Eigen::Isometry>& tf) {
  const T* m = tf.data();  // column-major 4x4: the columns start at 0, 4, 8
  const T det = m[0] * (m[5] * m[10] - m[6] * m[9]) + m[1] * (m[6] * m[8] - m[4] * m[10]) +
                m[2] * (m[4] * m[9] - m[5] * m[8]);
  return det > T(0);
}

// Two transforms checked at once, one a lane of SSE2 pairs (every two-box, two-capsule and two-hull query checks
// both): finite translations (x * 0 summed is 0 only for finite entries), orthonormal linear parts by the column
// Gram test in the scalar isOrthonormal's order, and with kRotation positive determinants x . (y x z). ~80
// instructions for both where two single checks and their calls took ~150.
template <bool kRotation, class S>
bool bothRigid(const Eigen::Transform<S, 3, Eigen::Isometry>& a, const Eigen::Transform<S, 3, Eigen::Isometry>& b) {
  const bool rigid = finiteTranslation(a) && finiteTranslation(b) && isOrthonormal(a) && isOrthonormal(b);
  if constexpr (kRotation) return rigid && positiveDeterminant(a) && positiveDeterminant(b);
  else return rigid;
}
#if defined(__SSE2__)
// bothRigidInline is the check inline, for a kernel that runs it beside its own arithmetic (capsule-capsule distance:
// 28.5 -> 27.9 ns, 498 -> 507 instructions, three alternating runs); bothRigid is its out-of-line call.
template <bool kRotation>
[[gnu::always_inline]] inline bool bothRigidInline(const Eigen::Transform<double, 3, Eigen::Isometry>& a,
                                                   const Eigen::Transform<double, 3, Eigen::Isometry>& b) {
  const double *m = a.data(), *n = b.data();  // column-major 4x4: the columns start at 0, 4, 8, the translation at 12
  const auto pair = [&](int k) { return _mm_loadh_pd(_mm_load_sd(m + k), n + k); };
  const auto add3 = [](__m128d p, __m128d q, __m128d r) { return _mm_add_pd(_mm_add_pd(p, q), r); };
  const auto dot = [&](__m128d x0, __m128d x1, __m128d x2, __m128d y0, __m128d y1, __m128d y2) {
    return add3(_mm_mul_pd(x0, y0), _mm_mul_pd(x1, y1), _mm_mul_pd(x2, y2));
  };
  const __m128d x0 = pair(0), x1 = pair(1), x2 = pair(2), y0 = pair(4), y1 = pair(5), y2 = pair(6);
  const __m128d z0 = pair(8), z1 = pair(9), z2 = pair(10), one = _mm_set1_pd(1.0), zero = _mm_setzero_pd();
  const __m128d xx = _mm_sub_pd(dot(x0, x1, x2, x0, x1, x2), one), yy = _mm_sub_pd(dot(y0, y1, y2, y0, y1, y2), one);
  const __m128d zz = _mm_sub_pd(dot(z0, z1, z2, z0, z1, z2), one);
  const __m128d xy = dot(x0, x1, x2, y0, y1, y2), xz = dot(x0, x1, x2, z0, z1, z2), yz = dot(y0, y1, y2, z0, z1, z2);
  const __m128d deviation = _mm_add_pd(add3(_mm_mul_pd(xx, xx), _mm_mul_pd(yy, yy), _mm_mul_pd(zz, zz)),
                                       _mm_mul_pd(_mm_set1_pd(2.0), dot(xy, xz, yz, xy, xz, yz)));
  const __m128d translation = dot(pair(12), pair(13), pair(14), zero, zero, zero);
  __m128d ok = _mm_and_pd(_mm_cmple_pd(deviation, _mm_set1_pd(kGramDeviationSq)), _mm_cmpeq_pd(translation, zero));
  if constexpr (kRotation) {
    const __m128d cx = _mm_sub_pd(_mm_mul_pd(y1, z2), _mm_mul_pd(y2, z1));
    const __m128d cy = _mm_sub_pd(_mm_mul_pd(y2, z0), _mm_mul_pd(y0, z2));
    const __m128d cz = _mm_sub_pd(_mm_mul_pd(y0, z1), _mm_mul_pd(y1, z0));
    ok = _mm_and_pd(ok, _mm_cmpgt_pd(dot(x0, x1, x2, cx, cy, cz), zero));
  }
  return _mm_movemask_pd(ok) == 3;
}
template <bool kRotation>
bool bothRigid(const Eigen::Transform<double, 3, Eigen::Isometry>& a,
               const Eigen::Transform<double, 3, Eigen::Isometry>& b) {
  return bothRigidInline<kRotation>(a, b);
}
#endif
template <bool kRotation, class S>
[[gnu::always_inline]] inline bool bothRigidInline(const Eigen::Transform<S, 3, Eigen::Isometry>& a,
                                                   const Eigen::Transform<S, 3, Eigen::Isometry>& b) {
  return bothRigid<kRotation>(a, b);
}

// The linear part where the converted shape's pose uses it (every frame but a sphere's) is a rotation: orthonormal
// by the Gram test and not a reflection (its quaternion would not be a rotation's); a sphere's only needs to be
// finite, which isFiniteTransforms checks. The converted pose's quaternion is no test: a sheared matrix (one
// off-diagonal entry 0.05) gives one within 1e-4 of unit.
template <class T>
bool rotationUsable(const Converted<T>& c, const Eigen::Transform<T, 3, Eigen::Isometry>& tf) {
  return c.frame == Frame::TranslationOnly || (isOrthonormal(tf) && positiveDeterminant(tf));
}

}  // namespace gq::fcl::internal
