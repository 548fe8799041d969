#include "embree_backend.h"

#include <cmath>
#include <limits>
#include <map>

#include <embree3/rtcore.h>

#include "gq/hit.h"
#include "native_shapes.h"
#include "timing.h"

namespace gq::cases {
namespace {

// One committed scene holding one mesh (scale applied), with the vertices kept for normals and culling.
struct EmbreeMesh {
  RTCScene scene = nullptr;
  std::vector<Vec3d> vertices;
  std::vector<std::array<std::uint32_t, 3>> triangles;
  ~EmbreeMesh() {
    if (scene) rtcReleaseScene(scene);
  }
  Vec3d faceNormal(std::uint32_t prim) const {
    const auto& t = triangles[prim];
    return (vertices[t[1]] - vertices[t[0]]).cross(vertices[t[2]] - vertices[t[0]]);
  }
};

// The intersect context the filter functions receive: RTCIntersectContext must be the first member.
struct RayContext {
  RTCIntersectContext base;
  const EmbreeMesh* mesh = nullptr;
  Vec3d localDir = Vec3d::UnitX();
  bool cullBackFaces = true;
  // The last accepted hit (rtcOccluded1 reports no hit data, so the filter records it).
  bool hit = false;
  float t = 0, u = 0, v = 0;
  std::uint32_t prim = 0;
};

// Rejects back faces of single-sided meshes and records every accepted hit. Embree sets the ray's tfar to the
// candidate's distance before calling the filter.
void filterHit(const RTCFilterFunctionNArguments* args) {
  auto* ctx = reinterpret_cast<RayContext*>(args->context);
  const std::uint32_t prim = RTCHitN_primID(args->hit, args->N, 0);
  if (ctx->cullBackFaces && ctx->mesh->faceNormal(prim).dot(ctx->localDir) > 0) {
    args->valid[0] = 0;
    return;
  }
  ctx->hit = true;
  ctx->t = RTCRayN_tfar(args->ray, args->N, 0);
  ctx->u = RTCHitN_u(args->hit, args->N, 0);
  ctx->v = RTCHitN_v(args->hit, args->N, 0);
  ctx->prim = prim;
}

RTCRayHit makeRay(const Vec3d& origin, const Vec3d& dir, double maxDist) {
  RTCRayHit rh{};
  rh.ray.org_x = float(origin.x());
  rh.ray.org_y = float(origin.y());
  rh.ray.org_z = float(origin.z());
  rh.ray.dir_x = float(dir.x());
  rh.ray.dir_y = float(dir.y());
  rh.ray.dir_z = float(dir.z());
  rh.ray.tnear = 0.0f;
  rh.ray.tfar = float(std::min(maxDist, double(std::numeric_limits<float>::max())));
  rh.ray.mask = 0xffffffffu;
  rh.ray.flags = 0;
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  return rh;
}

}  // namespace

struct EmbreeBackend::Impl {
  RTCDevice device = rtcNewDevice("threads=1");
  std::map<std::string, std::unique_ptr<EmbreeMesh>> meshes;
  ~Impl() {
    meshes.clear();
    if (device) rtcReleaseDevice(device);
  }

