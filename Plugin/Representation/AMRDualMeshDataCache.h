// The representation's data cache: what RequestData keeps for the view. On one process a
// shallow copy of the input; on N > 1 MPI ranks (pvbatch, pvserver) this rank's region of the
// AMR (and a ghost band), the level-0 proxy when asked for, and the region's and the domain's
// boxes (AMRDualMeshRedistribution.h moves the blocks). Not wrapped.
#ifndef AMRDualMeshDataCache_h
#define AMRDualMeshDataCache_h

#include "vtkSmartPointer.h" // For vtkSmartPointer

#include <string> // For std::string

class vtkMultiProcessController;
class vtkOverlappingAMR;

class AMRDualMeshDataCache
{
public:
  AMRDualMeshDataCache();

  /// Caches `input` (nullptr: nothing). With several ranks in `controller` this is collective:
  /// every rank calls it (`replicate`: every rank holds all blocks; `proxy`: plus level 0 of
  /// the whole domain). False with `error` when the AMR cannot be distributed: then nothing is
  /// cached (unordered local pieces would be wrong).
  bool Update(vtkMultiProcessController* controller,
    vtkOverlappingAMR* input,
    bool replicate,
    bool proxy,
    std::string& error);

  vtkSmartPointer<vtkOverlappingAMR> Cache; ///< a new object each Update (the mapper rebuilds)
  vtkSmartPointer<vtkOverlappingAMR> Proxy; ///< level 0 of the domain (proxy mode), else null
  double DataBounds[6];                     ///< the data's, or this rank's region when distributed
  double DomainBounds[6] = { 0, 0, 0, 0, 0, 0 };
  bool Distributed = false; ///< the last Update distributed the AMR over the ranks
  int RegionIndex = -1;     ///< this rank's region; -1 when not distributed
  double RedistributionSeconds = 0.0;
  double RedistributedBytes = 0.0;
};

#endif
