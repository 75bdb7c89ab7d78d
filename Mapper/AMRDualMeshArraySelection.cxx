// See AMRDualMeshArraySelection.h.
#include "AMRDualMeshArraySelection.h"
#include "AMRDualMeshVTKCompat.h"

#include "vtkAbstractMapper.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDataObject.h"
#include "vtkDataSetAttributes.h"
#include "vtkOverlappingAMR.h"
#include "vtkPointData.h"
#include "vtkImageData.h"

#include <cstring>

namespace amrdm_vtk
{

vtkImageData* FirstBlock(vtkOverlappingAMR* amr)
{
  for (unsigned l = 0; l < amrcompat::NumberOfLevels(amr); ++l)
  {
    for (unsigned i = 0; i < amrcompat::NumberOfBlocks(amr, l); ++i)
    {
      vtkImageData* g = amrcompat::Block(amr, l, i);
      if (g && g->GetNumberOfCells() > 0)
      {
        return g;
      }
    }
  }
  return nullptr;
}

namespace
{
bool HasArray(vtkOverlappingAMR* amr, const std::string& name, bool points)
{
  for (unsigned l = 0; l < amrcompat::NumberOfLevels(amr); ++l)
  {
    for (unsigned i = 0; i < amrcompat::NumberOfBlocks(amr, l); ++i)
    {
      vtkImageData* g = amrcompat::Block(amr, l, i);
      vtkDataSetAttributes* a = !g
                                  ? nullptr
                                  : (points ? static_cast<vtkDataSetAttributes*>(g->GetPointData())
                                            : static_cast<vtkDataSetAttributes*>(g->GetCellData()));
      if (a && a->GetArray(name.c_str()))
      {
        return true;
      }
    }
  }
  return false;
}

/// The active scalars, else the first numeric array that is not the ghost array.
const char* DefaultArray(vtkDataSetAttributes* attributes)
{
  if (attributes->GetScalars() && attributes->GetScalars()->GetName())
  {
    return attributes->GetScalars()->GetName();
  }
  for (int a = 0; a < attributes->GetNumberOfArrays(); ++a)
  {
    const char* name = attributes->GetArrayName(a);
    if (name && attributes->GetArray(a) && std::strcmp(name, amrcompat::GhostArrayName()) != 0)
    {
      return name;
    }
  }
  return nullptr;
}
} // namespace

bool HasCellArray(vtkOverlappingAMR* amr, const std::string& name)
{
  return HasArray(amr, name, false);
}

bool HasPointArray(vtkOverlappingAMR* amr, const std::string& name)
{
  return HasArray(amr, name, true);
}

ArraySelection SelectArray(vtkOverlappingAMR* amr,
  int scalarMode,
  int arrayAccessMode,
  int arrayId,
  const char* arrayName,
  std::string& array,
  int& association,
  std::string& message)
{
  array.clear();
  message.clear();
  association = vtkDataObject::FIELD_ASSOCIATION_CELLS;
  vtkImageData* first = FirstBlock(amr);
  const bool byName = arrayAccessMode == VTK_GET_ARRAY_BY_NAME && arrayName && *arrayName;
  const bool pointMode = scalarMode == VTK_SCALAR_MODE_USE_POINT_DATA ||
                         scalarMode == VTK_SCALAR_MODE_USE_POINT_FIELD_DATA;
  const bool cellMode = scalarMode == VTK_SCALAR_MODE_USE_CELL_DATA ||
                        scalarMode == VTK_SCALAR_MODE_USE_CELL_FIELD_DATA;
  if (byName)
  {
    const bool cell = !pointMode && HasCellArray(amr, arrayName);
    const bool point = !cellMode && !cell && HasPointArray(amr, arrayName);
    if (!cell && !point)
    {
      const char* kind = pointMode ? "point" : (cellMode ? "cell" : "cell or point");
      message = std::string("The input has no ") + kind + " array named '" + arrayName + "'";
      if (cellMode && HasPointArray(amr, arrayName))
      {
        message += " (it is a point array: call SetScalarModeToUsePointFieldData())";
      }
      else if (pointMode && HasCellArray(amr, arrayName))
      {
        message += " (it is a cell array: call SetScalarModeToUseCellFieldData())";
      }
      message += " (see SelectScalarArray()).";
      return ArraySelection::Missing;
    }
    array = arrayName;
    association =
      point ? vtkDataObject::FIELD_ASSOCIATION_POINTS : vtkDataObject::FIELD_ASSOCIATION_CELLS;
    return ArraySelection::Chosen;
  }
  vtkDataSetAttributes* cd = first->GetCellData();
  vtkDataSetAttributes* pd = first->GetPointData();
  vtkDataSetAttributes* chosen = pointMode ? pd : cd;
  if (arrayAccessMode == VTK_GET_ARRAY_BY_ID && arrayId >= 0)
  {
    vtkDataArray* a = chosen->GetArray(arrayId);
    if (!a || !a->GetName())
    {
      message = std::string("The input has no ") + (pointMode ? "point" : "cell") +
                " array number " + std::to_string(arrayId) + " (see SelectScalarArray()).";
      return ArraySelection::Missing;
    }
    array = a->GetName();
    association =
      pointMode ? vtkDataObject::FIELD_ASSOCIATION_POINTS : vtkDataObject::FIELD_ASSOCIATION_CELLS;
    return ArraySelection::Chosen;
  }
  const char* name = DefaultArray(chosen);
  if (!name && !pointMode && !cellMode)
  {
    chosen = pd; // the default mode falls back to point data when there is no cell array
    name = DefaultArray(pd);
  }
  if (!name)
  {
    message = std::string("The input has no numeric ") + (chosen == pd ? "point" : "cell") +
              " arrays to render.";
    return ArraySelection::Missing;
  }
  array = name;
  association =
    chosen == pd ? vtkDataObject::FIELD_ASSOCIATION_POINTS : vtkDataObject::FIELD_ASSOCIATION_CELLS;
  return ArraySelection::Chosen;
}

int ResolveAssociation(vtkOverlappingAMR* input, const std::string& array, int requested)
{
  if (requested == vtkDataObject::FIELD_ASSOCIATION_POINTS ||
      requested == vtkDataObject::FIELD_ASSOCIATION_CELLS)
  {
    return requested;
  }
  if (requested != -1)
  {
    return -2;
  }
  if (input && !array.empty() && !HasCellArray(input, array) && HasPointArray(input, array))
  {
    return vtkDataObject::FIELD_ASSOCIATION_POINTS;
  }
  return vtkDataObject::FIELD_ASSOCIATION_CELLS;
}
} // namespace amrdm_vtk
