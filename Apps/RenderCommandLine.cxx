#include "RenderCommandLine.h"

#include "CommandLineParser.h"
#include "CommandLineValues.h"
#include "TransferFunctionPresets.h"

#include "core/ParameterTable.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

namespace amrdm_app
{
namespace
{
using namespace cli;

/// Adds a light of `type` from X Y Z I (direction or position, intensity); refuses more than
/// amrdm::kMaxLights.
Apply light(amrdm::RenderParams& p, amrdm::LightType type)
{
  return [&p, type](const Values& v, std::string& error)
  {
    double d[4];
    if (!numbers([&](const double* x) { std::copy(x, x + 4, d); })(v, error))
      return false;
    if (p.numLights >= amrdm::kMaxLights)
    {
      error = "at most " + std::to_string(amrdm::kMaxLights) + " lights";
      return false;
    }
    amrdm::Light& l = p.lights[p.numLights++];
    l.type = type;
    (type == amrdm::LightType::Directional ? l.direction : l.position) =
      glm::vec3(d[0], d[1], d[2]);
    l.intensity = float(d[3]);
    return true;
  };
}

std::vector<Option> optionTable(RenderOptions& o)
{
  namespace param = amrdm::param;
  auto positive = [](double d) { return d > 0; };
  // The integrators by their short and long names (render/IntegratorList.h).
  static const std::map<std::string, amrdm::IntegratorType> integrators = []
  {
    std::map<std::string, amrdm::IntegratorType> m;
    for (const amrdm::IntegratorInfo& i : amrdm::kIntegrators)
    {
      m[i.shortName] = i.type;
      m[i.name] = i.type;
    }
    return m;
  }();
  static const std::string blendNames = []
  {
    std::string names;
    for (const amrdm::BlendModeInfo& b : amrdm::kBlendModes)
      names += (names.empty() ? "" : "|") + std::string(b.name);
    return names;
  }();
  static const std::string integratorNames = []
  {
    std::string names;
    for (const amrdm::IntegratorInfo& i : amrdm::kIntegrators)
    {
      names += (names.empty() ? "" : ", ") + std::string(i.shortName) + " (" + i.name + ")";
    }
    return names;
  }();
  amrdm::RenderParams& p = o.params;
  std::vector<Option> t = {
    { "-o",
      { "NAME.png" },
      "write NAME.png (sRGB over the background) and NAME.exr (float RGBA);\n"
      "NAME.exr alone; or NAME.jpg (sRGB, quality 95). Checked before rendering",
      [&](const Values& v, std::string&)
      {
        o.output = v[0];
        return true;
      } },
    { "--stats",
      {},
      "print dual-mesh counts, memory and build time as JSON",
      flag([&] { o.stats = true; }) },
    { "--list-arrays",
      {},
      "print the cell and point arrays with their ranges and exit",
      flag([&] { o.listArrays = true; }) },
    { "--export-scene",
      { "FILE" },
      "write the scene (hierarchy, transfer function, camera, lights, parameters) as a\n"
      "VTK-free scene file for amrdm-devcheck, then exit without rendering",
      [&](const Values& v, std::string&)
      {
        o.exportScene = v[0];
        return true;
      } },
    { "--array",
      { "NAME" },
      "cell or point array (default: the density, else a density-like array, else a temperature,\n"
      "else the first array whose range is not constant; said on stderr)",
      [&](const Values& v, std::string&)
      {
        o.array = v[0];
        return true;
      } },
    { "--component",
      { "N" },
      "component of a vector array (default -1: magnitude)",
      integer(-1, 1 << 20, o.component) },
    { "--log",
      {},
      "log10 values; cells <= 0 map a decade below the smallest positive value\n"
      "(default: log when the positive values span > 3 decades and at most 10 % of\n"
      "the volume is negative)",
      flag([&] { o.logScale = 1; }) },
    { "--linear", {}, "linear values", flag([&] { o.logScale = 0; }) },
    { "--range",
      { "LO", "HI" },
      "transfer-function domain (default: the volume-weighted median, i.e. the bulk, which\n"
      "stays transparent, to the 99.9th percentile of the leaf cells)",
      [&](const Values& v, std::string& error)
      {
        if (!numbers(
              [&](const double* d)
              {
                o.range[0] = d[0];
                o.range[1] = d[1];
              })(v, error))
          return false;
        if (!(o.range[0] < o.range[1]))
        {
          error = "expected LO < HI";
          return false;
        }
        o.hasRange = true;
        return true;
      } },
    { "--tf",
      { "PRESET|FILE" },
      std::string(PresetNames()) + " (default cool-warm),\nor a file of lines 'value r g b a'",
      [&](const Values& v, std::string&)
      {
        o.tf = v[0];
        return true;
      } },
    { "--max-opacity",
      { "A" },
      "top of the preset opacity ramp (default 0.5)",
      number([](double d) { return d >= 0 && d <= 1; },
        "a value in [0, 1]",
        [&](double d) { o.maxOpacity = d; }) },
    { "--opaque-bulk",
      {},
      "keep the preset ramp's opacity where values fill much of the volume (default: such\n"
      "values, e.g. the background or both sides of a front, fade so the structure shows)",
      flag([&] { o.opaqueBulk = true; }) },
    { "--unit-distance",
      { "U" },
      "opacity unit distance, world units (default: the framed bounds' diagonal / 8)",
      number(positive, "a positive distance", [&](double d) { o.unitDistance = d; }) },
    { "--exposure",
      { "STOPS" },
      "scale the image's RGB by 2^STOPS (every output; default " +
        shortNumber(kPathTracedExposure) +
        " for pt and ss,\nwhich makes them about as bright as rm, and 0 otherwise)",
      number([](double d) { return d >= -64 && d <= 64; },
        "stops in [-64, 64]",
        [&](double d)
        {
          o.exposure = d;
          o.hasExposure = true;
        }) },
    tableOption(
      param::Integrator,
      { "NAME" },
      [&](const Values& v, std::string& error)
      {
        const auto it = integrators.find(v[0]);
        if (it == integrators.end())
        {
          error = "unknown '" + v[0] + "'; expected one of " + integratorNames;
          return false;
        }
        p.integrator = it->second;
        o.hasIntegrator = true;
        return true;
      },
      integratorNames + "\n(cost: a heat map over the image's own range)",
      amrdm::kIntegrators[int(param::Integrator.defaultValue)].shortName),
    { "--spp",
      { "N" },
      "samples per pixel (default 16; one per frame)",
      integer(1, 1 << 20, o.spp) },
    { "--size",
      { "W", "H" },
      "image size (default 512 512)",
      [&](const Values& v, std::string& error)
      {
        return integer(1, 16384, p.width)({ v[0] }, error) &&
               integer(1, 16384, p.height)({ v[1] }, error);
      } },
    tableOption(
      param::ElementTest,
      { "NAME" },
      [&](const Values& v, std::string& error)
      {
        if (v[0] == "bilinear")
          p.elementTest.test = amrdm::ElementTest::Bilinear;
        else if (v[0] == "planar")
          p.elementTest.test = amrdm::ElementTest::PlanarFaces;
        else
        {
          error = "expected bilinear or planar, got '" + v[0] + "'";
          return false;
        }
        return true;
      },
      "bilinear (0) or planar (1)"),
    { "--shade", {}, "gradient shading for ray marching", flag([&] { p.gradientShading = true; }) },
    { "--blend",
      { "MODE" },
      blendNames +
        ": vtkVolumeMapper's blend modes (default composite;\n"
        "the others are drawn by ray marching, which they select unless --integrator is given)",
      [&](const Values& v, std::string& error)
      {
        for (const amrdm::BlendModeInfo& b : amrdm::kBlendModes)
          if (v[0] == b.name)
          {
            p.blendMode = b.mode;
            return true;
          }
        error = "unknown '" + v[0] + "'; expected one of " + blendNames;
        return false;
      } },
    { "--iso",
      { "V[,V...]" },
      "isosurface values of --blend iso (at most " + std::to_string(amrdm::kMaxIsoValues) +
        "; colour and opacity from the transfer function)",
      [&](const Values& v, std::string& error)
      {
        p.numIsoValues = 0;
        std::size_t start = 0;
        for (;;)
        {
          const std::size_t comma = v[0].find(',', start);
          const std::string item = v[0].substr(start, comma - start);
          double d = 0.0;
          if (!number([](double x) { return std::isfinite(x); },
                "a finite value",
                [&](double x) { d = x; })({ item }, error))
            return false;
          if (p.numIsoValues == amrdm::kMaxIsoValues)
          {
            error = "more than " + std::to_string(amrdm::kMaxIsoValues) + " values";
            return false;
          }
          p.isoValues[p.numIsoValues++] = float(d);
          if (comma == std::string::npos)
            return true;
          start = comma + 1;
        }
      } },
    tableOption(param::EmbedIsosurfaces,
      {},
      flag([&] { p.embedIsosurfaces = true; }),
      "(needs --iso; --blend composite)"),
    { "--slice",
      { "OX", "OY", "OZ", "NX", "NY", "NZ" },
      "plane of --blend slice: a point (world coordinates) and its normal",
      [&](const Values& v, std::string& error)
      {
        double x[6];
        for (int i = 0; i < 6; ++i)
          if (!number([](double d) { return std::isfinite(d); },
                "a finite number",
                [&](double d) { x[i] = d; })({ v[i] }, error))
            return false;
        if (x[3] == 0.0 && x[4] == 0.0 && x[5] == 0.0)
        {
          error = "the normal (NX NY NZ) is zero";
          return false;
        }
        for (int i = 0; i < 3; ++i)
        {
          o.sliceOrigin[i] = x[i];
          o.sliceNormal[i] = x[3 + i];
        }
        o.hasSlice = true;
        return true;
      } },
    { "--eye",
      { "X", "Y", "Z" },
      "camera position (default: framing the data)",
      numbers(
        [&](const double* d)
        {
          std::copy(d, d + 3, o.eye);
          o.hasEye = true;
        }) },
    { "--focal",
      { "X", "Y", "Z" },
      "focal point (default: the centre of the bounds)",
      numbers(
        [&](const double* d)
        {
          std::copy(d, d + 3, o.focal);
          o.hasFocal = true;
        }) },
    { "--up",
      { "X", "Y", "Z" },
      "view up (default 0 0 1)",
      numbers([&](const double* d) { std::copy(d, d + 3, o.up); }) },
    { "--azimuth",
      { "DEG" },
      "default-camera azimuth (default 35)",
      number([](double) { return true; }, "degrees", [&](double d) { o.azimuth = d; }) },
    { "--elevation",
      { "DEG" },
      "default-camera elevation (default 25)",
      number([](double) { return true; }, "degrees", [&](double d) { o.elevation = d; }) },
    { "--zoom",
      { "Z" },
      "default-camera zoom (default 1)",
      number(positive, "a positive factor", [&](double d) { o.zoom = d; }) },
    { "--view-angle",
      { "DEG" },
      "perspective view angle (default 30)",
      number([](double d) { return d > 0 && d < 180; },
        "degrees in (0, 180)",
        [&](double d) { p.camera.viewAngle = float(d); }) },
    { "--parallel", {}, "parallel projection", flag([&] { p.camera.parallel = true; }) },
    { "--no-jitter",
      {},
      "camera rays through pixel centres (default: random point per sample)",
      flag([&] { p.pixelJitter = false; }) },
    { "--light",
      { "X", "Y", "Z", "I" },
      "directional light toward (X,Y,Z) with irradiance I (repeatable)",
      light(p, amrdm::LightType::Directional) },
    { "--point-light",
      { "X", "Y", "Z", "I" },
      "point light (repeatable); without lights a key light is used",
      light(p, amrdm::LightType::Point) },
    { "--no-headlight", {}, "no light unless given", flag([&] { o.headlight = false; }) },
    { "--background",
      { "R", "G", "B" },
      "PNG/JPEG background, linear RGB (default 0 0 0)",
      numbers([&](const double* d) { std::copy(d, d + 3, o.background); }) },
    tableOption(
      param::Device,
      { "auto|cpu|cuda" },
      [&](const Values& v, std::string& error)
      {
        if (!amrdm::parseRenderDevice(v[0], o.device))
        {
          error = "expected auto, cpu or cuda, got '" + v[0] + "'";
          return false;
        }
        return true;
      },
      "auto: CUDA when a device is present, else the CPU; it also falls back to the CPU\n"
      "when the GPU runs out of memory",
      "auto"),
    { "--fps-frames",
      { "N" },
      "benchmark: N frames at 1 spp (replaces --spp), prints the mean time of frames\n"
      "11..N (all frames when N <= 10) and frames per second",
      integer(1, 1 << 20, o.fpsFrames) },
    // The table's rows with an option and a kernel field (core/ParameterTable.h).
    // BEGIN GENERATED cli-options (Tools/generate_parameters.py)
    // clang-format off
    tableOption(param::ScatteringAnisotropy, { "X" }, into(param::ScatteringAnisotropy, o.params.anisotropy)),
    tableOption(param::EnvironmentRadiance, { "R", "G", "B" }, into(param::EnvironmentRadiance, o.params.ambient)),
    tableOption(param::MaximumBounces, { "N" }, into(param::MaximumBounces, o.params.maxBounces)),
    tableOption(param::StepSize, { "X" }, into(param::StepSize, o.params.stepSize)),
    tableOption(param::SamplesPerCell, { "X" }, into(param::SamplesPerCell, o.params.samplesPerCell)),
    tableOption(param::MaxNewtonIterations, { "N" }, into(param::MaxNewtonIterations, o.params.elementTest.maxNewtonIterations)),
    tableOption(param::GridletSize, { "N" }, into(param::GridletSize, o.gridletSize)),
    tableOption(param::BVHLeafSize, { "N" }, into(param::BVHLeafSize, o.bvhLeafSize)),
    tableOption(param::MajorantResolution, { "N" }, into(param::MajorantResolution, o.params.majorantResolution)),
    tableOption(param::NumberOfThreads, { "N" }, into(param::NumberOfThreads, o.params.threads)),
    tableOption(param::Seed, { "N" }, into(param::Seed, o.params.seed)),
    // clang-format on
    // END GENERATED cli-options
    { "-h,--help", {}, "this help", flag([&] { o.help = true; }) },
  };
  return t;
}
}

std::string Usage()
{
  RenderOptions scratch;
  return cli::help(optionTable(scratch),
    "usage: amrdm-render [FILE] [options] [-o NAME.png]\n"
    "FILE: Enzo .hierarchy, AMReX plotfile folder, or .vthb; none = the embedded demo set "
    "(Enzo, array Density).\n");
}

bool ParseCommandLine(int argc, char* argv[], RenderOptions& o, std::string& error)
{
  // Removed aliases: one name per parameter in every layer (core/ParameterTable.h).
  static const char* const removed[][2] = {
    { "--ambient", amrdm::param::EnvironmentRadiance.cliOption },
    { "--g", amrdm::param::ScatteringAnisotropy.cliOption },
  };
  for (int a = 1; a < argc; ++a)
    for (const auto& r : removed)
      if (std::string(argv[a]) == r[0])
      {
        error = std::string(r[0]) + " was removed: use " + r[1] + " (the same values)";
        return false;
      }
  o.params.width = 512;
  o.params.height = 512;
  if (!cli::parse(optionTable(o), argc, argv, o.file, error))
    return false;
  if (o.fpsFrames > 0)
    o.spp = o.fpsFrames; // one sample per frame, as in every render
  return true;
}
}
