// The benchmark's mode: image size, time budgets per reference and per knob, and the settings
// of every knob that amrdm-bench sweeps. quickMode() is the smoke-test mode (--quick). The full
// mode's budgets keep the whole of Benchmarks/run.sh within 30 minutes on 2 cores (amrdm-bench
// about 8 of them on the four sets; run.sh prints each phase's wall time).
#pragma once

#include "render/RendererFactory.h"

#include <vector>

namespace amrdm_bench
{

struct Mode
{
  bool quick = false;
  /// The renderer timed in the "renderer" rows (the shipped CpuRenderer / CudaRenderer through
  /// the factory); every other row times the benchmark loop on the CPU.
  amrdm::RenderDevice device = amrdm::RenderDevice::Auto;
  int width = 256, height = 256;
  double ptRefBudget = 40.0; ///< seconds for the path-traced reference
  int ptRefMinSpp = 64, ptRefMaxSpp = 2048;
  double sppBudget = 20.0; ///< seconds for the progressive spp curve
  int sppMax = 1024;
  int knobFrames = 8;      ///< frames per knob setting (median time; image spp)
  double knobBudget = 4.0; ///< fewer frames (>= 5) when a frame is slower than budget/frames
  double rmRefBudget = 30.0;
  int rmRefMinSpp = 4, rmRefMaxSpp = 64;
  int rmFrames = 8;
  double rmBudget = 8.0; ///< per step size
  std::vector<int> uniformN{ 64, 128, 256 };
  std::vector<int> newton{ 1, 2, 3, 5 };
  std::vector<int> gridlets{ 2, 4, 8, 16 };
  std::vector<int> bvhLeaves{ 2, 4, 8, 16 };
  std::vector<int> majorantCells{ 2, 8, 32 };
  std::vector<int> bounces{ 0, 1, 4, 16 };
  std::vector<double> rmSteps{ 0.5, 1, 2, 4, 8, 16 };
  /// Level-adaptive ray marching (RenderParams::samplesPerCell), step floor = the base step.
  std::vector<double> rmSamplesPerCell{ 0.5, 1, 2, 4 };
};

inline Mode quickMode()
{
  Mode m;
  m.quick = true;
  m.width = m.height = 64;
  m.ptRefBudget = 3.0;
  m.ptRefMinSpp = 16;
  m.ptRefMaxSpp = 256;
  m.sppBudget = 2.0;
  m.sppMax = 64;
  m.knobFrames = 5;
  m.knobBudget = 1.0;
  m.rmRefBudget = 2.0;
  m.rmRefMinSpp = 2;
  m.rmRefMaxSpp = 16;
  m.rmFrames = 5;
  m.rmBudget = 1.0;
  m.uniformN = { 64 };
  m.newton = { 1 };
  m.gridlets = { 2, 4, 8, 16 };
  m.majorantCells = { 32 };
  m.bounces = { 0, 4 };
  m.rmSteps = { 1, 4 };
  m.rmSamplesPerCell = { 1 };
  return m;
}

} // namespace amrdm_bench
