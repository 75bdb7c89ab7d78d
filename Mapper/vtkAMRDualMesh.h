/**
 * @class   vtkAMRDualMesh
 * @brief   the dual-mesh field of a vtkOverlappingAMR: gridlets + stitching elements + BVH
 *
 * Builds, in memory, the dual mesh of one cell-data array of a vtkOverlappingAMR (Zellmann et
 * al., EuroVis 2023): same-level dual cells clustered into gridlets, level transitions covered by
 * tets, pyramids, wedges and hexes, and a BVH over both. The field it samples is the exact
 * dual-mesh interpolant: trilinear in gridlets, iso-parametric in stitching elements.
 *
 * A point-data (vertex-centred) array is used as it is, without conversion: each level's leaf
 * cells are trilinear cells over their own vertex values, stored as gridlets (no dual, no
 * stitching elements), and the field is C0 across level transitions (a finer level's vertices
 * on the boundary of its region take the coarser cells' interpolant; inside its region the finer
 * level's values win). See ArrayAssociation.
 *
 * Update() rebuilds only when the input, the array selection or a build parameter changed
 * (one vtkTimeStamp: BuildTime). Sampling parameters (ElementTest, MaxNewtonIterations) never
 * trigger a rebuild.
 *
 * Used by vtkAMRDualMeshProbeFilter and vtkAMRDualMeshVolumeMapper; usable on its own from C++
 * and Python (memory report, counts, point sampling).
 */
#ifndef vtkAMRDualMesh_h
#define vtkAMRDualMesh_h

#include "AMRDualMeshMapperModule.h" // For export macro
#include "vtkObject.h"

#include <memory> // For std::unique_ptr
#include <string> // For std::string

class vtkDataArray;
class vtkOverlappingAMR;
class vtkUnsignedCharArray;
#ifndef __VTK_WRAP__
namespace amrdm
{
struct DualMesh;
}
#endif

