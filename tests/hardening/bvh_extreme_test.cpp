// BVH cooking with vertex coordinates beyond the float range of the BVH's node boxes: the SAH binning once converted
// a NaN/inf bin position to int (undefined behaviour, found by the CI fuzz smoke under UBSan; this test runs under
// UBSan in scripts/sanitize). Cooking must answer a status, and a cooked mesh must answer rays without NaN.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "gq/cooking.h"
#include "gq/query.h"

namespace {

TEST(BvhExtreme, CoordinatesBeyondTheFloatRangeCookToAStatusAndRaysStayFinite) {
  for (const double far : {1e39, 3.4e38, 1e300}) {
    // Triangles spread from the origin to `far`, so centroid extents overflow float while some stay small.
    std::vector<gq::Vec3<double>> v;
    std::vector<gq::TriangleIndices> t;
    for (int i = 0; i < 64; ++i) {
      const double x = (i % 2 ? far : 1.0) * (i % 3 - 1), y = double(i), z = (i % 5) * 1e-30;
      const auto base = std::uint32_t(v.size());
      v.push_back(gq::Vec3<double>(x, y, z));
      v.push_back(gq::Vec3<double>(x + 1, y, z));
      v.push_back(gq::Vec3<double>(x, y + 1, z + 1));
      t.push_back({base, base + 1, base + 2});
    }
    std::shared_ptr<const gq::TriangleMesh<double>> mesh;
    const gq::Status s = gq::cookTriangleMesh(v, t, mesh);
    if (!s.ok()) {
      EXPECT_STRNE(s.message(), "");
      EXPECT_EQ(mesh, nullptr);
      continue;
    }
    gq::RaycastHit<double> hit;
    std::uint32_t n = 0;
    ASSERT_TRUE(gq::raycast<double>({0.25, 10.25, -5}, {0, 0, 1}, gq::TriangleMeshGeometry<double>(mesh),
                                    gq::Transform<double>(), 100.0, gq::kDefaultHitFlags | gq::HitFlag::MeshBothSides,
                                    1, &hit, n)
                    .ok());
    if (n == 1) EXPECT_TRUE(std::isfinite(hit.distance));
  }
}

}  // namespace
