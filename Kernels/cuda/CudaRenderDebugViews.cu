// The CUDA render-pass kernels of the debug views (primitive colours, cost heat map): one
// translation unit for both (see CudaRenderKernel.h).
#include "cuda/CudaRenderKernel.cuh"

namespace amrdm
{
namespace cuda
{
template void launchRenderPassWith<IntegratorType::DebugPrimitive>(const PassLaunch&);
template void launchRenderPassWith<IntegratorType::DebugCost>(const PassLaunch&);
} // namespace cuda
} // namespace amrdm
