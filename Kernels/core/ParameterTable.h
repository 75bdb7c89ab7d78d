// The user-visible rendering and mesh parameters, declared once: name, type, default, range and
// one line of documentation. The kernel structs (RenderParams, DualMeshBuildOptions) take their
// defaults from here; the mapper's Set/Get and PrintSelf, the ParaView XML and amrdm-render's
// options and --help are checked against this table by Testing/Python/TestParameterTable.py,
// which reads the rows below (keep one row per line, in this exact form).
#pragma once

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

/// Where a parameter appears besides the mapper (which has them all as Set<Name>/Get<Name>).
enum ParameterLayer : unsigned
{
  InMapper = 1u, ///< vtkAMRDualMeshVolumeMapper Set<Name>/Get<Name>, PrintSelf "<Name>: "
  InPlugin = 2u, ///< ParaView property <Name> (AMRDualMeshRepresentation.xml)
  InCli = 4u     ///< amrdm-render option cliOption with the table's help, range and default
};
// Every row with a cliOption is an amrdm-render option named, documented, defaulted and
// range-checked from the row (Apps/CommandLineValues.h tableOption()); InCli rows are also
// checked for the default and range by the test. The enums without InCli (Integrator, Device)
// take names on the command line, so their --help shows the default's name.

struct ParameterSpec
{
  const char* name; ///< mapper Set/Get and ParaView property name (CamelCase)
  ParameterType type;
  double defaultValue;   ///< (Double3: of each component)
  double minimum;        ///< inclusive
  double maximum;        ///< inclusive
  unsigned layers;       ///< ParameterLayer bits
  const char* cliOption; ///< amrdm-render option, "" when none (see InCli)
  const char* doc;       ///< one line of documentation
};

constexpr unsigned kAllLayers = InMapper | InPlugin | InCli;

// clang-format off
namespace param
{
// PARAMETER ROWS BEGIN
constexpr ParameterSpec Integrator{ "Integrator", ParameterType::Enum, 0, 0, 4, InMapper | InPlugin, "--integrator", "estimator: path tracer, single scatter, ray march, debug primitives, debug cost" };
constexpr ParameterSpec Device{ "Device", ParameterType::Enum, 0, 0, 2, InMapper | InPlugin, "--device", "where the image is rendered: auto, CPU or CUDA" };
constexpr ParameterSpec ElementTest{ "ElementTest", ParameterType::Enum, 0, 0, 1, kAllLayers, "--element-test", "inside test of level-transition cells: bilinear (exact) or planar faces" };
constexpr ParameterSpec MaxNewtonIterations{ "MaxNewtonIterations", ParameterType::Int, 10, 1, 64, kAllLayers, "--newton", "Newton iterations of the bilinear element test" };
constexpr ParameterSpec GridletSize{ "GridletSize", ParameterType::Int, 8, 2, 32, kAllLayers, "--gridlet-size", "gridlet edge in dual cells (rebuilds the mesh)" };
constexpr ParameterSpec BVHLeafSize{ "BVHLeafSize", ParameterType::Int, 8, 1, 16, kAllLayers, "--bvh-leaf-size", "primitives per BVH leaf: larger saves memory, may cost speed (rebuilds the mesh)" };
constexpr ParameterSpec SamplesPerRender{ "SamplesPerRender", ParameterType::Int, 1, 1, 4096, InMapper | InPlugin, "", "samples per pixel added by each render" };
constexpr ParameterSpec MaximumSamples{ "MaximumSamples", ParameterType::Int, 256, 1, 1073741824, InMapper | InPlugin, "", "samples per pixel after which rendering only re-composites" };
constexpr ParameterSpec MaximumBounces{ "MaximumBounces", ParameterType::Int, 64, 0, 100000, kAllLayers, "--max-bounces", "scattering events after which a path stops" };
constexpr ParameterSpec ScatteringAnisotropy{ "ScatteringAnisotropy", ParameterType::Double, 0, -0.99, 0.99, kAllLayers, "--scattering-anisotropy", "Henyey-Greenstein anisotropy g of the phase function" };
constexpr ParameterSpec StepSize{ "StepSize", ParameterType::Double, 0, 0, DBL_MAX, kAllLayers, "--step", "ray-marching step, world units (0: automatic)" };
constexpr ParameterSpec SamplesPerCell{ "SamplesPerCell", ParameterType::Double, 0, 0, 1e6, kAllLayers, "--samples-per-cell", "level-adaptive ray marching: samples per finest cell (0: uniform step)" };
constexpr ParameterSpec MajorantResolution{ "MajorantResolution", ParameterType::Int, 0, 0, 1024, kAllLayers, "--majorant-res", "majorant macrocells per axis (0: automatic)" };
constexpr ParameterSpec NumberOfThreads{ "NumberOfThreads", ParameterType::Int, 0, 0, 1024, kAllLayers, "--threads", "threads for building and rendering (0: all cores)" };
constexpr ParameterSpec Seed{ "Seed", ParameterType::Int, 0, INT_MIN, INT_MAX, kAllLayers, "--seed", "random seed" };
constexpr ParameterSpec EnvironmentRadiance{ "EnvironmentRadiance", ParameterType::Double3, 1, 0, DBL_MAX, kAllLayers, "--environment-radiance", "uniform environment radiance (RGB) seen by scattered paths" };
constexpr ParameterSpec InteractiveUpdateRate{ "InteractiveUpdateRate", ParameterType::Double, 1, 0, DBL_MAX, InMapper, "", "desired update rate (frames/s) at or above which a render is interactive" };
constexpr ParameterSpec InteractiveFrameTime{ "InteractiveFrameTime", ParameterType::Double, 0.1, 0, DBL_MAX, InMapper | InPlugin, "", "time budget (s) of an interactive frame (0: full resolution)" };
constexpr ParameterSpec EmbedIsosurfaces{ "EmbedIsosurfaces", ParameterType::Int, 0, 0, 1, InMapper | InPlugin, "--embed-iso", "draw the isosurface values inside the Composite volume (path tracer: lit, shadowed surfaces)" };
// PARAMETER ROWS END
} // namespace param
// clang-format on

/// Every parameter, for code that iterates over them.
constexpr const ParameterSpec* kParameters[] = { &param::Integrator,
  &param::Device,
  &param::ElementTest,
  &param::MaxNewtonIterations,
  &param::GridletSize,
  &param::BVHLeafSize,
  &param::SamplesPerRender,
  &param::MaximumSamples,
  &param::MaximumBounces,
  &param::ScatteringAnisotropy,
  &param::StepSize,
  &param::SamplesPerCell,
  &param::MajorantResolution,
  &param::NumberOfThreads,
  &param::Seed,
  &param::EnvironmentRadiance,
  &param::InteractiveUpdateRate,
  &param::InteractiveFrameTime,
  &param::EmbedIsosurfaces };

} // namespace amrdm
