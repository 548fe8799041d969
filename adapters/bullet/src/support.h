#pragma once
// Who answers for a Bullet shape: gq, Bullet's own algorithms, or nobody (bad input).
#include <cstdint>

namespace gq::bullet {

enum class Support : std::uint8_t {
  Gq,       // gq models the shape
  Bullet,   // valid parameters gq does not model (e.g. a hull of 3 points): Bullet's own algorithms answer
  Invalid,  // bad input (non-finite numbers, sizes <= 0, empty or degenerate mesh, absurd heightfield): no contact
            // and no hit is reported and callbacks are not called, as stock Bullet does for most such input
};

}  // namespace gq::bullet
