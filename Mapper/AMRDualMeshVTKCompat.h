// The one place that calls VTK's AMR API (issue 36). VTK 9.6 rewrote the AMR data model
// (vtkAMRDataObject, typed block getters, GetNumberOfBlocks(level), Initialize(vector),
// rectilinear levels) and VTK master removed the calls of 9.2-9.5 that 9.6 deprecated; every
// access to levels, blocks, boxes, spacing/origin, refinement ratios, grid description and
// blanking/ghost flags in the Mapper and the ParaView plugin goes through these functions, and the
// VTK version is chosen at compile time in AMRDualMeshVTKCompat.cxx (docs/VTK-COMPAT.md). The
// AMRAPICheck test (.ci/check-amr-api.sh) fails on an AMR call anywhere else in either.
//
// This header names only types that exist in every supported VTK (vtkOverlappingAMR,
// vtkImageData, vtkAMRBox, vtkUnsignedCharArray) and has no version branch.
#ifndef AMRDualMeshVTKCompat_h
#define AMRDualMeshVTKCompat_h

#include "AMRDualMeshMapperModule.h" // AMRDUALMESHMAPPER_EXPORT
#include "vtkDataSetAttributes.h"    // the ghost-cell flags (same values in every VTK)
#include "vtkSmartPointer.h"

#include <string>
#include <vector>

class vtkAMRBox;
class vtkDataSet;
class vtkImageData;
class vtkOverlappingAMR;
class vtkUnsignedCharArray;

namespace amrdm_vtk
{
namespace amrcompat
{
/// Which AMR API this build uses: "vtkUniformGridAMR (VTK <= 9.5)" or
/// "vtkAMRDataObject (VTK >= 9.6)".
AMRDUALMESHMAPPER_EXPORT const char* APIName();

/// Levels of `amr` (0 for nullptr).
AMRDUALMESHMAPPER_EXPORT unsigned NumberOfLevels(vtkOverlappingAMR* amr);
/// Blocks in the metadata of `level` (loaded here or not; 0 for nullptr or a level out of range).
AMRDUALMESHMAPPER_EXPORT unsigned NumberOfBlocks(vtkOverlappingAMR* amr, unsigned level);

/// What a (level, id) holds here: nothing (not loaded on this process), a uniform grid, or a
/// grid the dual mesh cannot use (a vtkRectilinearGrid level, possible from VTK 9.6 on).
enum class BlockState
{
  Absent,
  Image,
  Unsupported
};
/// The block at (level, id) and its state; `grid` is set only for BlockState::Image.
AMRDUALMESHMAPPER_EXPORT BlockState BlockAt(vtkOverlappingAMR* amr,
  unsigned level,
  unsigned id,
  vtkImageData*& grid);
/// The uniform grid at (level, id), or nullptr (absent or unsupported: callers that must refuse
/// unsupported blocks use BlockAt).
AMRDUALMESHMAPPER_EXPORT vtkImageData* Block(vtkOverlappingAMR* amr, unsigned level, unsigned id);
/// "level L block I is a vtkRectilinearGrid; expected ..." for an Unsupported block.
AMRDUALMESHMAPPER_EXPORT std::string UnsupportedBlockMessage(vtkOverlappingAMR* amr,
  unsigned level,
  unsigned id);

/// The metadata box of (level, id), loaded here or not.
AMRDUALMESHMAPPER_EXPORT const vtkAMRBox& Box(vtkOverlappingAMR* amr, unsigned level, unsigned id);
AMRDUALMESHMAPPER_EXPORT void SetBox(vtkOverlappingAMR* amr,
  unsigned level,
  unsigned id,
  const vtkAMRBox& box);

/// Cell size of `level` (the AMR's metadata).
AMRDUALMESHMAPPER_EXPORT void Spacing(vtkOverlappingAMR* amr, unsigned level, double h[3]);
AMRDUALMESHMAPPER_EXPORT void SetSpacing(vtkOverlappingAMR* amr, unsigned level, const double h[3]);
/// The AMR's origin (the lower corner of level-0 cell (0, 0, 0)).
AMRDUALMESHMAPPER_EXPORT const double* Origin(vtkOverlappingAMR* amr);
AMRDUALMESHMAPPER_EXPORT void SetOrigin(vtkOverlappingAMR* amr, const double origin[3]);
AMRDUALMESHMAPPER_EXPORT void SetRefinementRatio(vtkOverlappingAMR* amr, unsigned level, int ratio);
/// vtkStructuredData's grid description (VTK_XYZ_GRID = 8 for 3-D AMR).
AMRDUALMESHMAPPER_EXPORT int GridDescription(vtkOverlappingAMR* amr);
AMRDUALMESHMAPPER_EXPORT void SetGridDescription(vtkOverlappingAMR* amr, int description);

/// Resets `amr` to blocksPerLevel.size() levels with the given block counts (call it before the
/// origin, spacings and boxes: VTK 9.6+ makes new metadata here).
AMRDUALMESHMAPPER_EXPORT void InitializeLevels(vtkOverlappingAMR* amr,
  const std::vector<unsigned>& blocksPerLevel);
/// A new, empty uniform grid of the block class SetBlock accepts in every version.
AMRDUALMESHMAPPER_EXPORT vtkSmartPointer<vtkImageData> NewBlock();
/// Stores `grid` at (level, id). False, with `error` naming the block and what was expected,
/// when VTK refuses it (VTK 9.6+ refuses silently, so the result is read back).
AMRDUALMESHMAPPER_EXPORT bool SetBlock(vtkOverlappingAMR* amr,
  unsigned level,
  unsigned id,
  vtkImageData* grid,
  std::string& error);

/// The cell ghost/blanking array ("vtkGhostType") of a block, or nullptr.
AMRDUALMESHMAPPER_EXPORT vtkUnsignedCharArray* CellGhosts(vtkDataSet* grid);
/// "vtkGhostType".
AMRDUALMESHMAPPER_EXPORT const char* GhostArrayName();
/// Ghost-array flags: refined by a finer level, hidden (blanked) and duplicate cells.
constexpr unsigned char RefinedCell = vtkDataSetAttributes::REFINEDCELL;
constexpr unsigned char HiddenCell = vtkDataSetAttributes::HIDDENCELL;
constexpr unsigned char DuplicateCell = vtkDataSetAttributes::DUPLICATECELL;
}
}

#endif
