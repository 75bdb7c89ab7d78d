#include "AMRDualMeshInputSlot.h"

#include "AMRDualMeshArraySelection.h"
#include "AMRDualMeshRegion.h"
#include "vtkAMRDualMesh.h"
#include "vtkAMRDualMeshVolumeMapper.h"
#include "vtkAlgorithm.h"
#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkIndent.h"
#include "vtkMath.h"
#include "vtkOverlappingAMR.h"

#include <algorithm>

//------------------------------------------------------------------------------
AMRDualMeshInputSlot::AMRDualMeshInputSlot(vtkAMRDualMeshVolumeMapper* owner)
  : Owner(owner)
{
  this->ProgressForwarder->SetCallback(&AMRDualMeshInputSlot::ForwardProgress);
  this->ProgressForwarder->SetClientData(owner);
  this->Mesh->AddObserver(vtkCommand::ProgressEvent, this->ProgressForwarder);
  this->ErrorCatcher->SetCallback(&AMRDualMeshInputSlot::CatchError);
  this->ErrorCatcher->SetClientData(&this->MeshError);
  this->Mesh->AddObserver(vtkCommand::ErrorEvent, this->ErrorCatcher);
  this->ProxyMesh->AddObserver(vtkCommand::ErrorEvent, this->ErrorCatcher);
}

AMRDualMeshInputSlot::~AMRDualMeshInputSlot() = default;

void AMRDualMeshInputSlot::ForwardProgress(vtkObject*,
  unsigned long,
  void* clientData,
  void* callData)
{
  if (callData)
  {
    static_cast<vtkAlgorithm*>(clientData)->UpdateProgress(*static_cast<double*>(callData));
  }
}

void AMRDualMeshInputSlot::CatchError(vtkObject*, unsigned long, void* clientData, void* callData)
{
  *static_cast<std::string*>(clientData) =
    callData ? static_cast<const char*>(callData) : "unknown error";
}

//------------------------------------------------------------------------------
vtkOverlappingAMR* AMRDualMeshInputSlot::UpdateAndGetInput()
{
  vtkAlgorithm* owner = this->Owner;
  if (owner->GetNumberOfInputConnections(0) < 1)
  {
    return nullptr;
  }
  vtkDataObject* data = owner->GetInputDataObject(0, 0);
  // A data object of the wrong type is refused before the pipeline sees it.
  if (data && !vtkOverlappingAMR::SafeDownCast(data))
  {
    return nullptr;
  }
  if (vtkAlgorithm* producer = owner->GetInputAlgorithm())
  {
    producer->Update();
  }
  return vtkOverlappingAMR::SafeDownCast(owner->GetInputDataObject(0, 0));
}

vtkOverlappingAMR* AMRDualMeshInputSlot::CheckInput()
{
  vtkAlgorithm* owner = this->Owner;
  if (owner->GetNumberOfInputConnections(0) < 1 || !owner->GetInputDataObject(0, 0))
  {
    vtkErrorWithObjectMacro(
      owner, "No input: call SetInputData(vtkOverlappingAMR*) or SetInputConnection().");
    return nullptr;
  }
  vtkDataObject* data = owner->GetInputDataObject(0, 0);
  if (!vtkOverlappingAMR::SafeDownCast(data))
  {
    vtkErrorWithObjectMacro(owner,
      "The input is a " << data->GetClassName()
                        << "; vtkAMRDualMeshVolumeMapper renders vtkOverlappingAMR only "
                           "(use vtkSmartVolumeMapper for other data sets).");
    return nullptr;
  }
  vtkOverlappingAMR* amr = this->UpdateAndGetInput();
  if (!amr)
  {
    vtkErrorWithObjectMacro(owner, "The input is not a vtkOverlappingAMR after its update.");
  }
  return amr;
}

