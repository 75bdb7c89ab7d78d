// The Enzo check: the parameter file, the .hierarchy parsed as vtkAMREnzoReader parses it (word
// by word, but every search bounded to its grid block and every value checked), the grid tree
// its Pointer lines describe, the .procmap and .boundary totals, and each grid file's HDF5
// superblock and size.
#include "AMRFileChecks.h"

#include <cstdio>
#include <map>
#include <set>
#include <sstream>

namespace amrdm_filecheck
{
namespace
{
constexpr std::uint64_t kMaxTextBytes = std::uint64_t(1) << 31; // 2 GiB of hierarchy text
constexpr long long kMaxCellsPerAxis = 1 << 20;

struct Grid
{
  long long Start[3] = { 0, 0, 0 }, End[3] = { 0, 0, 0 };
  double Left[3] = { 0, 0, 0 }, Right[3] = { 0, 0, 0 };
  std::string File;
  long long Fields = 1;
  long long Pointer[2] = { -1, -1 }; // NextGridThisLevel, NextGridNextLevel (-1: not seen)
  int Level = -1;                    // as the reader assigns it
  int TreeLevel = -1;                // as the pointers define it
  long long Cells() const
  {
    return (End[0] - Start[0] + 1) * (End[1] - Start[1] + 1) * (End[2] - Start[2] + 1);
  }
};

std::vector<std::string> words(const std::string& text)
{
  std::vector<std::string> out;
  std::istringstream in(text);
  std::string w;
  while (in >> w)
    out.push_back(w);
  return out;
}

/// The words of the .hierarchy with a cursor; `next` fails at the end instead of looping.
struct Words
{
  const std::vector<std::string>& W;
  std::size_t I = 0;
  bool next(std::string& out)
  {
    if (I >= W.size())
      return false;
    out = W[I++];
    return true;
  }
  bool equals(const char* expected)
  {
    std::string w;
    return next(w) && w == expected;
  }
  bool integer(long long& v, long long lo, long long hi)
  {
    std::string w;
    if (!next(w))
      return false;
    TextCursor c(w);
    return c.Int(v, lo, hi) && c.AtEnd();
  }
  bool real(double& v)
  {
    std::string w;
    if (!next(w))
      return false;
    TextCursor c(w);
    return c.Double(v) && c.AtEnd();
  }
};

/// Finds `key` before the next "Grid" or "Pointer:" word (the reader would search on into the
/// next block, or for ever at the end of the file) and steps past its "=".
bool findKey(Words& in, const char* key)
{
  while (in.I < in.W.size() && in.W[in.I] != key)
  {
    if (in.W[in.I] == "Grid" || in.W[in.I] == "Pointer:")
      return false;
    ++in.I;
  }
  return in.I < in.W.size() && (++in.I, in.equals("="));
}

std::string parseGrid(Words& in, int rank, Grid& g, const std::string& where)
{
  const char* keys[] = { "GridStartIndex", "GridEndIndex", "GridLeftEdge", "GridRightEdge" };
  for (int k = 0; k < 4; ++k)
  {
    if (!findKey(in, keys[k]))
      return where + " has no '" + keys[k] +
             " = ...' line before the next grid or the end of the file (truncated?)";
    for (int d = 0; d < rank; ++d)
    {
      const bool ok = k < 2 ? in.integer(k == 0 ? g.Start[d] : g.End[d], 0, kMaxCellsPerAxis)
                            : in.real(k == 2 ? g.Left[d] : g.Right[d]);
      if (!ok)
        return where + ": " + keys[k] + " is not " + std::to_string(rank) +
               (k < 2 ? " integers in [0, 2^20]" : " finite numbers");
    }
  }
  for (int d = 0; d < rank; ++d)
  {
    if (g.End[d] < g.Start[d])
      return where + ": GridEndIndex < GridStartIndex on axis " + std::to_string(d);
    if (!(g.Right[d] > g.Left[d]))
      return where + ": GridRightEdge <= GridLeftEdge on axis " + std::to_string(d);
  }
  std::string name;
  if (!findKey(in, "BaryonFileName") || !in.next(name))
    return where + " has no 'BaryonFileName = ...' line before the next grid or the end of the "
                   "file (truncated?)";
  g.File = BaseName(name);
  long long particles = 0;
  if (!findKey(in, "NumberOfParticles") || !in.integer(particles, 0, 1LL << 40))
    return where + " has no valid 'NumberOfParticles = N' line before the next grid";
  if (particles > 0 && (!findKey(in, "ParticleFileName") || !in.next(name)))
    return where + " has particles but no 'ParticleFileName = ...' line before the next grid";
  return "";
}

std::string readRank(const std::string& parameterFile, int& rank)
{
  std::string text, error;
  if (!ReadWholeFile(parameterFile, kMaxTextBytes, text, error))
    return error + " (the Enzo parameter file next to the .hierarchy)";
  const std::vector<std::string> w = words(text);
  for (std::size_t i = 0; i + 2 < w.size(); ++i)
    if (w[i] == "TopGridRank" && w[i + 1] == "=")
    {
      TextCursor c(w[i + 2]);
      long long r = 0;
      if (!c.Int(r, 1, 3) || !c.AtEnd())
        return Quote(parameterFile) + ": TopGridRank is '" + w[i + 2] + "'; expected 1, 2 or 3";
      rank = static_cast<int>(r);
      return "";
    }
  return Quote(parameterFile) + " has no 'TopGridRank = N' line (truncated or not an Enzo file)";
}

/// The grids' levels from their NextGridThisLevel / NextGridNextLevel pointers: a tree rooted at
/// grid 1 in which every grid is reached exactly once.
std::string checkTree(std::vector<Grid>& grids, const std::string& file)
{
  const long long n = static_cast<long long>(grids.size()) - 1;
  grids[1].TreeLevel = 0;
  for (long long i = 1; i <= n; ++i)
  {
    for (int p = 0; p < 2; ++p)
    {
      const long long target = grids[std::size_t(i)].Pointer[p];
      if (target < 0)
        return Quote(file) + ": grid " + std::to_string(i) + " has no 'Pointer: Grid[" +
               std::to_string(i) + "]->" + (p == 0 ? "NextGridThisLevel" : "NextGridNextLevel") +
               "' line (truncated?)";
      if (target == 0)
        continue;
      if (target > n)
        return Quote(file) + ": grid " + std::to_string(i) + " points to grid " +
               std::to_string(target) + ", but the file describes " + std::to_string(n) +
               " grids (truncated?)";
      Grid& t = grids[std::size_t(target)];
      if (target <= i || t.TreeLevel >= 0)
        return Quote(file) + ": grid " + std::to_string(target) +
               " is reached twice or before its parent in the grid pointers (a damaged hierarchy)";
      t.TreeLevel = grids[std::size_t(i)].TreeLevel + p;
    }
  }
  for (long long i = 1; i <= n; ++i)
    if (grids[std::size_t(i)].TreeLevel < 0)
      return Quote(file) + ": no grid pointer reaches grid " + std::to_string(i) +
             " (a damaged hierarchy)";
    else if (grids[std::size_t(i)].TreeLevel != grids[std::size_t(i)].Level)
      return Quote(file) + ": grid " + std::to_string(i) + " is on level " +
             std::to_string(grids[std::size_t(i)].TreeLevel) +
             " by its pointers but listed where " + "a reader puts it on level " +
             std::to_string(grids[std::size_t(i)].Level) +
             " (grids out of order or a damaged hierarchy)";
  return "";
}

/// The .procmap (one line per grid) and the .boundary's field count, where those files exist.
std::string checkTotals(const std::string& base, const std::vector<Grid>& grids)
{
  std::uint64_t size = 0;
  std::string text, error;
  const std::string procmap = base + ".procmap";
  if (FileSize(procmap, size))
  {
    if (!ReadWholeFile(procmap, kMaxTextBytes, text, error))
      return error;
    // One line per grid ("N file GridNNNNNNNN"), possibly repeated by later writes: the grid
    // numbers it lists must be exactly 1..N of the .hierarchy.
    std::istringstream in(text);
    std::string line;
    std::vector<bool> seen(grids.size(), false);
    long long distinct = 0;
    for (int number = 1; std::getline(in, line); ++number)
    {
      TextCursor c(line);
      long long n = 0;
      if (c.AtEnd())
        continue;
      if (!c.Int(n, 1, static_cast<long long>(grids.size()) - 1))
        return Quote(procmap) + ": line " + std::to_string(number) + " does not start with a " +
               "grid number in [1, " + std::to_string(grids.size() - 1) + "] (the .hierarchy's " +
               "grids); one of them is truncated or damaged";
      distinct += seen[std::size_t(n)] ? 0 : 1;
      seen[std::size_t(n)] = true;
    }
    if (distinct != static_cast<long long>(grids.size()) - 1)
      return Quote(procmap) + " lists " + std::to_string(distinct) + " grids, the .hierarchy " +
             std::to_string(grids.size() - 1) + "; expected the same (one is truncated)";
  }
  const std::string boundary = base + ".boundary";
  if (FileSize(boundary, size))
  {
    if (!ReadWholeFile(boundary, kMaxTextBytes, text, error))
      return error;
    const std::vector<std::string> w = words(text);
    for (std::size_t i = 0; i + 2 < w.size(); ++i)
      if (w[i] == "NumberOfBaryonFields" && w[i + 1] == "=" &&
          w[i + 2] != std::to_string(grids[1].Fields))
        return Quote(boundary) + ": NumberOfBaryonFields = " + w[i + 2] + ", but grid 1 has " +
               std::to_string(grids[1].Fields) + "; expected the same";
  }
  return "";
}
}

Result CheckEnzo(const std::string& path)
{
  Result r;
  r.Format = "enzo";
  const std::string ext = path.substr(path.find_last_of('.'));
  const std::string base = path.substr(0, path.size() - ext.size());
  const std::string hierarchy = base + ".hierarchy";
  int rank = 0;
  if (!(r.Error = readRank(base, rank)).empty())
    return r;
  std::string text;
  if (!ReadWholeFile(hierarchy, kMaxTextBytes, text, r.Error))
    return r;
  const std::vector<std::string> w = words(text);
  Words in{ w };
  std::vector<Grid> grids(1); // grids[0]: the root, as in the reader
  int level = 0;
  std::string word;
  while (in.next(word))
  {
    if (word == "Grid")
    {
      long long index = 0;
      const std::string where = Quote(hierarchy) + ", grid " + std::to_string(grids.size());
      if (!in.equals("=") || !in.integer(index, 1, 1LL << 30))
        return r.Error = where + ": expected 'Grid = N' with N >= 1", r;
      if (index != static_cast<long long>(grids.size()))
        return r.Error = where + ": found 'Grid = " + std::to_string(index) +
                         "'; expected the grids numbered in order",
               r;
      Grid g;
      if (!(r.Error = parseGrid(in, rank, g, where)).empty())
        return r;
      g.Level = level;
      grids.push_back(g);
      // NumberOfBaryonFields sits before BaryonFileName; find it within this block.
      for (std::size_t i = in.I; i-- > 0 && w[i] != "Grid";)
        if (w[i] == "NumberOfBaryonFields" && i + 2 < w.size())
        {
          TextCursor c(w[i + 2]);
          long long f = 1;
          grids.back().Fields = c.Int(f, 0, 1 << 16) ? f : 1;
        }
    }
    else if (word == "Pointer:")
    {
      std::string target;
      long long from = 0, to = 0;
      in.next(target);
      // "Grid[N]->NextGridThisLevel" or "Grid[N]->NextGridNextLevel", as the reader expects.
      const std::string head = "Grid[", tailThis = "]->NextGridThisLevel",
                        tailNext = "]->NextGridNextLevel";
      const bool shaped =
        target.size() > head.size() + tailThis.size() && target.compare(0, head.size(), head) == 0;
      const std::string tail = shaped ? target.substr(target.size() - tailThis.size()) : "";
      const bool thisLevel = shaped && tail == tailThis;
      const bool nextLevel = shaped && tail == tailNext;
      const std::string number =
        shaped ? target.substr(head.size(), target.size() - head.size() - tailThis.size()) : "";
      TextCursor c(number);
      if ((!thisLevel && !nextLevel) || !c.Int(from, 1, 1LL << 30) || !c.AtEnd() ||
          !in.equals("=") || !in.integer(to, 0, 1LL << 30))
        return r.Error = Quote(hierarchy) + ": a 'Pointer:' line near word " +
                         std::to_string(in.I) + " is not 'Pointer: Grid[N]->NextGrid...Level = M'",
               r;
      if (from >= static_cast<long long>(grids.size()) ||
          grids[std::size_t(from)].Pointer[nextLevel ? 1 : 0] >= 0)
        return r.Error = Quote(hierarchy) + ": a pointer of grid " + std::to_string(from) +
                         " before that grid is described, or given twice (a damaged hierarchy)",
               r;
      grids[std::size_t(from)].Pointer[nextLevel ? 1 : 0] = to;
      if (nextLevel && to != 0)
        level = grids[std::size_t(from)].Level + 1;
    }
    else if (word == "Time")
    {
      double t = 0;
      if (!in.equals("=") || !in.real(t))
        return r.Error = Quote(hierarchy) + ": a 'Time' line is not 'Time = number'", r;
    }
  }
  if (grids.size() < 2)
    return r.Error = Quote(hierarchy) + " describes no grids; expected 'Grid = 1' ...", r;
  if (!(r.Error = checkTree(grids, hierarchy)).empty())
    return r;
  if (!(r.Error = checkTotals(base, grids)).empty())
    return r;

  // Each grid file: an HDF5 file whose superblock fits its size, large enough for the cells of
  // the grids stored in it (at least 4 bytes per cell and field).
  std::map<std::string, std::pair<std::uint64_t, std::uint64_t>> files; // size, needed
  std::map<std::string, std::set<std::string>> groups; // a file's root "Grid..." groups
  for (std::size_t i = 1; i < grids.size(); ++i)
  {
    const Grid& g = grids[i];
    const std::string file = Directory(path) + "/" + g.File;
    auto it = files.find(file);
    if (it == files.end())
    {
      std::uint64_t size = 0;
      if (!(r.Error = CheckHDF5(file, size)).empty())
        return r.Error += " (grid " + std::to_string(i) + " of " + Quote(hierarchy) + ")", r;
      it = files.emplace(file, std::make_pair(size, std::uint64_t(0))).first;
      r.DataBytes += size;
      std::vector<std::string> names;
      if (!(r.Error = HDF5RootNames(file, names)).empty())
        return r;
      for (const std::string& name : names)
        if (name.compare(0, 4, "Grid") == 0)
          groups[file].insert(name);
    }
    // Packed Enzo files hold grid N in the root group "Grid%08d" (vtkAMREnzoReader looks for it
    // and asserts when it is gone); unpacked ones have no Grid groups at all.
    char group[32];
    std::snprintf(group, sizeof(group), "Grid%08zu", i);
    const auto named = groups.find(file);
    if (named != groups.end() && !named->second.count(group))
      return r.Error = Quote(file) + " has no root group '" + group + "' for grid " +
                       std::to_string(i) + " of " + Quote(hierarchy) + " (a damaged HDF5 file)",
             r;
    it->second.second += std::uint64_t(g.Cells()) * std::uint64_t(g.Fields) * 4;
    if (it->second.second > it->second.first)
      return r.Error = Quote(file) + " has " + std::to_string(it->second.first) +
                       " bytes, fewer than the " + std::to_string(it->second.second) +
                       " that its grids up to grid " + std::to_string(i) +
                       " need (4 bytes per cell and field): truncated",
             r;
    if (static_cast<int>(r.BlocksPerLevel.size()) <= g.Level)
      r.BlocksPerLevel.resize(std::size_t(g.Level) + 1, 0);
    ++r.BlocksPerLevel[std::size_t(g.Level)];
    r.Cells += g.Cells();
  }
  return r;
}
}
