/**
 * @class   vtkAMRDualMeshVolumeMapper
 * @brief   path-traced volume rendering of a vtkOverlappingAMR through its dual mesh
 *
 * A drop-in vtkVolumeMapper (like vtkAMRVolumeMapper) for vtkOverlappingAMR input: it builds the
 * dual mesh of one cell or point array (vtkAMRDualMesh: gridlets, stitching elements, BVH;
 * Zellmann et al., EuroVis 2023) and renders it (CPU threads or CUDA, see Device) with a
 * volumetric path tracer, single scattering, emission-absorption ray marching or a debug view.
 * Each still Render() adds SamplesPerRender samples per pixel to a running mean (until
 * MaximumSamples) composited over the scene; interactive renders draw one cheap sample.
 *
 * The image follows the vtkVolumeProperty (component 0: colour, scalar opacity, log scale, unit
 * distance, shading), the scalar array chosen the VTK way (SelectScalarArray, ScalarMode), the
 * renderer's lights and camera (tiled viewports and screenshot tiles included), the mapper's
 * clipping planes, opaque depth, and the vtkVolume's matrix; any change restarts the
 * accumulation. The full contract (what each of these means, translucent geometry and depth
 * peeling, devices, regions, time stamps) is docs/MAPPER.md.
 *
 * @sa vtkAMRDualMesh vtkAMRVolumeMapper
 */
#ifndef vtkAMRDualMeshVolumeMapper_h
#define vtkAMRDualMeshVolumeMapper_h

#include "AMRDualMeshMapperModule.h" // For export macro
#include "vtkVolumeMapper.h"

#include <memory> // For std::unique_ptr

class vtkAMRDualMesh;
class vtkOverlappingAMR;
class vtkRenderWindow;
class vtkVolumeProperty;

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
  /// The input: a vtkOverlappingAMR (data or connection); others are an error at render time.
  virtual void SetInputData(vtkOverlappingAMR* amr);
  using vtkVolumeMapper::SetInputData;
  ///@}

  ///@{
  /// Bounds of the AMR data set or the region (updates the input); uninitialized without input.
  double* GetBounds() override;
  void GetBounds(double bounds[6]) override { this->vtkVolumeMapper::GetBounds(bounds); }
  ///@}

  /// Renders the volume: adds samples (unless MaximumSamples is reached) and composites.
  void Render(vtkRenderer* ren, vtkVolume* vol) override;

  /// Releases the texture, the quad and the depth framebuffer of `window`.
  void ReleaseGraphicsResources(vtkWindow* window) override;

  ///@{
  /// Estimator: an Integrators value (default PATH_TRACER) or any later row of the kernels'
  /// list (render/IntegratorList.h); a value outside it is clamped to it, with a warning.
  virtual void SetIntegrator(int integrator);
  /// The integrator's name in the kernels' list ("path-tracer", "ray-march", ...).
  const char* GetIntegratorAsString();
  vtkGetMacro(Integrator, int);
  void SetIntegratorToPathTracer() { this->SetIntegrator(PATH_TRACER); }
  void SetIntegratorToSingleScatter() { this->SetIntegrator(SINGLE_SCATTER); }
  void SetIntegratorToRayMarch() { this->SetIntegrator(RAY_MARCH); }
  ///@}

  ///@{
  /// Where the image is rendered: a Devices value, default DEVICE_AUTO (docs/MAPPER.md, Devices).
  vtkSetClampMacro(Device, int, DEVICE_AUTO, DEVICE_CUDA);
  vtkGetMacro(Device, int);
  void SetDeviceToAuto() { this->SetDevice(DEVICE_AUTO); }
  void SetDeviceToCPU() { this->SetDevice(DEVICE_CPU); }
  void SetDeviceToCUDA() { this->SetDevice(DEVICE_CUDA); }
  const char* GetDeviceAsString();
  ///@}

  /// Which device AUTO chose and why, or a fallback to the CPU; empty for CPU and CUDA.
  const char* GetDeviceReport();

  /// DEVICE_CPU or DEVICE_CUDA: the current renderer's; -1 before a Render() or after an error.
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
  /// Gridlet size G (up to G^3 dual cells per gridlet) of the dual mesh (rebuilt); 2..32,
  /// default 8.
  vtkSetClampMacro(GridletSize, int, 2, 32);
  vtkGetMacro(GridletSize, int);
  ///@}

  ///@{
  /// Most primitives per BVH leaf of the dual mesh (rebuilt); larger leaves need less memory and
  /// may sample slower. 1..16, default 8.
  vtkSetClampMacro(BVHLeafSize, int, 1, 16);
  vtkGetMacro(BVHLeafSize, int);
  ///@}

  ///@{
  /// Samples per pixel added by each Render(); 1..4096, default 1.
  vtkSetClampMacro(SamplesPerRender, int, 1, 4096);
  vtkGetMacro(SamplesPerRender, int);
  ///@}

  ///@{
  /// Samples per pixel after which Render() only re-composites; 1..2^30, default 256
  /// (Benchmarks/interaction.py prints how long it takes to reach).
  vtkSetClampMacro(MaximumSamples, int, 1, 1 << 30);
  vtkGetMacro(MaximumSamples, int);
  ///@}

  ///@{
  /// Scattering events after which a path stops; 0..100000, default 64 (0: lights' single
  /// scattering).
  vtkSetClampMacro(MaximumBounces, int, 0, 100000);
  vtkGetMacro(MaximumBounces, int);
  ///@}

  ///@{
  /// 1: with COMPOSITE_BLEND, the property's GetIsoSurfaceValues() drawn inside the volume
  /// (docs/ISOSURFACES.md; beyond vtkVolumeMapper's modes). 0 (default) or 1.
  vtkSetClampMacro(EmbedIsosurfaces, int, 0, 1);
  vtkGetMacro(EmbedIsosurfaces, int);
  ///@}

  ///@{
  /// Henyey-Greenstein anisotropy g of the phase function; -0.99..0.99, default 0 (isotropic).
  vtkSetClampMacro(ScatteringAnisotropy, double, -0.99, 0.99);
  vtkGetMacro(ScatteringAnisotropy, double);
  ///@}

  ///@{
  /// Ray-marching step in world units; default 0 = automatic: half the finest cell's smallest
  /// spacing, at least 1/1000 of the bounding-box diagonal (deep hierarchies).
  vtkSetClampMacro(StepSize, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(StepSize, double);
  ///@}

  ///@{
  /// Level-adaptive ray marching: samples per cell of each macrocell's finest level (never below
  /// StepSize); 0..1e6, default 0 = off. 1 to 2 is the uniform step's error at a fraction of its
  /// time on multi-level data (docs/BENCHMARKS.md).
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
  /// Threads for building and rendering; 0..1024, default 0 (GetEffectiveNumberOfThreads()).
  /// Images do not depend on it.
  vtkSetClampMacro(NumberOfThreads, int, 0, 1024);
  vtkGetMacro(NumberOfThreads, int);
  ///@}

  /// The threads the next build and render use: NumberOfThreads, or for 0
  /// VTK_SMP_MAX_THREADS or all cores.
  int GetEffectiveNumberOfThreads() const;

  ///@{
  /// Random seed, default 0: the same seed, sample count and scene give the same image.
  vtkSetMacro(Seed, int);
  vtkGetMacro(Seed, int);
  ///@}

  ///@{
  /// Uniform radiance (RGB, each >= 0) that scattered paths leaving the volume see; default
  /// (1, 1, 1) (docs/MAPPER.md, The environment).
  vtkSetVector3Macro(EnvironmentRadiance, double);
  vtkGetVector3Macro(EnvironmentRadiance, double);
  ///@}

  ///@{
  /// A Render() is interactive when the window's DesiredUpdateRate is at least this (frames per
  /// second); default 1 (as vtkSmartVolumeMapper), 0 = never interactive.
  vtkSetClampMacro(InteractiveUpdateRate, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(InteractiveUpdateRate, double);
  ///@}

  ///@{
  /// Time budget (seconds) of an interactive Render() (docs/MAPPER.md); default 0.1, 0 = full
  /// resolution.
  vtkSetClampMacro(InteractiveFrameTime, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(InteractiveFrameTime, double);
  ///@}

  /// True when the last Render() was interactive (see InteractiveUpdateRate).
  bool GetLastRenderInteractive();

  /// True when VTK's abort check stopped the last Render()'s pass between tiles (docs/MAPPER.md).
  bool GetLastRenderAborted();

  /// The per-axis resolution reduction of the last interactive Render() (1 = full resolution).
  int GetInteractiveReduction();

  /// The dual mesh this mapper builds and owns (its GetBuildCount() shows rebuilds).
  vtkAMRDualMesh* GetDualMesh();

  /// Samples per pixel accumulated so far (0 after a reset).
  int GetNumberOfSamples();

  /// The accumulation's reset key for a process that does not render (docs/MAPPER.md); 0 without
  /// a renderer, volume or property.
  vtkMTimeType GetAccumulationKey(vtkRenderer* ren, vtkVolume* vol);

  /// Calls window->Render() until the accumulation holds `samples` (at most MaximumSamples; no
  /// pass overshoots). Returns the number reached, early after an error or an empty render.
  int RenderUntil(vtkRenderWindow* window, int samples);

  /// Wall-clock seconds of the last Render()'s sampling and compositing (not the mesh build nor
  /// the transfer-function setup).
  vtkGetMacro(LastRenderSeconds, double);

  /// Host bytes the renderer keeps on top of the dual mesh (majorants, culling); 0 before the
  /// first render. Plus GetDualMesh()->GetTotalBytes(): the rendered data set's memory.
  vtkTypeUInt64 GetAccelerationBytes();

  ///@{
  /// Data-parallel rendering: this process draws region `index` (>= 0), the box `regionBounds`
  /// of `domainBounds`; ClearRegion() (the default) draws all (docs/MAPPER.md, Regions).
  void SetRegion(int index, const double regionBounds[6], const double domainBounds[6]);
  void ClearRegion();
  /// The region drawn, -1 without one.
  int GetRegionIndex();
  /// A coarse copy of the whole domain that scattered and shadow rays see outside the region
  /// (CPU only; null, the default, clears it; docs/MAPPER.md, Regions).
  void SetRegionProxy(vtkOverlappingAMR* proxy);
  ///@}

  /// Writes the accumulated image (premultiplied float RGBA) to OpenEXR; false after an error.
  bool WriteLastImageEXR(const char* fileName);

protected:
  vtkAMRDualMeshVolumeMapper();
  ~vtkAMRDualMeshVolumeMapper() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;

private:
  vtkAMRDualMeshVolumeMapper(const vtkAMRDualMeshVolumeMapper&) = delete;
  void operator=(const vtkAMRDualMeshVolumeMapper&) = delete;

  friend class AMRDualMeshFrameBuilder; // draws the frame: Render()'s last step

  int Device = DEVICE_AUTO;
  int Integrator = PATH_TRACER;
  int ElementTest = ELEMENT_TEST_BILINEAR;
  int MaxNewtonIterations = 10;
  int GridletSize = 8;
  int BVHLeafSize = 8;
  int SamplesPerRender = 1;
  int MaximumSamples = 256;
  int MaximumBounces = 64;
  int EmbedIsosurfaces = 0;
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
