// The user-visible rendering and mesh parameters, declared once: one row per parameter with its
// name, type, default, range, layers, class, amrdm-render option, kernel field, ParaView label
// and enumeration, and documentation. The kernel structs (RenderParams, DualMeshBuildOptions)
// take their defaults from here. Tools/generate_parameters.py reads the rows below (keep one row
// per line, in this exact form) and writes every layer's declaration between BEGIN/END
// GENERATED markers: the mapper's Set/Get, fields and PrintSelf lines, the ParaView
// representation's forwarders and XML properties, amrdm-render's option rows, the mapper frame
// builder's copy into RenderParams and the scene file's fields (stored by name with the row's
// range, so a new row needs no new scene-file version). After editing a row run
//   python3 Tools/generate_parameters.py --write
// (ctest ParametersGenerated fails while a generated block is stale; TestParameterTable checks
// the built layers against the rows). The Integrator row follows render/IntegratorList.h: its
// maximum is kIntegratorCount - 1, and an integrator without an enumeration text here is listed
// in ParaView under its long name in title case.
#pragma once

#include "render/IntegratorList.h" // For kIntegratorCount (the Integrator row's maximum)

#include <cfloat>
#include <climits>

namespace amrdm
{

enum class ParameterType : int
{
  Int,    ///< an integer
  Enum,   ///< an integer choice in [minimum, maximum]
  Double, ///< a real number
  Double3 ///< three real numbers (RGB), each with the same default and range
};

/// What a change of the parameter invalidates.
enum class ParameterClass : int
{
  Build,  ///< the dual mesh: rebuilt (the mapper's input slot passes it to vtkAMRDualMesh;
          ///< scene files store it)
  Render, ///< the image: a RenderParams field, copied by the mapper's frame builder each frame
          ///< (generated) and stored in scene files; a change restarts the accumulation
  View    ///< neither mesh nor image: how and when the mapper renders (threads, sample budget,
          ///< interactive frames); a kernel field of a View row is set by the mapper's own code
};

/// Where a parameter appears (the mapper has them all as Set<Name>/Get<Name>), and which of its
/// layers are written by hand instead of generated.
enum ParameterLayer : unsigned
{
  InMapper = 1u,        ///< vtkAMRDualMeshVolumeMapper Set<Name>/Get<Name>, PrintSelf "<Name>: "
  InPlugin = 2u,        ///< ParaView property <Name> (AMRDualMeshRepresentation.xml) + forwarder
  InCli = 4u,           ///< amrdm-render option cliOption, default and range from the row
  Advanced = 8u,        ///< ParaView: shown only with the panel's advanced (gear) button
  SetByHand = 16u,      ///< the mapper's Set<Name> is written by hand (the block declares it)
  CliByHand = 32u,      ///< the amrdm-render row is written by hand (it parses names)
  NotInSceneFile = 64u, ///< scene files do not store it (a machine setting; blend state)
  /// The field classes that share the row's Set/Get, field and PrintSelf line (generated):
  InDualMesh = 128u,    ///< vtkAMRDualMesh
  InProbeFilter = 256u, ///< vtkAMRDualMeshProbeFilter
  InExport = 512u       ///< vtkAMRDualMeshToUnstructuredGrid
};
constexpr unsigned kAllLayers = InMapper | InPlugin | InCli;

struct ParameterSpec
{
  const char* name; ///< mapper Set/Get and ParaView property name (CamelCase)
  ParameterType type;
  double defaultValue;   ///< (Double3: of each component)
  double minimum;        ///< inclusive
  double maximum;        ///< inclusive
  unsigned layers;       ///< ParameterLayer bits
  ParameterClass kind;   ///< what a change invalidates
  const char* cliOption; ///< amrdm-render option, "" when none
  /// The kernel field the value lands in: "RenderParams::<member>" or
  /// "DualMeshBuildOptions::<member>" (also RenderOptions'/SceneDescription's member of that
  /// name); "" when no kernel struct holds it (mapper-only policy). A RenderParams field is
  /// declared from the row (generated block render-params of render/RenderParams.h) with the
  /// type int, float or glm::vec3 by the row's type, or the type written before the name
  /// ("glm::ivec3 RenderParams::majorantResolution"); a nested field
  /// ("RenderParams::elementTest.test") is declared by its struct.
  const char* kernelField;
  const char* label;   ///< ParaView's panel label
  const char* choices; ///< Enum: ParaView's entry texts, '|'-separated, for minimum..maximum
  const char* doc;     ///< one line: mapper header, amrdm-render --help, ParaView tooltip
  const char* guide;   ///< longer ParaView documentation ("" = doc)
};

// clang-format off
namespace param
{
// PARAMETER ROWS BEGIN
constexpr ParameterSpec Integrator{ "Integrator", ParameterType::Enum, 0, 0, kIntegratorCount - 1, kAllLayers | SetByHand | CliByHand, ParameterClass::Render, "--integrator", "IntegratorType RenderParams::integrator", "Rendering Method", "Path Tracing|Single Scattering|Ray Marching|Debug: Dual-Mesh Cells|Debug: Cost", "estimator: path tracer, single scatter, ray march, debug primitives, debug cost", "Path Tracing: light scattered many times in the medium (the most realistic). Single Scattering: light scattered once, faster and darker. Ray Marching: classic emission-absorption volume rendering, like ParaView's Volume representation. Debug: Dual-Mesh Cells colours each pixel by the kind of dual-mesh cell it first hits (gridlet or stitching element); Debug: Cost shows the work per pixel." };
constexpr ParameterSpec Device{ "Device", ParameterType::Enum, 0, 0, 2, kAllLayers | Advanced | CliByHand, ParameterClass::View, "--device", "", "Device", "Automatic|CPU|CUDA", "where the image is rendered: auto, CPU or CUDA", "Where the image is rendered. Automatic: on an NVIDIA GPU (CUDA) when the plugin was built with CUDA and a device can be used, else on the CPU; the choice and its reason are printed once, and running out of GPU memory falls back to the CPU. CPU: CPU threads. CUDA: the GPU only; an error (and no image) when the build has no CUDA or no device is present." };
constexpr ParameterSpec SamplesPerRender{ "SamplesPerRender", ParameterType::Int, 1, 1, 4096, InMapper | InPlugin, ParameterClass::View, "", "RenderParams::samplesPerPass", "Samples Per Render", "", "samples per pixel added by each render", "Samples per pixel added by each render. More gives a cleaner first image but makes each render (and interaction) slower." };
constexpr ParameterSpec MaximumSamples{ "MaximumSamples", ParameterType::Int, 256, 1, 1073741824, InMapper | InPlugin, ParameterClass::View, "", "", "Maximum Samples Per Pixel", "", "samples per pixel after which rendering only re-composites", "The image stops refining when every pixel has this many samples (default 256; each render adds Samples Per Render). Accumulated Samples shows how far it got." };
constexpr ParameterSpec ScatteringAnisotropy{ "ScatteringAnisotropy", ParameterType::Double, 0, -0.99, 0.99, kAllLayers, ParameterClass::Render, "--scattering-anisotropy", "RenderParams::anisotropy", "Scattering Anisotropy", "", "Henyey-Greenstein anisotropy g of the phase function", "Direction of scattering: 0 scatters light equally in all directions, positive values mostly forward, negative values mostly backward." };
constexpr ParameterSpec EnvironmentRadiance{ "EnvironmentRadiance", ParameterType::Double3, 1, 0, DBL_MAX, kAllLayers, ParameterClass::Render, "--environment-radiance", "RenderParams::ambient", "Environment Light", "", "uniform environment radiance (RGB) seen by scattered paths", "Brightness (red, green, blue) of the uniform light that surrounds the volume, seen by scattered light that leaves it (Path Tracing and Single Scattering). The default, white 1, makes a dense medium look about as bright as ParaView's Volume representation with the same colour map (the colour is the medium's albedo: dark colours absorb and stay dark)." };
constexpr ParameterSpec EmbedIsosurfaces{ "EmbedIsosurfaces", ParameterType::Int, 0, 0, 1, kAllLayers | CliByHand | NotInSceneFile, ParameterClass::Render, "--embed-iso", "bool RenderParams::embedIsosurfaces", "Embed Isosurfaces", "", "draw the isosurface values inside the Composite volume (path tracer: lit, shadowed surfaces)", "With Blend Mode Composite, draws the Isosurfaces values inside the volume: with Path Tracing as lit surfaces that shadow the volume and are shadowed by it; with Ray Marching composited in depth order." };
constexpr ParameterSpec MaximumBounces{ "MaximumBounces", ParameterType::Int, 64, 0, 100000, kAllLayers | Advanced, ParameterClass::Render, "--max-bounces", "RenderParams::maxBounces", "Maximum Scattering Events", "", "scattering events after which a path stops", "A light path stops after this many scattering events (0: light scattered once from the lights only)." };
constexpr ParameterSpec StepSize{ "StepSize", ParameterType::Double, 0, 0, DBL_MAX, kAllLayers | Advanced, ParameterClass::Render, "--step", "RenderParams::stepSize", "Ray Marching Step", "", "ray-marching step, world units (0: automatic, where the most opaque colour adds 0.1 opacity per step, within [half the finest cell, >= 1/1000 of the diagonal; 1/32 of it])", "Step length (world units) of Ray Marching; 0 chooses the step at which the most opaque entry of the transfer function adds 0.1 opacity, never shorter than half the finest cell (and 1/1000 of the data's diagonal) nor longer than 1/32 of the diagonal." };
constexpr ParameterSpec SamplesPerCell{ "SamplesPerCell", ParameterType::Double, 0, 0, 1e6, kAllLayers | Advanced, ParameterClass::Render, "--samples-per-cell", "RenderParams::samplesPerCell", "Ray Marching Samples per Cell", "", "level-adaptive ray marching: samples per finest cell of each macrocell, step >= StepSize (0: uniform step)", "Adapts the Ray Marching step to the refinement level: each region is sampled this many times per cell of its finest level, so coarse regions take longer steps (never shorter than Ray Marching Step). 0 keeps one step everywhere; 1 to 2 is as accurate and several times faster on data with many levels." };
constexpr ParameterSpec ElementTest{ "ElementTest", ParameterType::Enum, 0, 0, 1, kAllLayers | Advanced | CliByHand | InDualMesh | InProbeFilter, ParameterClass::Render, "--element-test", "RenderParams::elementTest.test", "Level-Transition Cell Test", "Exact|Planar Faces (Faster)", "inside test of level-transition cells: bilinear (exact) or planar faces", "How a point is located in the cells that join two refinement levels: Exact follows their curved faces; Planar Faces is faster but slightly approximate where a face is twisted." };
constexpr ParameterSpec MaxNewtonIterations{ "MaxNewtonIterations", ParameterType::Int, 10, 1, 64, kAllLayers | Advanced | InDualMesh | InProbeFilter, ParameterClass::Render, "--newton", "RenderParams::elementTest.maxNewtonIterations", "Exact Test Iterations", "", "Newton iterations of the bilinear element test", "Iterations of the Exact level-transition cell test." };
constexpr ParameterSpec GridletSize{ "GridletSize", ParameterType::Int, 8, 2, 32, kAllLayers | Advanced | InDualMesh | InProbeFilter, ParameterClass::Build, "--gridlet-size", "DualMeshBuildOptions::gridletSize", "Gridlet Size", "", "gridlet edge in dual cells (rebuilds the mesh)", "Cells per axis of the small grids (gridlets) that hold the field; larger uses less memory for the search tree. Changing it rebuilds the dual mesh." };
constexpr ParameterSpec BVHLeafSize{ "BVHLeafSize", ParameterType::Int, 8, 1, 16, kAllLayers | Advanced | InDualMesh | InProbeFilter, ParameterClass::Build, "--bvh-leaf-size", "DualMeshBuildOptions::bvhLeafSize", "Search Tree Leaf Size", "", "primitives per BVH leaf: larger saves memory, may cost speed (rebuilds the mesh)", "Most gridlets and level-transition cells per leaf of the search tree (BVH); larger uses less memory and may render slower. Changing it rebuilds the dual mesh." };
constexpr ParameterSpec MajorantResolution{ "MajorantResolution", ParameterType::Int, 0, 0, 1024, kAllLayers | Advanced, ParameterClass::Render, "--majorant-res", "glm::ivec3 RenderParams::majorantResolution", "Density Bound Grid Resolution", "", "majorant macrocells per axis (0: automatic, 1 per 16 finest cells, <= 128, <= 1 per 64 leaf cells)", "Cells per axis of the coarse grid of density bounds that lets light skip thin regions quickly; 0 chooses one cell per 16 finest cells (at most 128 per axis, and at most one per 64 data cells)." };
constexpr ParameterSpec NumberOfThreads{ "NumberOfThreads", ParameterType::Int, 0, 0, 1024, kAllLayers | Advanced | NotInSceneFile | InDualMesh | InProbeFilter, ParameterClass::View, "--threads", "RenderParams::threads", "Threads", "", "threads for building, sampling and rendering (0: all cores, at most VTK_SMP_MAX_THREADS when that is set); results do not depend on it", "Threads used to build and render; 0 uses all cores. The image does not depend on it." };
constexpr ParameterSpec Seed{ "Seed", ParameterType::Int, 0, INT_MIN, INT_MAX, kAllLayers | Advanced, ParameterClass::Render, "--seed", "std::uint32_t RenderParams::seed", "Random Seed", "", "random seed", "Seed of the random numbers: the same seed, scene and number of samples give the same image." };
constexpr ParameterSpec InteractiveFrameTime{ "InteractiveFrameTime", ParameterType::Double, 0.1, 0, DBL_MAX, InMapper | InPlugin | Advanced, ParameterClass::View, "", "", "Interactive Frame Time", "", "time budget (s) of an interactive frame (0: full resolution)", "Seconds per frame while rotating, zooming or panning: such a frame takes one sample per pixel at a resolution reduced (by a factor of up to 16 per axis) to fit this time, measured from the frames before it; when the mouse is released the image refines at full resolution. 0 renders interactive frames at full resolution." };
constexpr ParameterSpec FinalRenderTime{ "FinalRenderTime", ParameterType::Double, 10, 0, DBL_MAX, InMapper | InPlugin | Advanced, ParameterClass::View, "", "", "Final Render Time", "", "time budget (s) of a final render (no interactor: pvbatch, pvpython; a screenshot): it adds samples until MaximumSamples or this budget (0: one pass)", "Quality target of SaveScreenshot and of pvbatch / pvpython renders: passes until Maximum Samples Per Pixel or this many seconds (0: one pass)." };
constexpr ParameterSpec InteractiveUpdateRate{ "InteractiveUpdateRate", ParameterType::Double, 1, 0, DBL_MAX, InMapper, ParameterClass::View, "", "", "", "", "desired update rate (frames/s) at or above which a render is interactive (0: never)", "" };
constexpr ParameterSpec Component{ "Component", ParameterType::Int, -1, -1, INT_MAX, InDualMesh | InProbeFilter | InExport, ParameterClass::Build, "", "", "Component", "", "component of a multi-component array (-1: the magnitude of a vector, the value of a scalar)", "" };
constexpr ParameterSpec LogScale{ "LogScale", ParameterType::Int, 0, 0, 1, InDualMesh | InExport, ParameterClass::Build, "", "", "Log Scale", "", "build the field from log10 of the values (values <= 0 become holes, one warning)", "" };
// PARAMETER ROWS END
} // namespace param
// clang-format on

/// Every parameter, in the rows' order (the ParaView panel's), for code that iterates over them.
constexpr const ParameterSpec* kParameters[] = {
  // BEGIN GENERATED table-index (Tools/generate_parameters.py)
  // clang-format off
  &param::Integrator,
  &param::Device,
  &param::SamplesPerRender,
  &param::MaximumSamples,
  &param::ScatteringAnisotropy,
  &param::EnvironmentRadiance,
  &param::EmbedIsosurfaces,
  &param::MaximumBounces,
  &param::StepSize,
  &param::SamplesPerCell,
  &param::ElementTest,
  &param::MaxNewtonIterations,
  &param::GridletSize,
  &param::BVHLeafSize,
  &param::MajorantResolution,
  &param::NumberOfThreads,
  &param::Seed,
  &param::InteractiveFrameTime,
  &param::FinalRenderTime,
  &param::InteractiveUpdateRate,
  &param::Component,
  &param::LogScale,
  // clang-format on
  // END GENERATED table-index
};

} // namespace amrdm
