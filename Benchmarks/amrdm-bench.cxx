// amrdm-bench: speed against accuracy for every knob of the dual-mesh volume renderer, and its
// memory, on the real AMR sets. Not a test: it only measures and writes
//   OUT/results.json   rows (one per setting of each knob), curves (error against time), sets
//   OUT/scenes.json    camera, transfer function and reference image per set, for
//                      Benchmarks/paraview_volume.py (ParaView's own AMR volume rendering)
//   OUT/*.exr, *.png   converged references (EXR, float RGBA) and small previews
//   OUT/ref-rm-SET.f32 the emission-absorption reference as raw float RGBA (for pvpython)
// Benchmarks/run.sh runs it, then ParaView, then writes docs/BENCHMARKS.md and the plots.
//
// Every knob is measured against a converged reference of the same integrator (path tracer:
// exact dual mesh, bilinear elements with 10 Newton iterations, majorant grid of 1 macrocell per
// 4 finest cells, many samples, seed 1000; ray marcher: the same field at a quarter of the base
// step, jittered, many samples). Every other run uses seed 0, so runs of one knob share their
// random numbers and differ only by the knob ("rmse_vs_baseline").
#include "AMRDualMeshImageIO.h"
#include "BenchResults.h"
#include "BenchScene.h"
#include "ImageMetrics.h"
#include "MediumMajorants.h"
#include "NearestCellMedium.h"
#include "ProgressiveRender.h"
#include "SceneExport.h"
#include "UniformGridMedium.h"

#include "mesh/DualMesh.h"
#include "sampling/FieldSampler.h"
#include "accel/MajorantGrid.h"
#include "sampling/Media.h"
#include "accel/PrimitiveCulling.h"
#include "render/RendererFactory.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <iostream>
#include <memory>
#include <sstream>
#include <sys/stat.h>

using namespace amrdm_bench;

