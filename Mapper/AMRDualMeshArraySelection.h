// Which cell array vtkAMRDualMeshVolumeMapper renders, chosen the VTK way (SelectScalarArray by
// name or index, else the active cell scalars of the first block, else its first numeric cell
// array), and the refusal of point (vertex-centred) arrays with what works instead.
#pragma once

#include <string>

class vtkOverlappingAMR;
class vtkUniformGrid;

namespace amrdm_vtk
{

/// The first block with cells, or null when the AMR data set has none.
vtkUniformGrid* FirstBlock(vtkOverlappingAMR* amr);

/// True when some block has a cell array called `name`.
bool HasCellArray(vtkOverlappingAMR* amr, const std::string& name);

enum class ArraySelection
{
  Chosen,    ///< `array` names the cell array to render
  PointData, ///< the request names point data: `message` says what works instead
  Missing    ///< nothing to render: `message` says what was asked and what exists
};

/// Chooses the array from the mapper's ScalarMode, ArrayAccessMode, ArrayId and ArrayName
/// (vtkAbstractVolumeMapper's fields). `amr` must have a block with cells (FirstBlock()).
ArraySelection SelectCellArray(vtkOverlappingAMR* amr,
  int scalarMode,
  int arrayAccessMode,
  int arrayId,
  const char* arrayName,
  std::string& array,
  std::string& message);

} // namespace amrdm_vtk
