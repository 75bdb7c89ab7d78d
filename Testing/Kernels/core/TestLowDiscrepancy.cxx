// The per-pixel low-discrepancy points (core/LowDiscrepancy.h, Rng::ld2): every power-of-two
// prefix of a pixel's pair is a (0, m, 2)-net (one point in each elementary interval), each
// point is uniform over pixels (what keeps an estimator unbiased), the sequence continues pass
// after pass, and a smooth integrand's error at 16 points is far below independent sampling's.
#define DOCTEST_CONFIG_IMPLEMENT_WITH_MAIN
#include <doctest/doctest.h>

#include "core/Random.h"

#include <cmath>
#include <vector>

using namespace amrdm;

TEST_CASE("Sobol pair: every power-of-two prefix is a (0, m, 2)-net, for any scramble")
{
  CHECK(reverseBits32(1u) == 0x80000000u);
  CHECK(reverseBits32(0x12345678u) == 0x1e6a2c48u);
  for (std::uint32_t seed : { 0u, 1u, 12345u, 0xdeadbeefu })
    for (int m = 0; m <= 10; ++m)
    {
      const std::uint32_t n = 1u << m;
      for (int a = 0; a <= m; ++a) // elementary intervals of 2^a x 2^(m-a)
      {
        std::vector<int> count(n, 0);
        for (std::uint32_t i = 0; i < n; ++i)
        {
          const glm::vec2 u = sobolOwen2D(i, seed);
          REQUIRE(u.x >= 0.0f);
          REQUIRE(u.x < 1.0f);
          REQUIRE(u.y >= 0.0f);
          REQUIRE(u.y < 1.0f);
          const std::uint32_t cx = std::uint32_t(u.x * float(1u << a));
          const std::uint32_t cy = std::uint32_t(u.y * float(1u << (m - a)));
          ++count[(cx << (m - a)) | cy];
        }
        int bad = 0;
        for (int c : count)
        {
          bad += c != 1;
        }
        INFO("seed ", seed, " m ", m, " a ", a);
        CHECK(bad == 0);
      }
    }
}

TEST_CASE("Sobol pair: one point is uniform over the scramble seeds (unbiased per sample)")
{
  // Index 5 (any index) over 2^16 pixel seeds: an 8 x 8 histogram of the pair passes a
  // chi-square test at 64 cells (99.99 % quantile of chi2(63) is about 117), and the means are
  // 1/2 within 5 standard errors.
  constexpr int kN = 1 << 16;
  for (std::uint32_t index : { 0u, 5u, 1000u })
  {
    std::vector<int> hist(64, 0);
    double sx = 0.0, sy = 0.0;
    for (int s = 0; s < kN; ++s)
    {
      const glm::vec2 u = sobolOwen2D(index, hash32(std::uint32_t(s)));
      ++hist[int(u.x * 8.0f) * 8 + int(u.y * 8.0f)];
      sx += u.x;
      sy += u.y;
    }
    double chi2 = 0.0;
    const double expected = double(kN) / 64.0;
    for (int h : hist)
    {
      chi2 += (h - expected) * (h - expected) / expected;
    }
    const double se = std::sqrt(1.0 / 12.0 / kN);
    INFO("index ", index, " chi2 ", chi2);
    CHECK(chi2 < 117.0);
    CHECK(std::fabs(sx / kN - 0.5) < 5.0 * se);
    CHECK(std::fabs(sy / kN - 0.5) < 5.0 * se);
  }
}

TEST_CASE("Rng::ld2: pairs of one sample are decorrelated, the stream is untouched, and a "
          "stream without the sequence draws from the hash")
{
  Rng a(3, 4, 5, 6), b(3, 4, 5, 6);
  a.lowDiscrepancy(9, 77);
  const glm::vec2 p0 = a.ld2(kLdPixelJitter), p1 = a.ld2(kLdCameraVertex);
  CHECK(p0 != p1);
  CHECK(a.ld2(kLdPixelJitter) == p0); // deterministic per (seed, index, pair)
  CHECK(a.next() == b.next());        // ld2 does not advance the hash stream
  Rng c(3, 4, 5, 6), d(3, 4, 5, 6);
  const glm::vec2 h = c.ld2(kLdFirstDirection);
  CHECK(h == d.next2());
  // Different pairs of one pixel are not the same permutation: over 64 samples the first
  // coordinates of pairs 0 and 1 are not rank-identical.
  int same = 0;
  for (std::uint32_t i = 0; i < 64; ++i)
  {
    Rng r(0, i, 0, 0);
    r.lowDiscrepancy(i, 1234u);
    const float x0 = r.ld2(kLdPixelJitter).x, x1 = r.ld2(kLdCameraVertex).x;
    same += int(x0 * 64.0f) == int(x1 * 64.0f);
  }
  CHECK(same < 16);
}

TEST_CASE("Sobol pair: a smooth integrand at 16 points per pixel beats independent sampling")
{
  // f(x, y) = exp(x) sin(3 y) + x y over [0,1)^2; exact integral (e - 1)(1 - cos 3)/3 + 1/4.
  const double exact = (std::exp(1.0) - 1.0) * (1.0 - std::cos(3.0)) / 3.0 + 0.25;
  auto f = [](glm::vec2 u)
  { return std::exp(double(u.x)) * std::sin(3.0 * u.y) + double(u.x) * double(u.y); };
  constexpr int kPixels = 4000, kSamples = 16;
  double mean = 0.0, seLd = 0.0, seRandom = 0.0;
  for (int p = 0; p < kPixels; ++p)
  {
    double ld = 0.0, rnd = 0.0;
    for (int i = 0; i < kSamples; ++i)
    {
      Rng r(std::uint64_t(p), std::uint64_t(i), 0, 11);
      rnd += f(r.next2());
      r.lowDiscrepancy(std::uint32_t(i), hash32(std::uint32_t(p)));
      ld += f(r.ld2(kLdCameraVertex));
    }
    ld /= kSamples;
    rnd /= kSamples;
    mean += ld / kPixels;
    seLd += (ld - exact) * (ld - exact) / kPixels;
    seRandom += (rnd - exact) * (rnd - exact) / kPixels;
  }
  const double rmsLd = std::sqrt(seLd), rmsRandom = std::sqrt(seRandom);
  MESSAGE("RMS error at 16 points: Sobol ", rmsLd, ", independent ", rmsRandom);
  // Unbiased: the mean over pixels is within 5 standard errors of the integral.
  CHECK(std::fabs(mean - exact) < 5.0 * rmsLd / std::sqrt(double(kPixels)));
  // Owen-scrambled nets converge as n^-3/2 on smooth integrands: expect 5x or more at 16.
  CHECK(rmsLd * 4.0 < rmsRandom);
}
