// Batch-mean estimates of an image on any Renderer (CPU or CUDA): `batches` independent renders
// of `sppPerBatch` samples with seeds seed, seed + 1, ...; per pixel and channel the mean of the
// batch means and its variance (sample variance of the batch means / batches, batches - 1 degrees
// of freedom), the form StatisticalImageTest.h compares. Host code, no VTK.
#pragma once

#include "render/Renderer.h"
#include "render/StatisticalImageTest.h"

#include <cstdint>

namespace amrdm_devcheck
{

struct BatchEstimate
{
  amrdm::ImageEstimate image;
  std::uint64_t majorantViolations = 0; ///< summed over the batches; must stay 0
  std::uint64_t stepLimitHits = 0;
  double seconds = 0.0; ///< wall time of all batches
};

/// Renders the batches on `renderer` (mesh and transfer function already set). batches >= 2.
BatchEstimate renderBatchMeans(amrdm::Renderer& renderer,
  amrdm::RenderParams params,
  std::uint32_t seed,
  int batches,
  int sppPerBatch);

} // namespace amrdm_devcheck
