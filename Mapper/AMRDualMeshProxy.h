// Data-parallel rendering, DistributionMode Proxy: the small copy of the whole domain that every
// rank holds so that scattered and shadow rays see the other regions. It is level 0 alone (no
// cell refined: each holds the level-0 value, which AMR codes average down from the finer
// levels), averaged further over f^3 cells (f a power of two) when level 0 has more than
// kProxyMaxCells cells. Every rank packs its level-0 blocks (PackCoarseBlocks), an all-gather
// moves them (the ParaView representation), and every rank assembles the same proxy
// (AssembleCoarse). No communication here. Not wrapped.
#ifndef AMRDualMeshProxy_h
#define AMRDualMeshProxy_h

#include "AMRDualMeshMapperModule.h" // For export macro
#include "vtkSmartPointer.h"         // For vtkSmartPointer

#include <string> // For std::string
#include <vector> // For std::vector

class vtkOverlappingAMR;

namespace amrdm_vtk
{
/// At most this many proxy cells (64^3: about 2.6 MB of dual mesh, 1 MB per float array), unless
/// no power-of-two coarsening of the domain gets there.
constexpr long long kProxyMaxCells = 1LL << 18;

/// Appends every local level-0 block of `amr` whole. False with `error` when a block's grid
/// does not match its AMR box.
AMRDUALMESHMAPPER_EXPORT bool PackCoarseBlocks(vtkOverlappingAMR* amr,
  std::vector<char>& buffer,
  std::string& error);

/// The proxy from every rank's PackCoarseBlocks buffer and `metadata` (levels, boxes, origin,
/// spacings): one level; level 0 itself when it has at most `maxCells` cells, else one block of
/// the domain averaged over f^3 level-0 cells, f the smallest power of two that divides the
/// domain's cell counts and corner and brings it to at most `maxCells` (or the largest such f).
/// A coarse cell averages the level-0 cells below it that are not hidden (per component, for
/// every numeric cell array); one with none is hidden. Null with `error` on a malformed buffer.
AMRDUALMESHMAPPER_EXPORT vtkSmartPointer<vtkOverlappingAMR> AssembleCoarse(
  vtkOverlappingAMR* metadata,
  const std::vector<std::vector<char>>& buffers,
  long long maxCells,
  std::string& error);
}

#endif
