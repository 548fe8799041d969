// libFuzzer target: the mesh queries (getTriangle, findOverlapTriangleMesh/HeightField with paging,
// findOverlapTriangleMeshPairs, generateMeshContacts, computeTriangleMeshPenetration/HeightFieldPenetration,
// sweepTriangles, generateTriangleContacts) on fuzzed meshes, heightfields, shapes and parameters. Contract: ok ->
// finite outputs and indices in range; error -> outputs untouched.
#include "fuzz_decode.h"

namespace {

template <class T> void run(gq::fuzz::Bytes& in) {
  using namespace gq;
  const Geometry<T> shape = fuzz::geometry<T>(in);
  const Transform<T> pose = in.pose<T>();
  const auto meshData = fuzz::mesh<T>(in);
  const MeshScale<T> meshScale = fuzz::meshScale<T>(in);
  const TriangleMeshGeometry<T> mesh(meshData, meshScale,
                                     in.flag() ? MeshGeometryFlag::DoubleSided : MeshGeometryFlag::None);
  const Transform<T> meshPose = in.pose<T>();
  // Every decoding step is its own statement: argument evaluation order differs between compilers, and a crash
  // input must decode the same in a gcc debug build.
  const auto hfData = fuzz::heightField<T>(in);
  const T hs = in.scalar<T>(), rs = in.scalar<T>(), cs = in.scalar<T>();
  const HeightFieldGeometry<T> hf(hfData, hs, rs, cs);
  const std::uint32_t meshTriangles = mesh.mesh->inputTriangleCount();
  {
    std::uint32_t results[8];
    const TriangleOverlapPage page{results, 8u, std::uint32_t(in.small(6))};
    TriangleOverlapPageResult received;
    received.count = 999;
    Status s = findOverlapTriangleMesh(shape, pose, mesh, meshPose, page, received);
    if (!s.ok()) fuzz::require(received.count == 999);
    for (std::uint32_t i = 0; s.ok() && i < received.count; ++i) fuzz::require(results[i] < meshTriangles);
    received.count = 999;
    s = findOverlapHeightField(shape, pose, hf, meshPose, page, received);
    if (!s.ok()) fuzz::require(received.count == 999);
  }
  {
    PenetrationResult<T> r;
    r.depth = T(-7);
    const std::uint32_t maxIter = std::uint32_t(in.small(6));
    Status s = computeTriangleMeshPenetration(r, shape, pose, mesh, meshPose, maxIter);
    if (!s.ok()) fuzz::require(r.depth == T(-7));
    else fuzz::require(isFinite(r.direction) && std::isfinite(r.depth));
    r.depth = T(-7);
    s = computeHeightFieldPenetration(r, shape, pose, hf, meshPose, maxIter);
    if (!s.ok()) fuzz::require(r.depth == T(-7));
    else fuzz::require(isFinite(r.direction) && std::isfinite(r.depth));
  }
  Triangle<T> tris[4];
  std::uint32_t triCount = 0;
  for (std::uint32_t k = 0; k < 4; ++k) {
    Triangle<T> t;
    t.verts[0].x() = T(-7);
    const std::uint32_t index = std::uint32_t(in.small(16));
    const Status s = (k & 1) ? getTriangle(hf, meshPose, index, t) : getTriangle(mesh, meshPose, index, t);
    if (!s.ok()) fuzz::require(t.verts[0].x() == T(-7));
    else tris[triCount++] = t;
  }
  if (in.flag() && triCount > 0) tris[0].verts[in.small(3)] = in.vec<T>();  // raw vertices too
  {
    SweepHit<T> hit;
    hit.distance = T(-7777);
    bool hasHit = true;
    const std::uint32_t cached = std::uint32_t(in.small(6));
    const Vec3<T> dir = in.direction<T>();
    const T maxDist = in.scalar<T>();
    const HitFlags flags = fuzz::hitFlags(in);
    const std::uint32_t* cachedIndex = in.flag() ? &cached : nullptr;
    const T inflation = in.flag() ? in.scalar<T>() : T(0);
    const bool doubleSided = in.flag();
    const Status s = sweepTriangles<T>(dir, maxDist, shape, pose, tris, triCount, hit, hasHit,
                                       TriangleSweepSettings<T>{flags, cachedIndex, inflation, doubleSided});
    if (!s.ok()) fuzz::require(hasHit && hit.distance == T(-7777));
    else if (hasHit)
      fuzz::require(isFinite(hit.position) && isFinite(hit.normal) && std::isfinite(hit.distance) &&
                    (!hit.flags.has(HitFlag::FaceIndex) || hit.faceIndex < triCount));
  }
  if (triCount > 0) {
    ContactBuffer<T> contacts;
    contacts.count = 999;
    const T contactDistance = in.scalar<T>(), margin = in.scalar<T>(), length = in.scalar<T>();
    const Status s = generateTriangleContacts(shape, pose, tris[0], 3u, contacts,
                                              TriangleContactSettings<T>{contactDistance, margin, length});
    if (!s.ok()) fuzz::require(contacts.count == 999);
    for (std::uint32_t i = 0; s.ok() && i < contacts.count; ++i)
      fuzz::require(isFinite(contacts.contacts[i].position) && isFinite(contacts.contacts[i].normal) &&
                    std::isfinite(contacts.contacts[i].separation));
  }
  {
    bool found = true;
    std::uint32_t pairs = 0;
    const auto otherMesh = fuzz::mesh<T>(in);
    const TriangleMeshGeometry<T> other(otherMesh, fuzz::meshScale<T>(in));
    const std::uint32_t otherTriangles = other.mesh->inputTriangleCount();
    const Transform<T> otherPose = in.pose<T>();
    const T tolerance = in.flag() ? in.scalar<T>() : T(0);
    const Status s = findOverlapTriangleMeshPairs<T>(
        [&](std::uint32_t a, std::uint32_t b) {
          fuzz::require(a < meshTriangles && b < otherTriangles);
          return ++pairs < 64;
        },
        mesh, meshPose, other, otherPose, found, tolerance);
    if (!s.ok()) fuzz::require(found && pairs == 0);
    bool contactFound = true;
    std::uint32_t contacts = 0;
    const Status c = generateMeshContacts<T>(
        [&](const MeshContact<T>& m) {
          fuzz::require(m.triangle0 < meshTriangles && m.triangle1 < otherTriangles && isFinite(m.position) &&
                        isFinite(m.normal) && std::isfinite(m.depth) && m.depth >= T(0));
          return ++contacts < 64;
        },
        Geometry<T>(mesh), meshPose, Geometry<T>(other), otherPose, contactFound);
    if (!c.ok()) fuzz::require(contactFound && contacts == 0);
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  gq::fuzz::Bytes in(data, size);
  if (in.flag()) run<float>(in);
  else run<double>(in);
  return 0;
}
