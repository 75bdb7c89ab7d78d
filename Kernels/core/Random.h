// Counter-based random numbers: every value is a hash of (pixel, sample, frame, dimension), so
// an image is bit-identical for any thread count or tile order, and the CPU and GPU can draw the
// same streams. Host/device code; no state beyond a key, a counter and the low-discrepancy
// sample index.
#pragma once

#include "core/HostDevice.h"
#include "core/LowDiscrepancy.h"

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

/// Pairs of a sample's vector drawn from the pixel's low-discrepancy sequence (ld2): the pixel
/// jitter, (the camera ray's vertex choice, its light choice), the first scattered direction,
/// (the first free-flight steps of the camera walk and of its vertex's shadow ray).
enum LdPair : int
{
  kLdPixelJitter = 0,
  kLdCameraVertex = 1,
  kLdFirstDirection = 2,
  kLdWalkStart = 3 ///< (the camera walk's first step, its vertex's shadow ray's first step)
};

/// Stream of uniform floats in [0, 1) for one (pixel, sample, frame); dimension = call count.
/// Optionally (lowDiscrepancy()) a few named pairs come from the pixel's Owen-scrambled Sobol
/// sequence (core/LowDiscrepancy.h) at the sample's index across passes; everything else, and
/// every pair of a stream without it, comes from the hash stream.
struct Rng
{
  std::uint64_t key = 0;
  std::uint32_t dimension = 0;
  std::uint32_t ldIndex = 0; ///< the pixel's sample number across passes
  std::uint32_t ldSeed = 0;  ///< the pixel's scramble seed
  bool ldEnabled = false;

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
  /// Takes `pair`s of ld2 from the Owen-scrambled Sobol sequence of scramble seed `seed` (one
  /// per pixel and render seed) at point `index` (the pixel's sample number across passes).
  AMRDM_HD void lowDiscrepancy(std::uint32_t index, std::uint32_t seed)
  {
    this->ldIndex = index;
    this->ldSeed = seed;
    this->ldEnabled = true;
  }
  /// Pair `pair` (LdPair) of this sample: uniform on [0, 1)^2 either way; stratified over the
  /// pixel's samples with lowDiscrepancy(), else the next two values of the stream.
  AMRDM_HD glm::vec2 ld2(int pair)
  {
    if (!this->ldEnabled)
    {
      return this->next2();
    }
    return sobolOwen2D(this->ldIndex, hash32(this->ldSeed + 0x9e3779b9u * std::uint32_t(pair)));
  }
};

} // namespace amrdm
