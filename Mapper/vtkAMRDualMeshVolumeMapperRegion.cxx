// vtkAMRDualMeshVolumeMapper: data-parallel rendering. The region this process draws (its
// box and the domain's, set by the ParaView representation on N MPI ranks) and the region's
// proxy (DistributionMode Proxy: level 0 of the whole domain) with its own dual mesh, which
// the renderer slot (AMRDualMeshRendererSlot) hands to the renderer.
#include "vtkAMRDualMeshVolumeMapperInternals.h"

//------------------------------------------------------------------------------
void vtkAMRDualMeshVolumeMapper::SetRegion(int index,
  const double regionBounds[6],
  const double domainBounds[6])
{
  amrdm_vtk::RegionClip& region = this->Internal->Region;
  bool same = region.Active() && region.Index == index;
  for (int i = 0; i < 6 && same; ++i)
  {
    same = region.Bounds[i] == regionBounds[i] && region.Domain[i] == domainBounds[i];
  }
  if (!same)
  {
    region.Set(index, regionBounds, domainBounds);
    this->Modified();
  }
}

void vtkAMRDualMeshVolumeMapper::ClearRegion()
{
  if (this->Internal->Region.Active())
  {
    this->Internal->Region.Clear();
    this->Modified();
  }
}

int vtkAMRDualMeshVolumeMapper::GetRegionIndex()
{
  return this->Internal->Region.Index;
}

void vtkAMRDualMeshVolumeMapper::SetRegionProxy(vtkOverlappingAMR* proxy)
{
  if (this->Internal->ProxyInput != proxy)
  {
    this->Internal->ProxyInput = proxy;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkAMRDualMeshVolumeMapper::UpdateRegionProxy(const std::string& array)
{
  Internals& in = *this->Internal;
  if (!in.ProxyInput || !in.Region.Active())
  {
    return;
  }
  // The region's proxy: the same array and build parameters.
  if (!this->BuildDualMesh(in.ProxyMesh, in.ProxyInput, array))
  {
    vtkErrorMacro("Cannot build the dual mesh of the region's proxy ('"
                  << array << "'): " << in.MeshError << "; drawing without it.");
    in.ProxyInput = nullptr;
  }
}

//------------------------------------------------------------------------------
void vtkAMRDualMeshVolumeMapper::PrintRegion(ostream& os, vtkIndent indent)
{
  const Internals& in = *this->Internal;
  os << indent << "RegionIndex: " << in.Region.Index << (in.Region.Active() ? "" : " (none)")
     << "\n";
  os << indent << "RegionProxy: "
     << (in.ProxyInput ? (in.Slot.GetProxyAccepted() ? "in use" : "set, not in use") : "none");
  if (in.ProxyInput && in.ProxyMesh->GetDualMesh())
  {
    os << " (" << in.ProxyMesh->GetNumberOfLeafCells() << " leaf cells, "
       << in.ProxyMesh->GetTotalBytes() << " bytes)";
  }
  os << "\n";
}
