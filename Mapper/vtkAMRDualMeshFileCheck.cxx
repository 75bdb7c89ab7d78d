#include "vtkAMRDualMeshFileCheck.h"
#include "AMRDualMeshVTKCompat.h"

#include "vtkAMRBox.h"
#include "vtkCellData.h"
#include "vtkPointData.h"
#include "vtkDataArray.h"
#include "vtkObjectFactory.h"
#include "vtkOverlappingAMR.h"
#include "vtkImageData.h"
#include "vtkUnsignedCharArray.h"

#include "AMRFileChecks.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <exception>
#include <set>

vtkStandardNewMacro(vtkAMRDualMeshFileCheck);

namespace
{
bool endsWith(const std::string& s, const char* suffix)
{
  const std::string t = suffix;
  return s.size() >= t.size() && s.compare(s.size() - t.size(), t.size(), t) == 0;
}

/// The REFINEDCELL flags of every block against the coverage by the next level's boxes
/// (coarsened by the ratio of the spacings); counts cells flagged hidden or duplicate.
std::string checkBlanking(vtkOverlappingAMR* amr, const std::string& file, long long& hidden)
{
  namespace compat = amrdm_vtk::amrcompat;
  const unsigned char refined = compat::RefinedCell;
  const unsigned char masked = compat::HiddenCell | compat::DuplicateCell;
  const unsigned int levels = compat::NumberOfLevels(amr);
  for (unsigned int level = 0; level < levels; ++level)
  {
    std::vector<vtkAMRBox> finer;
    int ratio = 1;
    if (level + 1 < levels)
    {
      double h0[3], h1[3];
      compat::Spacing(amr, level, h0);
      compat::Spacing(amr, level + 1, h1);
      ratio = static_cast<int>(std::lround(h0[0] / h1[0]));
      for (unsigned int j = 0; ratio >= 1 && j < compat::NumberOfBlocks(amr, level + 1); ++j)
        if (compat::Block(amr, level + 1, j))
          finer.push_back(compat::Box(amr, level + 1, j));
    }
    for (unsigned int i = 0; i < compat::NumberOfBlocks(amr, level); ++i)
    {
      vtkImageData* grid = compat::Block(amr, level, i);
      vtkUnsignedCharArray* ghosts = compat::CellGhosts(grid);
      const vtkAMRBox& box = compat::Box(amr, level, i);
      int dims[3];
      box.GetNumberOfCells(dims);
      const vtkIdType n = vtkIdType(dims[0]) * dims[1] * dims[2];
      if (!ghosts || ghosts->GetNumberOfTuples() != n || grid->GetNumberOfCells() != n)
        continue; // no blanking to check (the intake computes it, or refuses the sizes)
      std::vector<unsigned char> covered(static_cast<std::size_t>(n), 0);
      const int* lo = box.GetLoCorner();
      for (const vtkAMRBox& f : finer)
      {
        int a[3], b[3];
        bool overlaps = true;
        for (int d = 0; d < 3; ++d)
        {
          a[d] = std::max(lo[d], static_cast<int>(std::floor(double(f.GetLoCorner()[d]) / ratio)));
          b[d] = std::min(
            lo[d] + dims[d] - 1, static_cast<int>(std::floor(double(f.GetHiCorner()[d]) / ratio)));
          overlaps = overlaps && a[d] <= b[d];
        }
        for (int z = a[2]; overlaps && z <= b[2]; ++z)
          for (int y = a[1]; y <= b[1]; ++y)
            for (int x = a[0]; x <= b[0]; ++x)
              covered[std::size_t(((z - lo[2]) * dims[1] + (y - lo[1])) * dims[0] + (x - lo[0]))] =
                1;
      }
      long long wrong = 0;
      for (vtkIdType c = 0; c < n; ++c)
      {
        const unsigned char g = ghosts->GetValue(c);
        wrong += ((g & refined) != 0) != (covered[std::size_t(c)] != 0) ? 1 : 0;
        hidden += (g & refined) == 0 && (g & masked) != 0 ? 1 : 0;
      }
      if (wrong > 0)
        return file + ": block " + std::to_string(i) + " of level " + std::to_string(level) +
               " has " + std::to_string(wrong) + " of " + std::to_string(n) +
               " cells whose vtkGhostType refined flag disagrees with the next level's boxes "
               "(a damaged ghost array)";
    }
  }
  return "";
}

std::set<std::string> cellArrays(vtkImageData* grid)
{
  std::set<std::string> names;
  vtkCellData* cd = grid->GetCellData();
  for (int i = 0; i < cd->GetNumberOfArrays(); ++i)
    if (cd->GetArrayName(i) &&
        std::string(cd->GetArrayName(i)) != amrdm_vtk::amrcompat::GhostArrayName())
      names.insert(cd->GetArrayName(i));
  vtkPointData* pd = grid->GetPointData(); // point (vertex-centred) arrays count too
  for (int i = 0; i < pd->GetNumberOfArrays(); ++i)
    if (pd->GetArrayName(i))
      names.insert(std::string("points:") + pd->GetArrayName(i));
  return names;
}
}

void vtkAMRDualMeshFileCheck::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Path: " << this->Path << "\n"
     << indent << "Format: " << this->Format << "\n"
     << indent << "Levels: " << this->BlocksPerLevel.size() << "\n"
     << indent << "Error: " << this->Error << "\n";
}

std::string vtkAMRDualMeshFileCheck::Check(const std::string& path)
{
  vtkAMRDualMeshFileCheck* check = vtkAMRDualMeshFileCheck::New();
  check->CheckFile(path);
  const std::string error = check->GetError();
  check->Delete();
  return error;
}

