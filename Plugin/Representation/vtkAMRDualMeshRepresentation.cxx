#include "vtkAMRDualMeshRepresentation.h"

#include "AMRDualMeshDataCache.h"
#include "AMRDualMeshIdleRefinement.h"
#include "AMRDualMeshRemovedProperties.h"
#include "AMRDualMeshVTKCompat.h"
#include "AMRDualMeshViewCompositing.h"
#include "vtkAMRDualMeshVolumeMapper.h"
#include "vtkAlgorithmOutput.h"
#include "vtkColorTransferFunction.h"
#include "vtkDataObject.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMultiProcessController.h"
#include "vtkObjectFactory.h"
#include "vtkOverlappingAMR.h"
#include "vtkPVRenderView.h"
#include "vtkPiecewiseFunction.h"
#include "vtkRenderer.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <algorithm>

vtkStandardNewMacro(vtkAMRDualMeshRepresentation);

//------------------------------------------------------------------------------
vtkAMRDualMeshRepresentation::vtkAMRDualMeshRepresentation()
  : Data(new AMRDualMeshDataCache)
  , Removed(new AMRDualMeshRemovedProperties)
  , Refine(new AMRDualMeshIdleRefinement(this->Mapper,
      this->Volume,
      [this] { return this->GetVisibility() && this->RefineWhileIdle; }))
{
  this->Volume->SetMapper(this->Mapper);
  this->Volume->SetProperty(this->Property);
  this->Property->SetInterpolationTypeToLinear();
  this->Property->SetScalarOpacityUnitDistance(1.0);
  this->Volume->SetVisibility(false); // until there is data and an array to colour by
}

//------------------------------------------------------------------------------
vtkAMRDualMeshRepresentation::~vtkAMRDualMeshRepresentation() = default;

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
  vtkOverlappingAMR* input = inputVector[0]->GetNumberOfInformationObjects() == 1
                               ? vtkOverlappingAMR::GetData(inputVector[0], 0)
                               : nullptr;
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  std::string error;
  if (!this->Data->Update(controller,
        input,
        this->DistributionMode == REPLICATED,
        this->DistributionMode == PROXY,
        error))
  {
    vtkErrorMacro("Cannot distribute the AMR over " << controller->GetNumberOfProcesses()
                                                    << " ranks: " << error);
  }
  this->Refine->DataChanged();
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
    vtkPVView::SetPiece(inInfo, this, this->Data->Cache);
    if (amrdm_vtk::ClientOfSeveralRanks())
    {
      amrdm_vtk::SwitchOffFXAA(inInfo);
    }
    vtkPVRenderView::SetGeometryBounds(
      inInfo, this, this->Data->DataBounds, this->Volume->GetMatrix());
    vtkPVRenderView::SetRequiresDistributedRendering(inInfo, this, true);
    if (this->Data->Distributed)
    {
      // Sort-last: one disjoint box per rank, blended in visibility order (premultiplied RGBA
      // over). ParaView 5.11 reads the rank's box from the geometry bounds (it ignores the
      // bounds argument below), so those are this rank's region, not the data's.
      outInfo->Set(vtkPVRenderView::NEED_ORDERED_COMPOSITING(), 1);
      vtkPVRenderView::SetOrderedCompositingConfiguration(
        inInfo, this, vtkPVRenderView::USE_BOUNDS_FOR_REDISTRIBUTION, this->Data->DataBounds);
      vtkPVRenderView::SetDeliverToClientAndRenderingProcesses(inInfo, this, false, false);
      vtkPVRenderView::SetRequiresDistributedRenderingLOD(inInfo, this, true);
      amrdm_vtk::SwitchOffFXAA(inInfo);
    }
  }
  else if (request_type == vtkPVView::REQUEST_RENDER())
  {
    vtkAlgorithmOutput* producerPort = vtkPVRenderView::GetPieceProducer(inInfo, this);
    this->Mapper->SetInputConnection(producerPort); // no-op when unchanged
    vtkOverlappingAMR* amr = producerPort ? vtkOverlappingAMR::SafeDownCast(
                                              producerPort->GetProducer()->GetOutputDataObject(0))
                                          : nullptr;
    this->HasDataToRender = amrdm_vtk::amrcompat::NumberOfBlocks(amr, 0) > 0;
    if (this->Data->Distributed)
    {
      amrdm_vtk::SwitchOffFXAA(inInfo);
      this->Mapper->SetRegion(
        this->Data->RegionIndex, this->Data->DataBounds, this->Data->DomainBounds);
      this->Mapper->SetRegionProxy(this->Data->Proxy);
    }
    else
    {
      this->Mapper->ClearRegion();
      this->Mapper->SetRegionProxy(nullptr);
    }
    this->UpdateVolumeVisibility();
    this->Removed->Report(this, this->Property);
    this->Refine->Schedule(
      vtkPVRenderView::SafeDownCast(inInfo->Get(vtkPVView::VIEW())), this->RefineWhileIdle);
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
  this->Refine->Stop();
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
    this->Refine->Stop();
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
void vtkAMRDualMeshRepresentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ColorArray: " << (this->ColorArray.empty() ? "(none)" : this->ColorArray)
     << "\n";
  os << indent << "RefineWhileIdle: " << this->RefineWhileIdle << "\n";
  os << indent << "DistributionMode: "
     << (this->DistributionMode == PROXY ? "PROXY"
                                         : (this->DistributionMode ? "REPLICATED" : "PARTITIONED"))
     << (this->Data->Distributed ? " (region " + std::to_string(this->Data->RegionIndex) + ")" : "")
     << "\n";
  os << indent << "HasDataToRender: " << this->HasDataToRender << "\n";
  os << indent << "Mapper:\n";
  this->Mapper->PrintSelf(os, indent.GetNextIndent());
}
