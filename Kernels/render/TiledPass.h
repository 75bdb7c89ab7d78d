// One pass over the image on CPU threads: tiles of params.tileSize pixels (4..256) over
// parallelFor, samplePixelWith<I>() per pixel (PixelSamples.h; the integrator I chosen once per
// tile by withIntegrator, render/IntegratorList.h), the work counters summed per tile. The
// CPU renderer and the benchmark's progressive loop both run their passes through it, so their
// random streams (pixel, sample, pass index as `frame`, params.seed) and sums are the same; the
// CUDA renderer calls the same samplePixelWith<I> from one thread per pixel. Host code.
#pragma once

#include "core/ParallelFor.h"
#include "render/PixelSamples.h"
#include "render/PassCancellation.h"
#include "render/Renderer.h" // For PassTotals

#include <algorithm>
#include <atomic>
#include <cstdint>

namespace amrdm
{

/// Runs one pass of params.samplesPerPass samples per pixel over a params.width x
/// params.height image: `accumulate(pixel, samples)` gets each pixel's sums once (pixel =
/// y * width + x; tiles are disjoint, so no two threads touch one pixel). depthMaxT / minT:
/// optional per-pixel ray intervals (CpuRenderer.h). `cancel` (optional) counts finished tiles;
/// once it is requested the tiles not yet started are skipped (pixels are then either complete or
/// untouched). Counters go to `totals`.
template<typename Medium, typename Accumulate>
void runTiledPass(const Medium& medium,
  const MajorantGridView& grid,
  const RenderParams& params,
  std::uint32_t frame,
  const float* depthMaxT,
  const float* minT,
  PassCancellation* cancel,
  PassTotals& totals,
  Accumulate&& accumulate)
{
  const int width = params.width, height = params.height;
  const int tile = std::clamp(params.tileSize, 4, 256);
  const int tilesX = (width + tile - 1) / tile;
  const int tilesY = (height + tile - 1) / tile;
  parallelFor(static_cast<std::size_t>(tilesX) * tilesY,
    params.threads,
    [&](std::size_t tileIndex)
    {
      if (cancel && cancel->requested())
      {
        return;
      }
      const int x0 = static_cast<int>(tileIndex % tilesX) * tile;
      const int y0 = static_cast<int>(tileIndex / tilesX) * tile;
      const int x1 = std::min(x0 + tile, width), y1 = std::min(y0 + tile, height);
      TraceCounters counters;
      std::uint32_t rayHints[kRayHintSlots];
      std::fill(rayHints, rayHints + kRayHintSlots, ~0u);
      counters.rayHints = rayHints;
      std::uint64_t samples = 0;
      withIntegrator(params.integrator,
        [&](auto integrator)
        {
          constexpr IntegratorType I = decltype(integrator)::value;
          for (int y = y0; y < y1; ++y)
            for (int x = x0; x < x1; ++x)
            {
              const std::size_t pixel = static_cast<std::size_t>(y) * width + x;
              const float maxT = depthMaxT ? depthMaxT[pixel] : kInfinity;
              const float startT = minT ? minT[pixel] : 0.0f;
              accumulate(pixel,
                samplePixelWith<I>(medium, grid, params, x, y, frame, maxT, startT, counters));
              samples += static_cast<std::uint64_t>(params.samplesPerPass);
            }
        });
      totals.samples += samples;
      addWorkCounters(totals, counters);
      if (cancel)
      {
        cancel->addDone();
      }
    });
}

} // namespace amrdm
