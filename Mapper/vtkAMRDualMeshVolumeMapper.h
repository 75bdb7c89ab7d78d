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

#include <algorithm> // For std::copy (generated Set of RGB parameters)
#include <memory>    // For std::unique_ptr

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

  /// The values of ElementTest here, in vtkAMRDualMesh and in vtkAMRDualMeshProbeFilter (one
  /// enumeration for the module; amrdm_vtk::ToElementTest is its one conversion to the kernels'
  /// amrdm::ElementTest).
  enum ElementTests
  {
    ELEMENT_TEST_BILINEAR = 0,    ///< exact: the bilinear faces of level-transition cells
    ELEMENT_TEST_PLANAR_FACES = 1 ///< faster, approximate where a face is twisted
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

  // The parameters of core/ParameterTable.h, one Set/Get pair each (ranges clamped).
  // BEGIN GENERATED mapper-api (Tools/generate_parameters.py; edit the table, then run it)
  // clang-format off
  /// Estimator: path tracer, single scatter, ray march, debug primitives, debug cost; 0..4, default
  /// 0.
  virtual void SetIntegrator(int value); // by hand (see below)
  vtkGetMacro(Integrator, int);
  /// Where the image is rendered: auto, CPU or CUDA; 0..2, default 0.
  vtkSetClampMacro(Device, int, 0, 2);
  vtkGetMacro(Device, int);
  /// Samples per pixel added by each render; 1..4096, default 1.
  vtkSetClampMacro(SamplesPerRender, int, 1, 4096);
  vtkGetMacro(SamplesPerRender, int);
  /// Samples per pixel after which rendering only re-composites; 1..1073741824, default 256.
  vtkSetClampMacro(MaximumSamples, int, 1, 1073741824);
  vtkGetMacro(MaximumSamples, int);
  /// Henyey-Greenstein anisotropy g of the phase function; -0.99..0.99, default 0.
  vtkSetClampMacro(ScatteringAnisotropy, double, -0.99, 0.99);
  vtkGetMacro(ScatteringAnisotropy, double);
  /// Uniform environment radiance (RGB) seen by scattered paths; >= 0, default (1, 1, 1).
  virtual void SetEnvironmentRadiance(double r, double g, double b)
  {
    const double v[3] = {
      (r < 0.0 ? 0.0 : (r > VTK_DOUBLE_MAX ? VTK_DOUBLE_MAX : r)),
      (g < 0.0 ? 0.0 : (g > VTK_DOUBLE_MAX ? VTK_DOUBLE_MAX : g)),
      (b < 0.0 ? 0.0 : (b > VTK_DOUBLE_MAX ? VTK_DOUBLE_MAX : b)),
    };
    if (v[0] != this->EnvironmentRadiance[0] || v[1] != this->EnvironmentRadiance[1] ||
      v[2] != this->EnvironmentRadiance[2])
    {
      std::copy(v, v + 3, this->EnvironmentRadiance);
      this->Modified();
    }
  }
  void SetEnvironmentRadiance(const double rgb[3])
  {
    this->SetEnvironmentRadiance(rgb[0], rgb[1], rgb[2]);
  }
  vtkGetVector3Macro(EnvironmentRadiance, double);
  /// Draw the isosurface values inside the Composite volume (path tracer: lit, shadowed surfaces);
  /// 0..1, default 0.
  vtkSetClampMacro(EmbedIsosurfaces, int, 0, 1);
  vtkGetMacro(EmbedIsosurfaces, int);
  vtkBooleanMacro(EmbedIsosurfaces, int);
  /// Scattering events after which a path stops; 0..100000, default 64.
  vtkSetClampMacro(MaximumBounces, int, 0, 100000);
  vtkGetMacro(MaximumBounces, int);
  /// Ray-marching step, world units (0: automatic, where the most opaque colour adds 0.1 opacity
  /// per step, within [half the finest cell, >= 1/1000 of the diagonal; 1/32 of it]); >= 0, default
  /// 0.
  vtkSetClampMacro(StepSize, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(StepSize, double);
  /// Level-adaptive ray marching: samples per finest cell of each macrocell, step >= StepSize (0:
  /// uniform step); 0..1000000, default 0.
  vtkSetClampMacro(SamplesPerCell, double, 0.0, 1000000.0);
  vtkGetMacro(SamplesPerCell, double);
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
  /// Majorant macrocells per axis (0: automatic, 1 per 16 finest cells, <= 128, <= 1 per 64 leaf
  /// cells); 0..1024, default 0.
  vtkSetClampMacro(MajorantResolution, int, 0, 1024);
  vtkGetMacro(MajorantResolution, int);
  /// Threads for building, sampling and rendering (0: all cores, at most VTK_SMP_MAX_THREADS when
  /// that is set); results do not depend on it; 0..1024, default 0.
  vtkSetClampMacro(NumberOfThreads, int, 0, 1024);
  vtkGetMacro(NumberOfThreads, int);
  /// Random seed; any, default 0.
  vtkSetMacro(Seed, int);
  vtkGetMacro(Seed, int);
  /// Time budget (s) of an interactive frame (0: full resolution); >= 0, default 0.1.
  vtkSetClampMacro(InteractiveFrameTime, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(InteractiveFrameTime, double);
  /// Time budget (s) of a final render (no interactor: pvbatch, pvpython; a screenshot): it adds
  /// samples until MaximumSamples or this budget (0: one pass); >= 0, default 10.
  vtkSetClampMacro(FinalRenderTime, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(FinalRenderTime, double);
  /// Desired update rate (frames/s) at or above which a render is interactive (0: never); >= 0,
  /// default 1.
  vtkSetClampMacro(InteractiveUpdateRate, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(InteractiveUpdateRate, double);
  // clang-format on
  // END GENERATED mapper-api

  ///@{
  /// Integrator: an Integrators value or any later row of the kernels' list
  /// (render/IntegratorList.h); a value outside it is clamped to it, with a warning.
  /// GetIntegratorAsString(): the integrator's name in that list ("path-tracer", ...).
  const char* GetIntegratorAsString();
  void SetIntegratorToPathTracer() { this->SetIntegrator(PATH_TRACER); }
  void SetIntegratorToSingleScatter() { this->SetIntegrator(SINGLE_SCATTER); }
  void SetIntegratorToRayMarch() { this->SetIntegrator(RAY_MARCH); }
  ///@}

  ///@{
  /// Device: a Devices value, default DEVICE_AUTO (docs/MAPPER.md, Devices).
  void SetDeviceToAuto() { this->SetDevice(DEVICE_AUTO); }
  void SetDeviceToCPU() { this->SetDevice(DEVICE_CPU); }
  void SetDeviceToCUDA() { this->SetDevice(DEVICE_CUDA); }
  const char* GetDeviceAsString();
  ///@}

  /// Which device AUTO chose and why, or a fallback to the CPU; empty for CPU and CUDA.
  const char* GetDeviceReport();

  /// DEVICE_CPU or DEVICE_CUDA: the current renderer's; -1 before a Render() or after an error.
  int GetRenderingDevice();

  /// The threads the next build and render use: NumberOfThreads, or for 0
  /// VTK_SMP_MAX_THREADS or all cores. Images do not depend on it.
  int GetEffectiveNumberOfThreads() const;

  /// True when the last Render() was interactive (see InteractiveUpdateRate).
  bool GetLastRenderInteractive();

  /// The next still Render()s are final (ParaView: scripts, screenshots): they add passes toward
  /// MaximumSamples for up to FinalRenderTime seconds. Not a parameter: no restart.
  void MarkFinalRender(bool final) { this->FinalRender = final; }

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

  // BEGIN GENERATED mapper-fields (Tools/generate_parameters.py)
  // clang-format off
  int Integrator = 0;
  int Device = 0;
  int SamplesPerRender = 1;
  int MaximumSamples = 256;
  double ScatteringAnisotropy = 0.0;
  double EnvironmentRadiance[3] = { 1.0, 1.0, 1.0 };
  int EmbedIsosurfaces = 0;
  int MaximumBounces = 64;
  double StepSize = 0.0;
  double SamplesPerCell = 0.0;
  int ElementTest = 0;
  int MaxNewtonIterations = 10;
  int GridletSize = 8;
  int BVHLeafSize = 8;
  int MajorantResolution = 0;
  int NumberOfThreads = 0;
  int Seed = 0;
  double InteractiveFrameTime = 0.1;
  double FinalRenderTime = 10.0;
  double InteractiveUpdateRate = 1.0;
  // clang-format on
  // END GENERATED mapper-fields
  bool FinalRender = false;
  double LastRenderSeconds = 0.0;

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif
