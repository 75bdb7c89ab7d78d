#include "AMRIntake.h"
#include "AMRDualMeshVTKCompat.h"
#include "core/ParallelFor.h"

#include "vtkAMRBox.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDataSetAttributes.h"
#include "vtkAOSDataArrayTemplate.h"
#include "vtkOverlappingAMR.h"
#include "vtkPointData.h"
#include "vtkImageData.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <limits>
#include <sstream>
#include <utility>
#include <vector>

namespace amrdm_vtk
{
namespace
{
/// Level spacings are trusted the way VTK trusts them: a level's spacing within this relative
/// tolerance of level 0's spacing over the product of the refinement ratios is snapped to that
/// value. File formats store spacings as decimal text (`.vthb`: 6 significant digits, relative
/// error up to 5e-6) or single precision (1.2e-7); 1e-4 covers both with a margin.
constexpr double kSpacingTolerance = 1e-4;

/// A block's own origin must agree with its level's origin plus its AMR box to within
/// max(kOriginCellTolerance * level spacing, kOriginDomainTolerance * domain extent) per axis:
/// relative to the domain, because a 20-level hierarchy's finest cells are 2^-20 of it and the
/// boxes (not the blocks' origins) place the cells.
constexpr double kOriginCellTolerance = 1e-3;
constexpr double kOriginDomainTolerance = 1e-6;

/// Numbers in messages: the shortest form that reads back as the same double, so two numbers
/// that differ print differently (up to 17 significant digits).
std::string num(double v)
{
  std::string text;
  for (int digits = 6; digits <= 17; ++digits)
  {
    std::ostringstream s;
    s << std::setprecision(digits) << v;
    text = s.str();
    if (std::strtod(text.c_str(), nullptr) == v)
    {
      break;
    }
  }
  return text;
}

std::string where(unsigned level, unsigned id)
{
  return "level " + std::to_string(level) + " block " + std::to_string(id);
}
}

namespace
{
/// One block's values (component, magnitude or value; log10 on request) and, when the block
/// has a vtkGhostType array of its size, its cell states. Reads the arrays only.
void copyBlock(vtkDataArray* array,
  vtkUnsignedCharArray* ghosts,
  int component,
  bool logScale,
  amrdm::AmrBlock& block,
  vtkIdType n)
{
  const int numComponents = array->GetNumberOfComponents();
  block.values.clear(); // appended below: no zeroing pass over the copy before it is written
  block.values.reserve(static_cast<std::size_t>(n));
  // Float and double arrays are read directly; other types through vtkDataArray's virtuals.
  // The AOS templates, not vtkFloatArray/vtkDoubleArray: readers and filters may hand over a
  // plain vtkAOSDataArrayTemplate<double>, which is not a vtkDoubleArray object.
  auto* floats = vtkAOSDataArrayTemplate<float>::FastDownCast(array);
  auto* doubles = vtkAOSDataArrayTemplate<double>::FastDownCast(array);
  for (vtkIdType i = 0; i < n; ++i)
  {
    double v;
    if (numComponents == 1 || component >= 0)
    {
      const int c = component >= 0 ? component : 0;
      v = floats ? double(floats->GetTypedComponent(i, c))
                 : (doubles ? doubles->GetTypedComponent(i, c) : array->GetComponent(i, c));
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
    block.values.push_back(logScale ? amrdm::logScaleValue(v) : static_cast<float>(v));
  }
  // Blanking from vtkGhostType when present; otherwise computed from coverage later.
  n = block.numCells();
  if (ghosts && ghosts->GetNumberOfTuples() == n)
  {
    block.state.resize(static_cast<std::size_t>(n));
    for (vtkIdType i = 0; i < n; ++i)
    {
      const unsigned char g = ghosts->GetValue(i);
      block.state[static_cast<std::size_t>(i)] =
        (g & amrcompat::RefinedCell)
          ? amrdm::CellRefined
          : ((g & (amrcompat::HiddenCell | amrcompat::DuplicateCell)) ? amrdm::CellHidden
                                                                      : amrdm::CellLeaf);
    }
  }
}
}

bool ConvertAMR(vtkOverlappingAMR* amr,
  const char* arrayName,
  int component,
  bool logScale,
  amrdm::AmrHierarchy& out,
  std::string& error,
  int threads,
  amrdm::FieldAssociation association,
  amrdm::LevelBoxes* metadata)
{
  out = amrdm::AmrHierarchy();
  const bool points = association == amrdm::FieldAssociation::Points;
  out.association = association;
  const char* kind = points ? "point" : "cell";
  if (!amr)
  {
    error = "no input: expected a vtkOverlappingAMR";
    return false;
  }
  const unsigned numLevels = amrcompat::NumberOfLevels(amr);
  if (numLevels == 0)
  {
    error = "the AMR data set has no levels; expected at least one level with blocks";
    return false;
  }
  if (!arrayName || !*arrayName)
  {
    error = std::string("no scalar array selected; expected the name of a ") + kind + "-data array";
    return false;
  }
  // Refinement ratios from the level spacings (AMReX reports ratio 1 on the finest level).
  std::vector<double> spacing(3 * numLevels);
  for (unsigned l = 0; l < numLevels; ++l)
  {
    amrcompat::Spacing(amr, l, &spacing[3 * l]);
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
  std::vector<double> fileSpacing = spacing; // as stored, for messages
  for (unsigned l = 1; l < numLevels; ++l)
  {
    double r[3];
    for (int d = 0; d < 3; ++d)
    {
      r[d] = fileSpacing[3 * (l - 1) + d] / fileSpacing[3 * l + d];
    }
    const long ri = std::lround(r[0]);
    for (int d = 0; d < 3; ++d)
    {
      if (std::abs(r[d] - std::round(r[d])) > kSpacingTolerance * r[d] || std::lround(r[d]) < 2)
      {
        error = "the spacing ratio between level " + std::to_string(l - 1) + " and level " +
                std::to_string(l) + " is " + num(r[d]) + " on axis " + std::to_string(d) +
                " (spacings " + num(fileSpacing[3 * (l - 1) + d]) + " and " +
                num(fileSpacing[3 * l + d]) + "); expected an integer refinement ratio >= 2";
        return false;
      }
      if (std::lround(r[d]) != ri)
      {
        error = "inconsistent spacing: the refinement ratio from level " + std::to_string(l - 1) +
                " to " + std::to_string(l) + " differs between axes (" + num(r[0]) + ", " +
                num(r[1]) + ", " + num(r[2]) + "); expected the same integer ratio on every axis";
        return false;
      }
    }
    out.ratio[l] = static_cast<int>(ri);
    // Snap to level 0's spacing over the accumulated ratio (the stored value is rounded text).
    for (int d = 0; d < 3; ++d)
    {
      const double exact = spacing[3 * (l - 1) + d] / double(ri);
      if (std::abs(fileSpacing[3 * l + d] - exact) > kSpacingTolerance * exact)
      {
        error = "inconsistent spacing: level " + std::to_string(l) + " has spacing " +
                num(fileSpacing[3 * l + d]) + " on axis " + std::to_string(d) + "; expected " +
                num(exact) + " (level 0's spacing over the refinement ratios) within a relative " +
                num(kSpacingTolerance);
        return false;
      }
      spacing[3 * l + d] = exact;
    }
  }
  // The domain's extent per axis, from the level-0 boxes (the scale of the origin tolerance).
  double domainExtent[3] = { 0.0, 0.0, 0.0 };
  {
    int lo0[3] = { 0, 0, 0 }, hi0[3] = { 0, 0, 0 };
    bool any = false;
    for (unsigned id = 0; id < amrcompat::NumberOfBlocks(amr, 0); ++id)
    {
      const vtkAMRBox& box = amrcompat::Box(amr, 0, id);
      if (box.IsInvalid())
      {
        continue;
      }
      for (int d = 0; d < 3; ++d)
      {
        lo0[d] = any ? std::min(lo0[d], box.GetLoCorner()[d]) : box.GetLoCorner()[d];
        hi0[d] = any ? std::max(hi0[d], box.GetHiCorner()[d]) : box.GetHiCorner()[d];
      }
      any = true;
    }
    for (int d = 0; d < 3; ++d)
    {
      domainExtent[d] = any ? (double(hi0[d]) - lo0[d] + 1.0) * spacing[d] : spacing[d];
    }
  }
  // The AMR's boxes per level, loaded here or not: the parents of amrdm::checkNesting (run by
  // checkHierarchy/prepareHierarchy; the dual mesh's level transitions assume aligned, nested
  // boxes).
  if (metadata)
  {
    metadata->assign(numLevels, {});
    for (unsigned l = 0; l < numLevels; ++l)
    {
      for (unsigned id = 0; id < amrcompat::NumberOfBlocks(amr, l); ++id)
      {
        const vtkAMRBox& box = amrcompat::Box(amr, l, id);
        amrdm::CellBox cells; // an inverted (never reported) box when invalid
        for (int d = 0; d < 3 && !box.IsInvalid(); ++d)
        {
          cells.lower[d] = box.GetLoCorner()[d];
          cells.upper[d] = box.GetHiCorner()[d];
        }
        (*metadata)[l].push_back(cells);
      }
    }
  }
  // The AMR origin becomes the scene origin (double); grid point 0 sits at the scene frame's zero,
  // so renderers and float data only see positions relative to the AMR (1e6 offsets with 1e-6
  // cells keep their precision).
  const double* origin = amrcompat::Origin(amr);
  out.sceneOrigin = glm::dvec3(origin[0], origin[1], origin[2]);
  out.origin = glm::dvec3(0.0);
  const double* finest = &spacing[3 * (numLevels - 1)];
  out.finestSpacing = glm::dvec3(finest[0], finest[1], finest[2]);
  // Per block: its array and ghost array, copied in parallel once every block is checked.
  std::vector<std::pair<vtkDataArray*, vtkUnsignedCharArray*>> sources;

  for (unsigned l = 0; l < numLevels; ++l)
  {
    const double* h = &spacing[3 * l];
    for (unsigned id = 0; id < amrcompat::NumberOfBlocks(amr, l); ++id)
    {
      vtkImageData* grid = nullptr;
      if (amrcompat::BlockAt(amr, l, id, grid) == amrcompat::BlockState::Unsupported)
      {
        error = amrcompat::UnsupportedBlockMessage(amr, l, id);
        return false;
      }
      if (!grid)
      {
        continue; // not loaded here (another process, or the reader skipped it)
      }
      const vtkAMRBox& box = amrcompat::Box(amr, l, id);
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
        const double originTolerance =
          std::max(kOriginCellTolerance * h[d], kOriginDomainTolerance * domainExtent[d]);
        if (std::abs(gs[d] - h[d]) > kSpacingTolerance * h[d])
        {
          error = "inconsistent spacing: " + where(l, id) + " has spacing " + num(gs[d]) +
                  " on axis " + std::to_string(d) + "; expected its level's spacing " + num(h[d]) +
                  " within a relative " + num(kSpacingTolerance);
          return false;
        }
        if (!(std::abs(go[d] - expectOrigin) <= originTolerance))
        {
          error = "inconsistent origin: " + where(l, id) + " has origin " + num(go[d]) +
                  " on axis " + std::to_string(d) + "; expected " + num(expectOrigin) +
                  " (the AMR origin plus its box's first cell times the level spacing " +
                  num(h[d]) + ") within " + num(originTolerance) + ", off by " +
                  num(go[d] - expectOrigin);
          return false;
        }
      }
      vtkDataSetAttributes* attributes =
        points ? static_cast<vtkDataSetAttributes*>(grid->GetPointData())
               : static_cast<vtkDataSetAttributes*>(grid->GetCellData());
      vtkDataArray* array = attributes->GetArray(arrayName);
      if (!array)
      {
        std::ostringstream s;
        s << "no numeric " << kind << "-data array named '" << arrayName << "' in " << where(l, id)
          << "; expected it on every block (this block has:";
        for (int a = 0; a < attributes->GetNumberOfArrays(); ++a)
        {
          const char* name = attributes->GetArrayName(a);
          if (name && std::string(name) != amrcompat::GhostArrayName())
          {
            s << " '" << name << "'";
          }
        }
        s << ")";
        error = s.str();
        return false;
      }
      const int numComponents = array->GetNumberOfComponents();
      if (component >= numComponents)
      {
        error = "component " + std::to_string(component) + " requested but array '" + arrayName +
                "' has " + std::to_string(numComponents) +
                " components; expected -1 (magnitude) or 0.." + std::to_string(numComponents - 1);
        return false;
      }
      const vtkIdType n = points ? block.numPoints() : block.numCells();
      if (array->GetNumberOfTuples() != n)
      {
        error = std::string(kind) + " array '" + arrayName + "' in " + where(l, id) + " has " +
                std::to_string(array->GetNumberOfTuples()) + " tuples; expected one per " +
                (points ? "vertex" : "cell") + " (" + std::to_string(n) + ")";
        return false;
      }
      sources.push_back({ array, amrcompat::CellGhosts(grid) });
      out.blocks.push_back(std::move(block));
    }
  }
  if (out.blocks.empty())
  {
    error = "the AMR data set has no blocks with data; expected at least one vtkUniformGrid";
    return false;
  }
  amrdm::parallelFor(out.blocks.size(),
    threads,
    [&](std::size_t b)
    {
      amrdm::AmrBlock& block = out.blocks[b];
      copyBlock(sources[b].first,
        sources[b].second,
        component,
        logScale,
        block,
        points ? block.numPoints() : block.numCells());
    });
  return true;
}
}
