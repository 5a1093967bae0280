#include "base/random.h"

#include <cmath>

namespace acdplan {

std::uint64_t SplitMix64(std::uint64_t x) {
  x += 0x9E3779B97F4A7C15ULL;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ULL;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBULL;
  return x ^ (x >> 31);
}

std::uint64_t DeriveSeed(std::uint64_t seed, std::uint64_t index) {
  return SplitMix64(seed + 0x9E3779B97F4A7C15ULL * index);
}

double UniformReal(RandomEngine& rng, double lo, double hi) {
  return lo + (hi - lo) * (static_cast<double>(rng() >> 11) * 0x1.0p-53);
}

std::uint64_t UniformIndex(RandomEngine& rng, std::uint64_t n) {
  // Reject the lowest 2^64 mod n draws, so every residue is equally likely.
  const std::uint64_t threshold = (0 - n) % n;
  std::uint64_t x = rng();
  while (x < threshold) x = rng();
  return x % n;
}

double StandardNormal(RandomEngine& rng) {
  for (;;) {
    const double u = UniformReal(rng, -1.0, 1.0), v = UniformReal(rng, -1.0, 1.0);
    const double s = u * u + v * v;
    if (s > 0.0 && s < 1.0) return u * std::sqrt(-2.0 * std::log(s) / s);
  }
}

}  // namespace acdplan
