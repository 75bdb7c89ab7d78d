/**
 * @class   vtkAMRDualMeshRepresentation
 * @brief   ParaView representation that path-traces a vtkOverlappingAMR through its dual mesh
 *
 * "Dual-Mesh Path Tracer" in the representation list of AMR data (an extension of ParaView's
 * AMRRepresentation, see AMRDualMeshRepresentation.xml). It owns a vtkVolume drawn by a
 * vtkAMRDualMeshVolumeMapper and follows the pattern of ParaView's own volume representations:
 *
 * - RequestData() shallow-copies the input into a cache (on every data-server rank);
 *   REQUEST_UPDATE hands the cache to the view (vtkPVRenderView::SetPiece) with its bounds and
 *   asks for distributed rendering, so the AMR stays on the server and the server renders it in
 *   client/server sessions (the client only receives pixels); REQUEST_RENDER connects the mapper
 *   to the delivered piece (vtkPVRenderView::GetPieceProducer).
 * - Colouring is ParaView's: ColorArrayName (a cell array; SetInputArrayToProcess), LookupTable
 *   (SetColor), ScalarOpacityFunction (SetScalarOpacity), ScalarOpacityUnitDistance, Shade (the
 *   last three are the Volume representation's own properties, linked in the XML) and
 *   the lighting coefficients go to the vtkVolumeProperty. Without a cell array to colour by, the
 *   volume is not drawn.
 * - Everything else is forwarded to the mapper under the same name, default and range (one
 *   table: Kernels/core/ParameterTable.h; the setters are generated from it).
 *
 * Progressive refinement: each render adds SamplesPerRender samples per pixel (until
 * MaximumSamples); any change of camera, data, colouring or parameter restarts the
 * accumulation (the mapper decides). While RefineWhileIdle is on, the process that owns the
 * view's interactor (the GUI client, or pvpython after Interact()) arms a one-shot interactor
 * timer after each render; when it fires and the image still needs samples, it calls
 * vtkRenderWindowInteractor::Render(), which ParaView's interactor helper turns into a normal
 * view-proxy StillRender() (so in client/server the server renders the next pass and ships the
 * pixels). While the user interacts, ParaView renders through vtkPVRenderView::InteractiveRender()
 * (the render window's DesiredUpdateRate is 5): the mapper then draws cheap reduced-resolution
 * frames (InteractiveFrameTime) and the timer does not add passes; the still render ParaView
 * makes at mouse-up restarts the accumulation at full resolution. Processes
 * without an interactor (pvbatch, pvpython scripts, pvserver) never render on their own, so
 * scripted renders stay deterministic.
 *
 * @sa vtkAMRDualMeshVolumeMapper vtkAMRStreamingVolumeRepresentation
 */
#ifndef vtkAMRDualMeshRepresentation_h
#define vtkAMRDualMeshRepresentation_h

#include "AMRDualMeshRepresentationModule.h" // For export macro
#include "vtkNew.h"                          // For vtkNew
#include "vtkPVDataRepresentation.h"

#include <memory> // For std::unique_ptr
#include <string> // For std::string

class AMRDualMeshDataCache;
class AMRDualMeshIdleRefinement;
class AMRDualMeshRemovedProperties;

class vtkAMRDualMeshVolumeMapper;
class vtkColorTransferFunction;
class vtkImplicitFunction;
class vtkPiecewiseFunction;
class vtkPVRenderView;
class vtkVolume;
class vtkVolumeProperty;

class AMRDUALMESHREPRESENTATION_EXPORT vtkAMRDualMeshRepresentation : public vtkPVDataRepresentation
{
public:
  static vtkAMRDualMeshRepresentation* New();
  vtkTypeMacro(vtkAMRDualMeshRepresentation, vtkPVDataRepresentation);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  int ProcessViewRequest(vtkInformationRequestKey* request_type,
    vtkInformation* inInfo,
    vtkInformation* outInfo) override;

  void SetVisibility(bool val) override;

  ///@{
  /// The array to colour by (ColorArrayName): a cell array of the AMR data set.
  void SetInputArrayToProcess(int idx,
    int port,
    int connection,
    int fieldAssociation,
    const char* name) override;
  void SetInputArrayToProcess(int idx,
    int port,
    int connection,
    int fieldAssociation,
    int fieldAttributeType) override
  {
    this->Superclass::SetInputArrayToProcess(
      idx, port, connection, fieldAssociation, fieldAttributeType);
  }
  void SetInputArrayToProcess(int idx, vtkInformation* info) override
  {
    this->Superclass::SetInputArrayToProcess(idx, info);
  }
  void SetInputArrayToProcess(int idx,
    int port,
    int connection,
    const char* fieldAssociation,
    const char* attributeTypeorName) override
  {
    this->Superclass::SetInputArrayToProcess(
      idx, port, connection, fieldAssociation, attributeTypeorName);
  }
  ///@}

  ///@{
  /// Forwarded to the vtkVolumeProperty (ParaView's colouring and lighting properties).
  void SetColor(vtkColorTransferFunction* lut);
  void SetScalarOpacity(vtkPiecewiseFunction* pwf);
  void SetScalarOpacityUnitDistance(double val);
  void SetShade(bool val);
  // The vtkVolume's matrix (the Display panel's Translation, Orientation, Scale, Origin).
  void SetPosition(double x, double y, double z);
  void SetOrientation(double x, double y, double z);
  void SetScale(double x, double y, double z);
  void SetOrigin(double x, double y, double z);
  void SetAmbient(double val);
  void SetDiffuse(double val);
  void SetSpecular(double val);
  void SetSpecularPower(double val);
  // ParaView's Volume blend properties (vtkImageVolumeRepresentation's names; BlendMode: mapper).
  void SetIsosurfaceValue(int i, double value);
  void SetNumberOfIsosurfaces(int number);
  void SetSliceFunction(vtkImplicitFunction* slice);
  ///@}

