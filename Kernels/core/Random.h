// Counter-based random numbers: every value is a hash of (pixel, sample, frame, dimension), so
// an image is bit-identical for any thread count or tile order, and the CPU and GPU can draw the
// same streams. Host/device code; no state beyond a key and a counter.
#pragma once

#include "core/HostDevice.h"

#include <cstdint>

namespace amrdm
{

/// 64-bit finaliser of SplitMix64 (Steele, Lea, Flood 2014): a bijective avalanche mix.
AMRDM_HD std::uint64_t mix64(std::uint64_t z)
{
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

/// 2^-24: maps the top 24 bits of a hash to a float in [0, 1) exactly representable.
constexpr float kUnitFloat24 = 1.0f / 16777216.0f;

/// Stream of uniform floats in [0, 1) for one (pixel, sample, frame); dimension = call count.
struct Rng
{
  std::uint64_t key = 0;
  std::uint32_t dimension = 0;

  AMRDM_HD Rng() = default;
  AMRDM_HD Rng(std::uint64_t pixel,
    std::uint64_t sample,
    std::uint64_t frame,
    std::uint64_t seed = 0)
  {
    this->key = mix64(mix64(mix64(mix64(seed) ^ pixel) ^ sample) ^ frame);
    this->dimension = 0;
  }
  /// The next uniform in [0, 1).
  AMRDM_HD float next()
  {
    const std::uint64_t h =
      mix64(this->key + 0x9e3779b97f4a7c15ull * (std::uint64_t(this->dimension++) + 1));
    return float(h >> 40) * kUnitFloat24;
  }
  AMRDM_HD glm::vec2 next2()
  {
    const float a = this->next();
    return glm::vec2(a, this->next());
  }
};

} // namespace amrdm
