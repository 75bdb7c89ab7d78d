// Idle refinement of vtkAMRDualMeshRepresentation: where the view has an interactor, a one-shot
// timer after each render asks for another render while the image still needs samples (see the
// representation's class documentation). Where another process renders (a client of a
// remote-rendering pvserver), the samples are estimated: SamplesPerRender per still render while
// the mapper's accumulation key (vtkAMRDualMeshVolumeMapper::GetAccumulationKey) and the data
// stay the same.
#pragma once

#include "vtkType.h"
#include "vtkWeakPointer.h" // For vtkWeakPointer

#include <functional>

class vtkAMRDualMeshVolumeMapper;
class vtkObject;
class vtkPVRenderView;
class vtkRenderWindowInteractor;
class vtkVolume;

class AMRDualMeshIdleRefinement
{
public:
  /// `wanted` says at each timer tick whether refinement is still wanted (the representation is
  /// visible and RefineWhileIdle is on).
  AMRDualMeshIdleRefinement(vtkAMRDualMeshVolumeMapper* mapper,
    vtkVolume* volume,
    std::function<bool()> wanted);
  ~AMRDualMeshIdleRefinement();
  AMRDualMeshIdleRefinement(const AMRDualMeshIdleRefinement&) = delete;
  void operator=(const AMRDualMeshIdleRefinement&) = delete;

  /// Before each render of `view` (the REQUEST_RENDER pass): marks the mapper's render final
  /// (MarkFinalRender) in a script (pvbatch, or pvpython without an interactor) and while the
  /// view captures a screenshot; arms the timer, updates the estimate. Stops the timer instead
  /// when `enabled` is false or the view has no interactor.
  void Schedule(vtkPVRenderView* view, bool enabled);
  /// Removes the timer and the observer.
  void Stop();
  /// New data (RequestData): the estimate restarts.
  void DataChanged() { ++this->DataVersion; }

private:
  void OnTimer(vtkObject* caller, unsigned long event, void* callData);

  vtkAMRDualMeshVolumeMapper* Mapper;
  vtkVolume* Volume;
  std::function<bool()> Wanted;
  vtkWeakPointer<vtkPVRenderView> View;
  vtkWeakPointer<vtkRenderWindowInteractor> Interactor;
  unsigned long ObserverId = 0;
  int TimerId = 0;                ///< pending one-shot timer, 0 = none
  bool RenderedSinceTick = false; ///< a render pass ran since the last timer tick
  bool Interactive = false;       ///< the last render was interactive: no refinement passes
  vtkMTimeType Key = 0;           ///< the mapper's accumulation key at the last render
  unsigned long DataVersion = 0;
  unsigned long KeyDataVersion = 0;
  int EstimatedSamples = 0;
};
