// One render pass that VTK's abort check can stop: the pass runs on a worker thread while the
// calling (render) thread polls vtkRenderWindow::CheckAbortStatus(), which fires the window's
// AbortCheckEvent (vtkRenderWindowInteractor and ParaView's views set AbortRender there when
// the user has moved on, e.g. a pending mouse event). While the window asks to abort, the
// renderer's cancel() is called (amrdm::PassCancellation: it stops the running pass between
// tiles; finished tiles keep exact per-pixel samples, so the image stays a valid mean). The
// abort check runs on the calling thread only: observers (Qt event polling) are not thread
// safe. Private to the mapper; not wrapped.
#ifndef AMRDualMeshAbortablePass_h
#define AMRDualMeshAbortablePass_h

#include "render/RenderParams.h" // amrdm::RenderParams (and glm)

class vtkRenderWindow;

namespace amrdm
{
class Renderer;
}

namespace amrdm_vtk
{

/// How often the render thread asks the window whether to abort, in milliseconds.
constexpr int kAbortPollMilliseconds = 5;

enum class PassOutcome
{
  Completed, ///< every pixel got its samples
  Aborted    ///< the window asked to abort; finished tiles kept their samples
};

/// renderer.renderPass(params, tMax, tMin) with VTK's abort check. `window` may be null (no
/// abort check: the pass runs on the calling thread). Exceptions of the pass are rethrown here.
PassOutcome RenderAbortablePass(amrdm::Renderer& renderer,
  const amrdm::RenderParams& params,
  const float* tMax,
  const float* tMin,
  vtkRenderWindow* window);

} // namespace amrdm_vtk

#endif
