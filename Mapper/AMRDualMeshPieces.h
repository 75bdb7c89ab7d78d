// Data-parallel rendering: the byte format of one piece of an AMR block on its way to another
// rank (AMRDualMeshDistribution.cxx packs region and proxy pieces with it and reads them back):
// level, first cell and cell counts (int32), then every named cell array with one tuple per
// cell: name, VTK type, components, byte count and the cells [lo, hi), x fastest. Not wrapped.
#ifndef AMRDualMeshPieces_h
#define AMRDualMeshPieces_h

#include <vector> // For std::vector

class vtkUniformGrid;

namespace amrdm_vtk
{
/// Appends one piece: cells [lo, hi) of the level-`level` block `grid`, whose AMR box starts at
/// `blo` with `bdims` cells (the grid must match it), every named cell array that has one
/// tuple per cell.
void PackPiece(std::vector<char>& buffer,
  unsigned level,
  vtkUniformGrid* grid,
  const int blo[3],
  const int bdims[3],
  const int lo[3],
  const int hi[3]);
}

#endif
