// Sphere fit: the smallest sphere enclosing the hull vertices (exact, Welzl), and its shrinking for close fits.
#include "fit/fit_internal.h"

namespace gq::fit {

Solid fitSphere(const std::vector<Vec3d>& hull) {
  Solid s;
  s.kind = Solid::Kind::Sphere;
  enclosingSphere(hull, s.centre, s.radius);
  return s;
}

Solid shrunk(const Solid& s, double by) {
  Solid out = s;
  const auto less = [by](double v) { return std::max(v - by, 0.5 * v); };
  switch (s.kind) {
    case Solid::Kind::Sphere:
    case Solid::Kind::Capsule: out.radius = less(s.radius); break;
    case Solid::Kind::Cylinder:
      out.radius = less(s.radius);
      out.halfHeight = less(s.halfHeight);
      break;
    case Solid::Kind::Box:
      for (int i = 0; i < 3; ++i) out.halfExtents[i] = less(s.halfExtents[i]);
      break;
    case Solid::Kind::Polytope: break;
  }
  return out;
}

}  // namespace gq::fit
