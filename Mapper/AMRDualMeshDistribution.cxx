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

#include "mesh/DomainPartition.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <tuple>

namespace amrdm_vtk
{
namespace
{
/// Levels, ratios (from the spacings: AMReX reports ratio 1 on the finest level) and every
/// metadata box (loaded here or not), without values.
bool Metadata(vtkOverlappingAMR* amr, amrdm::AmrHierarchy& out, std::string& error)
{
  out = amrdm::AmrHierarchy();
  const unsigned levels = amrcompat::NumberOfLevels(amr);
  if (levels == 0)
  {
    error = "the AMR data set has no levels; expected at least one level-0 box";
    return false;
  }
  out.ratio.assign(levels, 1);
  for (unsigned l = 1; l < levels; ++l)
  {
    double coarse[3], fine[3];
    amrcompat::Spacing(amr, l - 1, coarse);
    amrcompat::Spacing(amr, l, fine);
    const double r = fine[0] > 0.0 ? coarse[0] / fine[0] : 0.0;
    if (!(std::abs(r - std::round(r)) <= 1e-4 * r) || std::lround(r) < 2)
    {
      error = "the spacings of levels " + std::to_string(l - 1) + " and " + std::to_string(l) +
              " give a refinement ratio of " + std::to_string(r) + "; expected an integer >= 2";
      return false;
    }
    out.ratio[l] = static_cast<int>(std::lround(r));
  }
  for (unsigned l = 0; l < levels; ++l)
  {
    for (unsigned id = 0; id < amrcompat::NumberOfBlocks(amr, l); ++id)
    {
      const vtkAMRBox& box = amrcompat::Box(amr, l, id);
      amrdm::AmrBlock b;
      b.level = static_cast<int>(l);
      bool empty = box.IsInvalid();
      for (int d = 0; d < 3; ++d)
      {
        b.lower[d] = box.GetLoCorner()[d];
        b.dims[d] = box.GetHiCorner()[d] - box.GetLoCorner()[d] + 1;
        empty = empty || b.dims[d] <= 0;
      }
      if (!empty)
      {
        out.blocks.push_back(std::move(b));
      }
    }
  }
  return true;
}

/// Level-`level` cells [lo, hi) region `r` needs: DomainPartition's band, rounded out to the
/// coarser level's cell faces.
void NeededRange(const amrdm::AmrHierarchy& meta,
  const amrdm::PartitionBox& region,
  int level,
  int lo[3],
  int hi[3])
{
  glm::ivec3 l, h;
  amrdm::regionCellRange(meta, region, level, l, h);
  const int r = level > 0 ? meta.ratio[static_cast<std::size_t>(level)] : 1;
  for (int d = 0; d < 3; ++d)
  {
    lo[d] = amrdm::floorDiv(l[d], r) * r;
    hi[d] = -amrdm::floorDiv(-h[d], r) * r;
  }
}

amrdm::PartitionBox ToBox(const AMRPartition& p, int region, vtkOverlappingAMR* amr)
{
  // Back from the data frame to level-0 cells (exact: the bounds were made from them).
  double h[3];
  amrcompat::Spacing(amr, 0, h);
  const double* origin = amrcompat::Origin(amr);
  amrdm::PartitionBox box;
  for (int d = 0; d < 3; ++d)
  {
    box.lower[d] = static_cast<int>(std::lround((p.Regions[region][2 * d] - origin[d]) / h[d]));
    box.upper[d] = static_cast<int>(std::lround((p.Regions[region][2 * d + 1] - origin[d]) / h[d]));
  }
  return box;
}

struct Reader
{
  const char* Data;
  std::size_t Size, At = 0;
  template<typename T>
  T Get()
  {
    if (this->At + sizeof(T) > this->Size)
    {
      throw std::runtime_error("truncated piece buffer");
    }
    T value;
    std::memcpy(&value, this->Data + this->At, sizeof(T));
    this->At += sizeof(T);
    return value;
  }
  const char* Bytes(std::size_t n)
  {
    if (this->At + n > this->Size)
    {
      throw std::runtime_error("truncated piece buffer");
    }
    const char* p = this->Data + this->At;
    this->At += n;
    return p;
  }
};

}

bool PartitionAMR(vtkOverlappingAMR* amr, int numRegions, AMRPartition& out, std::string& error)
{
  amrdm::AmrHierarchy meta;
  if (!Metadata(amr, meta, error))
  {
    return false;
  }
  amrdm::DomainPartition partition;
  try
  {
    partition = amrdm::partitionDomain(meta, numRegions);
  }
  catch (const std::exception& e)
  {
    error = e.what();
    return false;
  }
  double h[3];
  amrcompat::Spacing(amr, 0, h);
  const double* origin = amrcompat::Origin(amr);
  auto bounds = [&](const amrdm::PartitionBox& b)
  {
    std::array<double, 6> out6{};
    for (int d = 0; d < 3; ++d)
    {
      out6[2 * d] = origin[d] + b.lower[d] * h[d];
      out6[2 * d + 1] = origin[d] + b.upper[d] * h[d];
    }
    return out6;
  };
  out.Regions.clear();
  for (const amrdm::PartitionBox& b : partition.regions)
  {
    out.Regions.push_back(bounds(b));
  }
  out.Domain = bounds(partition.domain);
  out.LeafCells = partition.leafCells;
  return true;
}

bool PackRegionPieces(vtkOverlappingAMR* amr,
  const AMRPartition& partition,
  int region,
  bool whole,
  std::vector<char>& buffer,
  std::string& error)
{
  amrdm::AmrHierarchy meta;
  if (!Metadata(amr, meta, error))
  {
    return false;
  }
  const amrdm::PartitionBox box = ToBox(partition, region, amr);
  for (unsigned l = 0; l < amrcompat::NumberOfLevels(amr); ++l)
  {
    for (unsigned id = 0; id < amrcompat::NumberOfBlocks(amr, l); ++id)
    {
      vtkImageData* grid = amrcompat::Block(amr, l, id);
      int blo[3], bdims[3], lo[3], hi[3];
      if (!LoadedBlock(amr, l, id, blo, bdims, error))
      {
        if (!error.empty())
        {
          return false;
        }
        continue; // not loaded here
      }
      NeededRange(meta, box, static_cast<int>(l), lo, hi);
      bool empty = false;
      for (int d = 0; d < 3; ++d)
      {
        lo[d] = whole ? blo[d] : std::max(lo[d], blo[d]);
        hi[d] = whole ? blo[d] + bdims[d] : std::min(hi[d], blo[d] + bdims[d]);
        empty = empty || hi[d] <= lo[d];
      }
      if (empty)
      {
        continue;
      }
      PackPiece(buffer, l, grid, blo, bdims, lo, hi);
    }
  }
  return true;
}

vtkSmartPointer<vtkOverlappingAMR> AssembleRegion(vtkOverlappingAMR* metadata,
  const std::vector<std::vector<char>>& buffers,
  std::string& error)
{
  amrdm::AmrHierarchy meta;
  if (!Metadata(metadata, meta, error))
  {
    return nullptr;
  }
  struct Piece
  {
    int level;
    int lo[3], dims[3];
    vtkSmartPointer<vtkImageData> grid;
  };
  std::vector<Piece> pieces;
  const int levels = meta.numLevels();
  try
  {
    for (const std::vector<char>& buffer : buffers)
    {
      Reader in{ buffer.data(), buffer.size() };
      while (in.At < in.Size)
      {
        Piece p;
        p.level = in.Get<std::int32_t>();
        if (p.level < 0 || p.level >= levels)
        {
          throw std::runtime_error("a piece on level " + std::to_string(p.level));
        }
        for (int d = 0; d < 3; ++d)
        {
          p.lo[d] = in.Get<std::int32_t>();
        }
        for (int d = 0; d < 3; ++d)
        {
          p.dims[d] = in.Get<std::int32_t>();
        }
        const vtkIdType cells = vtkIdType(p.dims[0]) * p.dims[1] * p.dims[2];
        double h[3];
        amrcompat::Spacing(metadata, static_cast<unsigned>(p.level), h);
        const double* origin = amrcompat::Origin(metadata);
        p.grid = amrcompat::NewBlock();
        p.grid->SetDimensions(p.dims[0] + 1, p.dims[1] + 1, p.dims[2] + 1);
        p.grid->SetSpacing(h);
        p.grid->SetOrigin(
          origin[0] + p.lo[0] * h[0], origin[1] + p.lo[1] * h[1], origin[2] + p.lo[2] * h[2]);
        const int numArrays = in.Get<std::int32_t>();
        for (int a = 0; a < numArrays; ++a)
        {
          const int len = in.Get<std::int32_t>();
          const std::string name(in.Bytes(static_cast<std::size_t>(len)), len);
          const int type = in.Get<std::int32_t>(), comps = in.Get<std::int32_t>();
          const std::uint64_t bytes = in.Get<std::uint64_t>();
          vtkSmartPointer<vtkDataArray> array =
            vtkSmartPointer<vtkDataArray>::Take(vtkDataArray::CreateDataArray(type));
          if (!array || comps < 1)
          {
            throw std::runtime_error("array '" + name + "' of an unknown type");
          }
          array->SetName(name.c_str());
          array->SetNumberOfComponents(comps);
          array->SetNumberOfTuples(cells);
          if (bytes != std::uint64_t(cells) * comps * array->GetDataTypeSize())
          {
            throw std::runtime_error("array '" + name + "' of the wrong size");
          }
          std::memcpy(array->GetVoidPointer(0), in.Bytes(bytes), bytes);
          p.grid->GetCellData()->AddArray(array);
        }
        pieces.push_back(std::move(p));
      }
    }
  }
  catch (const std::exception& e)
  {
    error = std::string("malformed region data: ") + e.what();
    return nullptr;
  }
  auto result = vtkSmartPointer<vtkOverlappingAMR>::New();
  if (pieces.empty())
  {
    return result;
  }
  std::sort(pieces.begin(),
    pieces.end(),
    [](const Piece& a, const Piece& b)
    {
      return std::make_tuple(a.level, a.lo[2], a.lo[1], a.lo[0]) <
             std::make_tuple(b.level, b.lo[2], b.lo[1], b.lo[0]);
    });
  std::vector<unsigned> perLevel(static_cast<std::size_t>(levels), 0);
  for (const Piece& p : pieces)
  {
    ++perLevel[static_cast<std::size_t>(p.level)];
  }
  amrcompat::InitializeLevels(result, perLevel);
  amrcompat::SetOrigin(result, amrcompat::Origin(metadata));
  amrcompat::SetGridDescription(result, amrcompat::GridDescription(metadata));
  for (int l = 0; l < levels; ++l)
  {
    double h[3];
    amrcompat::Spacing(metadata, static_cast<unsigned>(l), h);
    amrcompat::SetSpacing(result, static_cast<unsigned>(l), h);
    if (l + 1 < levels)
    {
      amrcompat::SetRefinementRatio(
        result, static_cast<unsigned>(l), meta.ratio[static_cast<std::size_t>(l + 1)]);
    }
  }
  std::vector<int> next(static_cast<std::size_t>(levels), 0);
  for (const Piece& p : pieces)
  {
    // Refinement from the global boxes; hidden and duplicate flags as sent.
    const vtkIdType cells = p.grid->GetNumberOfCells();
    vtkUnsignedCharArray* ghosts = amrcompat::CellGhosts(p.grid);
    if (!ghosts)
    {
      vtkNew<vtkUnsignedCharArray> g;
      g->SetName(amrcompat::GhostArrayName());
      g->SetNumberOfTuples(cells);
      g->FillValue(0);
      p.grid->GetCellData()->AddArray(g);
      ghosts = g;
    }
    for (vtkIdType i = 0; i < cells; ++i)
    {
      ghosts->SetValue(
        i, static_cast<unsigned char>(ghosts->GetValue(i) & ~amrcompat::RefinedCell));
    }
    if (p.level + 1 < levels)
    {
      const int r = meta.ratio[static_cast<std::size_t>(p.level + 1)];
      for (const amrdm::AmrBlock& fine : meta.blocks)
      {
        if (fine.level != p.level + 1)
        {
          continue;
        }
        int lo[3], hi[3];
        bool empty = false;
        for (int d = 0; d < 3; ++d)
        {
          lo[d] = std::max(amrdm::floorDiv(fine.lower[d], r), p.lo[d]);
          hi[d] =
            std::min(amrdm::floorDiv(fine.lower[d] + fine.dims[d] - 1, r), p.lo[d] + p.dims[d] - 1);
          empty = empty || lo[d] > hi[d];
        }
        for (int z = lo[2]; !empty && z <= hi[2]; ++z)
          for (int y = lo[1]; y <= hi[1]; ++y)
            for (int x = lo[0]; x <= hi[0]; ++x)
            {
              const vtkIdType i =
                (vtkIdType(z - p.lo[2]) * p.dims[1] + (y - p.lo[1])) * p.dims[0] + (x - p.lo[0]);
              ghosts->SetValue(
                i, static_cast<unsigned char>(ghosts->GetValue(i) | amrcompat::RefinedCell));
            }
      }
    }
    const int hiCorner[3] = {
      p.lo[0] + p.dims[0] - 1, p.lo[1] + p.dims[1] - 1, p.lo[2] + p.dims[2] - 1
    };
    vtkAMRBox box(p.lo, hiCorner);
    const unsigned id = static_cast<unsigned>(next[static_cast<std::size_t>(p.level)]++);
    amrcompat::SetBox(result, static_cast<unsigned>(p.level), id, box);
    if (!amrcompat::SetBlock(result, static_cast<unsigned>(p.level), id, p.grid, error))
    {
      return nullptr;
    }
  }
  return result;
}
}