//------------------------------------------------------------------------------
bool AMRDualMeshInputSlot::Update(vtkOverlappingAMR* amr,
  const amrdm_vtk::RegionClip& region,
  bool& meshLost)
{
  meshLost = false;
  if (!amrdm_vtk::FirstBlock(amr))
  {
    vtkErrorWithObjectMacro(this->Owner,
      "The vtkOverlappingAMR input is empty (no blocks with cells); nothing to render.");
    return false;
  }
  // The array and its association (point data: the vertex-centred field), chosen the VTK way.
  std::string array, message;
  int association = 0;
  if (amrdm_vtk::SelectArray(amr,
        this->Owner->GetScalarMode(),
        this->Owner->GetArrayAccessMode(),
        this->Owner->GetArrayId(),
        this->Owner->GetArrayName(),
        array,
        association,
        message) == amrdm_vtk::ArraySelection::Missing)
  {
    vtkErrorWithObjectMacro(this->Owner, << message);
    return false;
  }
  this->Mesh->SetArrayAssociation(association);
  if (!this->Build(this->Mesh, amr, array))
  {
    vtkErrorWithObjectMacro(
      this->Owner, "Cannot build the dual mesh of '" << array << "': " << this->MeshError);
    meshLost = true;
    return false;
  }
  // The region's proxy: the same array and build parameters.
  if (this->ProxyInput && region.Active() && !this->Build(this->ProxyMesh, this->ProxyInput, array))
  {
    vtkErrorWithObjectMacro(this->Owner,
      "Cannot build the dual mesh of the region's proxy ('" << array << "'): " << this->MeshError
                                                            << "; drawing without it.");
    this->ProxyInput = nullptr;
  }
  return true;
}

bool AMRDualMeshInputSlot::Build(vtkAMRDualMesh* mesh,
  vtkOverlappingAMR* amr,
  const std::string& array)
{
  if (mesh->GetInputData() != amr)
  {
    mesh->SetInputData(amr);
  }
  if (!mesh->GetArrayName() || array != mesh->GetArrayName())
  {
    mesh->SetArrayName(array.c_str());
  }
  mesh->SetArrayAssociation(this->Mesh->GetArrayAssociation()); // the proxy's too
  mesh->SetGridletSize(this->Owner->GetGridletSize());
  mesh->SetBVHLeafSize(this->Owner->GetBVHLeafSize());
  mesh->SetNumberOfThreads(this->Owner->GetNumberOfThreads());
  this->MeshError.clear();
  return mesh->Update();
}

//------------------------------------------------------------------------------
bool AMRDualMeshInputSlot::SetProxy(vtkOverlappingAMR* proxy)
{
  if (this->ProxyInput == proxy)
  {
    return false;
  }
  this->ProxyInput = proxy;
  return true;
}

const amrdm::DualMesh* AMRDualMeshInputSlot::GetProxyToRender(
  const amrdm_vtk::RegionClip& region) const
{
  return this->ProxyInput && region.Active() ? this->ProxyMesh->GetDualMesh() : nullptr;
}

void AMRDualMeshInputSlot::PrintRegion(std::ostream& os,
  vtkIndent indent,
  const amrdm_vtk::RegionClip& region,
  bool proxyAccepted) const
{
  os << indent << "RegionIndex: " << region.Index << (region.Active() ? "" : " (none)") << "\n";
  os << indent << "RegionProxy: "
     << (this->ProxyInput ? (proxyAccepted ? "in use" : "set, not in use") : "none");
  if (this->ProxyInput && this->ProxyMesh->GetDualMesh())
  {
    os << " (" << this->ProxyMesh->GetNumberOfLeafCells() << " leaf cells, "
       << this->ProxyMesh->GetTotalBytes() << " bytes)";
  }
  os << "\n";
}

//------------------------------------------------------------------------------
void AMRDualMeshInputSlot::GetBounds(const amrdm_vtk::RegionClip& region, double bounds[6])
{
  vtkOverlappingAMR* amr = this->UpdateAndGetInput();
  if (!amr || !amrdm_vtk::FirstBlock(amr))
  {
    vtkMath::UninitializeBounds(bounds);
  }
  else if (region.Active())
  {
    std::copy(region.Bounds, region.Bounds + 6, bounds);
  }
  else
  {
    amr->GetBounds(bounds);
  }
}