  ///@{
  /// The removed names PathTracerScalarOpacityUnitDistance and PathTracerShade (before
  /// 2026-12-03 the representation had its own unit distance and shading; now it uses Volume's
  /// ScalarOpacityUnitDistance and Shade). Old state files and scripts still load: a value that
  /// differs from the current ScalarOpacityUnitDistance / Shade is not used, and the next render
  /// says so once per process (naming the property to set instead). 0 / -1: not set.
  void SetRemovedPathTracerScalarOpacityUnitDistance(double val);
  void SetRemovedPathTracerShade(int val);
  ///@}

  ///@{
  /// Forwarded to vtkAMRDualMeshVolumeMapper (see its documentation for meaning and ranges).
  void SetBlendMode(int mode);
  // BEGIN GENERATED representation-setters (Tools/generate_parameters.py)
  // clang-format off
  void SetIntegrator(int val);
  void SetDevice(int val);
  void SetSamplesPerRender(int val);
  void SetMaximumSamples(int val);
  void SetScatteringAnisotropy(double val);
  void SetEnvironmentRadiance(double r, double g, double b);
  void SetEmbedIsosurfaces(int val);
  void SetMaximumBounces(int val);
  void SetStepSize(double val);
  void SetSamplesPerCell(double val);
  void SetElementTest(int val);
  void SetMaxNewtonIterations(int val);
  void SetGridletSize(int val);
  void SetBVHLeafSize(int val);
  void SetMajorantResolution(int val);
  void SetNumberOfThreads(int val);
  void SetSeed(int val);
  void SetInteractiveFrameTime(double val);
  void SetFinalRenderTime(double val);
  // clang-format on
  // END GENERATED representation-setters
  ///@}

  /// Samples per pixel accumulated so far on this process (0 where it does not render).
  int GetNumberOfSamples();

  /// Seconds of the last render of the mapper on this process.
  double GetLastRenderSeconds();

  /// Bytes of this process's dual mesh (gridlets, elements, BVH; 0 before the first render).
  double GetDualMeshBytes();

  ///@{
  /// Keep rendering passes while the view is idle and the image has fewer than MaximumSamples
  /// samples per pixel (only where the view has an interactor, see the class documentation).
  /// Default on.
  vtkSetMacro(RefineWhileIdle, bool);
  vtkGetMacro(RefineWhileIdle, bool);
  ///@}

  enum DistributionModes
  {
    PARTITIONED = 0, ///< each rank holds its region and a ghost band (data-parallel)
    REPLICATED = 1,  ///< each rank holds all blocks; secondary rays see the whole medium
    PROXY = 2        ///< PARTITIONED plus a replicated level-0 proxy for secondary rays
  };

  ///@{
  /// On N > 1 MPI ranks (pvbatch, pvserver) every rank draws one box of a kd-tree partition of
  /// the domain and IceT blends the boxes in visibility order. PARTITIONED (default): a rank
  /// holds only its box and a ghost band one cell of each level wide: emission-absorption
  /// (RAY_MARCH) is exact, scattered and shadow rays stop at the box (an approximation).
  /// REPLICATED: every rank holds all blocks (memory of the whole AMR on each) and still draws
  /// only the camera rays' part in its box: exact in expectation for every integrator.
  /// PROXY: as PARTITIONED, plus level 0 of the whole domain on every rank (a coarse proxy):
  /// scattered and shadow rays of PATH_TRACER and SINGLE_SCATTER see the exact data inside the
  /// box and the proxy outside it (an approximation with a much smaller bias than
  /// PARTITIONED's; CPU device only). Without effect on one rank.
  void SetDistributionMode(int mode);
  vtkGetMacro(DistributionMode, int);
  ///@}

  /// This rank's region (-1 when not distributed) and its box (the data's bounds on one rank),
  /// the seconds and received bytes of the last redistribution.
  int GetRegionIndex();
  double* GetDataBounds() VTK_SIZEHINT(6);
  void GetDataBounds(double bounds[6]);
  double GetRedistributionSeconds();
  double GetRedistributedBytes();

protected:
  vtkAMRDualMeshRepresentation();
  ~vtkAMRDualMeshRepresentation() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  bool AddToView(vtkView* view) override;
  bool RemoveFromView(vtkView* view) override;

private:
  vtkAMRDualMeshRepresentation(const vtkAMRDualMeshRepresentation&) = delete;
  void operator=(const vtkAMRDualMeshRepresentation&) = delete;

  void UpdateVolumeVisibility();

  vtkNew<vtkAMRDualMeshVolumeMapper> Mapper;
  vtkNew<vtkVolumeProperty> Property;
  vtkNew<vtkVolume> Volume;
  int DistributionMode = PARTITIONED;
  std::string ColorArray; ///< empty: no cell array chosen, nothing drawn
  bool HasDataToRender = false;
  bool RefineWhileIdle = true;
  std::unique_ptr<AMRDualMeshDataCache> Data; ///< the input, or this rank's region of it
  std::unique_ptr<AMRDualMeshRemovedProperties> Removed;
  std::unique_ptr<AMRDualMeshIdleRefinement> Refine;
};

#endif
