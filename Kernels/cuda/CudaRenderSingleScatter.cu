// The CUDA render-pass kernel of single scattering: its own translation unit (see
// CudaRenderKernel.h).
#include "cuda/CudaRenderKernel.cuh"

namespace amrdm
{
namespace cuda
{
template void launchRenderPassWith<IntegratorType::SingleScatter>(const PassLaunch&);
} // namespace cuda
} // namespace amrdm
