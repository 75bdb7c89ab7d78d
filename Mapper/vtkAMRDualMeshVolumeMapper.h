/**
 * @class   vtkAMRDualMeshVolumeMapper
 * @brief   path-traced volume rendering of a vtkOverlappingAMR through its dual mesh
 *
 * A drop-in vtkVolumeMapper (like vtkAMRVolumeMapper) for vtkOverlappingAMR input: it builds the
 * dual mesh of one cell array (vtkAMRDualMesh: gridlets, stitching elements, BVH; Zellmann et
 * al., EuroVis 2023) and renders it (CPU threads or CUDA, see Device) with a volumetric path
 * tracer, single scattering, emission-absorption ray marching or a debug view. The image is
 * accumulated progressively:
 * every Render() adds SamplesPerRender samples per pixel (until MaximumSamples) and composites
 * the running mean over what the renderer already drew. While the user interacts (the render
 * window's DesiredUpdateRate is at least InteractiveUpdateRate, as VTK's interactor and
 * ParaView's interactive renders set it), each Render() instead draws one sample per pixel at a
 * resolution reduced to fit InteractiveFrameTime; the first still Render() after it starts
 * refining at full resolution.
 *
 * What the image follows, as a VTK user expects:
 * - vtkVolumeProperty (component 0) is the truth for appearance. The colour function
 *   (GetRGBTransferFunction, or GetGrayTransferFunction when ColorChannels is 1) and the scalar
 *   opacity function are sampled into one 256-entry RGBA table over the union of their ranges
 *   (values outside are clamped to the end entries, like VTK's volume mappers). A log scale
 *   (vtkColorTransferFunction::SetScaleToLog10, ParaView's UseLogScale, or
 *   vtkPiecewiseFunction::UseLogScaleOn) makes the table evenly spaced in log10 of the value,
 *   each entry the functions' own value there, and values are looked up by log10 (values <= 0
 *   take the first entry); a log scale over a range that is not positive is sampled linearly
 *   with a warning.
 *   ScalarOpacityUnitDistance is the distance over which a table opacity is reached. Shade turns
 *   on gradient (Phong) shading in RAY_MARCH mode with Ambient/Diffuse/Specular/SpecularPower.
 *   The path tracer uses the table colour as the scattering albedo. Gradient opacity and the
 *   interpolation type are ignored: the field is always the continuous dual-mesh interpolant.
 * - The scalar array is chosen the VTK way: SelectScalarArray(name or index) with ScalarMode
 *   default, UseCellData / UseCellFieldData (cell arrays: the dual mesh) or UsePointData /
 *   UsePointFieldData (point arrays: vertex-centred, each level's cells trilinear over their
 *   corners, C0 across levels; no conversion). Default: the active cell scalars of the first
 *   block, else its first cell array, else its point scalars or first point array; a name in
 *   the default mode is a cell array, else a point array (AMRDualMeshArraySelection.h).
 * - The renderer's lights (headlight, camera and scene lights; directional and positional, up
 *   to 8 switched on: VTK's and ParaView's five-light vtkLightKit is used whole; beyond 8 a
 *   warning says which are dropped) light the path tracer and single scattering. A light of
 * intensity I gives an irradiance of pi*I (the irradiance under which a white Lambertian surface
 * has radiance I, i.e. VTK's full-intensity white); a positional light becomes an isotropic point
 *   light with 1/d^2 falloff that delivers this irradiance at its focal point (cone angle and
 *   attenuation are ignored). Isotropic scattering is physically dimmer than a surface: single
 *   scattering from a dense white medium is about I/8, multiple scattering brings it toward I.
 *   RAY_MARCH shading uses the first directional light, else a headlight.
 * - The camera: the rays are those of the projection VTK draws the renderer's tiled viewport
 *   with (the camera's composite projection for the tiled aspect: perspective or parallel,
 *   window centre, view shear, the tiles of vtkWindowToImageFilter::SetScale,
 *   vtkRenderLargeImage and ParaView's SaveScreenshot at another resolution), unprojected in
 *   double. A tile of a vtkWindowToImageFilter / SaveScreenshot magnification (the window's
 *   TileScale > 1) is rendered to the sample count the untiled view had; vtkRenderLargeImage
 *   does not set the TileScale, so its tiles get SamplesPerRender each. A grab at the view's
 *   own size continues the accumulation.
 * - The mapper's clipping planes (any number, a vtkPlaneCollection in world coordinates; the
 *   side a normal points to is kept) clip each camera ray to one interval. Scattered and shadow
 *   rays are not clipped (a clipped region still casts shadows).
 * - Translucent geometry is drawn under the volume (VTK's default for volume mappers). With
 *   the renderer's UseDepthPeelingForVolumes (ParaView's "Depth Peeling For Volumes", on by
 *   default) the mapper switches that flag off on the renderer, once, and says so: the peeling
 *   pass expects a GPU mapper's shader hooks.
 * - Opaque geometry already drawn: the depth buffer (multisampled or not) is read and each
 *   camera ray stops at the surface.
 * - The vtkVolume's matrix (position, orientation, scale, origin, user matrix): rays are taken
 *   into the data frame through its inverse, and so are the clipping planes and the lights.
 *   Extinction is per unit of the data's own length, so a scaled volume keeps its optical
 *   depth (its contents scale with it). ParaView's Styling Opacity does not apply to volumes
 *   (ParaView's own Volume representation ignores it too): use the opacity transfer function.
 *
 * Time stamps: the dual mesh and BVH follow the input and the array (vtkAMRDualMesh::BuildTime);
 * the renderer (created for Device) takes the mesh when it was rebuilt (UploadTime); the majorants
 * follow the transfer function (TransferFunctionTime: the property's colour and opacity functions
 * and unit distance); the accumulation (its reset key, GetAccumulationKey()) follows everything:
 * any change of input, array, property, camera, light, window size, clipping planes, opaque depth
 * or mapper parameter resets it.
 *
 * @sa vtkAMRDualMesh vtkAMRVolumeMapper
 */
