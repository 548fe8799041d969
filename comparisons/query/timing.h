#pragma once
// Median wall time of one call over `repeat` runs (std::chrono::steady_clock).
#include <algorithm>
#include <chrono>
#include <vector>

namespace gq::cases {

template <class F> double medianNanoseconds(int repeat, F&& call) {
  std::vector<double> samples(static_cast<std::size_t>(std::max(repeat, 1)));
  for (double& s : samples) {
    const auto start = std::chrono::steady_clock::now();
    call();
    const auto stop = std::chrono::steady_clock::now();
    s = std::chrono::duration<double, std::nano>(stop - start).count();
  }
  const std::size_t mid = samples.size() / 2;
  std::nth_element(samples.begin(), samples.begin() + mid, samples.end());
  if (samples.size() % 2 == 1) return samples[mid];
  // Even count: mean of the two middle samples.
  const double upper = samples[mid];
  const double lower = *std::max_element(samples.begin(), samples.begin() + mid);
  return 0.5 * (lower + upper);
}

}  // namespace gq::cases
