/**
 * @class   vtkAMRDualMeshProbeFilter
 * @brief   samples the dual-mesh field of an AMR data set at the points of another data set
 *
 * Like vtkProbeFilter: input port 0 gives the points (any vtkDataSet), the source (port 1,
 * SetSourceConnection/SetSourceData) is a vtkOverlappingAMR. The output is a shallow copy of
 * the input with two point-data arrays: the sampled field (named like the source array, float)
 * and `vtkValidPointMask` (char, 1 where the dual mesh has a value). The dual mesh is rebuilt
 * only when the source or the array selection changes.
 */
#ifndef vtkAMRDualMeshProbeFilter_h
#define vtkAMRDualMeshProbeFilter_h

#include "AMRDualMeshMapperModule.h" // For export macro
#include "vtkDataSetAlgorithm.h"
#include "vtkNew.h" // For vtkNew

class vtkAMRDualMesh;
class vtkOverlappingAMR;

class AMRDUALMESHMAPPER_EXPORT vtkAMRDualMeshProbeFilter : public vtkDataSetAlgorithm
{
public:
  static vtkAMRDualMeshProbeFilter* New();
  vtkTypeMacro(vtkAMRDualMeshProbeFilter, vtkDataSetAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The AMR source (input port 1).
  void SetSourceConnection(vtkAlgorithmOutput* algOutput);
  void SetSourceData(vtkOverlappingAMR* source);
  ///@}

  ///@{
  /// Array of the source to sample: a cell array of that name, else a point array (vertex-
  /// centred data, sampled without conversion). Default: none (an error). To choose the
  /// association, use SetInputArrayToProcess(0, 1, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS
  /// or FIELD_ASSOCIATION_CELLS, name), which then wins over ArrayName.
  vtkSetStringMacro(ArrayName);
  vtkGetStringMacro(ArrayName);
  ///@}

  ///@{
  /// Build and sampling settings, the rows of core/ParameterTable.h marked InProbeFilter (the
  /// same as vtkAMRDualMesh's and the volume mapper's). NumberOfThreads 0:
  /// VTK_SMP_MAX_THREADS or all cores (vtkAMRDualMesh::ResolveNumberOfThreads()).
  // BEGIN GENERATED field-api (Tools/generate_parameters.py; edit the table, then run it)
  // clang-format off
  /// Inside test of level-transition cells: bilinear (exact) or planar faces; 0..1, default 0.
  vtkSetClampMacro(ElementTest, int, 0, 1);
  vtkGetMacro(ElementTest, int);
  /// Newton iterations of the bilinear element test; 1..64, default 10.
  vtkSetClampMacro(MaxNewtonIterations, int, 1, 64);
  vtkGetMacro(MaxNewtonIterations, int);
  /// Gridlet edge in dual cells (rebuilds the mesh); 2..32, default 8.
  vtkSetClampMacro(GridletSize, int, 2, 32);
  vtkGetMacro(GridletSize, int);
  /// Primitives per BVH leaf: larger saves memory, may cost speed (rebuilds the mesh); 1..16,
  /// default 8.
  vtkSetClampMacro(BVHLeafSize, int, 1, 16);
  vtkGetMacro(BVHLeafSize, int);
  /// Threads for building, sampling and rendering (0: all cores, at most VTK_SMP_MAX_THREADS when
  /// that is set); results do not depend on it; 0..1024, default 0.
  vtkSetClampMacro(NumberOfThreads, int, 0, 1024);
  vtkGetMacro(NumberOfThreads, int);
  /// Component of a multi-component array (-1: the magnitude of a vector, the value of a scalar);
  /// >= -1, default -1.
  vtkSetClampMacro(Component, int, -1, VTK_INT_MAX);
  vtkGetMacro(Component, int);
  // clang-format on
  // END GENERATED field-api
  ///@}

  ///@{
  /// Name of the mask array, default "vtkValidPointMask" (as vtkProbeFilter).
  vtkSetStringMacro(ValidPointMaskArrayName);
  vtkGetStringMacro(ValidPointMaskArrayName);
  ///@}

  /// The dual mesh this filter built (counts, memory report). Valid after Update().
  vtkAMRDualMesh* GetDualMesh();

protected:
  vtkAMRDualMeshProbeFilter();
  ~vtkAMRDualMeshProbeFilter() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  vtkAMRDualMeshProbeFilter(const vtkAMRDualMeshProbeFilter&) = delete;
  void operator=(const vtkAMRDualMeshProbeFilter&) = delete;

  char* ArrayName = nullptr;
  char* ValidPointMaskArrayName = nullptr;
  // BEGIN GENERATED field-fields (Tools/generate_parameters.py; edit the table, then run it)
  // clang-format off
  int ElementTest = 0;
  int MaxNewtonIterations = 10;
  int GridletSize = 8;
  int BVHLeafSize = 8;
  int NumberOfThreads = 0;
  int Component = -1;
  // clang-format on
  // END GENERATED field-fields
  vtkNew<vtkAMRDualMesh> Field;
};

#endif