#ifndef vtkAMRDualMeshVolumeMapper_h
#define vtkAMRDualMeshVolumeMapper_h

#include "AMRDualMeshMapperModule.h" // For export macro
#include "vtkVolumeMapper.h"

#include <memory> // For std::unique_ptr
#include <string> // For std::string

class vtkAMRDualMesh;
class vtkOverlappingAMR;
class vtkRenderWindow;
class vtkVolumeProperty;
namespace amrdm
{
struct RenderParams;
}

class AMRDUALMESHMAPPER_EXPORT vtkAMRDualMeshVolumeMapper : public vtkVolumeMapper
{
public:
  static vtkAMRDualMeshVolumeMapper* New();
  vtkTypeMacro(vtkAMRDualMeshVolumeMapper, vtkVolumeMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum Integrators
  {
    PATH_TRACER = 0,      ///< multiple scattering (delta tracking, next-event estimation)
    SINGLE_SCATTER = 1,   ///< first collision, direct light only
    RAY_MARCH = 2,        ///< emission-absorption ray marching (VTK volume-mapper conventions)
    DEBUG_PRIMITIVES = 3, ///< colour by the dual-mesh primitive at the first collision
    DEBUG_COST = 4        ///< heat map of the path tracer's work
  };

  enum Devices
  {
    DEVICE_AUTO = 0, ///< CUDA when this build has it and a device can be used, else the CPU
    DEVICE_CPU = 1,  ///< CPU threads
    DEVICE_CUDA = 2  ///< the CUDA renderer; an error when there is no CUDA build or device
  };

  enum ElementTests
  {
    ELEMENT_TEST_BILINEAR = 0,
    ELEMENT_TEST_PLANAR_FACES = 1
  };

  ///@{
  /// The input: a vtkOverlappingAMR (data or connection). Other data sets are refused with an
  /// error at render time.
  virtual void SetInputData(vtkOverlappingAMR* amr);
  using vtkVolumeMapper::SetInputData;
  ///@}

  ///@{
  /// Bounds of the AMR data set (updates the input). Uninitialized bounds without valid input.
  double* GetBounds() override;
  void GetBounds(double bounds[6]) override { this->vtkVolumeMapper::GetBounds(bounds); }
  ///@}

  /// Renders the volume: adds samples (unless MaximumSamples is reached) and composites.
  void Render(vtkRenderer* ren, vtkVolume* vol) override;

  /// Releases the texture, the quad and the depth framebuffer of `window`.
  void ReleaseGraphicsResources(vtkWindow* window) override;

  ///@{
  /// Estimator: PATH_TRACER (0, default), SINGLE_SCATTER (1), RAY_MARCH (2), DEBUG_PRIMITIVES (3),
  /// DEBUG_COST (4), or any later row of the kernels' integrator list (render/IntegratorList.h);
  /// a value outside the list is clamped to it, with a warning.
  virtual void SetIntegrator(int integrator);
  /// The integrator's name in the kernels' list ("path-tracer", "ray-march", ...).
  const char* GetIntegratorAsString();
  vtkGetMacro(Integrator, int);
  void SetIntegratorToPathTracer() { this->SetIntegrator(PATH_TRACER); }
  void SetIntegratorToSingleScatter() { this->SetIntegrator(SINGLE_SCATTER); }
  void SetIntegratorToRayMarch() { this->SetIntegrator(RAY_MARCH); }
  ///@}

  ///@{
  /// Where the image is rendered: DEVICE_AUTO (0, default), DEVICE_CPU (1) or DEVICE_CUDA (2).
  /// AUTO renders on CUDA when this build has it and a device can be used, else on the CPU, and
  /// says which and why once per process (plain text in the output window, and
  /// GetDeviceReport()); out of device memory it falls back to the CPU (said the same way). CUDA
  /// without a CUDA build or device is an error at render time (nothing is drawn). Both devices
  /// run the same kernel source, so their images are designed to agree within Monte Carlo
  /// noise; the CUDA path has not yet been run on a GPU by this project.
  vtkSetClampMacro(Device, int, DEVICE_AUTO, DEVICE_CUDA);
  vtkGetMacro(Device, int);
  void SetDeviceToAuto() { this->SetDevice(DEVICE_AUTO); }
  void SetDeviceToCPU() { this->SetDevice(DEVICE_CPU); }
  void SetDeviceToCUDA() { this->SetDevice(DEVICE_CUDA); }
  const char* GetDeviceAsString();
  ///@}

  /// The renderer factory's last line for this mapper: which device AUTO chose and why, or a
  /// fallback to the CPU; empty for CPU and CUDA.
  const char* GetDeviceReport();

  /// The device the current renderer runs on (DEVICE_CPU or DEVICE_CUDA), -1 before the first
  /// Render() or after a device error.
  int GetRenderingDevice();

  ///@{
  /// Inside test of pyramids, wedges and hexes: ELEMENT_TEST_BILINEAR (0, default: exact, Newton)
  /// or ELEMENT_TEST_PLANAR_FACES (1: faster, approximate on twisted elements).
  vtkSetClampMacro(ElementTest, int, ELEMENT_TEST_BILINEAR, ELEMENT_TEST_PLANAR_FACES);
  vtkGetMacro(ElementTest, int);
  ///@}

  ///@{
  /// Newton iterations of the bilinear element test; 1..64, default 10.
  vtkSetClampMacro(MaxNewtonIterations, int, 1, 64);
  vtkGetMacro(MaxNewtonIterations, int);
  ///@}

  ///@{
  /// Gridlet size G (up to G^3 dual cells per gridlet), forwarded to the dual mesh; changing it
  /// rebuilds the mesh. 2..32, default 8.
  vtkSetClampMacro(GridletSize, int, 2, 32);
  vtkGetMacro(GridletSize, int);
  ///@}

  ///@{
  /// Most primitives per BVH leaf, forwarded to the dual mesh; changing it rebuilds the mesh.
  /// Larger leaves need less memory (fewer nodes and culling ranges) and may sample slower.
  /// 1..16, default 8.
  vtkSetClampMacro(BVHLeafSize, int, 1, 16);
  vtkGetMacro(BVHLeafSize, int);
  ///@}

  ///@{
  /// Samples per pixel added by each Render(); 1..4096, default 1.
  vtkSetClampMacro(SamplesPerRender, int, 1, 4096);
  vtkGetMacro(SamplesPerRender, int);
  ///@}

  ///@{
  /// Samples per pixel after which Render() only re-composites; 1..2^30, default 256, where
  /// progressive refinement stops (Benchmarks/interaction.py prints how long it takes).
  vtkSetClampMacro(MaximumSamples, int, 1, 1 << 30);
  vtkGetMacro(MaximumSamples, int);
  ///@}

  ///@{
  /// Scattering events after which a path stops; 0..100000, default 64 (0 = single scattering
  /// of the lights).
  vtkSetClampMacro(MaximumBounces, int, 0, 100000);
  vtkGetMacro(MaximumBounces, int);
  ///@}

  ///@{
  /// Henyey-Greenstein anisotropy g of the phase function; -0.99..0.99, default 0 (isotropic).
  vtkSetClampMacro(ScatteringAnisotropy, double, -0.99, 0.99);
  vtkGetMacro(ScatteringAnisotropy, double);
  ///@}

  ///@{
  /// Ray-marching step in world units; 0..VTK_DOUBLE_MAX, default 0 = automatic: half the
  /// finest cell's smallest spacing, but at least 1/1000 of the bounding-box diagonal (deep
  /// hierarchies would otherwise take thousands of steps per ray).
  vtkSetClampMacro(StepSize, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(StepSize, double);
  ///@}

  ///@{
  /// Level-adaptive ray marching: samples per cell of the finest level present in each
  /// macrocell, so coarse regions take larger steps (never below StepSize); 0..1e6, default 0 =
  /// off (one uniform StepSize everywhere). 1 to 2 keeps the error of the uniform StepSize at a
  /// fraction of its time on multi-level data (docs/BENCHMARKS.md).
  vtkSetClampMacro(SamplesPerCell, double, 0.0, 1e6);
  vtkGetMacro(SamplesPerCell, double);
  ///@}

  ///@{
  /// Macrocells per axis of the majorant grid; 0..1024, default 0 = one per 8 finest cells, at
  /// most 128 per axis, scaled down to at most one macrocell per 8 leaf cells (min 4096).
  vtkSetClampMacro(MajorantResolution, int, 0, 1024);
  vtkGetMacro(MajorantResolution, int);
  ///@}

  ///@{
  /// Threads for building and rendering; 0..1024. 0 (default): VTK_SMP_MAX_THREADS when
  /// given, else all cores (vtkAMRDualMesh::ResolveNumberOfThreads()). Images do not depend on it.
  vtkSetClampMacro(NumberOfThreads, int, 0, 1024);
  vtkGetMacro(NumberOfThreads, int);
  ///@}

  /// The threads the next build and render use: NumberOfThreads, or for 0
  /// VTK_SMP_MAX_THREADS or all cores.
  int GetEffectiveNumberOfThreads() const;

  ///@{
  /// Random seed; any value, default 0. The same seed, sample count and scene give the same
  /// image.
  vtkSetMacro(Seed, int);
  vtkGetMacro(Seed, int);
  ///@}

  ///@{
  /// Uniform environment radiance (RGB, each 0..VTK_DOUBLE_MAX) seen by scattered paths that
  /// leave the volume (path tracer and single scattering); default (1, 1, 1), the default of
  /// the kernel and of amrdm-render: a dense white medium then looks white, as in ray marching
  /// (a colour map's colour is the albedo). Not vtkVolumeProperty's Ambient shading coefficient
  /// (used by RAY_MARCH). ParaView: EnvironmentRadiance; amrdm-render: --environment-radiance.
  vtkSetVector3Macro(EnvironmentRadiance, double);
  vtkGetVector3Macro(EnvironmentRadiance, double);
  ///@}

  ///@{
  /// A Render() is interactive when the render window's DesiredUpdateRate is at least this many
  /// frames per second (vtkRenderWindowInteractor sets 15 while the user interacts and 0.0001
  /// when still; ParaView's interactive renders set 5, still renders 0.002); 0..VTK_DOUBLE_MAX,
  /// default 1 (as vtkSmartVolumeMapper). 0 = never interactive.
  vtkSetClampMacro(InteractiveUpdateRate, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(InteractiveUpdateRate, double);
  ///@}

  ///@{
  /// Time budget (seconds) of an interactive Render(): it draws one sample per pixel at the
  /// largest resolution that the measured cost of earlier passes predicts to fit (each axis
  /// reduced by an integer factor up to 16), leaves the accumulation alone, and the next still
  /// Render() refines at full resolution from a fresh accumulation. 0..VTK_DOUBLE_MAX, default
  /// 0.1; 0 = interactive frames at full resolution (one sample per pixel).
  vtkSetClampMacro(InteractiveFrameTime, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(InteractiveFrameTime, double);
  ///@}

  /// True when the last Render() was interactive (see InteractiveUpdateRate).
  bool GetLastRenderInteractive();

  /// True when VTK's abort check stopped the last Render()'s pass: the render window's
  /// CheckAbortStatus() (AbortCheckEvent observers, e.g. an interactor with a pending event,
  /// set AbortRender) is polled while the pass runs, and a set flag stops it between tiles.
  /// Finished tiles keep their samples (the image stays a per-pixel mean); the next Render()
  /// continues the accumulation.
  bool GetLastRenderAborted();

  /// The per-axis resolution reduction of the last interactive Render() (1 = full resolution).
  int GetInteractiveReduction();

  /// The dual mesh this mapper builds and owns (its GetBuildCount() shows rebuilds).
  vtkAMRDualMesh* GetDualMesh();

  /// Samples per pixel accumulated so far (0 after a reset).
  int GetNumberOfSamples();

  /// The accumulation's reset key for a process that does not render itself (ParaView's client
  /// of a render server, which estimates the samples the server has): a number that changes
  /// whenever a render of `vol` in `ren` would restart the accumulation by what is known without
  /// rendering: this mapper's parameters and clipping planes, the volume's property and matrix,
  /// the renderer's camera, lights and tiled size. Not compared: the input (its dual mesh), the
  /// device and the opaque depth, which only a render sees. The same rule as Render()'s reset
  /// (AMRDualMeshAccumulation.h). 0 without a renderer, volume or property.
  vtkMTimeType GetAccumulationKey(vtkRenderer* ren, vtkVolume* vol);

  /// Calls window->Render() until the accumulation holds `samples` samples per pixel (at most
  /// MaximumSamples); no pass overshoots `samples`. Returns the number reached; stops early
  /// (after an error, or when a render adds nothing) and returns what was reached.
  int RenderUntil(vtkRenderWindow* window, int samples);

  /// Wall-clock seconds of the last Render(): sampling and compositing. The dual-mesh build and
  /// the transfer-function setup (majorants, culling) are excluded.
  vtkGetMacro(LastRenderSeconds, double);

  /// Host bytes of what the renderer keeps per mesh on top of the dual mesh (the majorant grid
  /// and the culling ranges and masks); 0 before the first render. GetDualMesh()'s
  /// GetTotalBytes() plus this is the all-in memory of the rendered data set.
  vtkTypeUInt64 GetAccelerationBytes();

  ///@{
  /// Data-parallel rendering (N MPI ranks render one AMR; set by the ParaView representation):
  /// this process draws region `index` (>= 0), the box `regionBounds` (xmin, xmax, ymin, ...,
  /// data frame) of the domain `domainBounds`. Camera rays are clipped to the region (secondary
  /// rays are not), GetBounds() reports the region, the automatic step size follows the domain
  /// and each region samples its own random stream (Seed mixed with the index). ClearRegion()
  /// (the default) draws all of the input. Changing the region restarts the accumulation.
  void SetRegion(int index, const double regionBounds[6], const double domainBounds[6]);
  void ClearRegion();
  /// The region drawn, -1 without one.
  int GetRegionIndex();
  /// A coarse copy of the whole domain (DistributionMode Proxy: its level 0, the same on every
  /// rank) that the scattered and shadow rays of PATH_TRACER and SINGLE_SCATTER see outside
  /// the region, so that light from and shadows of the other regions are approximated instead
  /// of missing. The same cell array is used as for the input. Only with a region, and only on
  /// the CPU device (an error otherwise, and the image is drawn without it). Null (the
  /// default) clears it. PrintSelf says whether the renderer uses it.
  void SetRegionProxy(vtkOverlappingAMR* proxy);
  ///@}

  /// Writes the current accumulated image (premultiplied float RGBA) to an OpenEXR file. Returns
  /// false (with an error) when there is no image or writing fails.
  bool WriteLastImageEXR(const char* fileName);

protected:
  vtkAMRDualMeshVolumeMapper();
  ~vtkAMRDualMeshVolumeMapper() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;

private:
  vtkAMRDualMeshVolumeMapper(const vtkAMRDualMeshVolumeMapper&) = delete;
  void operator=(const vtkAMRDualMeshVolumeMapper&) = delete;

  // Render() in steps, one per derived product (see the class documentation).
  vtkOverlappingAMR* UpdateAndGetInput();
  vtkOverlappingAMR* CheckInput();
  bool UpdateDualMesh(vtkOverlappingAMR* amr);
  /// Sets `mesh`'s input, array and build parameters (the mapper's) and updates it.
  bool BuildDualMesh(vtkAMRDualMesh* mesh, vtkOverlappingAMR* amr, const std::string& array);
  void UpdateRegionProxy(const std::string& array);
  void PrintRegion(ostream& os, vtkIndent indent);
  bool UpdateRendererSlot(vtkVolumeProperty* property);
  bool UpdateFrame(vtkRenderer* ren,
    vtkVolume* vol,
    const int viewport[4],
    amrdm::RenderParams& params);
  bool RenderStillFrame(vtkRenderer* ren,
    vtkVolume* vol,
    const amrdm::RenderParams& params,
    const int viewport[4]);
  bool RenderInteractiveFrame(vtkRenderer* ren,
    vtkVolume* vol,
    const amrdm::RenderParams& params,
    const int viewport[4]);

  int Device = DEVICE_AUTO;
  int Integrator = PATH_TRACER;
  int ElementTest = ELEMENT_TEST_BILINEAR;
  int MaxNewtonIterations = 10;
  int GridletSize = 8;
  int BVHLeafSize = 8;
  int SamplesPerRender = 1;
  int MaximumSamples = 256;
  int MaximumBounces = 64;
  double ScatteringAnisotropy = 0.0;
  double StepSize = 0.0;
  double SamplesPerCell = 0.0;
  int MajorantResolution = 0;
  int NumberOfThreads = 0;
  int Seed = 0;
  double EnvironmentRadiance[3] = { 1.0, 1.0, 1.0 };
  double InteractiveUpdateRate = 1.0;
  double InteractiveFrameTime = 0.1;
  double LastRenderSeconds = 0.0;

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif
