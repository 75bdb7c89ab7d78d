// Low-discrepancy sample points per pixel: padded, Owen-scrambled 2D Sobol points (Burley 2020,
// "Practical Hash-based Owen Scrambling", JCGT 9(4); pbrt-v4's PaddedSobolSampler). Each 2D
// "pair" of a pixel's sample vector is the (0,2)-sequence formed by the first two Sobol
// dimensions, indexed by the pixel's sample number (across passes), with
//  - a nested uniform (Owen) scramble of each coordinate, seeded per (pixel, pair, seed): every
//    point is uniformly distributed on [0, 1)^2 on its own, so an estimator fed one point is
//    unbiased exactly as with independent uniforms, while the first 2^k points of a pixel fill
//    every elementary interval of area 2^-k once (stratified in 1D and 2D at once);
//  - an Owen scramble of the index (a shuffle within aligned power-of-two blocks), seeded per
//    (pixel, pair): different pairs of one sample are decorrelated ("padding"), and the first 2^k
//    indices are still a permutation of the first 2^k.
// Deterministic per (pixel seed, sample index, pair): a progressive render continues the
// sequence pass after pass. Host/device code.
#pragma once

#include "core/HostDevice.h"

#include <cstdint>

namespace amrdm
{

AMRDM_HD std::uint32_t reverseBits32(std::uint32_t x)
{
#if defined(__CUDA_ARCH__)
  return __brev(x);
#else
  x = (x << 16) | (x >> 16);
  x = ((x & 0x00ff00ffu) << 8) | ((x & 0xff00ff00u) >> 8);
  x = ((x & 0x0f0f0f0fu) << 4) | ((x & 0xf0f0f0f0u) >> 4);
  x = ((x & 0x33333333u) << 2) | ((x & 0xccccccccu) >> 2);
  return ((x & 0x55555555u) << 1) | ((x & 0xaaaaaaaau) >> 1);
#endif
}

/// A hash that is an Owen scramble of the bit-REVERSED value: every operation changes a bit only
/// as a function of the bits below it (addition, multiplication by an odd constant, x ^= x * even),
/// so on reversed bits each digit is permuted as a function of the digits above it
/// (N. Vegdahl 2021, an improvement of Laine-Karras / Burley's permutation).
AMRDM_HD std::uint32_t owenHashReversed(std::uint32_t x, std::uint32_t seed)
{
  x ^= x * 0x3d20adeau;
  x += seed;
  x *= (seed >> 16) | 1u;
  x ^= x * 0x05526c56u;
  x ^= x * 0x53a22864u;
  return x;
}

/// Nested uniform (Owen) scramble of the 32-bit fixed-point fraction x with `seed`.
AMRDM_HD std::uint32_t owenScramble(std::uint32_t x, std::uint32_t seed)
{
  return reverseBits32(owenHashReversed(reverseBits32(x), seed));
}

/// 32-bit integer hash (lowbias32, C. Wellons 2020) to derive independent seeds.
AMRDM_HD std::uint32_t hash32(std::uint32_t x)
{
  x ^= x >> 16;
  x *= 0x7feb352du;
  x ^= x >> 15;
  x *= 0x846ca68bu;
  x ^= x >> 16;
  return x;
}

/// Sobol dimension 1 (dimension 0 is the bit-reversed index): direction numbers
/// v_0 = 2^31, v_k = v_{k-1} ^ (v_{k-1} >> 1).
AMRDM_HD std::uint32_t sobolDimension1(std::uint32_t index)
{
  std::uint32_t x = 0u, v = 0x80000000u;
  for (; index != 0u; index >>= 1, v ^= v >> 1)
  {
    if (index & 1u)
    {
      x ^= v;
    }
  }
  return x;
}

/// 2^-24 (as kUnitFloat24 in Random.h): the top 24 bits of a fraction as a float in [0, 1).
constexpr float kLdUnitFloat24 = 1.0f / 16777216.0f;

/// Point `index` of the Owen-scrambled 2D Sobol sequence with scramble seed `seed`, in [0, 1)^2.
AMRDM_HD glm::vec2 sobolOwen2D(std::uint32_t index, std::uint32_t seed)
{
  const std::uint32_t i = owenScramble(index, hash32(seed ^ 0x5bd1e995u));
  // Dimension 0 is reverseBits32(i); its scramble reverses the bits back: no reversal needed.
  const std::uint32_t x = reverseBits32(owenHashReversed(i, hash32(seed + 0x68bc21ebu)));
  const std::uint32_t y = owenScramble(sobolDimension1(i), hash32(seed + 0x02e5be93u));
  return glm::vec2(float(x >> 8) * kLdUnitFloat24, float(y >> 8) * kLdUnitFloat24);
}

} // namespace amrdm
