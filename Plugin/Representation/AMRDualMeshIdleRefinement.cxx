#include "AMRDualMeshIdleRefinement.h"

#include "vtkAMRDualMeshVolumeMapper.h"
#include "vtkCommand.h"
#include "vtkProcessModule.h"
#include "vtkPVRenderView.h"
#include "vtkRenderWindow.h"
#include "vtkRenderWindowInteractor.h"

#include <algorithm>
#include <utility>

namespace
{
/// vtkPVView::GetInCaptureScreenshot() is protected: read through a pointer to the member,
/// formed in a subclass (legal C++; no object of this class is made).
struct CaptureFlag : vtkPVView
{
  static bool Get(vtkPVView* view)
  {
    bool (vtkPVView::*get)() = &CaptureFlag::GetInCaptureScreenshot;
    return (view->*get)();
  }
};

/// Whether the view's current render is interactive for the mapper (the render window's
/// DesiredUpdateRate, which vtkPVRenderView sets to 5 in InteractiveRender(), 0.002 in
/// StillRender()).
bool IsInteractiveRender(vtkPVRenderView* view, vtkAMRDualMeshVolumeMapper* mapper)
{
  vtkRenderWindow* window = view ? view->GetRenderWindow() : nullptr;
  const double rate = mapper->GetInteractiveUpdateRate();
  return window && rate > 0.0 && window->GetDesiredUpdateRate() >= rate;
}
}

//------------------------------------------------------------------------------
AMRDualMeshIdleRefinement::AMRDualMeshIdleRefinement(vtkAMRDualMeshVolumeMapper* mapper,
  vtkVolume* volume,
  std::function<bool()> wanted)
  : Mapper(mapper)
  , Volume(volume)
  , Wanted(std::move(wanted))
{
}

AMRDualMeshIdleRefinement::~AMRDualMeshIdleRefinement()
{
  this->Stop();
}

//------------------------------------------------------------------------------
// Called in every REQUEST_RENDER pass, i.e. before each render of the view.
void AMRDualMeshIdleRefinement::Schedule(vtkPVRenderView* view, bool enabled)
{
  vtkRenderWindowInteractor* iren = view ? view->GetInteractor() : nullptr;
  // A render nobody will refine later is final: it refines to the quality target
  // (MaximumSamples or FinalRenderTime): a screenshot, and every still render of a script
  // (pvbatch; pvpython, a client without an interactor). Not a render server's: its client's
  // idle refinement adds the samples.
  const vtkProcessModule::ProcessTypes type = vtkProcessModule::GetProcessType();
  const bool script =
    type == vtkProcessModule::PROCESS_BATCH || (type == vtkProcessModule::PROCESS_CLIENT && !iren);
  this->Mapper->MarkFinalRender(view && (script || CaptureFlag::Get(view)));
  if (!enabled || !iren)
  {
    this->Stop();
    return;
  }
  if (iren != this->Interactor)
  {
    this->Stop();
    this->Interactor = iren;
    this->ObserverId =
      iren->AddObserver(vtkCommand::TimerEvent, this, &AMRDualMeshIdleRefinement::OnTimer);
  }
  this->View = view;
  this->RenderedSinceTick = true;
  // An interactive render (vtkPVRenderView::InteractiveRender()) draws a cheap frame and adds no
  // samples: no refinement until the still render that ends the interaction.
  this->Interactive = IsInteractiveRender(view, this->Mapper);

  // The estimate for remote rendering: restart on what restarts the mapper's accumulation (its
  // own key: parameters, property, camera, lights, size, clipping planes, volume matrix) and on
  // new data.
  const vtkMTimeType key = this->Mapper->GetAccumulationKey(view->GetRenderer(), this->Volume);
  if (key != this->Key || this->DataVersion != this->KeyDataVersion || this->Interactive)
  {
    this->Key = key;
    this->KeyDataVersion = this->DataVersion;
    this->EstimatedSamples = 0;
  }
  if (!this->Interactive)
  {
    this->EstimatedSamples = std::min(this->Mapper->GetMaximumSamples(),
      this->EstimatedSamples + this->Mapper->GetSamplesPerRender());
  }

  if (this->TimerId == 0)
  {
    this->TimerId = iren->CreateOneShotTimer(10);
  }
}

//------------------------------------------------------------------------------
void AMRDualMeshIdleRefinement::OnTimer(vtkObject*, unsigned long, void* callData)
{
  if (!callData || this->TimerId == 0 || *static_cast<int*>(callData) != this->TimerId)
  {
    return; // someone else's timer
  }
  this->TimerId = 0;
  vtkPVRenderView* view = this->View;
  vtkRenderWindowInteractor* iren = this->Interactor;
  if (!view || !iren || !this->Wanted() || !this->RenderedSinceTick || this->Interactive)
  {
    return;
  }
  this->RenderedSinceTick = false;
  bool more = false;
  if (view->GetUseDistributedRenderingForRender())
  {
    more = this->EstimatedSamples < this->Mapper->GetMaximumSamples(); // another process draws
  }
  else
  {
    const int samples = this->Mapper->GetNumberOfSamples(); // 0: not drawn (or an error)
    more = samples > 0 && samples < this->Mapper->GetMaximumSamples();
  }
  if (more)
  {
    iren->Render(); // ParaView's interactor helper turns this into a view-proxy StillRender()
  }
}

//------------------------------------------------------------------------------
void AMRDualMeshIdleRefinement::Stop()
{
  if (vtkRenderWindowInteractor* iren = this->Interactor)
  {
    if (this->TimerId != 0)
    {
      iren->DestroyTimer(this->TimerId);
    }
    if (this->ObserverId != 0)
    {
      iren->RemoveObserver(this->ObserverId);
    }
  }
  this->TimerId = 0;
  this->ObserverId = 0;
  this->Interactor = nullptr;
}
