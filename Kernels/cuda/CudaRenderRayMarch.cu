// The CUDA render-pass kernel of emission-absorption ray marching: its own translation unit (see
// CudaRenderKernel.h).
#include "cuda/CudaRenderKernel.cuh"

namespace amrdm
{
namespace cuda
{
template void launchRenderPassWith<IntegratorType::RayMarch>(const PassLaunch&);
} // namespace cuda
} // namespace amrdm
