#include "vtkAMRDualMeshRepresentation.h"

#include "AMRDualMeshRedistribution.h"
#include "vtkAMRDualMeshVolumeMapper.h"
#include "vtkAlgorithmOutput.h"
#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkCommand.h"
#include "vtkDataObject.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkMultiProcessController.h"
#include "vtkObjectFactory.h"
#include "vtkOverlappingAMR.h"
#include "vtkProcessModule.h"
#include "vtkOutputWindow.h"
#include "vtkPVRenderView.h"
#include "vtkPVServerInformation.h"
#include "vtkPVSession.h"
#include "vtkPiecewiseFunction.h"
#include "vtkRenderWindow.h"
#include "vtkRenderWindowInteractor.h"
#include "vtkRenderer.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"
#include "vtkWeakPointer.h"

#include <algorithm>
#include <array>
#include <mutex>

namespace
{
/// A client connected to a server of several ranks (whose views take the client's FXAA
/// setting with every render).
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

/// FXAA runs on each rank's image before IceT composites them: it blurs the hard edge where a
/// region's image ends, and the blur shows along every cut (measured: up to 15/255 off one
/// rank's image). Switched off on the view of a distributed representation and on a client's
/// view of several server ranks, before the update and before each render; said once per
/// process.
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

/// Bookkeeping of the idle refinement (only used where the view has an interactor).
struct vtkAMRDualMeshRepresentation::Refinement
{
  vtkWeakPointer<vtkPVRenderView> View;
  vtkWeakPointer<vtkRenderWindowInteractor> Interactor;
  unsigned long ObserverId = 0;
  int TimerId = 0;                ///< pending one-shot timer, 0 = none
  bool RenderedSinceTick = false; ///< a render pass ran since the last timer tick
  bool Interactive = false;       ///< the last render was interactive: no refinement passes
  // Where another process renders (client of a remote-rendering pvserver), the samples are
  // estimated: SamplesPerRender per render while nothing that resets the accumulation changed.
  std::array<double, 13> ViewState{};
  vtkMTimeType ConfigTime = 0;
  unsigned long DataVersion = 0;
  unsigned long StateDataVersion = 0;
  int EstimatedSamples = 0;
};

namespace
{
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

vtkStandardNewMacro(vtkAMRDualMeshRepresentation);

//------------------------------------------------------------------------------
vtkAMRDualMeshRepresentation::vtkAMRDualMeshRepresentation()
  : Refine(new Refinement)
{
  vtkMath::UninitializeBounds(this->DataBounds);
  this->Volume->SetMapper(this->Mapper);
  this->Volume->SetProperty(this->Property);
  this->Property->SetInterpolationTypeToLinear();
  this->Property->SetScalarOpacityUnitDistance(1.0);
  this->Volume->SetVisibility(false); // until there is data and an array to colour by
}

//------------------------------------------------------------------------------
vtkAMRDualMeshRepresentation::~vtkAMRDualMeshRepresentation()
{
  this->StopRefinement();
  delete this->Refine;
}

//------------------------------------------------------------------------------
int vtkAMRDualMeshRepresentation::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkOverlappingAMR");
  info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  return 1;
}

//------------------------------------------------------------------------------
int vtkAMRDualMeshRepresentation::RequestData(vtkInformation* request,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  // A new cache object each time: the mapper rebuilds its dual mesh only for new data.
  vtkSmartPointer<vtkOverlappingAMR> cache = vtkSmartPointer<vtkOverlappingAMR>::New();
  vtkMath::UninitializeBounds(this->DataBounds);
  this->Distributed = false;
  this->RegionIndex = -1;
  this->Proxy = nullptr;
  vtkOverlappingAMR* input = inputVector[0]->GetNumberOfInformationObjects() == 1
                               ? vtkOverlappingAMR::GetData(inputVector[0], 0)
                               : nullptr;
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  if (controller && controller->GetNumberOfProcesses() > 1)
  {
    // N ranks (pvbatch, pvserver): every rank gets its region's blocks (and a ghost band) and
    // draws only its box; IceT blends the boxes back to front. Collective: every rank is here.
    amrdm_vtk::RegionData region;
    std::string error;
    if (amrdm_vtk::RedistributeAMR(controller,
          input,
          this->DistributionMode == REPLICATED,
          this->DistributionMode == PROXY,
          region,
          error))
    {
      cache = region.Local;
      this->Proxy = region.Proxy;
      this->Distributed = true;
      this->RegionIndex = region.Rank;
      std::copy(region.Region.begin(), region.Region.end(), this->DataBounds);
      std::copy(region.Domain.begin(), region.Domain.end(), this->DomainBounds);
      this->RedistributionSeconds = region.Seconds;
      this->RedistributedBytes = region.BytesReceived;
    }
    else if (input && input->GetNumberOfLevels() > 0)
    {
      vtkErrorMacro("Cannot distribute the AMR over " << controller->GetNumberOfProcesses()
                                                      << " ranks: " << error);
      input = nullptr; // nothing drawn: unordered local pieces would be wrong
    }
  }
  else if (input)
  {
    cache->ShallowCopy(input);
    if (cache->GetNumberOfLevels() > 0)
    {
      cache->GetBounds(this->DataBounds);
    }
  }
  this->Cache = cache;
  ++this->Refine->DataVersion;
  return this->Superclass::RequestData(request, inputVector, outputVector);
}

//------------------------------------------------------------------------------
void vtkAMRDualMeshRepresentation::SetDistributionMode(int mode)
{
  mode = std::min(std::max(mode, int(PARTITIONED)), int(PROXY));
  if (mode != this->DistributionMode)
  {
    this->DistributionMode = mode;
    this->MarkModified(); // the data moves again in the next RequestData
  }
}

//------------------------------------------------------------------------------
int vtkAMRDualMeshRepresentation::ProcessViewRequest(vtkInformationRequestKey* request_type,
  vtkInformation* inInfo,
  vtkInformation* outInfo)
{
  if (!this->Superclass::ProcessViewRequest(request_type, inInfo, outInfo))
  {
    return 0; // not visible: nothing to do
  }
  if (request_type == vtkPVView::REQUEST_UPDATE())
  {
    // The data stays where it is: the (render) server draws the volume, the client gets pixels.
    vtkPVView::SetPiece(inInfo, this, this->Cache);
    if (ClientOfSeveralRanks())
    {
      SwitchOffFXAA(inInfo);
    }
    vtkPVRenderView::SetGeometryBounds(inInfo, this, this->DataBounds, this->Volume->GetMatrix());
    vtkPVRenderView::SetRequiresDistributedRendering(inInfo, this, true);
    if (this->Distributed)
    {
      // Sort-last: one disjoint box per rank, blended in visibility order (premultiplied RGBA
      // over). ParaView 5.11 reads the rank's box from the geometry bounds (it ignores the
      // bounds argument below), so those are this rank's region, not the data's.
      outInfo->Set(vtkPVRenderView::NEED_ORDERED_COMPOSITING(), 1);
      vtkPVRenderView::SetOrderedCompositingConfiguration(
        inInfo, this, vtkPVRenderView::USE_BOUNDS_FOR_REDISTRIBUTION, this->DataBounds);
      vtkPVRenderView::SetDeliverToClientAndRenderingProcesses(inInfo, this, false, false);
      vtkPVRenderView::SetRequiresDistributedRenderingLOD(inInfo, this, true);
      SwitchOffFXAA(inInfo);
    }
  }
  else if (request_type == vtkPVView::REQUEST_RENDER())
  {
    vtkAlgorithmOutput* producerPort = vtkPVRenderView::GetPieceProducer(inInfo, this);
    this->Mapper->SetInputConnection(producerPort); // no-op when unchanged
    vtkOverlappingAMR* amr = producerPort ? vtkOverlappingAMR::SafeDownCast(
                                              producerPort->GetProducer()->GetOutputDataObject(0))
                                          : nullptr;
    this->HasDataToRender = amr && amr->GetNumberOfLevels() > 0 && amr->GetNumberOfDataSets(0) > 0;
    if (this->Distributed)
    {
      SwitchOffFXAA(inInfo);
      this->Mapper->SetRegion(this->RegionIndex, this->DataBounds, this->DomainBounds);
      this->Mapper->SetRegionProxy(this->Proxy);
    }
    else
    {
      this->Mapper->ClearRegion();
      this->Mapper->SetRegionProxy(nullptr);
    }
    this->UpdateVolumeVisibility();
    this->ReportRemovedProperties();
    this->ScheduleRefinement(vtkPVRenderView::SafeDownCast(inInfo->Get(vtkPVView::VIEW())));
  }
  return 1;
}

//------------------------------------------------------------------------------
bool vtkAMRDualMeshRepresentation::AddToView(vtkView* view)
{
  vtkPVRenderView* rview = vtkPVRenderView::SafeDownCast(view);
  if (!rview)
  {
    return false;
  }
  rview->GetRenderer()->AddVolume(this->Volume);
  return this->Superclass::AddToView(view);
}

//------------------------------------------------------------------------------
bool vtkAMRDualMeshRepresentation::RemoveFromView(vtkView* view)
{
  vtkPVRenderView* rview = vtkPVRenderView::SafeDownCast(view);
  if (!rview)
  {
    return false;
  }
  this->StopRefinement();
  rview->GetRenderer()->RemoveVolume(this->Volume);
  return this->Superclass::RemoveFromView(view);
}

//------------------------------------------------------------------------------
void vtkAMRDualMeshRepresentation::SetVisibility(bool val)
{
  this->Superclass::SetVisibility(val);
  this->UpdateVolumeVisibility();
  if (!val)
  {
    this->StopRefinement();
  }
}

//------------------------------------------------------------------------------
void vtkAMRDualMeshRepresentation::UpdateVolumeVisibility()
{
  this->Volume->SetVisibility(
    this->GetVisibility() && this->HasDataToRender && !this->ColorArray.empty());
}

//------------------------------------------------------------------------------
void vtkAMRDualMeshRepresentation::SetInputArrayToProcess(int idx,
  int port,
  int connection,
  int fieldAssociation,
  const char* name)
{
  this->Superclass::SetInputArrayToProcess(idx, port, connection, fieldAssociation, name);
  // Cell arrays render through the dual mesh, point arrays as vertex-centred data (the mapper's
  // point scalar mode). Other associations (or no array, "Solid Color") draw nothing.
  const bool cells = fieldAssociation == vtkDataObject::FIELD_ASSOCIATION_CELLS;
  const bool points = fieldAssociation == vtkDataObject::FIELD_ASSOCIATION_POINTS;
  this->ColorArray = ((cells || points) && name) ? name : "";
  if (!this->ColorArray.empty())
  {
    const int mode =
      cells ? VTK_SCALAR_MODE_USE_CELL_FIELD_DATA : VTK_SCALAR_MODE_USE_POINT_FIELD_DATA;
    if (this->Mapper->GetScalarMode() != mode)
    {
      this->Mapper->SetScalarMode(mode);
    }
    const char* current = this->Mapper->GetArrayName();
    if (this->Mapper->GetArrayAccessMode() != VTK_GET_ARRAY_BY_NAME || !current ||
        this->ColorArray != current)
    {
      this->Mapper->SelectScalarArray(this->ColorArray.c_str());
    }
  }
  this->UpdateVolumeVisibility();
}

//------------------------------------------------------------------------------
// Idle refinement. Called in every REQUEST_RENDER pass, i.e. before each render of the view.
void vtkAMRDualMeshRepresentation::ScheduleRefinement(vtkPVRenderView* view)
{
  Refinement& r = *this->Refine;
  vtkRenderWindowInteractor* iren = view ? view->GetInteractor() : nullptr;
  if (!this->RefineWhileIdle || !iren)
  {
    this->StopRefinement();
    return;
  }
  if (iren != r.Interactor)
  {
    this->StopRefinement();
    r.Interactor = iren;
    r.ObserverId = iren->AddObserver(
      vtkCommand::TimerEvent, this, &vtkAMRDualMeshRepresentation::OnRefinementTimer);
  }
  r.View = view;
  r.RenderedSinceTick = true;
  // An interactive render (vtkPVRenderView::InteractiveRender()) draws a cheap frame and adds no
  // samples: no refinement until the still render that ends the interaction.
  r.Interactive = IsInteractiveRender(view, this->Mapper);

  // The estimate for remote rendering: restart on what restarts the mapper's accumulation.
  std::array<double, 13> state{};
  if (vtkCamera* camera = view->GetActiveCamera())
  {
    camera->GetPosition(&state[0]);
    camera->GetFocalPoint(&state[3]);
    camera->GetViewUp(&state[6]);
    state[9] = camera->GetViewAngle();
    state[10] = camera->GetParallelScale() * (camera->GetParallelProjection() ? 1 : -1);
  }
  const int* size = view->GetSize();
  state[11] = size[0];
  state[12] = size[1];
  const vtkMTimeType config = std::max(this->Mapper->GetMTime(), this->Property->GetMTime());
  if (state != r.ViewState || config != r.ConfigTime || r.DataVersion != r.StateDataVersion ||
      r.Interactive)
  {
    r.ViewState = state;
    r.ConfigTime = config;
    r.StateDataVersion = r.DataVersion;
    r.EstimatedSamples = 0;
  }
  if (!r.Interactive)
  {
    r.EstimatedSamples = std::min(
      this->Mapper->GetMaximumSamples(), r.EstimatedSamples + this->Mapper->GetSamplesPerRender());
  }

  if (r.TimerId == 0)
  {
    r.TimerId = iren->CreateOneShotTimer(10);
  }
}

//------------------------------------------------------------------------------
void vtkAMRDualMeshRepresentation::OnRefinementTimer(vtkObject*, unsigned long, void* callData)
{
  Refinement& r = *this->Refine;
  if (!callData || r.TimerId == 0 || *static_cast<int*>(callData) != r.TimerId)
  {
    return; // someone else's timer
  }
  r.TimerId = 0;
  vtkPVRenderView* view = r.View;
  vtkRenderWindowInteractor* iren = r.Interactor;
  if (!view || !iren || !this->GetVisibility() || !this->RefineWhileIdle || !r.RenderedSinceTick ||
      r.Interactive)
  {
    return;
  }
  r.RenderedSinceTick = false;
  bool more = false;
  if (view->GetUseDistributedRenderingForRender())
  {
    more = r.EstimatedSamples < this->Mapper->GetMaximumSamples(); // another process draws
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
void vtkAMRDualMeshRepresentation::StopRefinement()
{
  Refinement& r = *this->Refine;
  if (vtkRenderWindowInteractor* iren = r.Interactor)
  {
    if (r.TimerId != 0)
    {
      iren->DestroyTimer(r.TimerId);
    }
    if (r.ObserverId != 0)
    {
      iren->RemoveObserver(r.ObserverId);
    }
  }
  r.TimerId = 0;
  r.ObserverId = 0;
  r.Interactor = nullptr;
}

//------------------------------------------------------------------------------
void vtkAMRDualMeshRepresentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ColorArray: " << (this->ColorArray.empty() ? "(none)" : this->ColorArray)
     << "\n";
  os << indent << "RefineWhileIdle: " << this->RefineWhileIdle << "\n";
  os << indent << "DistributionMode: "
     << (this->DistributionMode == PROXY ? "PROXY"
                                         : (this->DistributionMode ? "REPLICATED" : "PARTITIONED"))
     << (this->Distributed ? " (region " + std::to_string(this->RegionIndex) + ")" : "") << "\n";
  os << indent << "HasDataToRender: " << this->HasDataToRender << "\n";
  os << indent << "Mapper:\n";
  this->Mapper->PrintSelf(os, indent.GetNextIndent());
}
