// See AMRDualMeshArraySelection.h.
#include "AMRDualMeshArraySelection.h"

#include "vtkAbstractMapper.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDataSetAttributes.h"
#include "vtkOverlappingAMR.h"
#include "vtkPointData.h"
#include "vtkUniformGrid.h"

#include <cstring>

namespace amrdm_vtk
{

vtkUniformGrid* FirstBlock(vtkOverlappingAMR* amr)
{
  for (unsigned l = 0; l < amr->GetNumberOfLevels(); ++l)
  {
    for (unsigned i = 0; i < amr->GetNumberOfDataSets(l); ++i)
    {
      vtkUniformGrid* g = amr->GetDataSet(l, i);
      if (g && g->GetNumberOfCells() > 0)
      {
        return g;
      }
    }
  }
  return nullptr;
}

bool HasCellArray(vtkOverlappingAMR* amr, const std::string& name)
{
  for (unsigned l = 0; l < amr->GetNumberOfLevels(); ++l)
  {
    for (unsigned i = 0; i < amr->GetNumberOfDataSets(l); ++i)
    {
      vtkUniformGrid* g = amr->GetDataSet(l, i);
      if (g && g->GetCellData()->GetArray(name.c_str()))
      {
        return true;
      }
    }
  }
  return false;
}

ArraySelection SelectCellArray(vtkOverlappingAMR* amr,
  int scalarMode,
  int arrayAccessMode,
  int arrayId,
  const char* arrayName,
  std::string& array,
  std::string& message)
{
  array.clear();
  message.clear();
  vtkUniformGrid* first = FirstBlock(amr);
  const bool byName = arrayAccessMode == VTK_GET_ARRAY_BY_NAME && arrayName && *arrayName;
  const bool pointMode = scalarMode == VTK_SCALAR_MODE_USE_POINT_DATA ||
                         scalarMode == VTK_SCALAR_MODE_USE_POINT_FIELD_DATA;
  if (pointMode ||
      (byName && !HasCellArray(amr, arrayName) && first->GetPointData()->GetArray(arrayName)))
  {
    vtkDataArray* scalars = first->GetPointData()->GetScalars();
    const std::string name = byName                          ? arrayName
                             : scalars && scalars->GetName() ? scalars->GetName()
                                                             : "(point scalars)";
    message =
      "The array '" + name +
      "' is point (vertex-centred) data; vtkAMRDualMeshVolumeMapper renders cell data, the "
      "cell-centred AMR arrays (its dual mesh joins the cell centres). Render a cell array, or "
      "convert this one with vtkPointDataToCellData (ParaView: the Point Data to Cell Data "
      "filter) first.";
    return ArraySelection::PointData;
  }
  vtkCellData* cd = first->GetCellData();
  if (byName)
  {
    if (!HasCellArray(amr, arrayName))
    {
      message = std::string("The input has no cell array named '") + arrayName +
                "' (see SelectScalarArray()).";
      return ArraySelection::Missing;
    }
    array = arrayName;
    return ArraySelection::Chosen;
  }
  if (arrayAccessMode == VTK_GET_ARRAY_BY_ID && arrayId >= 0)
  {
    vtkDataArray* a = cd->GetArray(arrayId);
    if (!a || !a->GetName())
    {
      message = "The input has no cell array number " + std::to_string(arrayId) +
                " (see SelectScalarArray()).";
      return ArraySelection::Missing;
    }
    array = a->GetName();
    return ArraySelection::Chosen;
  }
  if (cd->GetScalars() && cd->GetScalars()->GetName())
  {
    array = cd->GetScalars()->GetName();
    return ArraySelection::Chosen;
  }
  for (int a = 0; a < cd->GetNumberOfArrays(); ++a)
  {
    const char* name = cd->GetArrayName(a);
    if (name && cd->GetArray(a) && std::strcmp(name, vtkDataSetAttributes::GhostArrayName()) != 0)
    {
      array = name;
      return ArraySelection::Chosen;
    }
  }
  message = "The input has no numeric cell arrays to render.";
  return ArraySelection::Missing;
}

} // namespace amrdm_vtk
