// The format checks behind vtkAMRDualMeshFileCheck (plain C++, no VTK reader, no HDF5 library):
// each parses the metadata a VTK AMR reader would read, checks every count against the bytes
// that are there before it is used, and checks that every data file exists and is long enough
// for what the metadata says it holds. The first problem found is returned as one line naming
// the file and what was wrong.
#ifndef AMRFileChecks_h
#define AMRFileChecks_h

#include <cstdint>
#include <string>
#include <vector>

namespace amrdm_filecheck
{
struct Result
{
  std::string Error;               // empty: the files describe a whole, readable hierarchy
  std::string Format;              // "enzo", "amrex" or "vthb"
  std::vector<int> BlocksPerLevel; // as the metadata describes them
  long long Cells = 0;             // cells of all blocks (covered cells included)
  int EmptyBlocks = 0;             // .vthb DataSets without a file (not in BlocksPerLevel)
  long long EmptyCells = 0;        // their amr_box cells
  std::uint64_t DataBytes = 0;     // bytes of the files a reader would read
};

Result CheckEnzo(const std::string& path);
Result CheckAMReX(const std::string& folder);
Result CheckVthb(const std::string& path);

// --- helpers shared by the checks (AMRFileCheckText.cxx) ---------------------------------------
/// The size of a regular file; false if it is missing or not a regular file.
bool FileSize(const std::string& path, std::uint64_t& size);
bool IsDirectory(const std::string& path);
/// The whole file, at most `limit` bytes; an error text when it is missing, larger or unreadable.
bool ReadWholeFile(const std::string& path,
  std::uint64_t limit,
  std::string& text,
  std::string& error);
/// Up to `count` bytes from `offset` (fewer at the end of the file).
bool ReadBytes(const std::string& path, std::uint64_t offset, std::size_t count, std::string& out);
/// "" when `path` is an HDF5 file whose superblock's end-of-file address fits its size.
std::string CheckHDF5(const std::string& path, std::uint64_t& size);
/// The link names in the root group's local heap of an HDF5 file with a version 0/1 superblock
/// (the old-style groups Enzo writes): "" and the names, or "" and none when the file uses newer
/// groups, or a problem when the heap lies outside the file.
std::string HDF5RootNames(const std::string& path, std::vector<std::string>& names);
std::string Quote(const std::string& path);
std::string Directory(const std::string& path);
std::string BaseName(const std::string& path);

/// A cursor over text that reads numbers and words as `std::istream >>` would, but never past
/// the end and never a value out of range: every read says whether it succeeded.
class TextCursor
{
public:
  explicit TextCursor(const std::string& text)
    : Text(text)
  {
  }
  void SkipSpace();
  bool AtEnd();
  bool Char(char expected);    // the next non-space character is `expected`
  bool Word(std::string& out); // the next whitespace-delimited word
  bool Int(long long& out, long long lo, long long hi);
  bool Double(double& out); // finite
  std::size_t Position() const { return this->Pos; }
  std::size_t Remaining() const { return this->Text.size() - this->Pos; }
  /// Line number (1-based) of the current position, for messages.
  int Line() const;

private:
  const std::string& Text;
  std::size_t Pos = 0;
};
}

#endif
