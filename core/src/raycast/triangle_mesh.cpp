// Raycast against a triangle mesh (spec "Raycasts against Triangle Meshes"). The ray is taken into mesh space,
// x_mesh = S^-1 R^T (x_world - p), keeping its parameter: o' + t d' maps to o + t dir, so t is the world distance
// even under non-uniform scale. The 8-wide BVH (bvh/traverse.h) is walked front to back with the closest distance found so
// far as early-out; at a leaf the exact watertight test (mesh/triangle.h) runs in T on its (up to) 4 triangles at once
// (bvh/triangle_exact4.h, read from the mesh's triangle vertex copies), the scalar test only on lanes it cannot decide.
// Modes: closest hit (default), any hit (AnyHit, maxHits 1), or up to maxHits hits (MeshMultiple): we keep the
// maxHits closest hits and return them sorted by distance.
#include <algorithm>
#include <atomic>

#include <type_traits>

#include "bvh/traverse.h"
#include "bvh/triangle_exact4.h"
#include "mesh/mesh_instance.h"
#include "mesh/triangle.h"
#include "common/unit_vector.h"
#include "prepared/shape_ref.h"
#include "raycast/raycast.h"

namespace gq::detail {
namespace {

#ifdef GQ_SSE42
// The unit normal of the float triangle hit: (v1 - v0) x (v2 - v0) as Eigen's cross()
// computes each lane (a.y b.z - a.z b.y ...), divided by sqrt(x^2 + (y^2 + z^2)) as tryUnit does (the order of
// Eigen's squaredNorm on a 3-vector). False (unit unwritten) where tryUnit would rescale: a squared length outside
// the normal float range.
[[gnu::always_inline]] inline bool unitTriangleNormal(const MeshTriangleHit<float>& found, __m128& unit) {
  const float* x = found.values;
  const std::uint32_t stride = found.stride;
  // Vertex k's x, y, z in lanes 0-2 (lane 3 unused): p[0], p[stride], p[2 stride] each in its lane of a 4-lane load
  // (from p, p + stride - 1, p + 2 stride - 2: within the leaf's rows and the padding after the last leaf).
  auto vertex = [&](std::uint32_t k) __attribute__((always_inline)) {
    const float* p = x + 3 * k * stride;
    const __m128 xy = _mm_blend_ps(_mm_loadu_ps(p), _mm_loadu_ps(p + stride - 1), 2);
    return _mm_blend_ps(xy, _mm_loadu_ps(p + 2 * stride - 2), 4);
  };
  const __m128 v0 = vertex(0);
  const __m128 a = _mm_sub_ps(vertex(1), v0), b = _mm_sub_ps(vertex(2), v0);
  const __m128 aYzx = _mm_shuffle_ps(a, a, _MM_SHUFFLE(3, 0, 2, 1)), aZxy = _mm_shuffle_ps(a, a, _MM_SHUFFLE(3, 1, 0, 2));
  const __m128 bYzx = _mm_shuffle_ps(b, b, _MM_SHUFFLE(3, 0, 2, 1)), bZxy = _mm_shuffle_ps(b, b, _MM_SHUFFLE(3, 1, 0, 2));
  const __m128 n = _mm_sub_ps(_mm_mul_ps(aYzx, bZxy), _mm_mul_ps(aZxy, bYzx));
  const __m128 sq = _mm_mul_ps(n, n);
  const float len2 = _mm_cvtss_f32(_mm_add_ss(sq, _mm_add_ss(_mm_movehdup_ps(sq), _mm_movehl_ps(sq, sq))));
  if (!(len2 >= std::numeric_limits<float>::min() && len2 <= std::numeric_limits<float>::max())) return false;
  unit = _mm_div_ps(n, _mm_set1_ps(std::sqrt(len2)));
  return true;
}
#endif

template <class T> class MeshRaycaster {
 public:
  // Inlined into its callers (the single cast and a batch's), so the ray constants stay in registers.
  [[gnu::always_inline]] MeshRaycaster(const TriangleMesh<T>& mesh, const Vec3<T>& org, const Vec3<T>& dir,
                                       bool cullBackFaces)
      : mesh_(mesh), ray4_(makeRay4(org, dir)), bvhRay_(makeBvhRay<8>(org, dir)), cull_(cullBackFaces) {}

#ifdef GQ_SSE42
  // A float ray given as lanes (x, y, z in lanes 0-2, lane 3 0).
  [[gnu::always_inline]] MeshRaycaster(const TriangleMesh<T>& mesh, __m128 org, __m128 dir, bool cullBackFaces)
      : mesh_(mesh), ray4_(makeWatertightRay4Sse(org, dir)), bvhRay_(makeBvhRayLanes<8>(org, dir)),
        cull_(cullBackFaces) {}
#endif

  // The caster of origin + t dir on a mesh whose pose is the translation p alone (mesh space: origin - p); a float
  // ray goes to the constants in SSE lanes.
  [[gnu::always_inline]] static MeshRaycaster translated(const TriangleMesh<T>& mesh, const Vec3<T>& origin,
                                                         const Vec3<T>& p, const Vec3<T>& dir, bool cullBackFaces) {
#ifdef GQ_SSE42
    if constexpr (kFloat)
      return MeshRaycaster(mesh, _mm_sub_ps(floatLanes(origin), floatLanes(p)), floatLanes(dir), cullBackFaces);
    else
#endif
      return MeshRaycaster(mesh, Vec3<T>(origin - p), dir, cullBackFaces);
  }

  // The watertight constants (in SSE registers for float: the same bits).
  [[gnu::always_inline]] static WatertightRay4<T> makeRay4(const Vec3<T>& org, const Vec3<T>& dir) {
#ifdef GQ_SSE42
    if constexpr (kFloat) return makeWatertightRay4Sse(floatLanes(org), floatLanes(dir));
#endif
    return makeWatertightRay4(makeWatertightRay(org, dir));
  }

  // Out of line: it runs only on the lanes the wide test cannot decide (an exactly zero edge function, a non-finite
  // hit); inlined into the walk, its registers were paid at every leaf (any hit about 10 instructions a ray fewer).
  [[gnu::noinline]] bool testTriangle(std::uint32_t cooked, T maxT, TriangleRayHit<T>& hit) const {
    // Coordinates near the scalar's limit (|x| ~ 1e307) overflow the watertight test's products: its NaN t would
    // pass the t <= maxT test, so a hit must also be finite.
    return intersectRayTriangle(ray4_.ray, mesh_.triangleVertex(cooked, 0), mesh_.triangleVertex(cooked, 1),
                                mesh_.triangleVertex(cooked, 2), maxT, cull_, hit) &&
           std::isfinite(hit.t) &&
           std::isfinite(hit.u) && std::isfinite(hit.v);
  }

  // The leaf's triangles (cooked first + i) that the exact test may accept within maxT, as a bit mask over i, tested
  // 4 wide; the lanes it decides come with their hit in `hits` (hits.decided), bit-identical to the scalar test's, so
  // only the other candidates need testTriangle.
  // kAvx2: called from the AVX2 walk (double lanes 4 to a register).
  template <bool kAvx2> int candidates(const LeafRows<T>& rows, T maxT, TriangleHits4<T>& hits) const {
    return exactTriangleHits<T, kAvx2>(rows, ray4_, maxT, cull_, hits) & ((1 << rows.stride) - 1);
  }
  bool slabsMayGiveNaN() const { return bvhRay_.mayGiveNaN != 0; }
  LeafRows<T> leafRows(std::uint32_t leafRef) const {
    return {mesh_.leafValues(MeshBvhNode::leafFirst(leafRef)), MeshBvhNode::leafCount(leafRef)};
  }

  static std::uint32_t inputIndexOf(const MeshTriangleHit<T>& h) {
    return TriangleMesh<T>::inputIndexIn(h.values, h.stride);
  }

  // The hit of candidate lane `lane` (triangle `cooked`) within maxT: taken from the wide test when it decided the
  // lane, else from the scalar test.
  bool laneHit(const TriangleHits4<T>& hits, int lane, std::uint32_t cooked, T maxT, TriangleRayHit<T>& h) const {
    if ((hits.decided >> lane) & 1) {
      h.t = hits.t[lane];
      h.u = hits.u[lane];
      h.v = hits.v[lane];
      h.frontFace = ((hits.frontMask >> lane) & 1) != 0;
      return true;
    }
    return testTriangle(cooked, maxT, h);
  }

  // The leaf's triangles the watertight test hits at a distance up to about b, in lane order: fn(MeshTriangleHit) for
  // each until it returns true (then true). The tests compare t scaled by their determinant, which rounds either way of
  // a hit at the bound itself, so they get a bound a few units above b, and callers compare the hits' own distances
  // with b: the answers then do not depend on the order the leaves come in.
  template <bool kAvx2, class Fn> bool forEachHitNear(std::uint32_t ref, T b, Fn&& fn) const {
    const T bound = b * (T(1) + T(8) * std::numeric_limits<T>::epsilon()) + std::numeric_limits<T>::min();
    const LeafRows<T> rows = leafRows(ref);
    TriangleHits4<T> laneHits;
    for (int mask = candidates<kAvx2>(rows, bound, laneHits); mask; mask &= mask - 1) {
      const int lane = __builtin_ctz(unsigned(mask));
      MeshTriangleHit<T> h{MeshBvhNode::leafFirst(ref) + std::uint32_t(lane), rows.stride, rows.rows + lane, {}};
      if (laneHit(laneHits, lane, h.cooked, bound, h.tri) && fn(h)) return true;
    }
    return false;
  }

  // Closest hit within maxDist: leaves nearest first, each hit lowering the walk's bound. The hit is the least
  // distance, then the least input index (shared edges), over the triangles hit at t <= maxDist, whatever order the
  // leaves come in.
  template <class Lanes> bool closest(T maxDist, MeshTriangleHit<T>& best) const {
    T bestT = maxDist;
    float tMax = floatCeil(maxDist);
    bool found = false;
    walkRayLeaves<true, !kFloat, Lanes>(mesh_.accel->bvh, bvhRay_, tMax, [&](std::uint32_t ref) {
      bool lowered = false;
      forEachHitNear<Lanes::kAvx2>(ref, bestT, [&](const MeshTriangleHit<T>& h) {
        const T t = h.tri.t;
        const bool before =
            found ? t < bestT || (t == bestT && inputIndexOf(h) < inputIndexOf(best))
                  : t <= maxDist;
        if (before) {
          best = h;
          bestT = t;
          found = true;
          lowered = true;
        }
        return false;
      });
      if (lowered) tMax = floatCeil(bestT);
      return false;
    });
    return found;
  }

  // The first hit found within maxDist (any hit): the walk stops there. Children are pushed in lane order, unsorted
  // (lanes hold them largest surface area first): with 8-wide nodes this was measured cheaper per ray than
  // nearest-first on the shared meshes' rays.
  template <class Lanes> bool any(T maxDist, MeshTriangleHit<T>& best) const {
    float tMax = floatCeil(maxDist);
    bool found = false;
    walkRayLeaves<false, !kFloat, Lanes>(mesh_.accel->bvh, bvhRay_, tMax, [&](std::uint32_t ref) {
      return forEachHitNear<Lanes::kAvx2>(ref, maxDist, [&](const MeshTriangleHit<T>& h) {
        if (!(h.tri.t <= maxDist)) return false;
        best = h;
        found = true;
        return true;
      });
    });
    return found;
  }

  // Up to `cap` closest hits within maxDist, sorted by distance.
  template <class Lanes>
  std::uint32_t multiple(T maxDist, std::uint32_t cap, std::vector<MeshTriangleHit<T>>& hits) const {
    // A max-heap on t.
    auto farther = [](const MeshTriangleHit<T>& a, const MeshTriangleHit<T>& b) { return a.tri.t < b.tri.t; };
    T limit = maxDist;
    float tMax = floatCeil(maxDist);
    walkRayLeaves<true, !kFloat, Lanes>(mesh_.accel->bvh, bvhRay_, tMax, [&](std::uint32_t ref) {
      forEachHitNear<Lanes::kAvx2>(ref, limit, [&](const MeshTriangleHit<T>& h) {
        // Once full, only hits closer than the farthest kept one matter (limit is then its distance).
        const bool full = hits.size() == cap;
        if (!(h.tri.t <= maxDist) || (full && !(h.tri.t < limit))) return false;
        if (full) {
          std::pop_heap(hits.begin(), hits.end(), farther);
          hits.pop_back();
        }
        hits.push_back(h);
        std::push_heap(hits.begin(), hits.end(), farther);
        if (hits.size() == cap) {
          limit = hits.front().tri.t;
          tMax = floatCeil(limit);
        }
        return false;
      });
      return false;
    });
    std::sort_heap(hits.begin(), hits.end(), farther);
    return std::uint32_t(hits.size());
  }

 private:
  static constexpr bool kFloat = std::is_same_v<T, float>;
  const TriangleMesh<T>& mesh_;
  WatertightRay4<T> ray4_;  // with the scalar test's WatertightRay
  BvhRay<8> bvhRay_;
  bool cull_;
};

// The walks with the node test the CPU runs: 8 lanes in one AVX2 test, or two SSE4.2 halves (the same float
// operations, so both find the same hits); the AVX2 instantiations are compiled for AVX2 as a whole (flatten).
enum class MeshWalk { Avx2, Sse, Scalar };

std::atomic<bool> gBaselineOnly{false};
std::atomic<int> gWalk{-1};  // the MeshWalk in use, -1 until meshWalk() picks it

}  // namespace

void setMeshRaycastBaselineOnly(bool baselineOnly) {
  gBaselineOnly.store(baselineOnly);
#ifdef GQ_SSE42
  // The resolved choice, not -1: a walk picked concurrently from the old flag cannot overwrite it afterwards.
  gWalk.store(int(hasAvx2() && !baselineOnly ? MeshWalk::Avx2 : MeshWalk::Sse));
#endif
}

namespace {

MeshWalk meshWalk() {
#ifdef GQ_SSE42
  // One relaxed load per call: gWalk caches the choice (-1 until first asked, reset by setMeshRaycastBaselineOnly).
  int w = gWalk.load(std::memory_order_relaxed);
  if (w < 0) [[unlikely]] {
    w = int(hasAvx2() && !gBaselineOnly.load(std::memory_order_relaxed) ? MeshWalk::Avx2 : MeshWalk::Sse);
    gWalk.store(w, std::memory_order_relaxed);
  }
  return MeshWalk(w);
#else
  return MeshWalk::Scalar;
#endif
}

// The three walks as types, for withLanes: Walk::run<Lanes>(caster, args...) calls one of MeshRaycaster's walks.
struct ClosestWalk {
  template <class Lanes, class T> static bool run(const MeshRaycaster<T>& c, T maxDist, MeshTriangleHit<T>& best) {
    return c.template closest<Lanes>(maxDist, best);
  }
};
struct AnyWalk {
  template <class Lanes, class T> static bool run(const MeshRaycaster<T>& c, T maxDist, MeshTriangleHit<T>& best) {
    return c.template any<Lanes>(maxDist, best);
  }
};
struct MultipleWalk {
  template <class Lanes, class T>
  static std::uint32_t run(const MeshRaycaster<T>& c, T maxDist, std::uint32_t cap,
                           std::vector<MeshTriangleHit<T>>& hits) {
    return c.template multiple<Lanes>(maxDist, cap, hits);
  }
};

// Runs Walk with the node test the CPU runs. The AVX2 instantiation is compiled for AVX2 as a whole (flatten inlines
// the walk into it). (Arguments passed through, not captured by a lambda: the walk read the ray constants through the
// closure's pointers, measured 105 instructions more per bunny ray.)
#ifdef GQ_SSE42
// The node test's short form for the rays it serves (Bvh8LanesAvx2NaNFree), the NaN-first one for the others.
template <class Walk, class T, class... Args>
__attribute__((target("avx2"), flatten)) auto withAvx2Lanes(const MeshRaycaster<T>& caster, Args&&... args) {
  if (caster.slabsMayGiveNaN()) return Walk::template run<Bvh8LanesAvx2>(caster, args...);
  return Walk::template run<Bvh8LanesAvx2NaNFree>(caster, args...);
}
#endif
// The baseline walk out of line too: inlined into the caller, its registers and stack frame would be paid by every ray.
template <class Walk, class... Args> [[gnu::noinline]] auto withBaselineLanes(Args&&... args) {
  return Walk::template run<Bvh8LanesBaseline>(args...);
}
template <class Walk, class... Args> auto withLanes(MeshWalk w, Args&&... args) {
#ifdef GQ_SSE42
  if (w == MeshWalk::Avx2) return withAvx2Lanes<Walk>(args...);
#endif
  (void)w;
  return withBaselineLanes<Walk>(args...);
}

// Single-sided meshes cull back faces unless the ray asks for both sides.
template <class T>
[[gnu::always_inline]] inline bool cullsBackFaces(const TriangleMeshGeometry<T>& g, HitFlags flags) {
  return !(g.doubleSided() || flags.has(HitFlag::MeshBothSides));
}

// The one-hit walk the flags ask for (any hit or closest hit): true when `best` was found.
template <class T>
[[gnu::always_inline]] inline bool walkOneHit(MeshWalk walk, const MeshRaycaster<T>& caster, T maxDist,
                                              HitFlags flags, MeshTriangleHit<T>& best) {
  return flags.has(HitFlag::AnyHit) ? withLanes<AnyWalk>(walk, caster, maxDist, best)
                                    : withLanes<ClosestWalk>(walk, caster, maxDist, best);
}

}  // namespace

// Mesh space of the instance: S^-1 and the mirror flag. The identity scale (the common case) skips the matrix
// products; an identity pose rotation (a mesh placed in the world as cooked, the common case for static meshes) skips
// the quaternion products, whose result would be the same vectors.
template <class T>
[[gnu::always_inline]] inline TriangleMeshRays<T>::TriangleMeshRays(const TriangleMeshGeometry<T>& g,
                                                                    const Transform<T>& pose, bool scaled)
    : g_(g), pose_(pose), scaled_(scaled), rotated_(!isIdentityRotation(pose.q)), flips_(false),
      walk_(int(meshWalk())) {
  if (!scaled_) return;
  flips_ = g.scale.flipsWinding();
  invScaleDiagonal_ = g.scale.scale.cwiseInverse();
  // An axis-aligned scale (identity scale rotation, the common case) keeps S^-1 diagonal: no rotation matrix, and
  // three products per vector instead of a matrix product.
  const Quat<T>& q = g.scale.rotation;
  diagonal_ = q.w() == T(1) && q.x() == T(0) && q.y() == T(0) && q.z() == T(0);
  if (diagonal_) return;
  // MeshInstance's S^-1 = R diag(1/scale) R^T, without its S (rays need only the inverse).
  const Mat3<T> r = q.toRotationMatrix();
  invScale_ = r * invScaleDiagonal_.asDiagonal() * r.transpose();
}

// The world normal of the triangle hit (mesh space): S^-1 n_mesh rotated by the pose, with
// S^-1 = S^-T; under a mirrored scale the 1<->2 swap cancels the mirror, so it is outward either way. Double-sided
// meshes report the side the ray hit. A float mesh with an identity scale and pose rotation (the common case) takes
// it 4 lanes wide: Eigen's cross product and tryUnit's d / sqrt(|d|^2) as the same IEEE operations.
template <class T>
template <bool kCooked>
[[gnu::always_inline]] inline void TriangleMeshRays<T>::writeNormalIn(const TriangleMeshRays* frame,
                                                                      const TriangleMeshGeometry<T>& g,
                                                                      const MeshTriangleHit<T>& found,
                                                                      const Vec3<T>& rayDir, Vec3<T>& normal) {
  const bool flip = g.doubleSided() && !found.tri.frontFace;
  const bool scaled = !kCooked && frame->scaled_, rotated = !kCooked && frame->rotated_;
#ifdef GQ_SSE42
  if constexpr (std::is_same_v<T, float>) {
    __m128 unit;
    if (!scaled && !rotated && unitTriangleNormal(found, unit)) {
      if (flip) unit = _mm_xor_ps(unit, _mm_set1_ps(-0.0f));
      _mm_storel_pi(reinterpret_cast<__m64*>(normal.data()), unit);
      _mm_store_ss(normal.data() + 2, _mm_movehl_ps(unit, unit));
      return;
    }
  }
#endif
  // (v1 - v0) x (v2 - v0) in scalars, as Eigen's cross() computes each component (a.y b.z - a.z b.y ...), so the
  // vectors stay in registers; for float with SSE this is reached only when the SSE path above does not apply or its
  // range test failed (which the identity frame's test below then fails too).
  using Mesh = TriangleMesh<T>;
  const Vec3<T> v0 = Mesh::vertexIn(found.values, found.stride, 0);
  const Vec3<T> v1 = Mesh::vertexIn(found.values, found.stride, 1), v2 = Mesh::vertexIn(found.values, found.stride, 2);
  const T ax = v1.x() - v0.x(), ay = v1.y() - v0.y(), az = v1.z() - v0.z();
  const T bx = v2.x() - v0.x(), by = v2.y() - v0.y(), bz = v2.z() - v0.z();
  Vec3<T> n(ay * bz - az * by, az * bx - ax * bz, ax * by - ay * bx);
  if (scaled) n = frame->toMesh(n);  // S^-1 = S^-T is also the normal transform
  if (rotated) n = frame->pose_.rotate(n);
  // tryUnit's common case inline (n / sqrt(|n|^2), Eigen's order of the squared norm); unitOr for the others.
  const T len2 = n.squaredNorm();
  if (len2 >= std::numeric_limits<T>::min() && len2 <= std::numeric_limits<T>::max()) {
    const T len = flip ? -std::sqrt(len2) : std::sqrt(len2);
    normal = Vec3<T>(n.x() / len, n.y() / len, n.z() / len);
    return;
  }
  n = unitOr(n, Vec3<T>(-rayDir));
  normal = flip ? Vec3<T>(-n) : n;
}

// The requested fields of one hit, written in place, in the instance frame `frame`, or (kCooked, frame unused) for
// an unscaled mesh placed as cooked. A MeshRayHit has no position: it keeps the flag when asked.
template <class T>
template <bool kCooked, class Hit>
[[gnu::always_inline]] inline void TriangleMeshRays<T>::writeHitIn(const TriangleMeshRays* frame,
                                                                    const TriangleMeshGeometry<T>& g,
                                                                    const Vec3<T>& origin, const Vec3<T>& dir,
                                                                    HitFlags asked, const MeshTriangleHit<T>& found,
                                                                    Hit& hit) {
  // Every field written once: the requested ones, RaycastHit's defaults for the others. origin and dir may be this
  // hit's position and normal (a ray marched from its last hit): the position is computed before the normal is
  // written, the normal (which reads dir only before writing) before the position.
  const TriangleRayHit<T>& tri = found.tri;
  HitFlags flags = HitFlag::FaceIndex;
  Vec3<T> position = Vec3<T>::Zero();
  if (asked.has(HitFlag::Position)) {
    if constexpr (std::is_same_v<Hit, RaycastHit<T>>) position = origin + dir * tri.t;
    flags |= HitFlag::Position;
  }
  if (asked.has(HitFlag::Normal)) {
    writeNormalIn<kCooked>(frame, g, found, dir, hit.normal);
    flags |= HitFlag::Normal;
  } else {
    hit.normal = Vec3<T>::Zero();
  }
  if constexpr (std::is_same_v<Hit, RaycastHit<T>>) hit.position = position;
  hit.distance = tri.t;
  hit.faceIndex = TriangleMesh<T>::inputIndexIn(found.values, found.stride);  // from the rows the hit was tested on
  hit.u = T(0);
  hit.v = T(0);
  if (asked.has(HitFlag::UV)) {
    const bool flips = !kCooked && frame->flips_;
    hit.u = flips ? tri.v : tri.u;
    hit.v = flips ? tri.u : tri.v;
    flags |= HitFlag::UV;
  }
  hit.flags = flags;
}

// cast() into hits of type Hit (RaycastHit, or MeshRayHit for one hit).
template <class T>
template <class Hit>
[[gnu::always_inline]] inline std::uint32_t TriangleMeshRays<T>::castInto(const RayQuery<T>& ray, Hit* hits) const {
  if (!(ray.maxDist > T(0))) return 0;  // a zero-length ray never hits a mesh
  // The ray in mesh space (one branch per frame step, the identity ones skipped).
  Vec3<T> org = ray.origin - pose_.p, dir = ray.dir;
  if (rotated_) {
    org = pose_.rotateInv(org);
    dir = pose_.rotateInv(dir);
  }
  if (scaled_) {
    org = toMesh(org);
    dir = toMesh(dir);
  }
  const bool cull = cullsBackFaces(g_, ray.flags);
  const MeshRaycaster<T> caster(*g_.mesh, org, dir, cull);
  const MeshWalk walk = MeshWalk(walk_);
  if (std::is_same_v<Hit, RaycastHit<T>> && ray.maxHits > 1) {
    // Kept per thread (a mesh raycast runs no user code): no allocation once it holds the most hits a call kept.
    thread_local std::vector<MeshTriangleHit<T>> raw;
    raw.clear();
    const std::uint32_t n = withLanes<MultipleWalk>(walk, caster, ray.maxDist, ray.maxHits, raw);
    for (std::uint32_t i = 0; i < n; ++i)
      writeHitIn<false>(this, g_, ray.origin, ray.dir, ray.flags, raw[i], hits[i]);
    return n;
  }
  MeshTriangleHit<T> best;
  if (!walkOneHit(walk, caster, ray.maxDist, ray.flags, best)) return 0;
  writeHitIn<false>(this, g_, ray.origin, ray.dir, ray.flags, best, hits[0]);
  return 1;
}

template <class T>
[[gnu::always_inline]] inline std::uint32_t TriangleMeshRays<T>::cast(const RayQuery<T>& ray,
                                                                      RaycastHit<T>* hits) const {
  return castInto(ray, hits);
}

template <class T>
std::uint32_t TriangleMeshRays<T>::castOne(const RayQuery<T>& ray, MeshRayHit<T>& hit) const {
  const std::uint32_t n = castInto(ray, &hit);
  if (n == 0) hit.flags = HitFlags();
  return n;
}

template <class T>
std::uint32_t TriangleMeshRays<T>::castOneCooked(const TriangleMeshGeometry<T>& g, const Transform<T>& pose,
                                                 const Vec3<T>& origin, const Vec3<T>& dir, T maxDist,
                                                 HitFlags flags, RaycastHit<T>& hit) {
  const T maxD = finiteMaxDist(maxDist);
  if (!(maxD > T(0))) return 0;  // a zero-length ray never hits a mesh
  MeshTriangleHit<T> best;
  const MeshRaycaster<T> caster =
      MeshRaycaster<T>::translated(*g.mesh, origin, pose.p, dir, cullsBackFaces(g, flags));
  if (!walkOneHit(meshWalk(), caster, maxD, flags, best)) return 0;
  writeHitIn<true>(nullptr, g, origin, dir, flags, best, hit);  // origin, dir may alias hit
  return 1;
}

template class TriangleMeshRays<float>;
template class TriangleMeshRays<double>;

template <class T>
std::uint32_t raycastTriangleMesh(const TriangleMeshGeometry<T>& g, const Transform<T>& pose, const RayQuery<T>& ray,
                                  RaycastHit<T>* hits) {
  return TriangleMeshRays<T>(g, pose).cast(ray, hits);
}

namespace {
// raycastMeshShape's cast in the instance frame (a scaled or rotated mesh, or several hits), out of line: its frame
// and registers are not paid by the one-hit casts on meshes placed as cooked.
template <class T>
[[gnu::noinline]] Status castInInstanceFrame(const Vec3<T>& origin, const Vec3<T>& unitDir, const Shape<T>& shape,
                                             const Transform<T>& pose, T maxDist, HitFlags hitFlags,
                                             std::uint32_t maxHits, RaycastHit<T>* hits,
                                             std::uint32_t& hitCount) noexcept {
  // Keeping several hits may allocate (the first time a thread keeps that many): guarded.
  return guarded([&]() __attribute__((always_inline)) -> Status {
    const RayQuery<T> ray = rayQuery(origin, unitDir, maxDist, hitFlags, maxHits);
    const TriangleMeshRays<T> rays(shape.geometry().template get<TriangleMeshGeometry<T>>(), pose,
                                   !ShapeAccess<T>::rayMeshUnscaled(shape));
    hitCount = rays.cast(ray, hits);
    return Status();
  });
}
}  // namespace

template <class T>
Status raycastMeshShape(const Vec3<T>& origin, const Vec3<T>& unitDir, const Shape<T>& shape,
                        const Transform<T>& pose, T maxDist, HitFlags hitFlags, std::uint32_t maxHits,
                        RaycastHit<T>* hits, std::uint32_t& hitCount) noexcept {
  if (!(rayIsValid(origin, unitDir, pose.p) & raySettingsAreValid(pose, maxDist, hitFlags, maxHits, hits)))
    return raycastShapeChecked(origin, unitDir, shape, pose, maxDist, hitFlags, maxHits, hits, hitCount);
  // One hit on an unscaled mesh placed as cooked (the common case): no instance frame, no query object.
  if (ShapeAccess<T>::rayMeshUnscaled(shape) && isIdentityRotation(pose.q) &&
      !(hitFlags.has(HitFlag::MeshMultiple) && maxHits > 1)) {
    hitCount = TriangleMeshRays<T>::castOneCooked(shape.geometry().template get<TriangleMeshGeometry<T>>(), pose,
                                                  origin, unitDir, maxDist, hitFlags, hits[0]);
    return Status();
  }
  return castInInstanceFrame(origin, unitDir, shape, pose, maxDist, hitFlags, maxHits, hits, hitCount);
}

template Status raycastMeshShape<float>(const Vec3<float>&, const Vec3<float>&, const Shape<float>&,
                                        const Transform<float>&, float, HitFlags, std::uint32_t, RaycastHit<float>*,
                                        std::uint32_t&) noexcept;
template Status raycastMeshShape<double>(const Vec3<double>&, const Vec3<double>&, const Shape<double>&,
                                         const Transform<double>&, double, HitFlags, std::uint32_t,
                                         RaycastHit<double>*, std::uint32_t&) noexcept;

template std::uint32_t raycastTriangleMesh<float>(const TriangleMeshGeometry<float>&, const Transform<float>&,
                                                  const RayQuery<float>&, RaycastHit<float>*);
template std::uint32_t raycastTriangleMesh<double>(const TriangleMeshGeometry<double>&, const Transform<double>&,
                                                   const RayQuery<double>&, RaycastHit<double>*);

}  // namespace gq::detail
