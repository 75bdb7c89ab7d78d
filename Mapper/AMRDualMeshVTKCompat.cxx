#include "AMRDualMeshVTKCompat.h"

#include "vtkAMRBox.h"
#include "vtkCellData.h"
#include "vtkDataSet.h"
#include "vtkImageData.h"
#include "vtkOverlappingAMR.h"
#include "vtkUniformGrid.h"
#include "vtkUnsignedCharArray.h"
#include "vtkVersionMacros.h"

// VTK's AMR rewrite: vtkAMRDataObject with GetDataSetAs{ImageData,CartesianGrid},
// GetNumberOfBlocks(level) and Initialize(vector) landed on VTK master with merge 2966f83a
// (2025-09-11, in 9.6.0). Older versions (9.2 ... 9.5, ParaView 5.11 ... 6.0) have
// vtkUniformGridAMR's GetDataSet(level, id), GetNumberOfDataSets and Initialize(int, const int*),
// which 9.6/9.7 deprecate and VTK master removed. Master snapshots dated 2025-06-26 ... 2025-09-10
// carry half of the change and are not supported.
#if VTK_VERSION_NUMBER >= VTK_VERSION_CHECK(9, 5, 20250911)
#define AMRDM_VTK_AMR_2025 1
#include "vtkCartesianGrid.h"
#else
#define AMRDM_VTK_AMR_2025 0
#endif

namespace amrdm_vtk
{
namespace amrcompat
{
const char* APIName()
{
#if AMRDM_VTK_AMR_2025
  return "vtkAMRDataObject (VTK >= 9.6)";
#else
  return "vtkUniformGridAMR (VTK <= 9.5)";
#endif
}

unsigned NumberOfLevels(vtkOverlappingAMR* amr)
{
  return amr ? amr->GetNumberOfLevels() : 0U;
}

unsigned NumberOfBlocks(vtkOverlappingAMR* amr, unsigned level)
{
  if (!amr || level >= amr->GetNumberOfLevels())
  {
    return 0;
  }
#if AMRDM_VTK_AMR_2025
  return amr->GetNumberOfBlocks(level);
#else
  return amr->GetNumberOfDataSets(level);
#endif
}

BlockState BlockAt(vtkOverlappingAMR* amr, unsigned level, unsigned id, vtkImageData*& grid)
{
  grid = nullptr;
  if (id >= NumberOfBlocks(amr, level))
  {
    return BlockState::Absent;
  }
#if AMRDM_VTK_AMR_2025
  vtkCartesianGrid* block = amr->GetDataSetAsCartesianGrid(level, id);
  if (!block)
  {
    return BlockState::Absent;
  }
  grid = vtkImageData::SafeDownCast(block);
  return grid ? BlockState::Image : BlockState::Unsupported;
#else
  grid = amr->GetDataSet(level, id);
  return grid ? BlockState::Image : BlockState::Absent;
#endif
}

vtkImageData* Block(vtkOverlappingAMR* amr, unsigned level, unsigned id)
{
  vtkImageData* grid = nullptr;
  BlockAt(amr, level, id, grid);
  return grid;
}

std::string UnsupportedBlockMessage(vtkOverlappingAMR* amr, unsigned level, unsigned id)
{
  std::string what = "not a vtkImageData";
#if AMRDM_VTK_AMR_2025
  if (vtkCartesianGrid* block = amr ? amr->GetDataSetAsCartesianGrid(level, id) : nullptr)
  {
    what = std::string("a ") + block->GetClassName();
  }
#else
  (void)amr;
#endif
  return "level " + std::to_string(level) + " block " + std::to_string(id) + " is " + what +
         "; the dual mesh needs uniform (vtkImageData / vtkUniformGrid) AMR levels";
}

const vtkAMRBox& Box(vtkOverlappingAMR* amr, unsigned level, unsigned id)
{
  return amr->GetAMRBox(level, id);
}

void SetBox(vtkOverlappingAMR* amr, unsigned level, unsigned id, const vtkAMRBox& box)
{
  amr->SetAMRBox(level, id, box);
}

void Spacing(vtkOverlappingAMR* amr, unsigned level, double h[3])
{
  amr->GetSpacing(level, h);
}

void SetSpacing(vtkOverlappingAMR* amr, unsigned level, const double h[3])
{
  amr->SetSpacing(level, h);
}

const double* Origin(vtkOverlappingAMR* amr)
{
  return amr->GetOrigin();
}

void SetOrigin(vtkOverlappingAMR* amr, const double origin[3])
{
  amr->SetOrigin(origin);
}

void SetRefinementRatio(vtkOverlappingAMR* amr, unsigned level, int ratio)
{
  amr->SetRefinementRatio(level, ratio);
}

int GridDescription(vtkOverlappingAMR* amr)
{
  return amr->GetGridDescription();
}

void SetGridDescription(vtkOverlappingAMR* amr, int description)
{
  amr->SetGridDescription(description);
}

void InitializeLevels(vtkOverlappingAMR* amr, const std::vector<unsigned>& blocksPerLevel)
{
#if AMRDM_VTK_AMR_2025
  amr->Initialize(blocksPerLevel);
#else
  const std::vector<int> counts(blocksPerLevel.begin(), blocksPerLevel.end());
  amr->Initialize(static_cast<int>(counts.size()), counts.data());
#endif
}

vtkSmartPointer<vtkImageData> NewBlock()
{
  // vtkUniformGrid in every version: 9.2 stores nothing else, and VTK 9.6+ keeps one block class
  // per overlapping AMR (the readers make vtkUniformGrid too).
  return vtkSmartPointer<vtkUniformGrid>::New();
}

bool SetBlock(vtkOverlappingAMR* amr,
  unsigned level,
  unsigned id,
  vtkImageData* grid,
  std::string& error)
{
  const std::string where = "level " + std::to_string(level) + " block " + std::to_string(id);
  if (!amr || !grid)
  {
    error = "cannot store " + where + ": expected an AMR data set and a grid";
    return false;
  }
  if (id >= NumberOfBlocks(amr, level))
  {
    error = "cannot store " + where + ": the AMR has " +
            std::to_string(NumberOfBlocks(amr, level)) + " blocks on that level";
    return false;
  }
#if AMRDM_VTK_AMR_2025
  amr->SetDataSet(level, id, grid);
  if (amr->GetDataSetAsCartesianGrid(level, id) != grid)
  {
    error = "VTK refused " + where + " (a " + grid->GetClassName() +
            "); expected one block class and grid description per AMR data set";
    return false;
  }
#else
  vtkUniformGrid* uniform = vtkUniformGrid::SafeDownCast(grid);
  if (!uniform)
  {
    error = "cannot store " + where + ": it is a " + grid->GetClassName() +
            "; expected a vtkUniformGrid block (VTK <= 9.5)";
    return false;
  }
  amr->SetDataSet(level, id, uniform);
#endif
  return true;
}

vtkUnsignedCharArray* CellGhosts(vtkDataSet* grid)
{
  return grid ? vtkUnsignedCharArray::SafeDownCast(
                  grid->GetCellData()->GetArray(vtkDataSetAttributes::GhostArrayName()))
              : nullptr;
}

const char* GhostArrayName()
{
  return vtkDataSetAttributes::GhostArrayName();
}
}
}
