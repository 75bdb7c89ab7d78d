// The CUDA render-pass kernels of the integrators without a translation unit of their own (the
// rows of render/IntegratorList.h with ownCudaUnit 0: the debug views, and any new integrator
// until it earns its own unit; see CudaRenderKernel.h).
#include "cuda/CudaRenderKernel.cuh"

namespace amrdm
{
namespace cuda
{
#define AMRDM_INSTANTIATE_0(type)                                                                  \
  template void launchRenderPassWith<IntegratorType::type>(const PassLaunch&);
#define AMRDM_INSTANTIATE_1(type)
#define AMRDM_INSTANTIATE(type, shortName, name, vtkName, ownCudaUnit, ...)                        \
  AMRDM_INSTANTIATE_##ownCudaUnit(type)
AMRDM_INTEGRATORS(AMRDM_INSTANTIATE)
#undef AMRDM_INSTANTIATE
#undef AMRDM_INSTANTIATE_1
#undef AMRDM_INSTANTIATE_0
} // namespace cuda
} // namespace amrdm