class AMRDUALMESHMAPPER_EXPORT vtkAMRDualMesh : public vtkObject
{
public:
  static vtkAMRDualMesh* New();
  vtkTypeMacro(vtkAMRDualMesh, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The AMR data set. Not owned beyond a reference; its MTime triggers rebuilds.
  void SetInputData(vtkOverlappingAMR* amr);
  vtkOverlappingAMR* GetInputData();
  ///@}

  ///@{
  /// Name of the array to build the field from. Default: none (an error on Update). Where it
  /// lives is ArrayAssociation's choice; by default a cell array of that name, else a point
  /// array (a name that is unique needs nothing else).
  vtkSetStringMacro(ArrayName);
  vtkGetStringMacro(ArrayName);
  ///@}

  ///@{
  /// Where the array lives: vtkDataObject::FIELD_ASSOCIATION_CELLS (cell-centred: the dual
  /// mesh), FIELD_ASSOCIATION_POINTS (vertex-centred: each level's cells trilinear over their
  /// corners, C0 across level transitions, Kernels/mesh/VertexMeshBuilder.h), or -1 (default:
  /// cells when a cell array has the name, else points). Other values are refused on Update.
  vtkSetMacro(ArrayAssociation, int);
  vtkGetMacro(ArrayAssociation, int);
  ///@}

  /// The VTK way to choose the array: SetInputArrayToProcess(0, 0, 0,
  /// vtkDataObject::FIELD_ASSOCIATION_POINTS or FIELD_ASSOCIATION_CELLS, name) sets ArrayName
  /// and ArrayAssociation. idx, port and connection must be 0 (one array, one input).
  void SetInputArrayToProcess(int idx, int port, int connection, int association, const char* name);

  /// The association the last successful build used (FIELD_ASSOCIATION_CELLS or _POINTS).
  vtkGetMacro(BuiltAssociation, int);

  ///@{
  /// Build and sampling settings, the rows of core/ParameterTable.h marked InDualMesh (shared
  /// with the volume mapper, the probe filter and the unstructured-grid export): Component,
  /// LogScale, GridletSize and BVHLeafSize rebuild the mesh (log10: values <= 0 become holes,
  /// interpolation happens in log space); ElementTest (vtkAMRDualMeshVolumeMapper's
  /// ELEMENT_TEST_BILINEAR or ELEMENT_TEST_PLANAR_FACES, the one enumeration of the Mapper
  /// module) and MaxNewtonIterations apply to Sample()/SamplePoints();
  /// NumberOfThreads (0: VTK_SMP_MAX_THREADS when set, else all cores, see
  /// ResolveNumberOfThreads()) the build and batch sampling.
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
  /// Build the field from log10 of the values (values <= 0 become holes, one warning); 0..1,
  /// default 0.
  vtkSetClampMacro(LogScale, int, 0, 1);
  vtkGetMacro(LogScale, int);
  vtkBooleanMacro(LogScale, int);
  // clang-format on
  // END GENERATED field-api
  ///@}

  ///@{
  /// Memory the build may use, in MiB; 0 (default) = the physical memory available when the
  /// build starts. A build that would need more fails with an error before allocating it.
  vtkSetClampMacro(MemoryLimit, vtkTypeInt64, 0, VTK_TYPE_INT64_MAX);
  vtkGetMacro(MemoryLimit, vtkTypeInt64);
  ///@}

  /// The threads a build or batch sampling uses now: ResolveNumberOfThreads(NumberOfThreads).
  int GetEffectiveNumberOfThreads() const;

  /// The thread count for a requested one: `requested` when > 0; for 0, VTK_SMP_MAX_THREADS
  /// (the environment variable VTK's SMP tools honour) when set, else all cores; never more
  /// than the cores there are. vtkSMPTools::Initialize(n) does not change it: set
  /// NumberOfThreads instead. The volume mapper and the probe filter resolve their
  /// NumberOfThreads with it too.
  static int ResolveNumberOfThreads(int requested);

  /// Builds the dual mesh if anything it depends on changed. Returns false (after a
  /// vtkErrorMacro naming the problem) on bad input; the previous mesh is then released.
  bool Update();

  /// True when a mesh is built and current.
  bool IsValid() const;

  /// Samples the field at world position (x, y, z). Returns NaN where the dual mesh has no
  /// value (outside it, or in a hole). Call Update() first.
  double Sample(double x, double y, double z);

  /// Samples at every point of `points` (3 components). Fills `values` (one float component)
  /// and `mask` (1 where a value was found). Returns the number of points found, -1 on error.
  vtkIdType SamplePoints(vtkDataArray* points, vtkDataArray* values, vtkUnsignedCharArray* mask);

  ///@{
  /// Counts of the built mesh.
  vtkIdType GetNumberOfLeafCells() const;
  vtkIdType GetNumberOfGridlets() const;
  vtkIdType GetNumberOfPerfectCubes() const;
  vtkIdType GetNumberOfTets() const;
  vtkIdType GetNumberOfPyramids() const;
  vtkIdType GetNumberOfWedges() const;
  vtkIdType GetNumberOfHexes() const;
  vtkIdType GetNumberOfDegenerateHexes() const;
  vtkIdType GetNumberOfStitchingVertices() const;
  vtkIdType GetNumberOfNonFiniteValues() const;
  ///@}

  ///@{
  /// Memory in bytes by category, and per visible leaf cell.
  vtkTypeUInt64 GetGridletScalarBytes() const;
  vtkTypeUInt64 GetGridletHeaderBytes() const;
  vtkTypeUInt64 GetElementVertexBytes() const;
  vtkTypeUInt64 GetElementIndexBytes() const;
  vtkTypeUInt64 GetBVHBytes() const;
  vtkTypeUInt64 GetTotalBytes() const;
  double GetBytesPerLeafCell() const;
  ///@}

  /// Range (min, max) of the field's finite leaf values (after LogScale); (0, 0) before a build.
  vtkGetVector2Macro(ValueRange, double);

  /// Counts, memory and build time as one JSON object.
  std::string GetReportJSON() const;

  /// Wall-clock seconds of the last build, AMR intake included.
  vtkGetMacro(BuildSeconds, double);
  /// The part of BuildSeconds spent converting the vtkOverlappingAMR (reading arrays).
  vtkGetMacro(IntakeSeconds, double);
  /// How many times the mesh was built (tests use it to prove that nothing rebuilt).
  vtkGetMacro(BuildCount, int);

  /// The time of the last successful build.
  vtkMTimeType GetBuildTime() const { return this->BuildTime.GetMTime(); }

#ifndef __VTK_WRAP__
  /// The built mesh, or null. Owned by this object.
  const amrdm::DualMesh* GetDualMesh() const;
#endif

protected:
  vtkAMRDualMesh();
  ~vtkAMRDualMesh() override;

private:
  vtkAMRDualMesh(const vtkAMRDualMesh&) = delete;
  void operator=(const vtkAMRDualMesh&) = delete;

  vtkOverlappingAMR* Input = nullptr;
  char* ArrayName = nullptr;
  int ArrayAssociation = -1;
  int BuiltAssociation = 1; // vtkDataObject::FIELD_ASSOCIATION_CELLS
  // BEGIN GENERATED field-fields (Tools/generate_parameters.py; edit the table, then run it)
  // clang-format off
  int ElementTest = 0;
  int MaxNewtonIterations = 10;
  int GridletSize = 8;
  int BVHLeafSize = 8;
  int NumberOfThreads = 0;
  int Component = -1;
  int LogScale = 0;
  // clang-format on
  // END GENERATED field-fields
  vtkTypeInt64 MemoryLimit = 0;
  double BuildSeconds = 0.0;
  double IntakeSeconds = 0.0;
  double ValueRange[2] = { 0.0, 0.0 };
  int BuildCount = 0;
  vtkTimeStamp BuildTime; ///< when the dual mesh and BVH were last built

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif
