#pragma once
// A hash of doubles by their bits, for hash tables keyed by exact coordinates.

#include <cstdint>
#include <cstring>

namespace acdplan {

/// The start of a BitHash chain (FNV-1a's offset basis).
inline constexpr std::uint64_t kBitHashSeed = 1469598103934665603ull;

/// Mixes the bits of `value` into `hash`: FNV-1a's step on the whole word, then a shift that
/// spreads the high bits (the exponent) into the low ones a table indexes by. Equal bits, equal
/// hash: -0 and 0 differ, as do NaNs of other payloads.
inline std::uint64_t BitHash(std::uint64_t hash, double value) {
  std::uint64_t bits;
  std::memcpy(&bits, &value, sizeof bits);
  hash = (hash ^ bits) * 1099511628211ull;
  return hash ^ (hash >> 29);
}

}  // namespace acdplan
