// Batch-mean estimates (see BatchEstimate.h).
#include "BatchEstimate.h"

#include <chrono>
#include <stdexcept>
#include <string>

namespace amrdm_devcheck
{

BatchEstimate renderBatchMeans(amrdm::Renderer& renderer,
  amrdm::RenderParams params,
  std::uint32_t seed,
  int batches,
  int sppPerBatch)
{
  if (batches < 2 || sppPerBatch < 1)
  {
    throw std::invalid_argument("batch means need at least 2 batches of at least 1 sample (got " +
                                std::to_string(batches) + " x " + std::to_string(sppPerBatch) +
                                ")");
  }
  const auto t0 = std::chrono::steady_clock::now();
  params.samplesPerPass = sppPerBatch;
  const std::size_t n = std::size_t(params.width) * std::size_t(params.height) * 4;
  BatchEstimate e;
  e.image.mean.assign(n, 0.0);
  std::vector<double> m2(n, 0.0);
  for (int k = 0; k < batches; ++k)
  {
    renderer.reset();
    params.seed = seed + std::uint32_t(k);
    renderer.renderPass(params);
    const amrdm::RenderStats stats = renderer.stats();
    e.majorantViolations += stats.majorantViolations;
    e.stepLimitHits += stats.stepLimitHits;
    const std::vector<float> image = renderer.image();
    if (image.size() != n)
    {
      throw std::runtime_error("the renderer returned " + std::to_string(image.size()) +
                               " values; expected " + std::to_string(n));
    }
    for (std::size_t i = 0; i < n; ++i)
    {
      // Welford's update over the batch means.
      const double delta = image[i] - e.image.mean[i];
      e.image.mean[i] += delta / (k + 1);
      m2[i] += delta * (image[i] - e.image.mean[i]);
    }
  }
  e.image.var = m2;
  for (double& v : e.image.var)
    v /= double(batches - 1) * batches;
  e.image.dof = batches - 1;
  e.image.spp = batches * sppPerBatch;
  e.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return e;
}

} // namespace amrdm_devcheck
