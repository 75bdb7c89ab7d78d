#include "RenderCommandLine.h"

#include "TransferFunctionPresets.h"

#include <cstdlib>
#include <map>
#include <sstream>

namespace amrdm_app
{

std::string Usage()
{
  std::ostringstream s;
  s << "usage: amrdm-render [FILE] [options] [-o NAME.png]\n"
       "FILE: Enzo .hierarchy, AMReX plotfile folder, or .vthb; none = the embedded demo set (Enzo, array Density).\n"
       "  -o NAME.png              write NAME.png (sRGB over the background) and NAME.exr (float RGBA)\n"
       "  --stats                  print dual-mesh counts, memory and build time as JSON\n"
       "  --array NAME             cell array (default: the first one; Density for the demo set)\n"
       "  --component N            component of a vector array (default -1: magnitude)\n"
       "  --log | --linear         log10 or linear values (default: log when the range spans > 3 decades)\n"
       "  --range LO HI            transfer-function domain (default: the field's range)\n"
       "  --tf PRESET|FILE         "
    << PresetNames()
    << " (default cool-warm), or lines 'value r g b a'\n"
       "  --max-opacity A          top of the preset opacity ramp (default 0.5)\n"
       "  --unit-distance U        opacity unit distance, world units (default: diagonal / 8)\n"
       "  --integrator NAME        pt (path tracer, default), ss (single scattering), rm (ray marching),\n"
       "                           prims (primitive debug view), cost (cost heat map)\n"
       "  --spp N                  samples per pixel (default 16; one per frame)\n"
       "  --size W H               image size (default 512 512)\n"
       "  --element-test NAME      bilinear (default) or planar\n"
       "  --newton N               Newton iterations of the bilinear test (default 10)\n"
       "  --gridlet-size G         gridlet edge in dual cells (default 8)\n"
       "  --max-bounces N          path-tracer bounces (default 64)\n"
       "  --g G                    Henyey-Greenstein anisotropy (default 0)\n"
       "  --step S                 ray-marching step, world units (default: half the finest\n"
       "                           cell, at least 1/1000 of the bounding-box diagonal)\n"
       "  --samples-per-cell N     level-adaptive ray marching: N samples per cell of the finest\n"
       "                           level in each macrocell, step >= --step (default 0: off)\n"
       "  --shade                  gradient shading for ray marching\n"
       "  --majorant-res N         majorant macrocells per axis (default: 1 per 8 finest cells, <= 128,\n"
       "                           <= 1 per 8 leaf cells)\n"
       "  --eye X Y Z --focal X Y Z --up X Y Z     camera (default: framing the data)\n"
       "  --azimuth DEG --elevation DEG --zoom Z   default-camera direction and zoom\n"
       "  --view-angle DEG | --parallel            perspective angle (default 30) or parallel projection\n"
       "  --no-jitter              camera rays through pixel centres (default: random point per sample)\n"
       "  --light X Y Z I          directional light toward (X,Y,Z) with irradiance I (repeatable)\n"
       "  --point-light X Y Z I    point light (repeatable); without lights a headlight is used\n"
       "  --no-headlight           no light unless given\n"
       "  --ambient R G B          environment radiance (default 1 1 1)\n"
       "  --background R G B       PNG background, linear RGB (default 0 0 0)\n"
       "  --device auto|cpu|cuda   where to render (default auto: CUDA when a device is present, else\n"
       "                           the CPU; auto also falls back to the CPU when the GPU runs out of memory)\n"
       "  --fps-frames N           benchmark: N frames at 1 spp (replaces --spp), prints the mean time of\n"
       "                           frames 11..N (all frames when N <= 10) and frames per second\n"
       "  --threads N              CPU threads (default: all cores)\n"
       "  --seed N                 random seed (default 0)\n";
  return s.str();
}

bool ParseCommandLine(int argc, char* argv[], RenderOptions& o, std::string& error)
{
  o.params.width = 512;
  o.params.height = 512;
  int i = 1;
  auto need = [&](int n) {
    if (i + n >= argc)
    {
      error = std::string(argv[i]) + " needs " + std::to_string(n) + " value(s)";
      return false;
    }
    return true;
  };
  auto number = [&](int k, double& out) {
    char* end = nullptr;
    out = std::strtod(argv[i + k], &end);
    if (!end || *end)
    {
      error = std::string(argv[i]) + ": '" + argv[i + k] + "' is not a number";
      return false;
    }
    return true;
  };
  auto integer = [&](int k, int lo, int hi, int& out) {
    double v;
    if (!number(k, v))
      return false;
    if (v != double(long(v)) || v < lo || v > hi)
    {
      error = std::string(argv[i]) + ": expected an integer in [" + std::to_string(lo) + ", " +
        std::to_string(hi) + "], got " + argv[i + k];
      return false;
    }
    out = int(v);
    return true;
  };
  auto vec3 = [&](double* out) {
    return need(3) && number(1, out[0]) && number(2, out[1]) && number(3, out[2]);
  };
  auto addLight = [&](amrdm::LightType type) {
    double v[4];
    if (!need(4) || !number(1, v[0]) || !number(2, v[1]) || !number(3, v[2]) || !number(4, v[3]))
      return false;
    if (o.params.numLights >= amrdm::kMaxLights)
    {
      error = "at most " + std::to_string(amrdm::kMaxLights) + " lights";
      return false;
    }
    amrdm::Light& light = o.params.lights[o.params.numLights++];
    light.type = type;
    (type == amrdm::LightType::Directional ? light.direction : light.position) =
      glm::vec3(v[0], v[1], v[2]);
    light.intensity = float(v[3]);
    return true;
  };
  const std::map<std::string, amrdm::IntegratorType> integrators = {
    { "pt", amrdm::IntegratorType::PathTracer }, { "ss", amrdm::IntegratorType::SingleScatter },
    { "rm", amrdm::IntegratorType::RayMarch }, { "prims", amrdm::IntegratorType::DebugPrimitive },
    { "cost", amrdm::IntegratorType::DebugCost }
  };
  for (; i < argc; ++i)
  {
    const std::string a = argv[i];
    double d;
    bool ok = true;
    if (a == "-h" || a == "--help")
      o.help = true;
    else if (a == "-o" && (ok = need(1)))
      o.output = argv[++i];
    else if (a == "--stats")
      o.stats = true;
    else if (a == "--array" && (ok = need(1)))
      o.array = argv[++i];
    else if (a == "--component")
      ok = need(1) && integer(1, -1, 1 << 20, o.component) && ++i;
    else if (a == "--log")
      o.logScale = 1;
    else if (a == "--linear")
      o.logScale = 0;
    else if (a == "--range")
    {
      ok = need(2) && number(1, o.range[0]) && number(2, o.range[1]);
      if (ok && !(o.range[0] < o.range[1]))
      {
        error = "--range: expected LO < HI";
        ok = false;
      }
      o.hasRange = true;
      i += 2;
    }
    else if (a == "--tf" && (ok = need(1)))
      o.tf = argv[++i];
    else if (a == "--max-opacity")
    {
      ok = need(1) && number(1, o.maxOpacity) && o.maxOpacity >= 0 && o.maxOpacity <= 1;
      if (!ok && error.empty())
        error = "--max-opacity: expected a value in [0, 1]";
      ++i;
    }
    else if (a == "--unit-distance")
    {
      ok = need(1) && number(1, o.unitDistance) && o.unitDistance > 0;
      if (!ok && error.empty())
        error = "--unit-distance: expected a positive distance";
      ++i;
    }
    else if (a == "--integrator" && (ok = need(1)))
    {
      const auto it = integrators.find(argv[++i]);
      if (it == integrators.end())
      {
        error = std::string("--integrator: unknown '") + argv[i] + "'; expected pt, ss, rm, prims or cost";
        ok = false;
      }
      else
        o.params.integrator = it->second;
    }
    else if (a == "--spp")
      ok = need(1) && integer(1, 1, 1 << 20, o.spp) && ++i;
    else if (a == "--size")
      ok = need(2) && integer(1, 1, 16384, o.params.width) &&
        integer(2, 1, 16384, o.params.height) && (i += 2);
    else if (a == "--element-test" && (ok = need(1)))
    {
      const std::string t = argv[++i];
      if (t == "bilinear")
        o.params.elementTest.test = amrdm::ElementTest::Bilinear;
      else if (t == "planar")
        o.params.elementTest.test = amrdm::ElementTest::PlanarFaces;
      else
      {
        error = "--element-test: expected bilinear or planar, got '" + t + "'";
        ok = false;
      }
    }
    else if (a == "--newton")
      ok = need(1) && integer(1, 1, 64, o.params.elementTest.maxNewtonIterations) && ++i;
    else if (a == "--gridlet-size")
      ok = need(1) && integer(1, 2, 32, o.gridletSize) && ++i;
    else if (a == "--max-bounces")
      ok = need(1) && integer(1, 0, 100000, o.params.maxBounces) && ++i;
    else if (a == "--g")
      ok = need(1) && number(1, d) && (o.params.anisotropy = float(d), ++i);
    else if (a == "--step")
    {
      ok = need(1) && number(1, d) && d > 0;
      if (!ok && error.empty())
        error = "--step: expected a positive step";
      o.params.stepSize = float(d);
      ++i;
    }
    else if (a == "--samples-per-cell")
    {
      ok = need(1) && number(1, d) && d >= 0.0 && d <= 1e6;
      if (!ok && error.empty())
        error = "--samples-per-cell: expected a number in [0, 1e6]";
      o.params.samplesPerCell = float(d);
      ++i;
    }
    else if (a == "--shade")
      o.params.gradientShading = true;
    else if (a == "--majorant-res")
    {
      int n = 0;
      ok = need(1) && integer(1, 1, 4096, n) && ++i;
      o.params.majorantResolution = glm::ivec3(n);
    }
    else if (a == "--eye")
      ok = vec3(o.eye) && (o.hasEye = true) && (i += 3);
    else if (a == "--focal")
      ok = vec3(o.focal) && (o.hasFocal = true) && (i += 3);
    else if (a == "--up")
      ok = vec3(o.up) && (i += 3);
    else if (a == "--azimuth")
      ok = need(1) && number(1, o.azimuth) && ++i;
    else if (a == "--elevation")
      ok = need(1) && number(1, o.elevation) && ++i;
    else if (a == "--zoom")
    {
      ok = need(1) && number(1, o.zoom) && o.zoom > 0;
      if (!ok && error.empty())
        error = "--zoom: expected a positive factor";
      ++i;
    }
    else if (a == "--view-angle")
    {
      ok = need(1) && number(1, d) && d > 0 && d < 180;
      if (!ok && error.empty())
        error = "--view-angle: expected degrees in (0, 180)";
      o.params.camera.viewAngle = float(d);
      ++i;
    }
    else if (a == "--parallel")
      o.params.camera.parallel = true;
    else if (a == "--no-jitter")
      o.params.pixelJitter = false;
    else if (a == "--light")
      ok = addLight(amrdm::LightType::Directional) && (i += 4);
    else if (a == "--point-light")
      ok = addLight(amrdm::LightType::Point) && (i += 4);
    else if (a == "--no-headlight")
      o.headlight = false;
    else if (a == "--ambient")
    {
      double c[3];
      ok = vec3(c) && (i += 3);
      o.params.ambient = glm::vec3(c[0], c[1], c[2]);
    }
    else if (a == "--background")
      ok = vec3(o.background) && (i += 3);
    else if (a == "--device" && (ok = need(1)))
    {
      if (!amrdm::parseRenderDevice(argv[++i], o.device))
      {
        error = std::string("--device: expected auto, cpu or cuda, got '") + argv[i] + "'";
        ok = false;
      }
    }
    else if (a == "--fps-frames")
      ok = need(1) && integer(1, 1, 1 << 20, o.fpsFrames) && ++i;
    else if (a == "--threads")
      ok = need(1) && integer(1, 0, 1024, o.params.threads) && ++i;
    else if (a == "--seed")
    {
      int seed = 0;
      ok = need(1) && integer(1, 0, 1 << 30, seed) && ++i;
      o.params.seed = std::uint32_t(seed);
    }
    else if (!a.empty() && a[0] == '-')
    {
      error = "unknown option '" + a + "' (see --help)";
      ok = false;
    }
    else if (o.file.empty())
      o.file = a;
    else
    {
      error = "more than one input file: '" + o.file + "' and '" + a + "'";
      ok = false;
    }
    if (!ok)
    {
      if (error.empty())
        error = "bad value for " + a;
      return false;
    }
  }
  if (o.fpsFrames > 0)
    o.spp = o.fpsFrames; // one sample per frame, as in every render
  return true;
}
}
