// Data-parallel rendering, communication side: moves the blocks each MPI rank's region needs
// (Mapper/AMRDualMeshDistribution.h: the partition from metadata, the pieces, the assembly)
// with the process controller, in RequestData (never during Render). Collective: every rank of
// `controller` calls it with the same metadata. Not wrapped.
#ifndef AMRDualMeshRedistribution_h
#define AMRDualMeshRedistribution_h

#include "vtkSmartPointer.h" // For vtkSmartPointer

#include <array>  // For std::array
#include <string> // For std::string

class vtkMultiProcessController;
class vtkOverlappingAMR;

namespace amrdm_vtk
{
struct RegionData
{
  vtkSmartPointer<vtkOverlappingAMR> Local; ///< the region's blocks (+ ghost band), or all
  vtkSmartPointer<vtkOverlappingAMR> Proxy; ///< with `proxy`: level 0 of the whole domain
  std::array<double, 6> Region{};           ///< this rank's box (data frame)
  std::array<double, 6> Domain{};           ///< the whole domain
  int Rank = 0, NumRanks = 1;
  long long BytesSent = 0, BytesReceived = 0;
  double Seconds = 0.0; ///< wall time of partition, exchange and assembly
};

/// Partitions `input`'s domain into one box per rank and gives every rank its region's data
/// (`replicate`: every rank gets all blocks, and still draws only its box; `proxy`: every rank
/// also gets level 0 of the whole domain, out.Proxy). False with `error` (the same on every
/// rank) when it cannot; `out` then holds nothing.
bool RedistributeAMR(vtkMultiProcessController* controller,
  vtkOverlappingAMR* input,
  bool replicate,
  bool proxy,
  RegionData& out,
  std::string& error);
}

#endif
