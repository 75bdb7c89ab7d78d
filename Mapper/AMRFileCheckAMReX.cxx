// The AMReX plotfile check: the Header (variables, levels, boxes per level), each level's
// Cell_H (its box list and FabOnDisk entries, as vtkAMReXGridReader parses them) and, for each
// box, the FAB header in its data file and the file's length against offset + header + data.
#include "AMRFileChecks.h"

#include <map>

namespace amrdm_filecheck
{
namespace
{
constexpr std::uint64_t kMaxHeaderBytes = std::uint64_t(1) << 30;
constexpr long long kMaxIndex = 1LL << 30;

struct Box
{
  long long Lo[3] = { 0, 0, 0 }, Hi[3] = { 0, 0, 0 };
  long long Cells(int dim) const
  {
    long long n = 1;
    for (int d = 0; d < dim; ++d)
      n *= Hi[d] - Lo[d] + 1;
    return n;
  }
  bool operator!=(const Box& o) const
  {
    for (int d = 0; d < 3; ++d)
      if (Lo[d] != o.Lo[d] || Hi[d] != o.Hi[d])
        return true;
    return false;
  }
};

/// "((lo,..) (hi,..) (type,..))" as the reader reads it, with lo <= hi.
bool readBox(TextCursor& c, int dim, Box& b)
{
  long long type = 0;
  if (!c.Char('('))
    return false;
  for (int part = 0; part < 3; ++part)
  {
    if (!c.Char('('))
      return false;
    for (int d = 0; d < dim; ++d)
    {
      long long& v = part == 0 ? b.Lo[d] : part == 1 ? b.Hi[d] : type;
      if (!c.Int(v, part == 2 ? 0 : -kMaxIndex, part == 2 ? 1 : kMaxIndex) ||
          !c.Char(d + 1 < dim ? ',' : ')'))
        return false;
    }
  }
  if (!c.Char(')'))
    return false;
  for (int d = 0; d < dim; ++d)
    if (b.Hi[d] < b.Lo[d])
      return false;
  return true;
}

std::string at(const std::string& file, const TextCursor& c)
{
  return Quote(file) + " line " + std::to_string(c.Line());
}

/// One FAB: its header line at `offset` in `file` ("FAB ((8, (64 11 52 0 1 12 0 1023)),(8, (8 7
/// 6 5 4 3 2 1)))((lo) (hi) (type)) ncomp\n") and its data after it.
std::string checkFab(const std::string& file,
  std::uint64_t size,
  std::uint64_t offset,
  int dim,
  const Box& box,
  long long ncomp)
{
  std::string head;
  if (offset >= size || !ReadBytes(file, offset, 1024, head))
    return Quote(file) + " has " + std::to_string(size) + " bytes; a FAB starts at offset " +
           std::to_string(offset) + ": truncated";
  const std::size_t eol = head.find('\n');
  if (eol == std::string::npos && offset + head.size() == size)
    return Quote(file) + " ends at byte " + std::to_string(size) +
           ", inside the FAB header at offset " + std::to_string(offset) + ": truncated";
  if (head.compare(0, 4, "FAB ") != 0 || eol == std::string::npos)
    return Quote(file) + ": no 'FAB ...' header line at offset " + std::to_string(offset) +
           " (truncated or damaged)";
  const std::string line = head.substr(0, eol);
  TextCursor c(line);
  std::string word;
  long long n = 0, v = 0, bits = 0, fabComps = 0;
  c.Word(word); // FAB
  bool ok = c.Char('(') && c.Char('(') && c.Int(n, 8, 8) && c.Char(',') && c.Char('(');
  for (long long i = 0; ok && i < 8; ++i)
    ok = c.Int(v, 0, 1 << 16) && (i > 0 || (bits = v) != 0);
  long long bytes = 0;
  ok = ok && c.Char(')') && c.Char(')') && c.Char(',') && c.Char('(') && c.Int(bytes, 4, 8) &&
       bytes * 8 == bits && c.Char(',') && c.Char('(');
  for (long long i = 0; ok && i < bytes; ++i)
    ok = c.Int(v, 1, bytes);
  Box fabBox;
  ok = ok && c.Char(')') && c.Char(')') && c.Char(')') && readBox(c, dim, fabBox) &&
       c.Int(fabComps, 1, 1 << 20) && c.AtEnd();
  if (!ok || (bytes != 4 && bytes != 8))
    return Quote(file) + ": the FAB header at offset " + std::to_string(offset) +
           " is not 'FAB ((8, (32|64 ...)),(4|8, (...)))((lo) (hi) (type)) ncomp' (damaged)";
  if (fabBox != box || fabComps != ncomp)
    return Quote(file) + ": the FAB at offset " + std::to_string(offset) +
           " has another box or component count than its Cell_H says (damaged)";
  const std::uint64_t end =
    offset + eol + 1 + std::uint64_t(ncomp) * std::uint64_t(box.Cells(dim)) * std::uint64_t(bytes);
  if (end > size)
    return Quote(file) + " has " + std::to_string(size) + " bytes; the FAB at offset " +
           std::to_string(offset) + " needs " + std::to_string(end) + ": truncated";
  return "";
}

/// A level's Cell_H (version 1, the one with FAB headers that vtkAMReXGridReader reads) and its
/// data files.
std::string checkLevel(const std::string& folder,
  const std::string& levelDir,
  const std::string& cellH,
  int dim,
  long long nvars,
  long long boxes,
  Result& r,
  std::map<std::string, std::uint64_t>& sizes)
{
  std::string text, error;
  if (!ReadWholeFile(cellH, kMaxHeaderBytes, text, error))
    return error;
  TextCursor c(text);
  long long version = 0, how = 0, ncomp = 0, nghost = 0, n = 0, magic = 0, nfab = 0;
  if (!c.Int(version, -1, 10) || version != 1)
    return at(cellH, c) + ": version " + std::to_string(version) +
           "; expected 1 (FABs with headers, the version VTK's reader reads)";
  if (!c.Int(how, 0, 10) || !c.Int(ncomp, 1, 1 << 20) || !c.Int(nghost, 0, 1 << 10))
    return at(cellH, c) + ": expected 'how', the number of components and of ghost cells";
  if (ncomp != nvars)
    return Quote(cellH) + " has " + std::to_string(ncomp) + " components; the Header " +
           std::to_string(nvars) + " variables; expected the same";
  if (!c.Char('(') || !c.Int(n, 0, static_cast<long long>(c.Remaining() / 8)) ||
      !c.Int(magic, 0, 0) || n != boxes)
    return at(cellH, c) + ": expected '(" + std::to_string(boxes) +
           " 0' (the Header's box count for this level)";
  std::vector<Box> list(static_cast<std::size_t>(n));
  for (Box& b : list)
    if (!readBox(c, dim, b))
      return at(cellH, c) + ": expected a box '((lo) (hi) (type))' with lo <= hi (" +
             std::to_string(n) + " boxes)";
  if (!c.Char(')') || !c.Int(nfab, n, n))
    return at(cellH, c) + ": expected ')' and " + std::to_string(n) + " FabOnDisk entries";
  for (long long i = 0; i < n; ++i)
  {
    std::string tag, name;
    long long offset = 0;
    if (!c.Word(tag) || tag != "FabOnDisk:" || !c.Word(name) || !c.Int(offset, 0, 1LL << 50))
      return at(cellH, c) + ": expected 'FabOnDisk: FILE OFFSET' (entry " + std::to_string(i) +
             " of " + std::to_string(n) + ")";
    const std::string file = folder + "/" + levelDir + "/" + name;
    auto it = sizes.find(file);
    if (it == sizes.end())
    {
      std::uint64_t size = 0;
      if (!FileSize(file, size))
        return Quote(file) + " is missing (named by " + Quote(cellH) + ")";
      it = sizes.emplace(file, size).first;
      r.DataBytes += size;
    }
    if (!(error =
            checkFab(file, it->second, std::uint64_t(offset), dim, list[std::size_t(i)], ncomp))
           .empty())
      return error;
    r.Cells += list[std::size_t(i)].Cells(dim);
  }
  // The per-FAB minima and maxima: "nfab,ncomp" then nfab * ncomp "value," twice.
  for (int pass = 0; pass < 2; ++pass)
  {
    long long a = 0, b = 0;
    if (!c.Int(a, n, n) || !c.Char(',') || !c.Int(b, ncomp, ncomp))
      return at(cellH, c) + ": expected the " + (pass ? "maxima" : "minima") + " header '" +
             std::to_string(n) + "," + std::to_string(ncomp) + "' (truncated?)";
    for (long long i = 0; i < n * ncomp; ++i)
    {
      double v = 0;
      if (!c.Double(v) || !c.Char(','))
        return at(cellH, c) + ": expected " + std::to_string(n * ncomp) + " values 'v,' of the " +
               (pass ? "maxima" : "minima") + " (truncated?)";
    }
  }
  return "";
}
}

Result CheckAMReX(const std::string& folder)
{
  Result r;
  r.Format = "amrex";
  const std::string header = folder + "/Header";
  std::string text;
  if (!ReadWholeFile(header, kMaxHeaderBytes, text, r.Error))
    return r;
  TextCursor c(text);
  std::string word;
  long long nvars = 0, dim = 0, finest = 0, v = 0;
  double x = 0;
  if (!c.Word(word) || !c.Int(nvars, 1, static_cast<long long>(c.Remaining() / 2)))
    return r.Error = at(header, c) + ": expected a version and a number of variables", r;
  for (long long i = 0; i < nvars; ++i)
    if (!c.Word(word))
      return r.Error = at(header, c) + ": expected " + std::to_string(nvars) + " names", r;
  if (!c.Int(dim, 1, 3) || !c.Double(x) || !c.Int(finest, 0, 63))
    return r.Error = at(header, c) + ": expected the dimension (1-3), the time and the " +
                     "finest level (0-63)",
           r;
  const int d = static_cast<int>(dim);
  double lo[3] = { 0, 0, 0 }, hi[3] = { 0, 0, 0 };
  for (int i = 0; i < 2 * d; ++i)
    if (!c.Double(i < d ? lo[i] : hi[i - d]))
      return r.Error = at(header, c) + ": expected the problem domain's corners", r;
  for (long long i = 0; i < finest; ++i)
    if (!c.Int(v, 1, 1 << 10))
      return r.Error = at(header, c) + ": expected " + std::to_string(finest) +
                       " refinement ratios (1-1024)",
             r;
  Box domain;
  for (long long i = 0; i <= finest; ++i)
    if (!readBox(c, d, domain))
      return r.Error = at(header, c) + ": expected the domain box of level " + std::to_string(i) +
                       " '((lo) (hi) (type))'",
             r;
  for (long long i = 0; i <= finest; ++i)
    if (!c.Int(v, 0, 1LL << 50))
      return r.Error = at(header, c) + ": expected the step of each level", r;
  for (long long i = 0; i < (finest + 1) * dim; ++i)
    if (!c.Double(x) || !(x > 0))
      return r.Error = at(header, c) + ": expected positive cell sizes for every level", r;
  if (!c.Int(v, -10, 10) || !c.Int(v, -(1 << 20), 1 << 20))
    return r.Error = at(header, c) + ": expected the coordinate system and boundary width", r;
  std::map<std::string, std::uint64_t> sizes;
  for (long long level = 0; level <= finest; ++level)
  {
    long long lev = 0, boxes = 0;
    if (!c.Int(lev, level, level) ||
        !c.Int(boxes, 1, static_cast<long long>(c.Remaining() / (4 * std::size_t(d)))) ||
        !c.Double(x) || !c.Int(v, 0, 1LL << 50))
      return r.Error = at(header, c) + ": expected '" + std::to_string(level) +
                       " NBOXES TIME' and the step of level " + std::to_string(level),
             r;
    for (long long i = 0; i < 2 * boxes * dim; ++i)
      if (!c.Double(x))
        return r.Error = at(header, c) + ": expected " + std::to_string(boxes) +
                         " boxes of level " + std::to_string(level) + " (truncated?)",
               r;
    std::string path;
    const std::size_t slash = c.Word(path) ? path.find('/') : std::string::npos;
    if (slash == std::string::npos || slash == 0 || slash + 1 == path.size())
      return r.Error = at(header, c) + ": expected the level's 'Level_N/Cell' path", r;
    const std::string cellH = folder + "/" + path + "_H";
    if (!(r.Error = checkLevel(folder, path.substr(0, slash), cellH, d, nvars, boxes, r, sizes))
           .empty())
      return r;
    r.BlocksPerLevel.push_back(static_cast<int>(boxes));
  }
  // Extra multifabs (after the levels, optional): a count, then per multifab its variables and
  // one path per level, each with a Cell_H-like header and data files.
  long long extra = 0;
  if (!c.AtEnd() && !c.Int(extra, 0, static_cast<long long>(c.Remaining())))
    return r.Error = at(header, c) + ": expected the number of extra multifabs or the end", r;
  for (long long m = 0; m < extra; ++m)
  {
    long long n = 0;
    if (!c.Int(n, 1, static_cast<long long>(c.Remaining())))
      return r.Error = at(header, c) + ": expected the variable count of extra multifab " +
                       std::to_string(m),
             r;
    for (long long i = 0; i < n; ++i)
      if (!c.Word(word))
        return r.Error = at(header, c) + ": expected " + std::to_string(n) + " names", r;
    for (long long level = 0; level <= finest; ++level)
    {
      std::string path;
      const std::size_t slash = c.Word(path) ? path.find('/') : std::string::npos;
      if (slash == std::string::npos || slash == 0 || slash + 1 == path.size())
        return r.Error = at(header, c) + ": expected an extra multifab's 'Level_N/NAME' path", r;
      Result ignored;
      if (!(r.Error = checkLevel(folder,
              path.substr(0, slash),
              folder + "/" + path + "_H",
              d,
              n,
              r.BlocksPerLevel[std::size_t(level)],
              ignored,
              sizes))
             .empty())
        return r;
    }
  }
  return r;
}
}
