// The CUDA render-pass kernel of the path tracer (delta tracking, NEE, multiple scattering): its
// own translation unit (see CudaRenderKernel.h).
#include "cuda/CudaRenderKernel.cuh"

namespace amrdm
{
namespace cuda
{
template void launchRenderPassWith<IntegratorType::PathTracer>(const PassLaunch&);
} // namespace cuda
} // namespace amrdm
