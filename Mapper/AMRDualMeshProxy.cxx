#include "AMRDualMeshProxy.h"

#include "AMRDualMeshDistribution.h"
#include "AMRDualMeshPieces.h"
#include "vtkAMRBox.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDataSetAttributes.h"
#include "vtkNew.h"
#include "vtkOverlappingAMR.h"
#include "vtkUniformGrid.h"
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
  int f)
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
  fine->GetSpacing(0, h);
  const double* origin = fine->GetOrigin();
  vtkNew<vtkUniformGrid> grid;
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
  for (unsigned id = 0; id < fine->GetNumberOfDataSets(0); ++id)
  {
    vtkUniformGrid* block = fine->GetDataSet(0, id);
    if (!block)
    {
      continue;
    }
    const vtkAMRBox& box = fine->GetAMRBox(0, id);
    const int* blo = box.GetLoCorner();
    int bdims[3];
    block->GetDimensions(bdims);
    vtkCellData* cd = block->GetCellData();
    auto* ghosts =
      vtkUnsignedCharArray::SafeDownCast(cd->GetArray(vtkDataSetAttributes::GhostArrayName()));
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
          if (ghosts && (ghosts->GetValue(i) & vtkDataSetAttributes::HIDDENCELL))
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
  hidden->SetName(vtkDataSetAttributes::GhostArrayName());
  hidden->SetNumberOfTuples(cells);
  for (vtkIdType c = 0; c < cells; ++c)
  {
    hidden->SetValue(c,
      count[static_cast<std::size_t>(c)] > 0.0
        ? 0
        : static_cast<unsigned char>(vtkDataSetAttributes::HIDDENCELL));
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
  const int one = 1;
  result->Initialize(1, &one);
  result->SetOrigin(origin);
  result->SetGridDescription(fine->GetGridDescription());
  const double ch[3] = { h[0] * f, h[1] * f, h[2] * f };
  result->SetSpacing(0, ch);
  result->SetAMRBox(0, 0, vtkAMRBox(clo, chi));
  result->SetDataSet(0, 0, grid);
  return result;
}
}

bool PackCoarseBlocks(vtkOverlappingAMR* amr, std::vector<char>& buffer, std::string& error)
{
  if (!amr || amr->GetNumberOfLevels() == 0)
  {
    return true; // nothing here: other ranks hold level 0
  }
  for (unsigned id = 0; id < amr->GetNumberOfDataSets(0); ++id)
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
    vtkUniformGrid* grid = amr->GetDataSet(0, id);
    PackPiece(buffer, 0, grid, blo, bdims, blo, hi);
  }
  return true;
}

vtkSmartPointer<vtkOverlappingAMR> AssembleCoarse(vtkOverlappingAMR* metadata,
  const std::vector<std::vector<char>>& buffers,
  long long maxCells,
  std::string& error)
{
  if (!metadata || metadata->GetNumberOfLevels() == 0)
  {
    error = "the AMR data set has no levels; expected at least one level-0 box";
    return nullptr;
  }
  vtkNew<vtkOverlappingAMR> coarse;
  const int blocks = static_cast<int>(metadata->GetNumberOfDataSets(0));
  coarse->Initialize(1, &blocks);
  coarse->SetOrigin(metadata->GetOrigin());
  coarse->SetGridDescription(metadata->GetGridDescription());
  double h[3];
  metadata->GetSpacing(0, h);
  coarse->SetSpacing(0, h);
  int lo[3] = { INT_MAX, INT_MAX, INT_MAX }, hi[3] = { INT_MIN, INT_MIN, INT_MIN };
  for (unsigned id = 0; id < metadata->GetNumberOfDataSets(0); ++id)
  {
    const vtkAMRBox& box = metadata->GetAMRBox(0, id);
    coarse->SetAMRBox(0, id, box);
    for (int d = 0; d < 3; ++d)
    {
      lo[d] = std::min(lo[d], box.GetLoCorner()[d]);
      hi[d] = std::max(hi[d], box.GetHiCorner()[d] + 1);
    }
  }
  vtkSmartPointer<vtkOverlappingAMR> level0 = AssembleRegion(coarse, buffers, error);
  if (!level0 || level0->GetNumberOfLevels() == 0)
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
  return f == 1 ? level0 : Coarsen(level0, lo, dims, f);
}
}
