#include "libccd_backend.h"

#include <ccd/ccd.h>

#include "libccd_support.h"
#include "native_shapes.h"
#include "timing.h"

namespace gq::cases {
namespace {

using native::SupportShape;

Vec3d fromCcd(const ccd_vec3_t& v) { return Vec3d(v.v[0], v.v[1], v.v[2]); }

void ccdSupport(const void* obj, const ccd_vec3_t* dir, ccd_vec3_t* out) {
  const Vec3d s = static_cast<const SupportShape*>(obj)->support(fromCcd(*dir));
  ccdVec3Set(out, s.x(), s.y(), s.z());
}

void ccdCenter(const void* obj, ccd_vec3_t* out) {
  const Vec3d c = static_cast<const SupportShape*>(obj)->center();
  ccdVec3Set(out, c.x(), c.y(), c.z());
}

ccd_t makeCcd() {
  ccd_t ccd;
  CCD_INIT(&ccd);
  ccd.support1 = ccd.support2 = ccdSupport;
  ccd.center1 = ccd.center2 = ccdCenter;
  ccd.max_iterations = 500;
  return ccd;
}

Result success(double ns, ResultFields fields) {
  Result r;
  r.ok = true;
  r.ns = ns;
  r.fields = std::move(fields);
  return r;
}

}  // namespace

Result LibccdBackend::run(const Case& c, int repeat) {
  if (c.query != QueryKind::Overlap && c.query != QueryKind::Penetration)
    return native::unsupportedQuery("libccd", c.query, "any geometry (it answers overlap and penetration)");
  const PairCase& q = std::get<PairCase>(c.input);
  SupportShape a, b;
  std::string error;
  if (!native::makeSupportShape(q.geom0, q.pose0, a, error) || !native::makeSupportShape(q.geom1, q.pose1, b, error))
    return Result::failure(error);
  const ccd_t ccd = makeCcd();
  if (c.query == QueryKind::Overlap) {
    bool overlapping = false;
    const double ns = medianNanoseconds(repeat, [&] { overlapping = ccdGJKIntersect(&a, &b, &ccd) != 0; });
    return success(ns, OverlapOut{overlapping});
  }
  ccd_real_t depth = 0;
  ccd_vec3_t dir, pos;
  int status = -1;
  const double ns = medianNanoseconds(repeat, [&] {
    status = method_ == CcdPenetration::Mpr ? ccdMPRPenetration(&a, &b, &ccd, &depth, &dir, &pos)
                                            : ccdGJKPenetration(&a, &b, &ccd, &depth, &dir, &pos);
  });
  if (status == -2) return Result::failure("libccd: out of memory in EPA", ns);
  PenetrationOut out;
  if (status == 0) {
    // libccd's dir moves obj2 (geom1) out by depth; gq's direction moves geom0, hence the minus sign.
    out.penetrating = true;
    out.depth = double(depth);
    out.direction = -fromCcd(dir);
  }
  return success(ns, out);
}

}  // namespace gq::cases