bool vtkAMRDualMeshFileCheck::CheckFile(const std::string& path)
{
  using namespace amrdm_filecheck;
  this->Path = path;
  this->Format.clear();
  this->BlocksPerLevel.clear();
  this->Cells = 0;
  this->EmptyBlocks = 0;
  this->EmptyCells = 0;
  this->DataBytes = 0;
  std::uint64_t size = 0;
  Result r;
  try
  {
    if (IsDirectory(path))
      r = FileSize(path + "/Header", size)
            ? CheckAMReX(path)
            : Result{ Quote(path) +
                      " is a folder without a Header file; expected an AMReX plotfile" };
    else if (!FileSize(path, size))
      r.Error = Quote(path) + " does not exist (or is not a regular file)";
    else if (endsWith(path, ".hierarchy") || endsWith(path, ".boundary"))
      r = CheckEnzo(path);
    else if (endsWith(path, ".vthb") || endsWith(path, ".vth"))
      r = CheckVthb(path);
    else
      r.Error =
        Quote(path) +
        " is not a supported AMR file; expected an Enzo .hierarchy, an AMReX plotfile folder or "
        "a .vthb file";
  }
  catch (const std::exception& e) // std::bad_alloc on a machine out of memory, nothing else
  {
    r.Error = Quote(path) + ": the check failed: " + e.what();
  }
  // One line whatever bytes a damaged file put into a name: control characters become '?'.
  for (char& ch : r.Error)
    if (static_cast<unsigned char>(ch) < 0x20 || ch == 0x7f)
      ch = '?';
  this->Error = r.Error;
  this->Format = r.Format;
  if (this->Error.empty())
  {
    this->BlocksPerLevel = r.BlocksPerLevel;
    this->Cells = r.Cells;
    this->EmptyBlocks = r.EmptyBlocks;
    this->EmptyCells = r.EmptyCells;
    this->DataBytes = static_cast<double>(r.DataBytes);
  }
  this->Modified();
  return this->Error.empty();
}

int vtkAMRDualMeshFileCheck::GetNumberOfBlocks(int level) const
{
  return level >= 0 && level < this->GetNumberOfLevels()
           ? this->BlocksPerLevel[static_cast<std::size_t>(level)]
           : 0;
}

double vtkAMRDualMeshFileCheck::GetReadTimeoutSeconds() const
{
  const char* env = std::getenv("AMRDM_READ_TIMEOUT");
  if (env && *env)
  {
    char* end = nullptr;
    const double v = std::strtod(env, &end);
    if (end != env && *end == '\0' && v > 0)
      return v;
  }
  return 10.0 + this->DataBytes / 5e6;
}

std::string vtkAMRDualMeshFileCheck::CheckOutput(vtkOverlappingAMR* amr)
{
  const std::string file = "'" + this->Path + "'";
  this->Warning.clear();
  if (!amr)
    return this->Error = file + ": the reader returned no vtkOverlappingAMR";
  const int levels = static_cast<int>(amrdm_vtk::amrcompat::NumberOfLevels(amr));
  std::string missing;
  long long read = 0, described = 0;
  std::set<std::string> arrays;
  bool first = true;
  for (int level = 0; level < std::max(levels, this->GetNumberOfLevels()); ++level)
  {
    const int expected = this->GetNumberOfBlocks(level);
    int got = 0;
    const unsigned int n =
      level < levels ? amrdm_vtk::amrcompat::NumberOfBlocks(amr, static_cast<unsigned>(level)) : 0;
    for (unsigned int i = 0; i < n; ++i)
    {
      vtkImageData* grid = nullptr;
      if (amrdm_vtk::amrcompat::BlockAt(amr, static_cast<unsigned>(level), i, grid) ==
          amrdm_vtk::amrcompat::BlockState::Unsupported)
        return this->Error = file + ": " +
                             amrdm_vtk::amrcompat::UnsupportedBlockMessage(
                               amr, static_cast<unsigned>(level), i);
      if (!grid)
        continue;
      ++got;
      const std::set<std::string> names = cellArrays(grid);
      if (first)
        arrays = names;
      else if (names != arrays)
        return this->Error = file + ": block " + std::to_string(i) + " of level " +
                             std::to_string(level) + " has " + std::to_string(names.size()) +
                             " cell arrays, " + "others " + std::to_string(arrays.size()) +
                             "; the reader could not read them all (a damaged data file?)";
      first = false;
    }
    read += got;
    described += expected;
    if (got != expected && missing.empty())
      missing = "level " + std::to_string(level) + ": " + std::to_string(got) + " of " +
                std::to_string(expected) + " blocks";
  }
  if (!missing.empty())
    return this->Error = file + ": the reader returned " + std::to_string(read) + " of the " +
                         std::to_string(described) + " blocks its metadata describes (" + missing +
                         "); refusing a partial hierarchy";
  if (arrays.empty())
    return this->Error =
             file + ": the reader returned no cell or point arrays (a damaged data file?)";
  long long hidden = 0;
  this->Error = checkBlanking(amr, file, hidden);
  if (this->Error.empty() && hidden > 0)
    this->Warning =
      file + ": " + std::to_string(hidden) +
      " cells are flagged hidden or duplicate in vtkGhostType and are not rendered (a damaged "
      "ghost array, or data masked on purpose)";
  if (this->Error.empty() && this->EmptyBlocks > 0)
    this->Warning += (this->Warning.empty() ? file + ": " : std::string("; ")) +
                     std::to_string(this->EmptyBlocks) + " of " +
                     std::to_string(described + this->EmptyBlocks) + " blocks (" +
                     std::to_string(this->EmptyCells) + " of " +
                     std::to_string(this->Cells + this->EmptyCells) +
                     " cells) have no file (empty blocks) and are not rendered";
  return this->Error;
}
