#include "AMRDualMeshProxy.h"

#include "AMRDualMeshDistribution.h"
#include "AMRDualMeshPieces.h"
#include "AMRDualMeshVTKCompat.h"
#include "vtkAMRBox.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDataSetAttributes.h"
#include "vtkNew.h"
#include "vtkOverlappingAMR.h"
#include "vtkImageData.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <climits>

namespace amrdm_vtk
{
namespace
{
/// Level 0 of `fine` (one level, blocks of equal arrays) averaged over f^3 cells into one
/// block covering [lo, lo + dims) level-0 cells.
vtkSmartPointer<vtkOverlappingAMR> Coarsen(vtkOverlappingAMR* fine,
  const int lo[3],
  const int dims[3],
  int f,
  std::string& error)
{
  int cdims[3], clo[3], chi[3];
  for (int d = 0; d < 3; ++d)
  {
    cdims[d] = dims[d] / f;
    clo[d] = lo[d] / f;
    chi[d] = clo[d] + cdims[d] - 1;
  }
  const vtkIdType cells = vtkIdType(cdims[0]) * cdims[1] * cdims[2];
  double h[3];
  amrcompat::Spacing(fine, 0, h);
  const double* origin = amrcompat::Origin(fine);
  vtkSmartPointer<vtkImageData> grid = amrcompat::NewBlock();
  grid->SetDimensions(cdims[0] + 1, cdims[1] + 1, cdims[2] + 1);
  grid->SetSpacing(h[0] * f, h[1] * f, h[2] * f);
  grid->SetOrigin(origin[0] + lo[0] * h[0], origin[1] + lo[1] * h[1], origin[2] + lo[2] * h[2]);
  // Sums per coarse cell and component, and the count of visible cells below it.
  std::vector<double> count(static_cast<std::size_t>(cells), 0.0);
  struct Sum
  {
    vtkDataArray* like;
    std::vector<double> values;
  };
  std::vector<Sum> sums;
  for (unsigned id = 0; id < amrcompat::NumberOfBlocks(fine, 0); ++id)
  {
    vtkImageData* block = amrcompat::Block(fine, 0, id);
    if (!block)
    {
      continue;
    }
    const vtkAMRBox& box = amrcompat::Box(fine, 0, id);
    const int* blo = box.GetLoCorner();
    int bdims[3];
    block->GetDimensions(bdims);
    vtkCellData* cd = block->GetCellData();
    vtkUnsignedCharArray* ghosts = amrcompat::CellGhosts(block);
    if (sums.empty())
    {
      for (int a = 0; a < cd->GetNumberOfArrays(); ++a)
      {
        vtkDataArray* array = cd->GetArray(a);
        if (array && array->GetName() && array != ghosts)
        {
          sums.push_back({ array,
            std::vector<double>(
              static_cast<std::size_t>(cells) * array->GetNumberOfComponents()) });
        }
      }
    }
    // This block's arrays by name, in the order of `sums` (null where it lacks one).
    std::vector<vtkDataArray*> arrays;
    for (const Sum& s : sums)
    {
      vtkDataArray* array = cd->GetArray(s.like->GetName());
      const bool fits = array && array->GetNumberOfTuples() == block->GetNumberOfCells() &&
                        array->GetNumberOfComponents() == s.like->GetNumberOfComponents();
      arrays.push_back(fits ? array : nullptr);
    }
    const int n[3] = { bdims[0] - 1, bdims[1] - 1, bdims[2] - 1 };
    for (int z = 0; z < n[2]; ++z)
      for (int y = 0; y < n[1]; ++y)
        for (int x = 0; x < n[0]; ++x)
        {
          const vtkIdType i = (vtkIdType(z) * n[1] + y) * n[0] + x;
          if (ghosts && (ghosts->GetValue(i) & amrcompat::HiddenCell))
          {
            continue;
          }
          const vtkIdType c =
            (vtkIdType((blo[2] + z - lo[2]) / f) * cdims[1] + (blo[1] + y - lo[1]) / f) * cdims[0] +
            (blo[0] + x - lo[0]) / f;
          count[static_cast<std::size_t>(c)] += 1.0;
          for (std::size_t s = 0; s < sums.size(); ++s)
          {
            const int comps = arrays[s] ? sums[s].like->GetNumberOfComponents() : 0;
            for (int k = 0; k < comps; ++k)
            {
              sums[s].values[static_cast<std::size_t>(c) * comps + k] +=
                arrays[s]->GetComponent(i, k);
            }
          }
        }
  }
  vtkNew<vtkUnsignedCharArray> hidden;
  hidden->SetName(amrcompat::GhostArrayName());
  hidden->SetNumberOfTuples(cells);
  for (vtkIdType c = 0; c < cells; ++c)
  {
    hidden->SetValue(c, count[static_cast<std::size_t>(c)] > 0.0 ? 0 : amrcompat::HiddenCell);
  }
  grid->GetCellData()->AddArray(hidden);
  for (const Sum& s : sums)
  {
    vtkSmartPointer<vtkDataArray> out = vtkSmartPointer<vtkDataArray>::Take(s.like->NewInstance());
    out->SetName(s.like->GetName());
    const int comps = s.like->GetNumberOfComponents();
    out->SetNumberOfComponents(comps);
    out->SetNumberOfTuples(cells);
    for (vtkIdType c = 0; c < cells; ++c)
    {
      const double w = count[static_cast<std::size_t>(c)];
      for (int k = 0; k < comps; ++k)
      {
        out->SetComponent(
          c, k, w > 0.0 ? s.values[static_cast<std::size_t>(c) * comps + k] / w : 0.0);
      }
    }
    grid->GetCellData()->AddArray(out);
  }
  auto result = vtkSmartPointer<vtkOverlappingAMR>::New();
  amrcompat::InitializeLevels(result, { 1U });
  amrcompat::SetOrigin(result, origin);
  amrcompat::SetGridDescription(result, amrcompat::GridDescription(fine));
  const double ch[3] = { h[0] * f, h[1] * f, h[2] * f };
  amrcompat::SetSpacing(result, 0, ch);
  amrcompat::SetBox(result, 0, 0, vtkAMRBox(clo, chi));
  if (!amrcompat::SetBlock(result, 0, 0, grid, error))
  {
    return nullptr;
  }
  return result;
}
}

bool PackCoarseBlocks(vtkOverlappingAMR* amr, std::vector<char>& buffer, std::string& error)
{
  if (amrcompat::NumberOfLevels(amr) == 0)
  {
    return true; // nothing here: other ranks hold level 0
  }
  for (unsigned id = 0; id < amrcompat::NumberOfBlocks(amr, 0); ++id)
  {
    int blo[3], bdims[3], hi[3];
    if (!LoadedBlock(amr, 0, id, blo, bdims, error))
    {
      if (!error.empty())
      {
        return false;
      }
      continue; // not loaded here
    }
    for (int d = 0; d < 3; ++d)
    {
      hi[d] = blo[d] + bdims[d];
    }
    vtkImageData* grid = amrcompat::Block(amr, 0, id);
    PackPiece(buffer, 0, grid, blo, bdims, blo, hi);
  }
  return true;
}

vtkSmartPointer<vtkOverlappingAMR> AssembleCoarse(vtkOverlappingAMR* metadata,
  const std::vector<std::vector<char>>& buffers,
  long long maxCells,
  std::string& error)
{
  if (amrcompat::NumberOfLevels(metadata) == 0)
  {
    error = "the AMR data set has no levels; expected at least one level-0 box";
    return nullptr;
  }
  vtkNew<vtkOverlappingAMR> coarse;
  amrcompat::InitializeLevels(coarse, { amrcompat::NumberOfBlocks(metadata, 0) });
  amrcompat::SetOrigin(coarse, amrcompat::Origin(metadata));
  amrcompat::SetGridDescription(coarse, amrcompat::GridDescription(metadata));
  double h[3];
  amrcompat::Spacing(metadata, 0, h);
  amrcompat::SetSpacing(coarse, 0, h);
  int lo[3] = { INT_MAX, INT_MAX, INT_MAX }, hi[3] = { INT_MIN, INT_MIN, INT_MIN };
  for (unsigned id = 0; id < amrcompat::NumberOfBlocks(metadata, 0); ++id)
  {
    const vtkAMRBox& box = amrcompat::Box(metadata, 0, id);
    amrcompat::SetBox(coarse, 0, id, box);
    for (int d = 0; d < 3; ++d)
    {
      lo[d] = std::min(lo[d], box.GetLoCorner()[d]);
      hi[d] = std::max(hi[d], box.GetHiCorner()[d] + 1);
    }
  }
  vtkSmartPointer<vtkOverlappingAMR> level0 = AssembleRegion(coarse, buffers, error);
  if (amrcompat::NumberOfLevels(level0) == 0)
  {
    return level0;
  }
  const int dims[3] = { hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2] };
  const long long cells = 1LL * dims[0] * dims[1] * dims[2];
  int f = 1;
  for (int g = 2; cells / (1LL * f * f * f) > maxCells; g *= 2)
  {
    bool divides = true;
    for (int d = 0; d < 3; ++d)
    {
      divides = divides && dims[d] % g == 0 && lo[d] % g == 0;
    }
    if (!divides)
    {
      break;
    }
    f = g;
  }
  return f == 1 ? level0 : Coarsen(level0, lo, dims, f, error);
}
}
