// AMR intake: vtkOverlappingAMR -> amrdm::AmrHierarchy (leaf cells in integer finest-level
// units, refinement ratio from the spacing, one scalar per cell, or per vertex for a point
// array). Not wrapped.
#ifndef AMRIntake_h
#define AMRIntake_h

#include "mesh/PrepareHierarchy.h" // For amrdm::AmrHierarchy, amrdm::LevelBoxes

#include <string>

class vtkOverlappingAMR;

namespace amrdm_vtk
{
/// Component -1 means the magnitude for multi-component arrays and the value for single ones.
/// Returns false and sets `error` (naming what was wrong and what was expected) on bad input.
/// With `logScale`, values go through amrdm::logScaleValue without a floor: values <= 0 become
/// NaN (holes, counted by AmrHierarchy::finalizeCellStates as non-finite). The blocks' values
/// and ghost states are copied on `threads` threads (0 = all cores; the result does not depend
/// on them).
/// `association` Points reads a point-data array ((nx+1)(ny+1)(nz+1) tuples per block, refused
/// naming the block otherwise) into a FieldAssociation::Points hierarchy (the vertex-centred
/// mesh, mesh/VertexMeshBuilder.h); Cells (default) reads a cell-data array.
/// The intake checks what only VTK knows (spacings, origins, grids against their boxes, arrays);
/// the hierarchy itself is checked and prepared by the one pipeline, mesh/PrepareHierarchy.h:
/// pass `metadata` (every AMR box per level, loaded here or not) to amrdm::prepareHierarchy or
/// amrdm::checkHierarchy so the nesting check sees the boxes of blocks not loaded here.
bool ConvertAMR(vtkOverlappingAMR* amr,
  const char* arrayName,
  int component,
  bool logScale,
  amrdm::AmrHierarchy& out,
  std::string& error,
  int threads = 0,
  amrdm::FieldAssociation association = amrdm::FieldAssociation::Cells,
  amrdm::LevelBoxes* metadata = nullptr);
}

#endif
