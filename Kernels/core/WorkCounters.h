// The work counters a render reports, listed once. TraceCounters (transport/DeltaTracking.h)
// counts them per sample, RenderStats and PassTotals (render/Renderer.h) per pass, the CUDA
// kernel per launch (cuda/CudaRenderKernel.cuh); each declares and sums them through this list,
// so a new counter is one X(...) row here (and the code that counts it). Host/device code.
#pragma once

#include "core/HostDevice.h"

// X(name, what it counts)
// clang-format off
#define AMRDM_WORK_COUNTERS(X)                                                                     \
  X(steps, "tentative collisions (medium evaluations)")                                            \
  X(primitiveTests, "primitive tests, when the medium counts them (the DebugCost view)")         \
  X(stepLimitHits, "walks cut at RenderParams::maxStepsPerWalk")                                   \
  X(majorantViolations, "sigma_t > sigma_maj seen (a bug if ever > 0)")
// clang-format on

namespace amrdm
{

#define AMRDM_COUNT_ONE(name, doc) +1 // NOLINT(bugprone-macro-parentheses): a term of a sum
constexpr int kWorkCounterCount = 0 AMRDM_WORK_COUNTERS(AMRDM_COUNT_ONE);
#undef AMRDM_COUNT_ONE

/// to.<counter> += from.<counter> for every work counter (to may hold wider or atomic counts).
#ifdef __CUDACC__
#pragma nv_exec_check_disable
#endif
template<typename To, typename From>
AMRDM_HD void addWorkCounters(To& to, const From& from)
{
#define AMRDM_ADD_COUNTER(name, doc) to.name += from.name;
  AMRDM_WORK_COUNTERS(AMRDM_ADD_COUNTER)
#undef AMRDM_ADD_COUNTER
}

} // namespace amrdm
