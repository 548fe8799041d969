#include "gq_backend.h"

#include <exception>
#include <vector>

#include "gq/query.h"
#include "timing.h"

namespace gq::cases {
namespace {

template <class T> Vec3d toDouble(const Vec3<T>& v) { return v.template cast<double>(); }

template <class T> RayHitOut toRayHit(const RaycastHit<T>& h, HitFlags requested) {
  RayHitOut out;
  out.distance = double(h.distance);
  // A field prints when it was asked for and the kernel says it is valid.
  if (requested.has(HitFlag::Position) && h.flags.has(HitFlag::Position)) out.position = toDouble(h.position);
  if (requested.has(HitFlag::Normal) && h.flags.has(HitFlag::Normal)) out.normal = toDouble(h.normal);
  if (requested.has(HitFlag::UV) && h.flags.has(HitFlag::UV)) out.uv = std::array<double, 2>{double(h.u), double(h.v)};
  out.faceIndex = h.faceIndex;
  return out;
}

// Geometry + pose of one side of a query, or the status that prevents building it.
template <class T> struct Placed {
  Geometry<T> geom;
  Transform<T> pose;
};

template <class T> Status place(GqShapeFactory<T>& shapes, const ShapeDesc& d, const PoseDesc& p, Placed<T>& out) {
  out.pose = toTransform<T>(p);
  return shapes.build(d, out.geom);
}

template <class T> Result finish(const Status& status, double ns, ResultFields fields) {
  if (!status.ok()) return Result::failure(status.toString(), ns);
  Result r;
  r.ok = true;
  r.ns = ns;
  r.fields = std::move(fields);
  return r;
}

template <class T> Result runRaycast(GqShapeFactory<T>& shapes, const RaycastCase& q, int repeat) {
  Placed<T> target;
  if (Status s = place(shapes, q.geom, q.pose, target); !s.ok()) return Result::failure(s.toString());
  const HitFlags flags(q.flags);
  const Vec3<T> origin = q.origin.cast<T>(), dir = q.dir.cast<T>();
  std::vector<RaycastHit<T>> hits(q.maxHits);
  std::uint32_t count = 0;
  Status status;
  const double ns = medianNanoseconds(repeat, [&] {
    status = raycast<T>(origin, dir, target.geom, target.pose, T(q.maxDist), flags, q.maxHits, hits.data(), count);
  });
  RaycastOut out;
  if (status.ok())
    for (std::uint32_t i = 0; i < count && i < q.maxHits; ++i) out.hits.push_back(toRayHit(hits[i], flags));
  return finish<T>(status, ns, std::move(out));
}

template <class T> Result runPair(GqShapeFactory<T>& shapes, QueryKind kind, const PairCase& q, int repeat) {
  Placed<T> a, b;
  if (Status s = place(shapes, q.geom0, q.pose0, a); !s.ok()) return Result::failure(s.toString());
  if (Status s = place(shapes, q.geom1, q.pose1, b); !s.ok()) return Result::failure(s.toString());
  Status status;
  if (kind == QueryKind::Overlap) {
    bool overlapping = false;
    const double ns = medianNanoseconds(repeat, [&] { status = overlap<T>(a.geom, a.pose, b.geom, b.pose, overlapping); });
    return finish<T>(status, ns, OverlapOut{overlapping});
  }
  if (kind == QueryKind::Penetration) {
    PenetrationResult<T> pen;
    const double ns =
        medianNanoseconds(repeat, [&] { status = computePenetration<T>(pen, a.geom, a.pose, b.geom, b.pose); });
    return finish<T>(status, ns, PenetrationOut{pen.penetrating, toDouble(pen.direction), double(pen.depth)});
  }
  DistanceResult<T> dist;
  // No warm start: every repeat measures a cold query.
  const double ns = medianNanoseconds(repeat, [&] { status = distance<T>(dist, a.geom, a.pose, b.geom, b.pose); });
  return finish<T>(status, ns,
                   DistanceOut{double(dist.distance), toDouble(dist.point0), toDouble(dist.point1), toDouble(dist.normal)});
}

template <class T> Result runPointDistance(GqShapeFactory<T>& shapes, const PointDistanceCase& q, int repeat) {
  Placed<T> target;
  if (Status s = place(shapes, q.geom, q.pose, target); !s.ok()) return Result::failure(s.toString());
  const Vec3<T> point = q.point.cast<T>();
  PointDistanceResult<T> res;
  Status status;
  const double ns = medianNanoseconds(repeat, [&] { status = pointDistance<T>(point, target.geom, target.pose, res); });
  return finish<T>(status, ns, PointDistanceOut{double(res.distance), toDouble(res.closestPoint), res.closestIndex});
}

template <class T> Result runSweep(GqShapeFactory<T>& shapes, const SweepCase& q, int repeat) {
  Placed<T> a, b;
  if (Status s = place(shapes, q.geom0, q.pose0, a); !s.ok()) return Result::failure(s.toString());
  if (Status s = place(shapes, q.geom1, q.pose1, b); !s.ok()) return Result::failure(s.toString());
  const Vec3<T> dir = q.dir.cast<T>();
  const HitFlags flags(q.flags);
  SweepHit<T> hit;
  bool hasHit = false;
  Status status;
  const double ns = medianNanoseconds(repeat, [&] {
    status = sweep<T>(dir, T(q.maxDist), a.geom, a.pose, b.geom, b.pose, hit, hasHit, flags, T(q.inflation));
  });
  SweepOut out;
  out.hit = hasHit;
  if (hasHit) {
    out.distance = double(hit.distance);
    if (hit.flags.has(HitFlag::Position)) out.position = toDouble(hit.position);
    if (hit.flags.has(HitFlag::Normal)) out.normal = toDouble(hit.normal);
    out.faceIndex = hit.faceIndex;
    out.initialOverlap = hit.initialOverlap;
  }
  return finish<T>(status, ns, std::move(out));
}

template <class T> Result runBounds(GqShapeFactory<T>& shapes, const BoundsCase& q, int repeat) {
  Placed<T> target;
  if (Status s = place(shapes, q.geom, q.pose, target); !s.ok()) return Result::failure(s.toString());
  Bounds3<T> bounds;
  Status status;
  const double ns = medianNanoseconds(repeat, [&] {
    status = computeGeomBounds<T>(bounds, target.geom, target.pose, T(q.offset), T(q.inflation));
  });
  return finish<T>(status, ns, BoundsOut{toDouble(bounds.min), toDouble(bounds.max)});
}

}  // namespace

template <> GqShapeFactory<float>& GqBackend::shapes<float>() { return floatShapes_; }
template <> GqShapeFactory<double>& GqBackend::shapes<double>() { return doubleShapes_; }

template <class T> Result GqBackend::runIn(const Case& c, int repeat) {
  GqShapeFactory<T>& factory = shapes<T>();
  switch (c.query) {
    case QueryKind::Raycast: return runRaycast<T>(factory, std::get<RaycastCase>(c.input), repeat);
    case QueryKind::Overlap:
    case QueryKind::Penetration:
    case QueryKind::Distance: return runPair<T>(factory, c.query, std::get<PairCase>(c.input), repeat);
    case QueryKind::PointDistance: return runPointDistance<T>(factory, std::get<PointDistanceCase>(c.input), repeat);
    case QueryKind::Sweep: return runSweep<T>(factory, std::get<SweepCase>(c.input), repeat);
    case QueryKind::Bounds: return runBounds<T>(factory, std::get<BoundsCase>(c.input), repeat);
  }
  return Result::failure("unknown query");
}

Result GqBackend::run(const Case& c, int repeat) {
  try {
    return c.precision == Precision::Float ? runIn<float>(c, repeat) : runIn<double>(c, repeat);
  } catch (const std::exception& e) {  // e.g. a hit buffer too large to allocate
    return Result::failure(std::string("internal error: ") + e.what());
  }
}

}  // namespace gq::cases
