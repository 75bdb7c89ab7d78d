// Data-parallel rendering: the byte format of one piece of an AMR block on its way to another
// rank (AMRDualMeshDistribution.cxx packs region and proxy pieces with it and reads them back):
// level, first cell and cell counts (int32), then every named cell array with one tuple per
// cell: name, VTK type, components, byte count and the cells [lo, hi), x fastest. Not wrapped.
#ifndef AMRDualMeshPieces_h
#define AMRDualMeshPieces_h

#include <string> // For std::string
#include <vector> // For std::vector

class vtkImageData;

class vtkOverlappingAMR;

namespace amrdm_vtk
{
/// Block `id` of `level`: true with its first cell and cell counts (its AMR box) when its grid
/// is loaded on this process; false with `error` empty when it is not, and false with `error`
/// set (naming the block, the axis and both counts) when the grid does not match its box.
bool LoadedBlock(vtkOverlappingAMR* amr,
  unsigned level,
  unsigned id,
  int blo[3],
  int bdims[3],
  std::string& error);

/// Appends one piece: cells [lo, hi) of the level-`level` block `grid`, whose AMR box starts at
/// `blo` with `bdims` cells (the grid must match it), every named cell array that has one
/// tuple per cell.
void PackPiece(std::vector<char>& buffer,
  unsigned level,
  vtkImageData* grid,
  const int blo[3],
  const int bdims[3],
  const int lo[3],
  const int hi[3]);
}

#endif
