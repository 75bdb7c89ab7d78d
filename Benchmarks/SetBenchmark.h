// Everything amrdm-bench measures on one AMR set, one step per knob: the path-traced reference
// and its spp curve, the shipped renderer, the samplers (nearest cell, uniform resamples), the
// element test, the gridlet size, the majorant grid, the bounce limit, and the ray marcher's
// reference, step sizes and samplers; then the set's facts and the scene for ParaView.
// Every knob is scored against the converged reference of the same integrator and timed by
// BenchLoop's runFrames; the baseline is re-timed next to each knob's other settings.
#pragma once

#include "BenchLoop.h"
#include "BenchMode.h"
#include "BenchScene.h"
#include "NearestCellMedium.h"
#include "UniformGridMedium.h"

#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace amrdm_bench
{

/// What the whole run writes: results.json (rows, curves, sets) and scenes.json.
struct Outputs
{
  std::vector<Row> rows;
  std::vector<CurvePoint> curves;
  std::vector<nlohmann::ordered_json> sets;
  std::vector<nlohmann::ordered_json> scenes; ///< for Benchmarks/paraview_volume.py
};

/// Writes OUT/results.json and OUT/scenes.json (rewritten after every set).
void writeResults(const std::string& out, const Mode& mode, const Outputs& o, double totalSeconds);

class SetBenchmark
{
public:
  SetBenchmark(const SetSpec& spec, const Mode& mode, int threads, std::string out, Outputs& o);
  /// Runs every knob; false (with a message on stderr) when the set cannot be read or converted.
  bool run();

private:
  /// A uniform resample of the field with its majorants.
  struct Uniform
  {
    std::string label;
    std::unique_ptr<UniformGrid> grid;
    amrdm::MajorantGrid majorants;
    double buildSeconds = 0.0;
  };

  bool load();
  void pathTracerReference();
  void shippedRenderer();
  bool nearestSampler();
  void uniformSamplers();
  void elementTest();
  void gridletSize();
  /// One path-tracer row of a mesh knob (`knob` names which of the two settings varies).
  void meshKnob(const std::string& knob, int gridletSize, int bvhLeafSize);
  void majorantGrid();
  void maxBounces();
  void sppRows();
  void rayMarchReference();
  void rayMarchSteps();
  void rayMarchSamplers();
  void setFacts();
  void sceneForParaView();

  void addUniform(const std::string& label, glm::ivec3 dims, bool fromDual);
  void runRayMarch(const amrdm::RenderParams& p,
    double probe,
    const char* knob,
    const std::string& label,
    bool isBase);
  /// One table row: `image` scored against `ref` (and against `baseImage` when given).
  void addRow(Row r,
    const std::vector<float>& image,
    const std::vector<float>& ref,
    const std::vector<float>* baseImage);
  /// A row of the path tracer with K frames (image of K spp).
  void addPtRow(const std::string& knob,
    const std::string& setting,
    const RunOutput& run,
    double bytes,
    double buildSeconds);
  /// The path tracer's baseline, re-timed next to `knob`'s other settings.
  void addBase(const std::string& knob, const std::string& setting, double bytes);
  void writeImages(const std::string& name,
    const amrdm::RenderParams& p,
    const std::vector<float>& image,
    bool exr = false,
    bool raw = false) const;
  glm::ivec3 fineRes(int cells) const;
  glm::ivec3 uniformDims(int n) const;

  const SetSpec spec;
  const Mode mode;
  const int threads;
  const std::string out;
  Outputs& o;
  std::chrono::steady_clock::time_point start;

  Scene scene;
  const amrdm::ElementTestParams exact; // bilinear, 10 Newton iterations
  double minSpacing = 0.0, longest = 0.0, dualBytes = 0.0;

  // Path tracer.
  amrdm::RenderParams pt; // 64 bounces, seed 0
  std::unique_ptr<DualSetup> base, refSetup;
  double ptProbeMs = 0.0, ptRefSeconds = 0.0, refNoise = kNaN;
  int refSpp = 0, K = 0;
  std::vector<float> ptRef, baseImage;
  glm::ivec3 defaultRes{ 0 };
  nlohmann::ordered_json gridlets = nlohmann::ordered_json::array();
  nlohmann::ordered_json bvhLeaves = nlohmann::ordered_json::array();

  // Other samplers.
  NearestCellField nearest;
  double nearestBuild = 0.0;
  NearestCellMedium nearestMedium;
  amrdm::MajorantGrid nearestMaj;
  std::unique_ptr<DualSetup> samplerSetup; // culling off for resampling
  std::vector<Uniform> uniforms;

  // Ray marcher.
  amrdm::RenderParams rm;
  double hBase = 0.0, rmProbe = 0.0, rmRefSeconds = 0.0;
  int rmRefSpp = 0, rmK = 0;
  std::vector<float> rmRef, rmBaseImage;
};

} // namespace amrdm_bench
