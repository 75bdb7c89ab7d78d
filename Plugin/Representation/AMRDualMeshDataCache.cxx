#include "AMRDualMeshDataCache.h"

#include "AMRDualMeshRedistribution.h"
#include "AMRDualMeshVTKCompat.h"
#include "vtkMath.h"
#include "vtkMultiProcessController.h"
#include "vtkOverlappingAMR.h"

#include <algorithm>

AMRDualMeshDataCache::AMRDualMeshDataCache()
{
  vtkMath::UninitializeBounds(this->DataBounds);
}

bool AMRDualMeshDataCache::Update(vtkMultiProcessController* controller,
  vtkOverlappingAMR* input,
  bool replicate,
  bool proxy,
  std::string& error)
{
  // A new cache object each time: the mapper rebuilds its dual mesh only for new data.
  vtkSmartPointer<vtkOverlappingAMR> cache = vtkSmartPointer<vtkOverlappingAMR>::New();
  vtkMath::UninitializeBounds(this->DataBounds);
  this->Distributed = false;
  this->RegionIndex = -1;
  this->Proxy = nullptr;
  this->Cache = cache;
  if (controller && controller->GetNumberOfProcesses() > 1)
  {
    // N ranks: every rank gets its region's blocks (and a ghost band) and draws only its box;
    // IceT blends the boxes back to front. Collective: every rank is here.
    amrdm_vtk::RegionData region;
    if (!amrdm_vtk::RedistributeAMR(controller, input, replicate, proxy, region, error))
    {
      return amrdm_vtk::amrcompat::NumberOfLevels(input) == 0; // no data is no error
    }
    this->Cache = region.Local;
    this->Proxy = region.Proxy;
    this->Distributed = true;
    this->RegionIndex = region.Rank;
    std::copy(region.Region.begin(), region.Region.end(), this->DataBounds);
    std::copy(region.Domain.begin(), region.Domain.end(), this->DomainBounds);
    this->RedistributionSeconds = region.Seconds;
    this->RedistributedBytes = region.BytesReceived;
  }
  else if (input)
  {
    cache->ShallowCopy(input);
    if (amrdm_vtk::amrcompat::NumberOfLevels(cache) > 0)
    {
      cache->GetBounds(this->DataBounds);
    }
  }
  return true;
}
