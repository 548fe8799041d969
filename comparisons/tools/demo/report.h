#pragma once
// The demo report: one section per query family, each a fixed-width table.
#include <cstdint>
#include <iosfwd>

namespace gq::demo {

struct DemoOptions {
  std::uint32_t rays = 100000;   // per geometry
  int repetitions = 3;           // timed passes; ns/ray is the median
  std::uint64_t seed = 20240601; // fixes the ray set
};

// Raycast speed against error, float and double, for every geometry type of the embedded scene.
void printRaycastSection(const DemoOptions& options, std::ostream& out);

}  // namespace gq::demo
