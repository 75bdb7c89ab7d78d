// Data-parallel rendering, data side: the partition of a vtkOverlappingAMR's domain into one box
// per MPI rank, computed from the AMR's metadata alone (the same on every rank: a kd-tree cut on
// level-0 cell faces, balanced by leaf cells; Kernels/mesh/DomainPartition.h), and the pieces of
// blocks each region needs, packed for an exchange and assembled into the region's own
// vtkOverlappingAMR. No communication here: the ParaView representation moves the buffers.
//
// A region's pieces: every block cropped to the region plus its ghost band (one cell of each
// level, DomainPartition's tight rule, rounded out to the coarser level's cell faces so that the
// cropped boxes stay aligned and properly nested). Refinement flags (vtkGhostType REFINEDCELL)
// of the assembled blocks come from the global metadata, never from what is local, so the
// region's dual mesh equals the serial one inside the region (TestDomainPartition proves the
// rule); hidden/duplicate flags of the input travel with the data.
#ifndef AMRDualMeshDistribution_h
#define AMRDualMeshDistribution_h

#include "AMRDualMeshMapperModule.h" // For export macro
#include "vtkSmartPointer.h"         // For vtkSmartPointer

#include <array>  // For std::array
#include <string> // For std::string
#include <vector> // For std::vector

class vtkOverlappingAMR;

namespace amrdm_vtk
{
/// One box per region, in the AMR's data frame (xmin, xmax, ymin, ymax, zmin, zmax).
struct AMRPartition
{
  std::vector<std::array<double, 6>> Regions;
  std::array<double, 6> Domain{}; ///< bounding box of the level-0 boxes (the union of Regions)
  std::vector<double> LeafCells;  ///< estimated leaf cells per region (the balance)
};

/// The partition of `amr`'s domain (metadata: boxes, spacings, origin) into `numRegions`
/// boxes. False with `error` set when the metadata has no level-0 box, the spacings give no
/// integer refinement ratios, or there are more regions than level-0 cells.
AMRDUALMESHMAPPER_EXPORT bool PartitionAMR(vtkOverlappingAMR* amr,
  int numRegions,
  AMRPartition& out,
  std::string& error);

/// Appends to `buffer` the pieces of `amr`'s local blocks (those with data on this process)
/// that region `region` needs; with `whole`, every local block uncropped (replicated data).
/// All numeric cell arrays travel. False with `error` when a block's grid does not match its
/// AMR box.
AMRDUALMESHMAPPER_EXPORT bool PackRegionPieces(vtkOverlappingAMR* amr,
  const AMRPartition& partition,
  int region,
  bool whole,
  std::vector<char>& buffer,
  std::string& error);

/// The region's vtkOverlappingAMR from the received `buffers` (as PackRegionPieces wrote
/// them): `metadata`'s levels, origin and spacings, one block per piece, refinement flags from
/// `metadata`'s boxes. Null with `error` on a malformed buffer; an AMR with no levels when no
/// piece arrived.
AMRDUALMESHMAPPER_EXPORT vtkSmartPointer<vtkOverlappingAMR> AssembleRegion(
  vtkOverlappingAMR* metadata,
  const std::vector<std::vector<char>>& buffers,
  std::string& error);
}

#endif
