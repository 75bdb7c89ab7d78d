/**
 * @class   vtkAMRDualMeshFileCheck
 * @brief   checks an AMR file before a VTK reader sees it, and the reader's output after
 *
 * VTK's AMR readers trust their files: a truncated Enzo `.hierarchy` makes vtkAMREnzoReader
 * search for ever or stop early (a partial hierarchy, no message), a damaged AMReX `Header` or
 * `Cell_H` makes vtkAMReXGridReader allocate unbounded counts or index past its arrays, and a
 * truncated data file gives std::bad_alloc or arrays that silently go missing. This class parses
 * the metadata those readers parse, in plain C++ (no HDF5 library), checking every count against
 * the bytes that are there before using it, and checks that every data file the metadata names
 * exists and is long enough:
 *
 * - Enzo (`.hierarchy` or `.boundary` path): the parameter file's TopGridRank; every Grid block
 *   of the `.hierarchy` complete (GridStartIndex, GridEndIndex, GridLeftEdge, GridRightEdge,
 *   BaryonFileName, NumberOfParticles, in that order, before the next grid), the grids numbered
 *   in order, their Pointer lines a tree rooted at grid 1 that reaches every grid once (a file
 *   cut between grids leaves a pointer to a missing grid or a missing pointer), the `.procmap`
 *   grid count and the `.boundary` field count where those files exist; each grid file an HDF5
 *   file whose superblock's end-of-file address fits its size and large enough for 4 bytes per
 *   cell and field of its grids.
 * - AMReX plotfile (folder): the Header (variables, dimension, levels, domain boxes, cell sizes,
 *   boxes per level), each level's `Cell_H` (version 1; components, box list, FabOnDisk entries,
 *   minima and maxima), and for each box the FAB header at its offset in its data file (format,
 *   box and components equal to the Cell_H's) and the file's length against offset + header +
 *   components * cells * bytes.
 * - `.vthb`: the XML parses, and each block file exists, parses as ImageData and, for appended
 *   raw data, covers each array's offset, header and bytes (the bytes its extent implies).
 *
 * A problem is one line naming the file and what was wrong. The check reads metadata and a few
 * bytes per data block, so it takes milliseconds for the sets here.
 *
 * CheckOutput() then compares what a reader returned with the metadata: the same number of
 * non-empty blocks on every level and the same cell arrays on every block, so a reader that stops
 * early or drops an array is an error instead of a partial render.
 */
#ifndef vtkAMRDualMeshFileCheck_h
#define vtkAMRDualMeshFileCheck_h

#include "AMRDualMeshMapperModule.h" // For export macro
#include "vtkObject.h"

#include <string> // For std::string
#include <vector> // For std::vector

class vtkOverlappingAMR;

class AMRDUALMESHMAPPER_EXPORT vtkAMRDualMeshFileCheck : public vtkObject
{
public:
  static vtkAMRDualMeshFileCheck* New();
  vtkTypeMacro(vtkAMRDualMeshFileCheck, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// "" when `path` (an Enzo .hierarchy/.boundary, an AMReX plotfile folder or a .vthb) is
  /// whole and readable, else one line naming the file and the problem.
  static std::string Check(const std::string& path);

  /// Checks `path` and keeps what its metadata says; true when it is fine (GetError() is "").
  bool CheckFile(const std::string& path);
  /// The last CheckFile's or CheckOutput's problem ("" if none).
  std::string GetError() const { return this->Error; }
  /// "enzo", "amrex", "vthb" (after CheckFile), or "".
  std::string GetFormat() const { return this->Format; }
  int GetNumberOfLevels() const { return static_cast<int>(this->BlocksPerLevel.size()); }
  /// Blocks the metadata describes on `level` (0 outside the levels).
  int GetNumberOfBlocks(int level) const;
  /// Cells of all blocks (covered cells included), from the metadata.
  long long GetNumberOfCells() const { return this->Cells; }
  /// Bytes of the data files a reader reads.
  double GetDataBytes() const { return this->DataBytes; }

  /// Seconds a reader may take on the last checked file before a caller should give up: the
  /// environment variable AMRDM_READ_TIMEOUT (seconds) when set to a positive number, else
  /// 10 s + 1 s per 5 MB of data files.
  double GetReadTimeoutSeconds() const;

  /// Compares a reader's output with the last CheckFile: "" when every level has the blocks the
  /// metadata describes, each non-empty, all with the same cell arrays; else one line saying how
  /// much was read (e.g. "level 2: 3 of 5 blocks").
  ///
  /// It also compares each block's vtkGhostType with the boxes: the REFINEDCELL flag must be set
  /// exactly where a block of the next level covers the cell (an error otherwise, naming the
  /// block and the count). Cells flagged HIDDENCELL or DUPLICATECELL are not rendered; they are
  /// counted in GetWarning() (a damaged ghost array, or data masked on purpose).
  std::string CheckOutput(vtkOverlappingAMR* amr);
  /// CheckOutput's warning ("" if none): how many cells the ghost array hides, and how many
  /// blocks (and cells) a .vthb describes without a file (empty blocks, not rendered).
  std::string GetWarning() const { return this->Warning; }

protected:
  vtkAMRDualMeshFileCheck() = default;
  ~vtkAMRDualMeshFileCheck() override = default;

private:
  vtkAMRDualMeshFileCheck(const vtkAMRDualMeshFileCheck&) = delete;
  void operator=(const vtkAMRDualMeshFileCheck&) = delete;

  std::string Path;
  std::string Error;
  std::string Warning;
  std::string Format;
  std::vector<int> BlocksPerLevel;
  long long Cells = 0;
  int EmptyBlocks = 0;
  long long EmptyCells = 0;
  double DataBytes = 0;
};

#endif
