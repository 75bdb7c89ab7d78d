// amrdm-devcheck's command line: defaults are the GPU protocol; CPU mode in CI passes small
// sizes and frame counts. Host code.
#pragma once

#include "render/Renderer.h"

#include <string>
#include <vector>

namespace amrdm_devcheck
{

struct DevCheckOptions
{
  /// The renderer checked against the CPU reference (cpu: a second, independent CPU render).
  amrdm::RenderDevice device = amrdm::RenderDevice::Cuda;
  std::vector<std::string> scenes;
  std::string json;          ///< summary file; empty = none
  int compareSize = 128;     ///< agreement images are compareSize x compareSize
  int batches = 16;          ///< independent batches per agreement estimate (dof = batches - 1)
  int batchSpp = 8;          ///< samples per pixel per batch
  double alpha = 0.01;       ///< chance that an unbiased device fails any comparison of the run
  int fpsSize = 1024;        ///< frames-per-second image edge
  int fpsFrames = 510;       ///< frames rendered; the mean is over frames 11..fpsFrames
  double fpsSeconds = 60.0;  ///< wall-time cap of one frames-per-second run
  int threads = 0;           ///< CPU threads (0 = all cores)
  bool requirePower = false; ///< fail when a 1.5x denser medium on the device is not rejected
  bool help = false;
};

/// Parses argv; false with `error` naming the bad option and what was expected.
bool parseDevCheckOptions(int argc, char* argv[], DevCheckOptions& out, std::string& error);

std::string devCheckUsage();

} // namespace amrdm_devcheck