  const EmbreeMesh& mesh(const ShapeDesc& d) {
    const std::string key = native::scaledKey(d);
    if (auto it = meshes.find(key); it != meshes.end()) return *it->second;
    auto m = std::make_unique<EmbreeMesh>();
    m->vertices = native::scaledPoints(d);
    m->triangles = native::scaledTriangles(d);
    m->scene = rtcNewScene(device);
    RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    // One padding float: Embree reads vertex buffers with 16-byte loads.
    auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                          3 * sizeof(float), m->vertices.size() + 1));
    for (std::size_t i = 0; i < m->vertices.size(); ++i)
      for (int k = 0; k < 3; ++k) v[3 * i + k] = float(m->vertices[i][k]);
    auto* idx = static_cast<unsigned*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                               3 * sizeof(unsigned), m->triangles.size()));
    for (std::size_t i = 0; i < m->triangles.size(); ++i)
      for (int k = 0; k < 3; ++k) idx[3 * i + k] = m->triangles[i][k];
    rtcSetGeometryIntersectFilterFunction(geom, filterHit);
    rtcSetGeometryOccludedFilterFunction(geom, filterHit);
    rtcCommitGeometry(geom);
    rtcAttachGeometry(m->scene, geom);
    rtcReleaseGeometry(geom);
    rtcCommitScene(m->scene);
    return *meshes.emplace(key, std::move(m)).first->second;
  }

  Result raycast(const RaycastCase& q, int repeat) {
    const HitFlags flags(q.flags);
    if (q.geom.kind != ShapeKind::Mesh)
      return native::unsupportedQuery("embree", QueryKind::Raycast, toString(q.geom.kind));
    if (flags.has(HitFlag::MeshMultiple)) return Result::failure("unsupported: embree backend reports one hit (meshMultiple)");
    if (q.maxHits == 0) return Result::failure("maxHits must be at least 1");
    const EmbreeMesh& m = mesh(q.geom);
    // The ray in the mesh frame (rigid pose: distances are unchanged).
    const Mat3<double> r = q.pose.q.toRotationMatrix();
    const Vec3d origin = r.transpose() * (q.origin - q.pose.p), dir = r.transpose() * q.dir;
    RayContext ctx;
    ctx.mesh = &m;
    ctx.localDir = dir;
    ctx.cullBackFaces = !q.geom.doubleSided && !flags.has(HitFlag::MeshBothSides);
    const bool anyHit = flags.has(HitFlag::AnyHit);
    const double ns = medianNanoseconds(repeat, [&] {
      rtcInitIntersectContext(&ctx.base);
      ctx.hit = false;
      RTCRayHit rh = makeRay(origin, dir, q.maxDist);
      if (anyHit) {
        rtcOccluded1(m.scene, &ctx.base, &rh.ray);
        return;
      }
      rtcIntersect1(m.scene, &ctx.base, &rh);
      // The filter saw candidates in traversal order; the committed hit is the closest.
      ctx.hit = rh.hit.geomID != RTC_INVALID_GEOMETRY_ID;
      ctx.t = rh.ray.tfar;
      ctx.u = rh.hit.u;
      ctx.v = rh.hit.v;
      ctx.prim = rh.hit.primID;
    });
    RaycastOut out;
    if (ctx.hit) {
      RayHitOut hit;
      hit.distance = double(ctx.t);
      if (flags.has(HitFlag::Position)) hit.position = q.origin + hit.distance * q.dir;
      if (flags.has(HitFlag::Normal)) {
        Vec3d n = native::unitOrZero(m.faceNormal(ctx.prim));
        if (n.dot(dir) > 0) n = -n;  // a back-side hit reports the face turned towards the ray
        hit.normal = r * n;
      }
      if (flags.has(HitFlag::UV)) hit.uv = std::array<double, 2>{double(ctx.u), double(ctx.v)};
      hit.faceIndex = ctx.prim;
      out.hits.push_back(hit);
    }
    Result res;
    res.ok = true;
    res.ns = ns;
    res.fields = std::move(out);
    return res;
  }
};

EmbreeBackend::EmbreeBackend() : impl_(new Impl) {}
EmbreeBackend::~EmbreeBackend() = default;

Result EmbreeBackend::run(const Case& c, int repeat) {
  if (c.query != QueryKind::Raycast)
    return native::unsupportedQuery("embree", c.query, "any geometry (it answers raycasts against meshes)");
  if (!impl_->device) return Result::failure("embree: rtcNewDevice failed");
  return impl_->raycast(std::get<RaycastCase>(c.input), repeat);
}

}  // namespace gq::cases
