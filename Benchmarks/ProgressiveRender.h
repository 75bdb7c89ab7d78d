// The benchmark's render loop over any medium (Kernels/Media.h interface): tiles of
// params.tileSize pixels over Kernels' parallelFor, one renderSample() per pixel and sample,
// accumulated progressively. Random streams are keyed exactly as in CpuRenderer (pixel,
// sample index within the pass, pass index as `frame`, params.seed), so two runs with the same
// seed differ only by the medium or the knob under test. Host-only.
#pragma once

#include "Integrators.h"
#include "ParallelFor.h"

#include <algorithm>
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
    this->Sum.assign(std::size_t(width) * height, glm::vec4(0.0f));
    this->Passes = 0;
  }
  int passes() const { return this->Passes; }

  /// Adds one pass of params.samplesPerPass samples per pixel; returns its wall time, ms.
  template <typename Medium>
  double pass(const Medium& medium, const amrdm::MajorantGridView& grid, const amrdm::RenderParams& params)
  {
    const auto t0 = std::chrono::steady_clock::now();
    const int tile = std::clamp(params.tileSize, 4, 256);
    const int tilesX = (this->Width + tile - 1) / tile, tilesY = (this->Height + tile - 1) / tile;
    const std::uint32_t frame = std::uint32_t(this->Passes);
    const int spp = std::max(1, params.samplesPerPass);
    amrdm::parallelFor(std::size_t(tilesX) * tilesY, params.threads, [&](std::size_t t) {
      const int x0 = int(t % tilesX) * tile, y0 = int(t / tilesX) * tile;
      const int x1 = std::min(x0 + tile, this->Width), y1 = std::min(y0 + tile, this->Height);
      amrdm::TraceCounters counters;
      for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x)
        {
          glm::vec4 sum(0.0f);
          for (int s = 0; s < spp; ++s)
          {
            const amrdm::SampleResult r = amrdm::renderSample(
              medium, grid, params, x, y, std::uint32_t(s), frame, amrdm::kInfinity, counters);
            sum += glm::vec4(r.L, r.alpha);
          }
          this->Sum[std::size_t(y) * this->Width + x] += sum;
        }
    });
    this->SppDone += spp;
    ++this->Passes;
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  }

  /// Mean premultiplied RGBA, rows from the bottom (4 floats per pixel).
  std::vector<float> image() const
  {
    std::vector<float> out(this->Sum.size() * 4);
    const float inv = this->SppDone > 0 ? 1.0f / float(this->SppDone) : 0.0f;
    for (std::size_t i = 0; i < this->Sum.size(); ++i)
      for (int c = 0; c < 4; ++c)
        out[4 * i + c] = this->Sum[i][c] * inv;
    return out;
  }
  int samplesPerPixel() const { return this->SppDone; }

private:
  int Width = 0, Height = 0, Passes = 0, SppDone = 0;
  std::vector<glm::vec4> Sum;
};

} // namespace amrdm_bench
