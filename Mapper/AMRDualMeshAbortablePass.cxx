#include "AMRDualMeshAbortablePass.h"

#include "render/Renderer.h"

#include <vtkRenderWindow.h>

#include <chrono>
#include <future>

namespace amrdm_vtk
{

PassOutcome RenderAbortablePass(amrdm::Renderer& renderer,
  const amrdm::RenderParams& params,
  const float* tMax,
  const float* tMin,
  vtkRenderWindow* window)
{
  if (!window)
  {
    return renderer.renderPass(params, tMax, tMin) ? PassOutcome::Completed : PassOutcome::Aborted;
  }
  std::future<bool> pass = std::async(std::launch::async,
    [&renderer, &params, tMax, tMin] { return renderer.renderPass(params, tMax, tMin); });
  while (
    pass.wait_for(std::chrono::milliseconds(kAbortPollMilliseconds)) != std::future_status::ready)
  {
    // Asked again on every poll while the window wants to abort: a request made before the
    // worker began its pass is dropped (PassCancellation), the next one reaches it.
    if (window->CheckAbortStatus())
    {
      renderer.cancel();
    }
  }
  return pass.get() ? PassOutcome::Completed : PassOutcome::Aborted; // rethrows its exception
}

} // namespace amrdm_vtk
