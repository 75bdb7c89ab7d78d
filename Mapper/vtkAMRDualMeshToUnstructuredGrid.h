/**
 * @class   vtkAMRDualMeshToUnstructuredGrid
 * @brief   the dual mesh of a vtkOverlappingAMR as a plain vtkUnstructuredGrid
 *
 * Input: a vtkOverlappingAMR (port 0). Output: its dual mesh (vtkAMRDualMesh) as an
 * unstructured grid, the "plain dual unstructured mesh" route of the gridlet paper: one point
 * per leaf-cell centre that the mesh uses (shared between gridlet cells and stitching
 * elements, merged on their exact grid position), the point-data array named like the input
 * array (float, the leaf values after LogScale), and one cell per dual cell: every perfect
 * dual cube of every gridlet as a VTK_HEXAHEDRON, and the stitching elements as VTK_TETRA,
 * VTK_PYRAMID, VTK_WEDGE and VTK_HEXAHEDRON in VTK corner order, each turned to VTK's
 * orientation (positive volume) by a mirror symmetry of its reference cell where the dual mesh
 * has it inverted (our kernels accept either orientation). A cell-data array
 * `vtkDualCellSource` says where each cell came from (0 gridlet, 1 tet, 2 pyramid, 3 wedge,
 * 4 stitching hex).
 *
 * Linear interpolation of this grid by VTK is the dual-mesh interpolant wherever VTK
 * interpolates the same way (gridlet hexes: trilinear; tets: barycentric; VTK's pyramids,
 * wedges and hexes are iso-parametric like ours). It exists for comparisons with VTK's
 * unstructured volume mappers and for export; our own renderers never use it.
 */
#ifndef vtkAMRDualMeshToUnstructuredGrid_h
#define vtkAMRDualMeshToUnstructuredGrid_h

#include "AMRDualMeshMapperModule.h" // For export macro
#include "vtkNew.h"                  // For vtkNew
#include "vtkUnstructuredGridAlgorithm.h"

class vtkAMRDualMesh;

class AMRDUALMESHMAPPER_EXPORT vtkAMRDualMeshToUnstructuredGrid
  : public vtkUnstructuredGridAlgorithm
{
public:
  static vtkAMRDualMeshToUnstructuredGrid* New();
  vtkTypeMacro(vtkAMRDualMeshToUnstructuredGrid, vtkUnstructuredGridAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Cell-data array of the input to build the dual mesh from. Default: none (an error).
  vtkSetStringMacro(ArrayName);
  vtkGetStringMacro(ArrayName);
  ///@}

  ///@{
  /// The rows of core/ParameterTable.h marked InExport, as vtkAMRDualMesh's.
  // BEGIN GENERATED field-api (Tools/generate_parameters.py; edit the table, then run it)
  // clang-format off
  /// Component of a multi-component array (-1: the magnitude of a vector, the value of a scalar);
  /// >= -1, default -1.
  vtkSetClampMacro(Component, int, -1, VTK_INT_MAX);
  vtkGetMacro(Component, int);
  /// Build the field from log10 of the values (values <= 0 become holes, one warning); 0..1,
  /// default 0.
  vtkSetClampMacro(LogScale, int, 0, 1);
  vtkGetMacro(LogScale, int);
  vtkBooleanMacro(LogScale, int);
  // clang-format on
  // END GENERATED field-api
  ///@}

  /// The dual mesh the last output was made from (its counts and memory report).
  vtkAMRDualMesh* GetDualMesh();

protected:
  vtkAMRDualMeshToUnstructuredGrid();
  ~vtkAMRDualMeshToUnstructuredGrid() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation* request,
    vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

private:
  vtkAMRDualMeshToUnstructuredGrid(const vtkAMRDualMeshToUnstructuredGrid&) = delete;
  void operator=(const vtkAMRDualMeshToUnstructuredGrid&) = delete;

  char* ArrayName = nullptr;
  // BEGIN GENERATED field-fields (Tools/generate_parameters.py; edit the table, then run it)
  // clang-format off
  int Component = -1;
  int LogScale = 0;
  // clang-format on
  // END GENERATED field-fields
  vtkNew<vtkAMRDualMesh> Field;
};

#endif
