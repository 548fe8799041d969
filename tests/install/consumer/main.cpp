// A program outside the tree: one raycast through the installed package.
#include <gq/query.h>

#include <cstdio>

int main() {
  const gq::Geometry<double> sphere = gq::SphereGeometry<double>(1.0);
  gq::RaycastHit<double> hit;
  std::uint32_t n = 0;
  const gq::Status s = gq::raycast<double>({-5, 0, 0}, {1, 0, 0}, sphere, gq::Transform<double>(), 10.0,
                                           gq::kDefaultHitFlags, 1, &hit, n);
  if (!s.ok() || n != 1 || std::abs(hit.distance - 4.0) > 1e-12) {
    std::fprintf(stderr, "unexpected: %s n=%u d=%g\n", s.toString().c_str(), n, n ? hit.distance : -1.0);
    return 1;
  }
  std::printf("consumer ok: distance %.3f\n", hit.distance);
  return 0;
}
