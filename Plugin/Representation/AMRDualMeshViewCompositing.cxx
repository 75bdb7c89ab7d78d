#include "AMRDualMeshViewCompositing.h"

#include "vtkInformation.h"
#include "vtkOutputWindow.h"
#include "vtkPVRenderView.h"
#include "vtkPVServerInformation.h"
#include "vtkPVSession.h"
#include "vtkProcessModule.h"

#include <mutex>

namespace amrdm_vtk
{
bool ClientOfSeveralRanks()
{
  vtkProcessModule* pm = vtkProcessModule::GetProcessModule();
  auto* session = pm ? vtkPVSession::SafeDownCast(pm->GetActiveSession()) : nullptr;
  if (!session || session->HasProcessRole(vtkPVSession::RENDER_SERVER))
  {
    return false;
  }
  vtkPVServerInformation* info = session->GetServerInformation();
  return info && info->GetNumberOfProcesses() > 1;
}

void SwitchOffFXAA(vtkInformation* inInfo)
{
  auto* view = vtkPVRenderView::SafeDownCast(inInfo->Get(vtkPVView::VIEW()));
  if (view && view->GetUseFXAA())
  {
    view->SetUseFXAA(false);
    static std::once_flag said;
    std::call_once(said,
      []
      {
        vtkOutputWindowDisplayText("Dual-Mesh Path Tracer: FXAA is switched off in this view on "
                                   "N ranks; it would blur the ranks' cuts.\n");
      });
  }
}
}