namespace
{

struct Mode
{
  bool quick = false;
  /// The renderer timed in the "renderer" rows (the shipped CpuRenderer / CudaRenderer through
  /// the factory); every other row times the benchmark loop on the CPU.
  amrdm::RenderDevice device = amrdm::RenderDevice::Auto;
  int width = 256, height = 256;
  double ptRefBudget = 75.0; ///< seconds for the path-traced reference
  int ptRefMinSpp = 64, ptRefMaxSpp = 2048;
  double sppBudget = 45.0; ///< seconds for the progressive spp curve
  int sppMax = 1024;
  int knobFrames = 8;      ///< frames per knob setting (median time; image spp)
  double knobBudget = 8.0; ///< fewer frames (>= 5) when a frame is slower than budget/frames
  double rmRefBudget = 60.0;
  int rmRefMinSpp = 4, rmRefMaxSpp = 64;
  int rmFrames = 8;
  double rmBudget = 25.0; ///< per step size
  std::vector<int> uniformN{ 64, 128, 256 };
  std::vector<int> newton{ 1, 2, 3, 5 };
  std::vector<int> gridlets{ 2, 4, 8, 16 };
  std::vector<int> majorantCells{ 2, 4, 16, 32, 64 };
  std::vector<int> bounces{ 0, 1, 2, 4, 8, 16 };
  std::vector<double> rmSteps{ 0.5, 1, 2, 4, 8, 16 };
  /// Level-adaptive ray marching (RenderParams::samplesPerCell), step floor = the base step.
  std::vector<double> rmSamplesPerCell{ 0.5, 1, 2, 4 };
};

Mode quickMode()
{
  Mode m;
  m.quick = true;
  m.width = m.height = 64;
  m.ptRefBudget = 3.0;
  m.ptRefMinSpp = 16;
  m.ptRefMaxSpp = 256;
  m.sppBudget = 2.0;
  m.sppMax = 64;
  m.knobFrames = 5;
  m.knobBudget = 1.0;
  m.rmRefBudget = 2.0;
  m.rmRefMinSpp = 2;
  m.rmRefMaxSpp = 16;
  m.rmFrames = 5;
  m.rmBudget = 1.0;
  m.uniformN = { 64 };
  m.newton = { 1 };
  m.gridlets = { 2, 4, 8, 16 };
  m.majorantCells = { 32 };
  m.bounces = { 0, 4 };
  m.rmSteps = { 1, 4 };
  m.rmSamplesPerCell = { 1 };
  return m;
}

double seconds(std::chrono::steady_clock::time_point t0)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

double median(std::vector<double> v)
{
  if (v.empty())
    return kNaN;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

int floorPow2(double x)
{
  int p = 1;
  while (2.0 * p <= x)
    p *= 2;
  return p;
}

bool isPow2(int n)
{
  return n > 0 && (n & (n - 1)) == 0;
}

bool exists(const std::string& path)
{
  struct stat st;
  return stat(path.c_str(), &st) == 0;
}

/// The dual mesh of a scene as the kernels' medium, with its culling masks and majorant grid.
struct DualSetup
{
  amrdm::PrimitiveCulling culling;
  amrdm::MajorantGrid majorants;
  amrdm::DualMeshMedium medium;

  DualSetup(const amrdm::DualMesh& mesh,
    const amrdm::TransferFunction& tf,
    amrdm::ElementTestParams test,
    glm::ivec3 res,
    int threads)
  {
    this->culling = amrdm::buildPrimitiveRanges(mesh, threads);
    amrdm::updatePrimitiveVisibility(this->culling, tf.view(), threads);
    this->majorants = amrdm::buildMajorantRanges(mesh, res, threads);
    amrdm::updateMajorants(this->majorants, tf.view(), threads);
    this->medium.mesh = mesh.view();
    this->medium.mesh.bvh = this->culling.apply(this->medium.mesh.bvh);
    this->medium.tf = tf.view();
    this->medium.elementTest = test;
    this->medium.origin = glm::vec3(mesh.origin);
    this->medium.invSpacing = 1.0f / glm::vec3(mesh.finestSpacing);
  }
};

std::uint64_t majorantBytes(const amrdm::MajorantGrid& g)
{
  return g.bytes();
}

/// Renders `frames` 1-spp passes; returns the frame times (ms) and the image. When `curve` is
/// given, appends (spp, cumulative seconds, rmse vs ref) at every power of two and at the end.
struct RunOutput
{
  std::vector<double> frameMs;
  std::vector<float> image;
  std::vector<float> imageAt; ///< image after `keepAt` frames (when requested)
};

template<typename Medium>
RunOutput runFrames(const Medium& medium,
  const amrdm::MajorantGrid& grid,
  amrdm::RenderParams params,
  int frames,
  const std::vector<float>* ref = nullptr,
  std::vector<CurvePoint>* curve = nullptr,
  const CurvePoint* curveTemplate = nullptr,
  int keepAt = 0)
{
  RunOutput out;
  params.samplesPerPass = 1;
  const amrdm::MajorantGridView view = grid.view();
  {
    // One untimed warm-up frame (caches, page faults) in a scratch buffer: the measured run
    // below still starts at frame 0, with the same random numbers as every other run.
    ProgressiveRender warmup(params.width, params.height);
    warmup.pass(medium, view, params);
  }
  ProgressiveRender render(params.width, params.height);
  double total = 0.0;
  for (int f = 1; f <= frames; ++f)
  {
    const double ms = render.pass(medium, view, params);
    out.frameMs.push_back(ms);
    total += ms;
    if (f == keepAt)
      out.imageAt = render.image();
    if (curve && ref && (isPow2(f) || f == frames))
    {
      CurvePoint c = *curveTemplate;
      c.spp = f;
      c.seconds = total / 1e3;
      c.rmse = rmseRGB(render.image(), *ref);
      curve->push_back(c);
    }
  }
  out.image = render.image();
  return out;
}

/// Frames for one knob setting: `base` unless a frame is so slow that the budget would be
/// exceeded, never fewer than 5 (the median needs them).
int framesFor(double frameMs, int base, double budgetSeconds)
{
  const int byBudget = frameMs > 0.0 ? int(budgetSeconds * 1e3 / frameMs) : base;
  return std::max(5, std::min(base, byBudget));
}

glm::ivec3 uniformDims(const Scene& s, int n)
{
  const glm::dvec3 ext = s.hi - s.lo;
  const double longest = std::max(ext.x, std::max(ext.y, ext.z));
  glm::ivec3 d;
  for (int a = 0; a < 3; ++a)
    d[a] = std::max(2, std::min(s.finestDims[a], int(std::lround(n * ext[a] / longest))));
  return d;
}

std::string dimsLabel(const glm::ivec3& d)
{
  return std::to_string(d.x) + "x" + std::to_string(d.y) + "x" + std::to_string(d.z);
}

void printRow(const Row& r)
{
  std::printf("  %-8s %-16s %-30s %3s %9.2f ms  %3d spp  rmse %.5f  psnr %6.2f dB  vs-base %.5f  "
              "%10.0f B%s\n",
    r.set.c_str(),
    r.knob.c_str(),
    r.setting.c_str(),
    r.integrator.c_str(),
    r.msPerFrame,
    r.frames,
    r.rmse,
    r.psnr,
    r.rmseVsBaseline,
    r.bytes,
    r.baseline ? "  (baseline)" : "");
  std::fflush(stdout);
}

void writeImages(const std::string& base,
  const amrdm::RenderParams& p,
  const std::vector<float>& image,
  bool exr,
  bool raw)
{
  std::string error;
  const double black[3] = { 0, 0, 0 };
  amrdm_vtk::WritePNG(base + ".png", p.width, p.height, image.data(), black, error);
  if (exr)
    amrdm_vtk::WriteEXR(base + ".exr", p.width, p.height, image.data(), error);
  if (raw)
  {
    std::ofstream f(base + ".f32", std::ios::binary);
    f.write(
      reinterpret_cast<const char*>(image.data()), std::streamsize(image.size() * sizeof(float)));
  }
}

std::string vec3Json(const glm::dvec3& v)
{
  return "[" + jsonNumber(v.x) + ", " + jsonNumber(v.y) + ", " + jsonNumber(v.z) + "]";
}

struct Outputs
{
  std::vector<Row> rows;
  std::vector<CurvePoint> curves;
  std::vector<std::string> sets;   ///< JSON objects
  std::vector<std::string> scenes; ///< JSON objects for ParaView
};

void writeResults(const std::string& out, const Mode& mode, const Outputs& o, double totalSeconds)
{
  std::ofstream f(out + "/results.json");
  f << "{\"mode\": \"" << (mode.quick ? "quick" : "full") << "\", \"width\": " << mode.width
    << ", \"height\": " << mode.height << ", \"total_s\": " << jsonNumber(totalSeconds)
    << ",\n\"sets\": [";
  for (std::size_t i = 0; i < o.sets.size(); ++i)
    f << (i ? ",\n" : "\n") << o.sets[i];
  f << "\n],\n\"rows\": " << jsonArray(o.rows) << ",\n\"curves\": " << jsonArray(o.curves) << "}\n";
  std::ofstream s(out + "/scenes.json");
  s << "[";
  for (std::size_t i = 0; i < o.scenes.size(); ++i)
    s << (i ? ",\n" : "\n") << o.scenes[i];
  s << "\n]\n";
}

/// Everything measured on one set.
void benchSet(const SetSpec& spec,
  const Mode& mode,
  int threads,
  const std::string& out,
  Outputs& o)
{
  const auto setStart = std::chrono::steady_clock::now();
  Scene scene;
  std::string error;
  std::printf("\n=== %s: %s (%s%s) ===\n",
    spec.name.c_str(),
    spec.path.c_str(),
    spec.array.c_str(),
    spec.logScale ? ", log10" : "");
  if (!loadScene(spec, mode.width, mode.height, threads, scene, error))
  {
    std::fprintf(stderr, "amrdm-bench: %s: %s\n", spec.name.c_str(), error.c_str());
    return;
  }
  vtkAMRDualMesh* field = scene.field;
  const amrdm::DualMesh& mesh = *field->GetDualMesh();
  const amrdm::TransferFunction& tf = scene.tf;
  const amrdm::ElementTestParams exact; // bilinear, 10 Newton iterations
  const double minSpacing =
    std::min(scene.finestSpacing.x, std::min(scene.finestSpacing.y, scene.finestSpacing.z));
  const glm::dvec3 ext = scene.hi - scene.lo;
  const double longest = std::max(ext.x, std::max(ext.y, ext.z));
  std::printf("read %.2f s, dual mesh built in %.2f s: %lld leaf cells, %.2f MB, %.2f B/leaf cell; "
              "finest level %s cells over the bounds\n",
    scene.readSeconds,
    field->GetBuildSeconds(),
    (long long)field->GetNumberOfLeafCells(),
    field->GetTotalBytes() / 1e6,
    field->GetBytesPerLeafCell(),
    dimsLabel(scene.finestDims).c_str());

  // --- Path tracer: reference, baseline with its spp curve ------------------------------------
  amrdm::RenderParams pt = scene.params; // path tracer, 64 bounces, seed 0
  DualSetup base(mesh, tf, exact, glm::ivec3(0), threads);
  auto fineRes = [&](int cells)
  { return glm::clamp((scene.finestDims + cells - 1) / cells, glm::ivec3(1), glm::ivec3(256)); };
  const double probeMs = median(runFrames(base.medium, base.majorants, pt, 2).frameMs);

  DualSetup refSetup(mesh, tf, exact, fineRes(4), threads);
  const double refProbeMs = median(runFrames(refSetup.medium, refSetup.majorants, pt, 2).frameMs);
  const int refSpp = std::clamp(floorPow2(mode.ptRefBudget * 1e3 / std::max(refProbeMs, 1e-3)),
    mode.ptRefMinSpp,
    mode.ptRefMaxSpp);
  amrdm::RenderParams refParams = pt;
  refParams.seed = 1000;
  auto t0 = std::chrono::steady_clock::now();
  const std::vector<float> ptRef =
    runFrames(refSetup.medium, refSetup.majorants, refParams, refSpp).image;
  const double ptRefSeconds = seconds(t0);
  writeImages(out + "/ref-pt-" + spec.name, pt, ptRef, true, false);
  std::printf("path-traced reference: %d spp in %.1f s (majorant grid %s)\n",
    refSpp,
    ptRefSeconds,
    dimsLabel(refSetup.majorants.res).c_str());

  const int K = framesFor(probeMs, mode.knobFrames, mode.knobBudget);
  const int sppMax = std::clamp(
    floorPow2(mode.sppBudget * 1e3 / std::max(probeMs, 1e-3)), std::max(16, K), mode.sppMax);
  CurvePoint ct;
  ct.set = spec.name;
  ct.knob = "spp";
  ct.setting = "dual mesh, defaults";
  ct.integrator = "pt";
  const RunOutput baseRun =
    runFrames(base.medium, base.majorants, pt, sppMax, &ptRef, &o.curves, &ct, K);
  const std::vector<float>& baseImage = baseRun.imageAt;
  writeImages(out + "/pt-" + spec.name + "-dual", pt, baseImage, false, false);
  const double refNoise = o.curves.empty()
                            ? kNaN
                            : rmseRGB(runFrames(base.medium, base.majorants, pt, 1).image, ptRef) /
                                std::sqrt(double(refSpp));
  std::printf("spp curve: 1..%d spp (%d frames per knob setting); reference noise ~%.5f RMSE\n",
    sppMax,
    K,
    refNoise);

  auto addRow = [&](const std::string& knob,
                  const std::string& setting,
                  const std::string& integ,
                  double ms,
                  int frames,
                  const std::vector<float>& image,
                  const std::vector<float>& ref,
                  const std::vector<float>* baseImg,
                  double bytes,
                  double buildS,
                  bool isBase)
  {
    Row r;
    r.set = spec.name;
    r.knob = knob;
    r.setting = setting;
    r.integrator = integ;
    r.msPerFrame = ms;
    r.frames = frames;
    r.rmse = rmseRGB(image, ref);
    r.psnr = psnr(r.rmse);
    r.rmseVsBaseline = baseImg ? rmseRGB(image, *baseImg) : kNaN;
    r.bytes = bytes;
    r.buildSeconds = buildS;
    r.baseline = isBase;
    printRow(r);
    o.rows.push_back(r);
  };
  const double dualBytes = double(field->GetTotalBytes());
  // The baseline is re-timed next to each knob's other settings (its image is the same: same
  // seed, same frames), so that a change of machine load between knobs does not bias the table.
  auto addBase = [&](const std::string& knob, const std::string& setting, double bytes)
  {
    const double ms = median(runFrames(base.medium, base.majorants, pt, K).frameMs);
    addRow(knob,
      setting,
      "pt",
      ms,
      K,
      baseImage,
      ptRef,
      &baseImage,
      bytes,
      field->GetBuildSeconds(),
      true);
  };

  // --- The shipped renderer (RendererFactory, --device) against the benchmark loop --------------
  std::printf("-- renderer (path tracer, --device %s)\n", amrdm::renderDeviceName(mode.device));
  {
    addBase("renderer", "benchmark loop (cpu)", dualBytes);
    std::unique_ptr<amrdm::Renderer> renderer = amrdm::createRenderer(
      mode.device, [](const std::string& line) { std::printf("amrdm-bench: %s\n", line.c_str()); });
    renderer->setMesh(&mesh, pt.majorantResolution, threads);
    renderer->setTransferFunction(tf, threads);
    amrdm::RenderParams p = pt;
    p.samplesPerPass = 1;
    p.threads = threads;
    renderer->renderPass(p); // warm-up (caches, device buffers), then the same K frames
    renderer->reset();
    std::vector<double> ms;
    for (int f = 0; f < K; ++f)
    {
      const auto f0 = std::chrono::steady_clock::now();
      renderer->renderPass(p);
      ms.push_back(1e3 * seconds(f0));
    }
    addRow("renderer",
      std::string(amrdm::renderDeviceName(renderer->device())) + " renderer",
      "pt",
      median(ms),
      K,
      renderer->image(),
      ptRef,
      &baseImage,
      dualBytes,
      field->GetBuildSeconds(),
      false);
  }

  // --- Sampler ---------------------------------------------------------------------------------
  std::printf("-- sampler (path tracer)\n");
  addBase("sampler", "dual mesh (exact)", dualBytes);
  NearestCellField nearest;
  t0 = std::chrono::steady_clock::now();
  if (!convertHierarchy(scene, nearest.amr, error))
  {
    std::fprintf(stderr, "amrdm-bench: %s\n", error.c_str());
    return;
  }
  nearest.init();
  const double nearestBuild = seconds(t0);
  NearestCellMedium nearestMedium;
  nearestMedium.field = &nearest;
  nearestMedium.tf = tf.view();
  const glm::ivec3 defaultRes = base.majorants.res;
  const amrdm::MajorantGrid nearestMaj = buildNearestCellMajorants(nearest, defaultRes, tf.view());
  {
    const RunOutput r = runFrames(nearestMedium, nearestMaj, pt, K);
    addRow("sampler",
      "nearest finest cell",
      "pt",
      median(r.frameMs),
      K,
      r.image,
      ptRef,
      &baseImage,
      double(nearest.bytes()),
      nearestBuild,
      false);
    writeImages(out + "/pt-" + spec.name + "-nearest", pt, r.image, false, false);
  }
  // Uniform resamples: from the dual mesh, and donor cell like ParaView (incl. its default cap).
  struct Uniform
  {
    std::string label;
    std::unique_ptr<UniformGrid> grid;
    amrdm::MajorantGrid majorants;
    double buildSeconds = 0.0;
  };
  std::vector<Uniform> uniforms;
  const DualSetup samplerSetup(
    mesh, tf, exact, glm::ivec3(0), threads); // culling off for resampling
  amrdm::DualMeshMedium fullDual = samplerSetup.medium;
  fullDual.mesh.bvh = mesh.view().bvh; // every primitive: resampling must see the whole field
  auto donor = [&](const glm::vec3& p, float& v) { return nearest.value(p, v); };
  auto dualSource = [&](const glm::vec3& p, float& v)
  {
    amrdm::TraceCounters c;
    return fullDual.value(p, v, c) || nearest.value(p, v);
  };
  auto addUniform = [&](const std::string& label, glm::ivec3 dims, bool fromDual)
  {
    if (double(dims.x) * dims.y * dims.z > 70e6)
    {
      std::printf("  (skipped %s: %s values)\n", label.c_str(), dimsLabel(dims).c_str());
      return;
    }
    Uniform u;
    u.label = label;
    u.grid.reset(new UniformGrid());
    const auto t = std::chrono::steady_clock::now();
    if (fromDual)
      u.grid->fill(glm::vec3(scene.lo), glm::vec3(scene.hi), dims, dualSource, threads);
    else
      u.grid->fill(glm::vec3(scene.lo), glm::vec3(scene.hi), dims, donor, threads);
    u.buildSeconds = seconds(t);
    u.majorants = buildUniformGridMajorants(*u.grid, defaultRes, tf.view());
    uniforms.push_back(std::move(u));
  };
  addUniform(
    "ParaView default cap, donor " + dimsLabel(glm::min(scene.finestDims, glm::ivec3(64, 128, 64))),
    glm::min(scene.finestDims, glm::ivec3(64, 128, 64)),
    false);
  for (int n : mode.uniformN)
  {
    addUniform(
      "uniform " + dimsLabel(uniformDims(scene, n)) + ", donor", uniformDims(scene, n), false);
    addUniform(
      "uniform " + dimsLabel(uniformDims(scene, n)) + ", from dual", uniformDims(scene, n), true);
  }
  for (std::size_t i = 0; i < uniforms.size(); ++i)
  {
    UniformGridMedium m;
    m.grid = uniforms[i].grid.get();
    m.tf = tf.view();
    const RunOutput r = runFrames(m, uniforms[i].majorants, pt, K);
    addRow("sampler",
      uniforms[i].label,
      "pt",
      median(r.frameMs),
      K,
      r.image,
      ptRef,
      &baseImage,
      double(uniforms[i].grid->bytes()),
      uniforms[i].buildSeconds,
      false);
    if (i == 0)
      writeImages(out + "/pt-" + spec.name + "-pvcap", pt, r.image, false, false);
  }

  // --- Element test ------------------------------------------------------------------------------
  std::printf("-- element test (path tracer)\n");
  addBase("element test", "bilinear, 10 Newton it.", dualBytes);
  for (int it : mode.newton)
  {
    amrdm::ElementTestParams e;
    e.maxNewtonIterations = it;
    DualSetup s(mesh, tf, e, glm::ivec3(0), threads);
    const RunOutput r = runFrames(s.medium, s.majorants, pt, K);
    addRow("element test",
      "bilinear, " + std::to_string(it) + " Newton it.",
      "pt",
      median(r.frameMs),
      K,
      r.image,
      ptRef,
      &baseImage,
      dualBytes,
      kNaN,
      false);
  }
  {
    amrdm::ElementTestParams e;
    e.test = amrdm::ElementTest::PlanarFaces;
    DualSetup s(mesh, tf, e, glm::ivec3(0), threads);
    const RunOutput r = runFrames(s.medium, s.majorants, pt, K);
    addRow("element test",
      "planar faces",
      "pt",
      median(r.frameMs),
      K,
      r.image,
      ptRef,
      &baseImage,
      dualBytes,
      kNaN,
      false);
  }

  // --- Gridlet size
  // --------------------------------------------------------------------------------
  std::printf("-- gridlet size (path tracer; memory, build time)\n");
  std::string gridletJson = "[";
  for (int g : mode.gridlets)
  {
    vtkNew<vtkAMRDualMesh> f;
    f->SetInputData(scene.amr);
    f->SetArrayName(spec.array.c_str());
    f->SetLogScale(spec.logScale);
    f->SetGridletSize(g);
    f->SetNumberOfThreads(threads);
    if (!f->Update())
      continue;
    DualSetup s(*f->GetDualMesh(), tf, exact, glm::ivec3(0), threads);
    const RunOutput r = runFrames(s.medium, s.majorants, pt, K);
    addRow("gridlet size",
      std::to_string(g),
      "pt",
      median(r.frameMs),
      K,
      r.image,
      ptRef,
      &baseImage,
      double(f->GetTotalBytes()),
      f->GetBuildSeconds(),
      g == 8);
    gridletJson += std::string(gridletJson.size() > 1 ? ", " : "") +
                   "{\"gridlet_size\": " + std::to_string(g) +
                   ", \"gridlets\": " + std::to_string(f->GetNumberOfGridlets()) +
                   ", \"gridlet_scalars\": " + std::to_string(f->GetGridletScalarBytes()) +
                   ", \"gridlet_headers\": " + std::to_string(f->GetGridletHeaderBytes()) +
                   ", \"element_vertices\": " + std::to_string(f->GetElementVertexBytes()) +
                   ", \"element_indices\": " + std::to_string(f->GetElementIndexBytes()) +
                   ", \"bvh\": " + std::to_string(f->GetBVHBytes()) +
                   ", \"total\": " + std::to_string(f->GetTotalBytes()) +
                   ", \"bytes_per_leaf_cell\": " + jsonNumber(f->GetBytesPerLeafCell()) +
                   ", \"build_s\": " + jsonNumber(f->GetBuildSeconds()) + "}";
  }
  gridletJson += "]";

  // --- Majorant grid resolution
  // ----------------------------------------------------------------------
  std::printf("-- majorant grid (path tracer)\n");
  addBase(
    "majorant grid", "default " + dimsLabel(defaultRes), double(majorantBytes(base.majorants)));
  for (int cells : mode.majorantCells)
  {
    const glm::ivec3 res = fineRes(cells);
    if (res == defaultRes)
      continue;
    DualSetup s(mesh, tf, exact, res, threads);
    const RunOutput r = runFrames(s.medium, s.majorants, pt, K);
    addRow("majorant grid",
      dimsLabel(res) + " (" + std::to_string(cells) + " cells)",
      "pt",
      median(r.frameMs),
      K,
      r.image,
      ptRef,
      &baseImage,
      double(majorantBytes(s.majorants)),
      kNaN,
      false);
  }

  // --- Maximum bounces
  // -------------------------------------------------------------------------------
  std::printf("-- maximum bounces (path tracer)\n");
  addBase("max bounces", "64", dualBytes);
  for (int b : mode.bounces)
  {
    amrdm::RenderParams p = pt;
    p.maxBounces = b;
    p.rouletteStartBounce = std::min(p.rouletteStartBounce, b);
    const RunOutput r = runFrames(base.medium, base.majorants, p, K);
    addRow("max bounces",
      std::to_string(b),
      "pt",
      median(r.frameMs),
      K,
      r.image,
      ptRef,
      &baseImage,
      dualBytes,
      kNaN,
      false);
  }
  for (const CurvePoint& c : o.curves)
    if (c.set == spec.name && c.knob == "spp" && c.spp <= 1024)
    {
      Row r;
      r.set = c.set;
      r.knob = "spp";
      r.setting = std::to_string(c.spp);
      r.integrator = "pt";
      r.msPerFrame = c.seconds * 1e3;
      r.frames = c.spp;
      r.rmse = c.rmse;
      r.psnr = psnr(c.rmse);
      r.bytes = dualBytes;
      o.rows.push_back(r);
    }

  // --- Ray marching (emission-absorption, the ParaView comparison)
  // -----------------------------------
  std::printf("-- ray marching: step size (emission-absorption, no shading)\n");
  const double hBase = std::max(0.5 * minSpacing, longest / 1024.0);
  amrdm::RenderParams rm = scene.params;
  rm.integrator = amrdm::IntegratorType::RayMarch;
  rm.stepSize = float(hBase);
  const double rmProbe = median(runFrames(base.medium, base.majorants, rm, 1).frameMs);
  amrdm::RenderParams rmRefParams = rm;
  rmRefParams.seed = 1000;
  rmRefParams.stepSize = float(hBase / 4.0);
  const int rmRefSpp = std::clamp(floorPow2(mode.rmRefBudget * 1e3 / std::max(4.0 * rmProbe, 1e-3)),
    mode.rmRefMinSpp,
    mode.rmRefMaxSpp);
  t0 = std::chrono::steady_clock::now();
  const std::vector<float> rmRef =
    runFrames(refSetup.medium, refSetup.majorants, rmRefParams, rmRefSpp).image;
  const double rmRefSeconds = seconds(t0);
  writeImages(out + "/ref-rm-" + spec.name, rm, rmRef, true, true);
  std::printf("ray-marched reference: step %.4g (base step %.4g / 4), %d spp in %.1f s\n",
    rmRefParams.stepSize,
    hBase,
    rmRefSpp,
    rmRefSeconds);
  std::vector<float> rmBaseImage;
  int rmK = 0;
  // One ray-marching setting: frames by its probe time, a progressive error curve, a table row.
  auto runRm = [&](const amrdm::RenderParams& p,
                 double probe,
                 const char* knob,
                 const std::string& label,
                 bool isBase)
  {
    const int frames = framesFor(probe, mode.rmFrames, mode.rmBudget);
    CurvePoint c;
    c.set = spec.name;
    c.knob = knob;
    c.integrator = "rm";
    c.setting = label;
    const RunOutput r = runFrames(base.medium, base.majorants, p, frames, &rmRef, &o.curves, &c);
    if (isBase)
    {
      rmBaseImage = r.image;
      rmK = frames;
      writeImages(out + "/rm-" + spec.name + "-dual", p, r.image, false, false);
    }
    addRow(knob,
      label,
      "rm",
      median(r.frameMs),
      frames,
      r.image,
      rmRef,
      &rmBaseImage,
      dualBytes,
      kNaN,
      isBase);
  };
  std::vector<double> steps = mode.rmSteps; // the base step first: the others compare with it
  steps.erase(std::remove(steps.begin(), steps.end(), 1.0), steps.end());
  steps.insert(steps.begin(), 1.0);
  for (double f : steps)
  {
    amrdm::RenderParams p = rm;
    p.stepSize = float(hBase * f);
    const double probe =
      f == 1.0 ? rmProbe : median(runFrames(base.medium, base.majorants, p, 1).frameMs);
    char label[64];
    std::snprintf(label, sizeof label, "%g x base (%.3g)", f, p.stepSize);
    runRm(p, probe, "rm step", label, f == 1.0);
  }
  if (rmK == 0)
    rmK = mode.rmFrames;
  std::printf("-- ray marching: level-adaptive step (samples per cell, floor = base step)\n");
  for (double spc : mode.rmSamplesPerCell)
  {
    amrdm::RenderParams p = rm;
    p.samplesPerCell = float(spc);
    char label[64];
    std::snprintf(label, sizeof label, "%g per cell", spc);
    runRm(
      p, median(runFrames(base.medium, base.majorants, p, 1).frameMs), "rm adaptive", label, false);
  }

  std::printf("-- ray marching: sampler (base step)\n");
  {
    const RunOutput r = runFrames(nearestMedium, nearestMaj, rm, rmK);
    addRow("rm sampler",
      "nearest finest cell",
      "rm",
      median(r.frameMs),
      rmK,
      r.image,
      rmRef,
      rmBaseImage.empty() ? nullptr : &rmBaseImage,
      double(nearest.bytes()),
      nearestBuild,
      false);
  }
  for (std::size_t i = 0; i < uniforms.size(); ++i)
  {
    // The ParaView-like grid and the two finest resamples (ray marching is slow: not all).
    if (i != 0 && i + 2 < uniforms.size())
      continue;
    UniformGridMedium m;
    m.grid = uniforms[i].grid.get();
    m.tf = tf.view();
    const RunOutput r = runFrames(m, uniforms[i].majorants, rm, rmK);
    addRow("rm sampler",
      uniforms[i].label,
      "rm",
      median(r.frameMs),
      rmK,
      r.image,
      rmRef,
      rmBaseImage.empty() ? nullptr : &rmBaseImage,
      double(uniforms[i].grid->bytes()),
      uniforms[i].buildSeconds,
      false);
    if (i == 0)
      writeImages(out + "/rm-" + spec.name + "-pvcap", rm, r.image, false, false);
  }

  // --- Per-set facts, and the scene for ParaView
  // ----------------------------------------------------
  std::ostringstream js;
  js << "{\"name\": " << jsonString(spec.name) << ", \"path\": " << jsonString(spec.path)
     << ", \"array\": " << jsonString(spec.array)
     << ", \"log_scale\": " << (spec.logScale ? "true" : "false")
     << ", \"read_s\": " << jsonNumber(scene.readSeconds) << ", \"finest_dims\": ["
     << scene.finestDims.x << ", " << scene.finestDims.y << ", " << scene.finestDims.z << "]"
     << ", \"levels\": " << scene.amr->GetNumberOfLevels()
     << ", \"dual_mesh\": " << field->GetReportJSON()
     << ", \"perfect_cubes\": " << field->GetNumberOfPerfectCubes() << ", \"elements\": "
     << (field->GetNumberOfTets() + field->GetNumberOfPyramids() + field->GetNumberOfWedges() +
          field->GetNumberOfHexes())
     << ", \"majorant_default\": [" << defaultRes.x << ", " << defaultRes.y << ", " << defaultRes.z
     << "]"
     << ", \"majorant_bytes\": " << majorantBytes(base.majorants) << ", \"culling_bytes\": "
     << (base.culling.slotRange.size() * 8 + base.culling.nodeRange.size() * 8 +
          base.culling.slotVisible.size() + base.culling.nodeVisible.size())
     << ", \"nearest_bytes\": " << nearest.bytes() << ", \"gridlets\": " << gridletJson
     << ", \"pt_ref_spp\": " << refSpp << ", \"pt_ref_s\": " << jsonNumber(ptRefSeconds)
     << ", \"pt_ref_noise\": " << jsonNumber(refNoise) << ", \"pt_frames\": " << K
     << ", \"rm_base_step\": " << jsonNumber(hBase)
     << ", \"rm_ref_step\": " << jsonNumber(hBase / 4.0) << ", \"rm_ref_spp\": " << rmRefSpp
     << ", \"rm_ref_s\": " << jsonNumber(rmRefSeconds)
     << ", \"set_s\": " << jsonNumber(seconds(setStart)) << "}";
  o.sets.push_back(js.str());

  std::ostringstream sc;
  const amrdm::CameraParams& cam = scene.params.camera;
  sc << "{\"name\": " << jsonString(spec.name) << ", \"path\": " << jsonString(spec.path)
     << ", \"reader\": " << jsonString(spec.reader) << ", \"array\": " << jsonString(spec.array)
     << ", \"log_scale\": " << (spec.logScale ? "true" : "false") << ", \"width\": " << mode.width
     << ", \"height\": " << mode.height
     << ", \"camera\": {\"position\": " << vec3Json(glm::dvec3(cam.position) + scene.sceneOrigin)
     << ", \"focal_point\": " << vec3Json(glm::dvec3(scene.focalPoint) + scene.sceneOrigin)
     << ", \"view_up\": " << vec3Json(cam.up) << ", \"view_angle\": " << jsonNumber(cam.viewAngle)
     << "}"
     << ", \"tf\": {\"lo\": " << jsonNumber(tf.lo) << ", \"hi\": " << jsonNumber(tf.hi)
     << ", \"unit_distance\": " << jsonNumber(tf.unitDistance) << ", \"table\": [";
  for (std::size_t i = 0; i < tf.table.size(); ++i)
    sc << (i ? ", " : "") << "[" << jsonNumber(tf.table[i].r) << ", " << jsonNumber(tf.table[i].g)
       << ", " << jsonNumber(tf.table[i].b) << ", " << jsonNumber(tf.table[i].a) << "]";
  sc << "]}, \"finest_dims\": [" << scene.finestDims.x << ", " << scene.finestDims.y << ", "
     << scene.finestDims.z
     << "], \"reference\": " << jsonString(out + "/ref-rm-" + spec.name + ".f32") << "}";
  o.scenes.push_back(sc.str());
  std::printf("%s done in %.1f s\n", spec.name.c_str(), seconds(setStart));
}

int usage(const char* message)
{
  if (message)
    std::fprintf(stderr, "amrdm-bench: %s\n", message);
  std::fprintf(stderr,
    "usage: amrdm-bench [--quick] [--out DIR] [--sets NAME,...] [--size W H] [--threads N]\n"
    "                   [--shared-data DIR] [--device auto|cpu|cuda] [--export-scenes DIR]\n"
    "  --device: the renderer timed in the \"renderer\" rows (default auto)\n"
    "  --export-scenes DIR: write DIR/SET.amrdmscene per set (scene files for amrdm-devcheck)\n"
    "  and exit without benchmarking\n"
    "  sets: enzo, flame, advection, vortex (vortex only when DIR/amrex-singlevortex3d-128 "
    "exists;\n"
    "  DIR defaults to ../shared/amr-data next to the source tree)\n");
  return message ? 1 : 0;
}

} // namespace

int main(int argc, char* argv[])
{
  Mode mode;
  std::string out = "bench";
  std::string only;
  std::string shared = std::string(AMRDM_SOURCE_DIR) + "/../shared/amr-data";
  int threads = 0, width = 0, height = 0;
  std::string exportDir;
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    if (a == "--device")
    {
      if (i + 1 >= argc || !amrdm::parseRenderDevice(argv[i + 1], mode.device))
        return usage("--device expects auto, cpu or cuda");
      ++i;
    }
    else if (a == "--export-scenes" && i + 1 < argc)
      exportDir = argv[++i];
    else if (a == "--quick")
    {
      const Mode q = quickMode();
      mode = q;
    }
    else if (a == "--out" && i + 1 < argc)
      out = argv[++i];
    else if (a == "--sets" && i + 1 < argc)
      only = std::string(",") + argv[++i] + ",";
    else if (a == "--shared-data" && i + 1 < argc)
      shared = argv[++i];
    else if (a == "--threads" && i + 1 < argc)
      threads = std::atoi(argv[++i]);
    else if (a == "--size" && i + 2 < argc)
    {
      width = std::atoi(argv[++i]);
      height = std::atoi(argv[++i]);
    }
    else if (a == "--help" || a == "-h")
      return usage(nullptr);
    else
      return usage(("unknown option " + a).c_str());
  }
  if (width > 0 && height > 0)
  {
    mode.width = width;
    mode.height = height;
  }
  std::string reason;
  if (mode.device == amrdm::RenderDevice::Cuda && !amrdm::cudaRenderingAvailable(&reason))
    return usage(("--device cuda: CUDA rendering was requested, but " + reason).c_str());

