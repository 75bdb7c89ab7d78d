// Which array vtkAMRDualMeshVolumeMapper renders, chosen the VTK way: the ScalarMode picks the
// association (point modes: point data, the vertex-centred field; cell modes: cell data; the
// default mode: cell data, else point data), SelectScalarArray picks the array by name or
// index, else the active scalars of the first block, else its first numeric array.
#pragma once

#include <string>

class vtkOverlappingAMR;
class vtkImageData;

namespace amrdm_vtk
{

/// The first block with cells, or null when the AMR data set has none.
vtkImageData* FirstBlock(vtkOverlappingAMR* amr);

/// True when some block has a cell array called `name`.
bool HasCellArray(vtkOverlappingAMR* amr, const std::string& name);
/// True when some block has a point array called `name`.
bool HasPointArray(vtkOverlappingAMR* amr, const std::string& name);

/// The association to build (vtkDataObject::FIELD_ASSOCIATION_*) from vtkAMRDualMesh's
/// ArrayAssociation: `requested` when it is points or cells, else (-1) cells when a cell array
/// has the name, else points when a point array has it, else cells (the intake then says that
/// the array is missing). -2 when `requested` is none of these.
int ResolveAssociation(vtkOverlappingAMR* input, const std::string& array, int requested);

enum class ArraySelection
{
  Chosen, ///< `array` names the array to render, `association` says where it lives
  Missing ///< nothing to render: `message` says what was asked and what exists
};

/// Chooses the array from the mapper's ScalarMode, ArrayAccessMode, ArrayId and ArrayName
/// (vtkAbstractVolumeMapper's fields). `amr` must have a block with cells (FirstBlock()).
/// `association` is vtkDataObject::FIELD_ASSOCIATION_CELLS or FIELD_ASSOCIATION_POINTS.
ArraySelection SelectArray(vtkOverlappingAMR* amr,
  int scalarMode,
  int arrayAccessMode,
  int arrayId,
  const char* arrayName,
  std::string& array,
  int& association,
  std::string& message);

} // namespace amrdm_vtk
