#pragma once
// Checked link pairs ordered by how often they touch: a check that stops at its first colliding pair ends sooner
// on colliding configurations when the usual offenders come first. Both checkers (gq's and the FCL reference) use
// the same order, so it speeds up both and leaves their ratio to the geometry.
#include <algorithm>
#include <cstdint>
#include <vector>

#include "gq/urdf/self_collision.h"

namespace gq::urdf::internal {

// Configurations sampled once per checker by default (CheckerOptions::orderingSamples), and the sampler's seed
// (fixed: the order is a function of the model).
inline constexpr std::uint64_t kOrderingSamples = CheckerOptions().orderingSamples;
inline constexpr std::uint64_t kOrderingSeed = 0x6f72646572ull;

// Stable sort of `pairs` by decreasing contact count over `samples` random configurations; `linksOf(pair)` gives its
// LinkPair, `checkAll(q, result)` answers with every colliding pair. A failing check (or samples = 0) leaves the order.
template <class T, class Pair, class LinksOf, class CheckAll>
void orderByContactFrequency(const RobotModel<T>& model, std::vector<Pair>& pairs, LinksOf linksOf, CheckAll checkAll,
                             std::uint64_t samples = kOrderingSamples) {
  if (samples == 0) return;
  const std::size_t n = model.links.size();
  std::vector<std::uint64_t> contacts(n * n, 0);
  std::uint64_t rng = kOrderingSeed;
  CollisionResult r;
  for (std::uint64_t k = 0; k < samples; ++k) {
    if (!checkAll(randomConfiguration(model, rng), r).ok()) return;
    for (const LinkPair& p : r.pairs) ++contacts[p.a * n + p.b];
  }
  std::stable_sort(pairs.begin(), pairs.end(), [&](const Pair& x, const Pair& y) {
    const LinkPair lx = linksOf(x), ly = linksOf(y);
    return contacts[lx.a * n + lx.b] > contacts[ly.a * n + ly.b];
  });
}

}  // namespace gq::urdf::internal
