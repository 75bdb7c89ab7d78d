// Options of amrdm-render. Every option maps to one documented parameter of vtkAMRDualMesh
// (build) or amrdm::RenderParams (render). The options are one table (RenderCommandLine.cxx):
// each row has its names, its values, its help text and what it sets; CLI11 parses the rows and
// prints `--help` from them (CommandLineParser.h), so a new option is one row. A parameter of the
// parameter table (core/ParameterTable.h) takes its option name, default, range and help from
// the table's row.
#ifndef RenderCommandLine_h
#define RenderCommandLine_h

#include "DefaultView.h"         // For kDefaultAzimuth, kDefaultElevation
#include "core/ParameterTable.h" // For the defaults of table parameters
#include "render/RenderParams.h" // For amrdm::RenderParams
#include "render/Renderer.h"     // For amrdm::RenderDevice

#include <string>

namespace amrdm_app
{
struct RenderOptions
{
  std::string file;        ///< AMR file; empty = the embedded demo set
  std::string output;      ///< NAME.png (+ NAME.exr), NAME.exr or NAME.jpg; empty = no image
  bool stats = false;      ///< print dual-mesh counts, memory, build time as JSON and exit
  bool listArrays = false; ///< print the cell arrays and their ranges, then exit
  std::string exportScene; ///< write this scene file (SceneExport.h) instead of rendering
  bool help = false;
  std::string array;  ///< empty = chosen (FieldDefaults.h: density first)
  int component = -1; ///< -1 = magnitude for vectors
  int logScale = -1;  ///< -1 auto (positive values span > 3 decades), 0 linear, 1 log10
  bool hasRange = false;
  double range[2] = { 0, 0 }; ///< transfer-function domain; default bulk .. 99.9th percentile
  std::string tf = "cool-warm";
  double maxOpacity = 0.5;   ///< top of the preset opacity ramp
  bool opaqueBulk = false;   ///< keep the ramp where values fill much of the volume
  double unitDistance = 0.0; ///< 0 = an eighth of the framed bounds' diagonal
  bool hasExposure = false;
  double exposure = 0.0; ///< stops; default kPathTracedExposure for pt/ss, 0 otherwise
  int gridletSize = int(amrdm::param::GridletSize.defaultValue);
  int bvhLeafSize = int(amrdm::param::BVHLeafSize.defaultValue);
  int spp = 16; ///< samples per pixel in total, one per frame
  bool hasEye = false, hasFocal = false;
  double eye[3] = { 0, 0, 0 }, focal[3] = { 0, 0, 0 }, up[3] = { 0, 0, 1 };
  double azimuth = kDefaultAzimuth, elevation = kDefaultElevation; ///< view direction, degrees
  double zoom = 1.0;
  double background[3] = { 0, 0, 0 };
  amrdm::RenderParams params; ///< integrator, size, lights, ... (see RenderParams.h)
  bool hasIntegrator = false; ///< --integrator was given (else --blend picks ray marching)
  bool hasSlice = false;      ///< --slice was given (world coordinates; params get the scene frame)
  double sliceOrigin[3] = { 0, 0, 0 }, sliceNormal[3] = { 0, 0, 1 };
  bool headlight = true; ///< add a light when none was given on the command line
  amrdm::RenderDevice device = amrdm::RenderDevice::Auto; ///< --device auto|cpu|cuda
  int fpsFrames = 0; ///< > 0: benchmark, N frames at 1 spp, mean ms of frames 11..N
};

/// Default exposure (stops) of the path tracer and single scattering: a path-traced image of a
/// bright colour map is then about as bright as the ray-marched (emission-absorption) image of
/// the same scene: the median of log2(mean rm / mean pt) over the shared sets with the cool-warm
/// and white maps (Apps/tools/measure_defaults.py; README "Defaults, measured").
constexpr double kPathTracedExposure = -0.35;

/// Parses argv. Returns false and sets `error` (one line, naming the option) on a bad option or
/// value.
bool ParseCommandLine(int argc, char* argv[], RenderOptions& options, std::string& error);

/// The --help text, printed from the option table.
std::string Usage();
}

#endif
