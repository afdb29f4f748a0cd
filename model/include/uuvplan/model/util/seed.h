// Deterministic seeds: every random draw of uuvplan takes one, derived from the user's seed.
#pragma once

#include <cstdint>

namespace uuvplan::model {

/// splitmix64 (Steele, Lea & Flood 2014): a well-mixed 64-bit value from `x`.
constexpr std::uint64_t SplitMix64(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

/// The seed of stream `i` (trial, sensor, replicate) of a run seeded with `seed`.
constexpr std::uint64_t StreamSeed(std::uint64_t seed, std::uint64_t i) {
  return SplitMix64(seed ^ SplitMix64(i + 1));
}

}  // namespace uuvplan::model
