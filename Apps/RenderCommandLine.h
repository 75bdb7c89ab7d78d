// Options of amrdm-render. Every option maps to one documented parameter of vtkAMRDualMesh
// (build) or amrdm::RenderParams (render); `amrdm-render --help` prints this list.
#ifndef RenderCommandLine_h
#define RenderCommandLine_h

#include "RenderParams.h" // For amrdm::RenderParams
#include "Renderer.h"     // For amrdm::RenderDevice

#include <string>

namespace amrdm_app
{
struct RenderOptions
{
  std::string file;            ///< AMR file; empty = the embedded demo set
  std::string output;          ///< NAME.png (NAME.exr is written next to it); empty = no image
  bool stats = false;          ///< print dual-mesh counts, memory, build time as JSON and exit
  bool help = false;
  std::string array;           ///< empty = first cell array
  int component = -1;          ///< -1 = magnitude for vectors
  int logScale = -1;           ///< -1 auto (range spans > 3 decades), 0 linear, 1 log10
  bool hasRange = false;
  double range[2] = { 0, 0 };  ///< transfer-function domain; default the field's range
  std::string tf = "cool-warm";
  double maxOpacity = 0.5;     ///< top of the preset opacity ramp
  double unitDistance = 0.0;   ///< 0 = an eighth of the bounding-box diagonal
  int gridletSize = 8;
  int spp = 16;                ///< samples per pixel in total, one per frame
  bool hasEye = false, hasFocal = false;
  double eye[3] = { 0, 0, 0 }, focal[3] = { 0, 0, 0 }, up[3] = { 0, 0, 1 };
  double azimuth = 35.0, elevation = 25.0; ///< default view direction, degrees
  double zoom = 1.0;
  double background[3] = { 0, 0, 0 };
  amrdm::RenderParams params;  ///< integrator, size, lights, ... (see RenderParams.h)
  bool headlight = true;       ///< add a light when none was given on the command line
  amrdm::RenderDevice device = amrdm::RenderDevice::Auto; ///< --device auto|cpu|cuda
  int fpsFrames = 0;           ///< > 0: benchmark, N frames at 1 spp, mean ms of frames 11..N
};

/// Parses argv. Returns false and sets `error` on a bad option or value.
bool ParseCommandLine(int argc, char* argv[], RenderOptions& options, std::string& error);

/// The --help text.
std::string Usage();
}

#endif
