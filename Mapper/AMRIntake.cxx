#include "AMRIntake.h"

#include "vtkAMRBox.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDataSetAttributes.h"
#include "vtkOverlappingAMR.h"
#include "vtkUniformGrid.h"
#include "vtkUnsignedCharArray.h"

#include <cmath>
#include <limits>
#include <sstream>

namespace amrdm_vtk
{
namespace
{
/// Spacings and origins are compared with this relative tolerance (file formats store them in
/// decimal text or single precision).
constexpr double kSpacingTolerance = 1e-5;

std::string where(unsigned level, unsigned id)
{
  return "level " + std::to_string(level) + " block " + std::to_string(id);
}
}

bool ConvertAMR(vtkOverlappingAMR* amr, const char* arrayName, int component, bool logScale,
  amrdm::AmrHierarchy& out, std::string& error)
{
  out = amrdm::AmrHierarchy();
  if (!amr)
  {
    error = "no input: expected a vtkOverlappingAMR";
    return false;
  }
  const unsigned numLevels = amr->GetNumberOfLevels();
  if (numLevels == 0)
  {
    error = "the AMR data set has no levels; expected at least one level with blocks";
    return false;
  }
  if (!arrayName || !*arrayName)
  {
    error = "no scalar array selected; expected the name of a cell-data array";
    return false;
  }
  // Refinement ratios from the level spacings (AMReX reports ratio 1 on the finest level).
  std::vector<double> spacing(3 * numLevels);
  for (unsigned l = 0; l < numLevels; ++l)
  {
    amr->GetSpacing(l, &spacing[3 * l]);
    for (int d = 0; d < 3; ++d)
    {
      if (!(spacing[3 * l + d] > 0.0) || !std::isfinite(spacing[3 * l + d]))
      {
        error = "level " + std::to_string(l) + " has spacing " +
          std::to_string(spacing[3 * l + d]) + " on axis " + std::to_string(d) +
          "; expected a positive, finite spacing";
        return false;
      }
    }
  }
  out.ratio.assign(numLevels, 1);
  for (unsigned l = 1; l < numLevels; ++l)
  {
    double r[3];
    for (int d = 0; d < 3; ++d)
    {
      r[d] = spacing[3 * (l - 1) + d] / spacing[3 * l + d];
    }
    const long ri = std::lround(r[0]);
    for (int d = 0; d < 3; ++d)
    {
      if (std::abs(r[d] - std::round(r[d])) > kSpacingTolerance * r[d] || std::lround(r[d]) < 2)
      {
        std::ostringstream s;
        s << "the spacing ratio between level " << l - 1 << " and level " << l << " is " << r[d]
          << " on axis " << d << "; expected an integer refinement ratio >= 2";
        error = s.str();
        return false;
      }
      if (std::lround(r[d]) != ri)
      {
        std::ostringstream s;
        s << "inconsistent spacing: the refinement ratio from level " << l - 1 << " to " << l
          << " differs between axes (" << r[0] << ", " << r[1] << ", " << r[2]
          << "); expected the same integer ratio on every axis";
        error = s.str();
        return false;
      }
    }
    out.ratio[l] = static_cast<int>(ri);
  }
  // The AMR origin becomes the scene origin (double); grid point 0 sits at the scene frame's zero,
  // so renderers and float data only see positions relative to the AMR (1e6 offsets with 1e-6
  // cells keep their precision).
  const double* origin = amr->GetOrigin();
  out.sceneOrigin = glm::dvec3(origin[0], origin[1], origin[2]);
  out.origin = glm::dvec3(0.0);
  const double* finest = &spacing[3 * (numLevels - 1)];
  out.finestSpacing = glm::dvec3(finest[0], finest[1], finest[2]);

  for (unsigned l = 0; l < numLevels; ++l)
  {
    const double* h = &spacing[3 * l];
    for (unsigned id = 0; id < amr->GetNumberOfDataSets(l); ++id)
    {
      vtkUniformGrid* grid = amr->GetDataSet(l, id);
      if (!grid)
      {
        continue; // not loaded here (another process, or the reader skipped it)
      }
      const vtkAMRBox& box = amr->GetAMRBox(l, id);
      bool emptyBox = box.IsInvalid();
      for (int d = 0; d < 3; ++d)
      {
        emptyBox = emptyBox || box.GetHiCorner()[d] < box.GetLoCorner()[d];
      }
      if (emptyBox)
      {
        error = where(l, id) + " has an empty AMR box; expected at least one cell per axis";
        return false;
      }
      amrdm::AmrBlock block;
      block.level = static_cast<int>(l);
      int gridDims[3];
      grid->GetDimensions(gridDims);
      for (int d = 0; d < 3; ++d)
      {
        block.lower[d] = box.GetLoCorner()[d];
        block.dims[d] = box.GetHiCorner()[d] - box.GetLoCorner()[d] + 1;
        if (gridDims[d] - 1 != block.dims[d])
        {
          error = where(l, id) + " has " + std::to_string(gridDims[d] - 1) + " cells on axis " +
            std::to_string(d) + " but its AMR box says " + std::to_string(block.dims[d]) +
            "; expected a 3D grid that matches its box";
          return false;
        }
      }
      double gs[3], go[3];
      grid->GetSpacing(gs);
      grid->GetOrigin(go);
      for (int d = 0; d < 3; ++d)
      {
        const double expectOrigin = origin[d] + block.lower[d] * h[d];
        if (std::abs(gs[d] - h[d]) > kSpacingTolerance * h[d] ||
          std::abs(go[d] - expectOrigin) > 1e-3 * h[d])
        {
          std::ostringstream s;
          s << "inconsistent spacing: " << where(l, id) << " has spacing " << gs[d]
            << " and origin " << go[d] << " on axis " << d << "; expected spacing " << h[d]
            << " and origin " << expectOrigin << " from the level and its box";
          error = s.str();
          return false;
        }
      }
      vtkDataArray* array = grid->GetCellData()->GetArray(arrayName);
      if (!array)
      {
        std::ostringstream s;
        s << "no numeric cell-data array named '" << arrayName << "' in " << where(l, id)
          << "; available:";
        for (int a = 0; a < grid->GetCellData()->GetNumberOfArrays(); ++a)
        {
          const char* name = grid->GetCellData()->GetArrayName(a);
          if (name && std::string(name) != vtkDataSetAttributes::GhostArrayName())
          {
            s << " '" << name << "'";
          }
        }
        error = s.str();
        return false;
      }
      const int numComponents = array->GetNumberOfComponents();
      if (component >= numComponents)
      {
        error = "component " + std::to_string(component) + " requested but array '" +
          arrayName + "' has " + std::to_string(numComponents) +
          " components; expected -1 (magnitude) or 0.." + std::to_string(numComponents - 1);
        return false;
      }
      const vtkIdType n = block.numCells();
      if (array->GetNumberOfTuples() != n)
      {
        error = "array '" + std::string(arrayName) + "' in " + where(l, id) + " has " +
          std::to_string(array->GetNumberOfTuples()) + " tuples; expected one per cell (" +
          std::to_string(n) + ")";
        return false;
      }
      block.values.resize(static_cast<std::size_t>(n));
      for (vtkIdType i = 0; i < n; ++i)
      {
        double v;
        if (component >= 0)
        {
          v = array->GetComponent(i, component);
        }
        else if (numComponents == 1)
        {
          v = array->GetComponent(i, 0);
        }
        else
        {
          double sum = 0.0;
          for (int c = 0; c < numComponents; ++c)
          {
            const double x = array->GetComponent(i, c);
            sum += x * x;
          }
          v = std::sqrt(sum);
        }
        if (logScale)
        {
          v = v > 0.0 ? std::log10(v) : std::numeric_limits<double>::quiet_NaN();
        }
        block.values[static_cast<std::size_t>(i)] = static_cast<float>(v);
      }
      // Blanking from vtkGhostType when present; otherwise computed from coverage later.
      if (auto* ghosts = vtkUnsignedCharArray::SafeDownCast(
            grid->GetCellData()->GetArray(vtkDataSetAttributes::GhostArrayName())))
      {
        if (ghosts->GetNumberOfTuples() == n)
        {
          block.state.resize(static_cast<std::size_t>(n));
          for (vtkIdType i = 0; i < n; ++i)
          {
            const unsigned char g = ghosts->GetValue(i);
            block.state[static_cast<std::size_t>(i)] = (g & vtkDataSetAttributes::REFINEDCELL)
              ? amrdm::CellRefined
              : ((g & (vtkDataSetAttributes::HIDDENCELL | vtkDataSetAttributes::DUPLICATECELL))
                    ? amrdm::CellHidden
                    : amrdm::CellLeaf);
          }
        }
      }
      out.blocks.push_back(std::move(block));
    }
  }
  if (out.blocks.empty())
  {
    error = "the AMR data set has no blocks with data; expected at least one vtkUniformGrid";
    return false;
  }
  return true;
}
}
