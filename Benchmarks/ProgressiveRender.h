// The benchmark's progressive loop over any medium (Kernels/sampling/Media.h interface): passes run
// through Kernels' runTiledPass (TiledPass.h), the CPU renderer's own pass loop, so random
// streams (pixel, sample index within the pass, pass index as `frame`, params.seed) and double
// sums are exactly CpuRenderer's: two runs with the same seed differ only by the medium or the
// knob under test. What it adds is the medium type (nearest-cell and uniform-grid media for
// comparison) and a timer. Host-only.
#pragma once

#include "render/TiledPass.h"

#include <chrono>
#include <vector>

namespace amrdm_bench
{

class ProgressiveRender
{
public:
  explicit ProgressiveRender(int width = 0, int height = 0) { this->resize(width, height); }

  void resize(int width, int height)
  {
    this->Width = width;
    this->Height = height;
    this->Sum.assign(std::size_t(width) * height, glm::dvec4(0.0));
    this->Passes = 0;
    this->SppDone = 0;
  }
  int passes() const { return this->Passes; }

  /// Adds one pass of params.samplesPerPass samples per pixel; returns its wall time, ms.
  template<typename Medium>
  double pass(const Medium& medium, const amrdm::MajorantGridView& grid, amrdm::RenderParams params)
  {
    const auto t0 = std::chrono::steady_clock::now();
    params.width = this->Width;
    params.height = this->Height;
    params.samplesPerPass = std::max(1, params.samplesPerPass);
    amrdm::runTiledPass(medium,
      grid,
      params,
      std::uint32_t(this->Passes),
      nullptr,
      nullptr,
      nullptr,
      this->Totals,
      [&](std::size_t pixel, const amrdm::PixelSamples& p) { this->Sum[pixel] += p.sum; });
    this->SppDone += params.samplesPerPass;
    ++this->Passes;
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  }

  /// Mean premultiplied RGBA, rows from the bottom (4 floats per pixel).
  std::vector<float> image() const
  {
    std::vector<float> out(this->Sum.size() * 4);
    for (std::size_t i = 0; i < this->Sum.size(); ++i)
    {
      const glm::vec4 m = amrdm::accumulatedMean(this->Sum[i], std::uint32_t(this->SppDone));
      for (int c = 0; c < 4; ++c)
        out[4 * i + c] = m[c];
    }
    return out;
  }
  int samplesPerPixel() const { return this->SppDone; }

private:
  int Width = 0, Height = 0, Passes = 0, SppDone = 0;
  std::vector<glm::dvec4> Sum;
  amrdm::PassTotals Totals;
};

} // namespace amrdm_bench
