#include <gtest/gtest.h>

#include "gq/query.h"

TEST(Raycast, InvalidDirectionIsRejectedAndWritesNothing) {
  const gq::Geometry<double> sphere = gq::SphereGeometry<double>(1.0);
  gq::RaycastHit<double> hit;
  hit.distance = 42.0;
  std::uint32_t n = 7;
  const gq::Status s = gq::raycast<double>({-5, 0, 0}, {2, 0, 0}, sphere, gq::Transform<double>(), 10.0,
                                           gq::kDefaultHitFlags, 1, &hit, n);
  EXPECT_EQ(s.code, gq::StatusCode::InvalidArgument);
  EXPECT_EQ(n, 7u);
  EXPECT_EQ(hit.distance, 42.0);
}