  const std::string data = std::string(AMRDM_SOURCE_DIR) + "/Testing/Data/";
  std::vector<SetSpec> sets = {
    { "enzo", data + "enzo-moving7_DD0010/moving7_0010.hierarchy", "Density", true, "enzo" },
    { "flame", data + "amrex-pelelmex-flame3d_plt", "temp", false, "amrex" },
    { "advection", data + "amrex-advection-amrcore3d/plt00040", "phi", false, "amrex" },
  };
  const std::string vortex = shared + "/amrex-singlevortex3d-128/plt00040";
  if (exists(vortex))
    sets.push_back({ "vortex", vortex, "phi", false, "amrex" });
  else
    std::printf("(no %s: the 6.7M-cell set is skipped)\n", vortex.c_str());

  if (!exportDir.empty())
  {
    // Scene files of the benchmark's scenes (camera, lights, transfer function, mode size).
    for (std::size_t slash = exportDir.find('/', 1); slash != std::string::npos;
         slash = exportDir.find('/', slash + 1))
      mkdir(exportDir.substr(0, slash).c_str(), 0755); // the parents, as mkdir -p
    mkdir(exportDir.c_str(), 0755);
    int failed = 0;
    for (const SetSpec& s : sets)
    {
      if (!only.empty() && only.find("," + s.name + ",") == std::string::npos)
        continue;
      Scene scene;
      std::string error;
      const bool ok =
        loadScene(s, mode.width, mode.height, threads, scene, error) &&
        amrdm_app::ExportScene(exportDir + "/" + s.name + ".amrdmscene",
          s.name + ": " + s.path + " (" + s.array + (s.logScale ? ", log10" : "") + ")",
          scene.amr,
          s.array,
          -1,
          s.logScale,
          8,
          scene.params,
          scene.tf,
          error);
      if (!ok)
      {
        std::fprintf(stderr, "amrdm-bench: %s: %s\n", s.name.c_str(), error.c_str());
        ++failed;
      }
    }
    return failed ? 1 : 0;
  }
  mkdir(out.c_str(), 0755);
  std::printf("amrdm-bench (%s mode): %dx%d, %d threads, output in %s\n",
    mode.quick ? "quick" : "full",
    mode.width,
    mode.height,
    amrdm::resolveThreadCount(threads),
    out.c_str());
  const auto start = std::chrono::steady_clock::now();
  Outputs o;
  for (const SetSpec& s : sets)
  {
    if (!only.empty() && only.find("," + s.name + ",") == std::string::npos)
      continue;
    benchSet(s, mode, threads, out, o);
    writeResults(out, mode, o, seconds(start));
  }
  writeResults(out, mode, o, seconds(start));
  std::printf("\namrdm-bench: %zu rows, %zu curve points in %.1f s; wrote %s/results.json\n",
    o.rows.size(),
    o.curves.size(),
    seconds(start),
    out.c_str());
  return 0;
}
