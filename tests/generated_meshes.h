// Closed meshes generated without data files, shared by tests and benchmarks.
#pragma once

#include <cmath>
#include <cstdint>

#include "gq/cooking.h"

namespace gqtest {

// A torus about Z (tube centre radius R, tube radius r) on an nu x nv (u, v) grid: vertex (R + r cos v) (cos u, sin u)
// + r sin v Z, closed and outward-facing.
inline gq::MeshData<double> torusMesh(double R, double r, std::uint32_t nu, std::uint32_t nv) {
  gq::MeshData<double> m;
  for (std::uint32_t i = 0; i < nu; ++i)
    for (std::uint32_t j = 0; j < nv; ++j) {
      const double u = 2 * M_PI * i / nu, v = 2 * M_PI * j / nv;
      m.vertices.emplace_back((R + r * std::cos(v)) * std::cos(u), (R + r * std::cos(v)) * std::sin(u), r * std::sin(v));
    }
  const auto at = [&](std::uint32_t i, std::uint32_t j) { return (i % nu) * nv + j % nv; };
  for (std::uint32_t i = 0; i < nu; ++i)
    for (std::uint32_t j = 0; j < nv; ++j) {
      m.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      m.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  return m;
}

}  // namespace gqtest
