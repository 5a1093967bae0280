#pragma once
// Seeds and random numbers that are the same on every platform.
//
// std::mt19937_64's sequence is fixed by the C++ standard, but std::uniform_real_distribution,
// std::normal_distribution and std::uniform_int_distribution are implementation-defined: the
// same seed gives other numbers with another standard library. Draw through these functions
// instead, so a seed reproduces a run anywhere.

#include <cstdint>
#include <random>

namespace acdplan {

/// The random engine of the project (its sequence is fixed by the standard).
using RandomEngine = std::mt19937_64;

/// SplitMix64's output function of the state `x` (S. Vigna; the state advances by the golden
/// gamma 0x9E3779B97F4A7C15 before mixing): a bijective 64-bit mix in which every input bit
/// affects every output bit.
std::uint64_t SplitMix64(std::uint64_t x);

/// A well-mixed seed for the `index`-th consumer (sampler, thread, run) of `seed`:
/// SplitMix64(seed + index x golden gamma), i.e. the index-th output of a SplitMix64 stream
/// started at `seed`. Distinct indices give unrelated engines.
std::uint64_t DeriveSeed(std::uint64_t seed, std::uint64_t index);

/// A uniform double in [lo, hi): the engine's top 53 bits scaled (one draw).
double UniformReal(RandomEngine& rng, double lo, double hi);

/// A uniform integer in [0, n) for n >= 1, without modulo bias (draws below 2^64 mod n are
/// rejected).
std::uint64_t UniformIndex(RandomEngine& rng, std::uint64_t n);

/// A standard normal deviate (Marsaglia's polar method; the second deviate of a pair is
/// dropped so the function keeps no state).
double StandardNormal(RandomEngine& rng);

}  // namespace acdplan
