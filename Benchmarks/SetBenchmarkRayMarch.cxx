// SetBenchmark: the ray marcher (emission-absorption, the ParaView comparison): its converged
// reference, the step size and the level-adaptive step, and the other samplers under it.
#include "SetBenchmark.h"

#include <cstdio>

namespace amrdm_bench
{

void SetBenchmark::rayMarchReference()
{
  std::printf("-- ray marching: step size (emission-absorption, no shading)\n");
  this->hBase = std::max(0.5 * this->minSpacing, this->longest / 1024.0);
  this->rm = this->scene.params;
  this->rm.integrator = amrdm::IntegratorType::RayMarch;
  this->rm.stepSize = float(this->hBase);
  this->rmProbe = probeMs(this->base->medium, this->base->majorants, this->rm, 1);
  amrdm::RenderParams refParams = this->rm;
  refParams.seed = 1000;
  refParams.stepSize = float(this->hBase / 4.0);
  this->rmRefSpp =
    std::clamp(floorPow2(this->mode.rmRefBudget * 1e3 / std::max(4.0 * this->rmProbe, 1e-3)),
      this->mode.rmRefMinSpp,
      this->mode.rmRefMaxSpp);
  const auto t0 = std::chrono::steady_clock::now();
  this->rmRef =
    runFrames(this->refSetup->medium, this->refSetup->majorants, refParams, this->rmRefSpp).image;
  this->rmRefSeconds = seconds(t0);
  this->writeImages("ref-rm-" + this->spec.name, this->rm, this->rmRef, true, true);
  std::printf("ray-marched reference: step %.4g (base step %.4g / 4), %d spp in %.1f s\n",
    refParams.stepSize,
    this->hBase,
    this->rmRefSpp,
    this->rmRefSeconds);
}

// One ray-marching setting: frames by its probe time, a progressive error curve, a table row.
void SetBenchmark::runRayMarch(const amrdm::RenderParams& p,
  double probe,
  const char* knob,
  const std::string& label,
  bool isBase)
{
  const int frames = framesFor(probe, this->mode.rmFrames, this->mode.rmBudget);
  CurveRequest curve;
  curve.ref = &this->rmRef;
  curve.curve = &this->o.curves;
  curve.label.set = this->spec.name;
  curve.label.knob = knob;
  curve.label.integrator = "rm";
  curve.label.setting = label;
  const RunOutput r = runFrames(this->base->medium, this->base->majorants, p, frames, &curve);
  if (isBase)
  {
    this->rmBaseImage = r.image;
    this->rmK = frames;
    this->writeImages("rm-" + this->spec.name + "-dual", p, r.image);
  }
  Row row;
  row.knob = knob;
  row.setting = label;
  row.integrator = "rm";
  row.msPerFrame = median(r.frameMs);
  row.frames = frames;
  row.bytes = this->dualBytes;
  row.baseline = isBase;
  this->addRow(row, r.image, this->rmRef, &this->rmBaseImage);
}

void SetBenchmark::rayMarchSteps()
{
  std::vector<double> steps = this->mode.rmSteps; // the base step first: the others compare
  steps.erase(std::remove(steps.begin(), steps.end(), 1.0), steps.end());
  steps.insert(steps.begin(), 1.0);
  for (double f : steps)
  {
    amrdm::RenderParams p = this->rm;
    p.stepSize = float(this->hBase * f);
    const double probe =
      f == 1.0 ? this->rmProbe : probeMs(this->base->medium, this->base->majorants, p, 1);
    char label[64];
    std::snprintf(label, sizeof label, "%g x base (%.3g)", f, p.stepSize);
    this->runRayMarch(p, probe, "rm step", label, f == 1.0);
  }
  if (this->rmK == 0)
    this->rmK = this->mode.rmFrames;
  std::printf("-- ray marching: level-adaptive step (samples per cell, floor = base step)\n");
  for (double spc : this->mode.rmSamplesPerCell)
  {
    amrdm::RenderParams p = this->rm;
    p.samplesPerCell = float(spc);
    char label[64];
    std::snprintf(label, sizeof label, "%g per cell", spc);
    this->runRayMarch(
      p, probeMs(this->base->medium, this->base->majorants, p, 1), "rm adaptive", label, false);
  }
}

void SetBenchmark::rayMarchSamplers()
{
  std::printf("-- ray marching: sampler (base step)\n");
  const std::vector<float>* baseImg = this->rmBaseImage.empty() ? nullptr : &this->rmBaseImage;
  auto row = [&](const std::string& label, const RunOutput& r, double bytes, double buildS)
  {
    Row out;
    out.knob = "rm sampler";
    out.setting = label;
    out.integrator = "rm";
    out.msPerFrame = median(r.frameMs);
    out.frames = this->rmK;
    out.bytes = bytes;
    out.buildSeconds = buildS;
    this->addRow(out, r.image, this->rmRef, baseImg);
  };
  row("nearest finest cell",
    runFrames(this->nearestMedium, this->nearestMaj, this->rm, this->rmK),
    double(this->nearest.bytes()),
    this->nearestBuild);
  for (std::size_t i = 0; i < this->uniforms.size(); ++i)
  {
    // The ParaView-like grid and the two finest resamples (ray marching is slow: not all).
    if (i != 0 && i + 2 < this->uniforms.size())
      continue;
    const Uniform& u = this->uniforms[i];
    UniformGridMedium m;
    m.field = u.grid.get();
    m.tf = this->scene.tf.view();
    const RunOutput r = runFrames(m, u.majorants, this->rm, this->rmK);
    row(u.label, r, double(u.grid->bytes()), u.buildSeconds);
    if (i == 0)
      this->writeImages("rm-" + this->spec.name + "-pvcap", this->rm, r.image);
  }
}

} // namespace amrdm_bench
