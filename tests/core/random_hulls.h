#pragma once
// Seeded random hulls for the penetration tests: cooked hulls of points on an ellipsoid (semi-axes 1, 0.8, 0.6), so
// faces, edges and their Gauss maps vary in size and no two hulls share a face direction by construction.
#include <gtest/gtest.h>

#include <memory>
#include <vector>

#include "gq/cooking.h"
#include "test_util.h"

namespace gq::test {

template <class T> std::shared_ptr<const ConvexMesh<T>> ellipsoidHull(int n, Rng& rng) {
  std::vector<Vec3<T>> pts;
  for (int i = 0; i < n; ++i) pts.push_back(rng.unitVector<T>().cwiseProduct(Vec3<T>(T(1), T(0.8), T(0.6))));
  std::shared_ptr<const ConvexMesh<T>> out;
  EXPECT_TRUE(cookConvexMesh(pts, out).ok());
  return out;
}

}  // namespace gq::test
