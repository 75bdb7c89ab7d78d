// Helpers of the file checks: file sizes, bounded reads, a bounded text cursor and the HDF5
// superblock check.
#include "AMRFileChecks.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sys/stat.h>

namespace amrdm_filecheck
{
bool FileSize(const std::string& path, std::uint64_t& size)
{
  struct stat st;
  if (stat(path.c_str(), &st) != 0 || !S_ISREG(st.st_mode))
    return false;
  size = static_cast<std::uint64_t>(st.st_size);
  return true;
}

bool IsDirectory(const std::string& path)
{
  struct stat st;
  return stat(path.c_str(), &st) == 0 && S_ISDIR(st.st_mode);
}

std::string Quote(const std::string& path)
{
  return "'" + path + "'";
}

std::string Directory(const std::string& path)
{
  const std::size_t slash = path.find_last_of('/');
  return slash == std::string::npos ? std::string(".") : path.substr(0, slash == 0 ? 1 : slash);
}

std::string BaseName(const std::string& path)
{
  const std::size_t slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

bool ReadWholeFile(const std::string& path,
  std::uint64_t limit,
  std::string& text,
  std::string& error)
{
  std::uint64_t size = 0;
  if (!FileSize(path, size))
  {
    error = Quote(path) + " is missing (or not a regular file)";
    return false;
  }
  if (size > limit)
  {
    error = Quote(path) + " has " + std::to_string(size) + " bytes; expected at most " +
            std::to_string(limit) + " for this kind of file";
    return false;
  }
  if (size == 0)
  {
    error = Quote(path) + " is empty";
    return false;
  }
  std::ifstream in(path, std::ios::binary);
  text.assign(static_cast<std::size_t>(size), '\0');
  if (!in || !in.read(&text[0], static_cast<std::streamsize>(size)))
  {
    error = Quote(path) + " could not be read";
    return false;
  }
  const std::size_t nul = text.find('\0');
  if (nul != std::string::npos)
  {
    error =
      Quote(path) + " has a NUL byte at offset " + std::to_string(nul) + "; expected a text file";
    return false;
  }
  return true;
}

bool ReadBytes(const std::string& path, std::uint64_t offset, std::size_t count, std::string& out)
{
  std::ifstream in(path, std::ios::binary);
  if (!in)
    return false;
  in.seekg(static_cast<std::streamoff>(offset));
  if (!in)
    return false;
  out.assign(count, '\0');
  in.read(&out[0], static_cast<std::streamsize>(count));
  out.resize(static_cast<std::size_t>(in.gcount()));
  return true;
}

namespace
{
std::uint64_t littleEndian(const std::string& bytes, std::size_t at, int width)
{
  std::uint64_t v = 0;
  for (int i = width - 1; i >= 0; --i)
    v = (v << 8) | static_cast<unsigned char>(bytes[at + static_cast<std::size_t>(i)]);
  return v;
}
}

std::string CheckHDF5(const std::string& path, std::uint64_t& size)
{
  if (!FileSize(path, size))
    return Quote(path) + " is missing (or not a regular file); expected an HDF5 grid file";
  static const char signature[] = "\x89HDF\r\n\x1a\n";
  // The superblock sits at 0 or, after a user block, at 512, 1024, 2048, ...
  for (std::uint64_t at = 0; at + 8 <= size && at <= (std::uint64_t(1) << 24);
       at = at == 0 ? 512 : at * 2)
  {
    std::string sb;
    if (!ReadBytes(path, at, 96, sb) || sb.size() < 8 || sb.compare(0, 8, signature, 8) != 0)
      continue;
    if (sb.size() < 16)
      break;
    const int version = static_cast<unsigned char>(sb[8]);
    int offsetSize = 0;
    std::size_t eofAt = 0;
    if (version == 0 || version == 1)
    {
      offsetSize = static_cast<unsigned char>(sb[13]);
      eofAt = 24 + (version == 1 ? 4 : 0) + 2 * static_cast<std::size_t>(offsetSize);
    }
    else if (version == 2 || version == 3)
    {
      offsetSize = static_cast<unsigned char>(sb[9]);
      eofAt = 12 + 2 * static_cast<std::size_t>(offsetSize);
    }
    else
      return Quote(path) + " has HDF5 superblock version " + std::to_string(version) +
             "; expected 0 to 3";
    if (offsetSize != 2 && offsetSize != 4 && offsetSize != 8)
      return Quote(path) + " has an HDF5 superblock with offset size " +
             std::to_string(offsetSize) + "; expected 2, 4 or 8 (a damaged file)";
    if (sb.size() < eofAt + static_cast<std::size_t>(offsetSize))
      return Quote(path) + " ends inside its HDF5 superblock (" + std::to_string(size) +
             " bytes): truncated";
    const std::uint64_t base = littleEndian(sb, eofAt - 2 * std::size_t(offsetSize), offsetSize);
    const std::uint64_t eof = littleEndian(sb, eofAt, offsetSize);
    const std::uint64_t end = (version <= 1 ? base : at) + eof;
    if (end > size || end < eof)
      return Quote(path) + " has " + std::to_string(size) +
             " bytes, but its HDF5 superblock says " + std::to_string(end) +
             ": truncated (or a damaged superblock)";
    return "";
  }
  return Quote(path) + " is not an HDF5 file (no HDF5 signature); expected an HDF5 grid file";
}

std::string HDF5RootNames(const std::string& path, std::vector<std::string>& names)
{
  names.clear();
  std::uint64_t size = 0;
  std::string sb;
  if (!FileSize(path, size) || !ReadBytes(path, 0, 160, sb) || sb.size() < 16)
    return "";
  const int version = static_cast<unsigned char>(sb[8]);
  const int o = static_cast<unsigned char>(sb[13]), l = static_cast<unsigned char>(sb[14]);
  if (sb.compare(0, 8, "\x89HDF\r\n\x1a\n", 8) != 0 || version > 1 || (o != 4 && o != 8) ||
      (l != 4 && l != 8))
    return ""; // newer superblocks (and user blocks): not checked here
  const std::size_t root = 24 + (version == 1 ? 4 : 0) + 4 * std::size_t(o);
  if (sb.size() < root + 2 * std::size_t(o) + 8 + 2 * std::size_t(o))
    return "";
  const std::uint64_t base = littleEndian(sb, 24 + (version == 1 ? 4 : 0), o);
  if (littleEndian(sb, root + 2 * std::size_t(o), 4) != 1)
    return ""; // the root entry caches no symbol table
  const std::uint64_t heap = base + littleEndian(sb, root + 2 * std::size_t(o) + 8 + o, o);
  std::string h;
  if (!ReadBytes(path, heap, 8 + 2 * std::size_t(l) + std::size_t(o), h) ||
      h.size() < 8 + 2 * std::size_t(l) + std::size_t(o) || h.compare(0, 4, "HEAP") != 0)
    return Quote(path) + ": the root group's local heap (at byte " + std::to_string(heap) +
           ") is not there: a damaged or truncated HDF5 file";
  const std::uint64_t length = littleEndian(h, 8, l);
  const std::uint64_t at = base + littleEndian(h, 8 + 2 * std::size_t(l), o);
  if (length > (std::uint64_t(1) << 26) || at > size || length > size - at)
    return Quote(path) + ": the root group's name heap (" + std::to_string(length) + " bytes at " +
           std::to_string(at) + ") does not fit the file: damaged or truncated";
  std::string segment;
  ReadBytes(path, at, std::size_t(length), segment);
  for (std::size_t i = 0; i < segment.size();)
  {
    const std::size_t end = std::min(segment.find('\0', i), segment.size());
    if (end > i)
      names.push_back(segment.substr(i, end - i));
    i = end + 1;
  }
  return "";
}

// --- TextCursor ---------------------------------------------------------------------------------
void TextCursor::SkipSpace()
{
  while (this->Pos < this->Text.size() &&
         std::isspace(static_cast<unsigned char>(this->Text[this->Pos])))
    ++this->Pos;
}

bool TextCursor::AtEnd()
{
  this->SkipSpace();
  return this->Pos >= this->Text.size();
}

bool TextCursor::Char(char expected)
{
  this->SkipSpace();
  if (this->Pos < this->Text.size() && this->Text[this->Pos] == expected)
  {
    ++this->Pos;
    return true;
  }
  return false;
}

bool TextCursor::Word(std::string& out)
{
  this->SkipSpace();
  const std::size_t start = this->Pos;
  while (this->Pos < this->Text.size() &&
         !std::isspace(static_cast<unsigned char>(this->Text[this->Pos])))
    ++this->Pos;
  out = this->Text.substr(start, this->Pos - start);
  return !out.empty();
}

bool TextCursor::Int(long long& out, long long lo, long long hi)
{
  this->SkipSpace();
  const char* begin = this->Text.c_str() + this->Pos;
  char* end = nullptr;
  errno = 0;
  const long long v = std::strtoll(begin, &end, 10);
  if (end == begin || errno != 0 || v < lo || v > hi)
    return false;
  this->Pos += static_cast<std::size_t>(end - begin);
  out = v;
  return true;
}

bool TextCursor::Double(double& out)
{
  this->SkipSpace();
  const char* begin = this->Text.c_str() + this->Pos;
  char* end = nullptr;
  const double v = std::strtod(begin, &end);
  if (end == begin || !std::isfinite(v))
    return false;
  this->Pos += static_cast<std::size_t>(end - begin);
  out = v;
  return true;
}

int TextCursor::Line() const
{
  int line = 1;
  for (std::size_t i = 0; i < this->Pos && i < this->Text.size(); ++i)
    line += this->Text[i] == '\n' ? 1 : 0;
  return line;
}
}
