// SetBenchmark: reading the set, the path-traced reference with its spp curve, the shipped
// renderer, and the row bookkeeping every knob shares.
#include "SetBenchmark.h"

#include "AMRDualMeshImageIO.h"

#include <cmath>
#include <cstdio>
#include <fstream>

namespace amrdm_bench
{

namespace
{

std::string dimsText(const glm::ivec3& d)
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

} // namespace

SetBenchmark::SetBenchmark(const SetSpec& spec_,
  const Mode& mode_,
  int threads_,
  std::string out_,
  Outputs& o_)
  : spec(spec_)
  , mode(mode_)
  , threads(threads_)
  , out(std::move(out_))
  , o(o_)
{
}

bool SetBenchmark::run()
{
  this->start = std::chrono::steady_clock::now();
  if (!this->load())
  {
    return false;
  }
  this->pathTracerReference();
  this->shippedRenderer();
  std::printf("-- sampler (path tracer)\n");
  this->addBase("sampler", "dual mesh (exact)", this->dualBytes);
  if (!this->nearestSampler())
  {
    return false;
  }
  this->uniformSamplers();
  this->elementTest();
  this->gridletSize();
  this->majorantGrid();
  this->maxBounces();
  this->sppRows();
  this->rayMarchReference();
  this->rayMarchSteps();
  this->rayMarchSamplers();
  this->setFacts();
  this->sceneForParaView();
  std::printf("%s done in %.1f s\n", this->spec.name.c_str(), seconds(this->start));
  return true;
}

bool SetBenchmark::load()
{
  std::string error;
  std::printf("\n=== %s: %s (%s%s) ===\n",
    this->spec.name.c_str(),
    this->spec.path.c_str(),
    this->spec.array.c_str(),
    this->spec.logScale ? ", log10" : "");
  if (!loadScene(
        this->spec, this->mode.width, this->mode.height, this->threads, this->scene, error))
  {
    std::fprintf(stderr, "amrdm-bench: %s: %s\n", this->spec.name.c_str(), error.c_str());
    return false;
  }
  const glm::dvec3 s = this->scene.finestSpacing;
  this->minSpacing = std::min(s.x, std::min(s.y, s.z));
  const glm::dvec3 ext = this->scene.hi - this->scene.lo;
  this->longest = std::max(ext.x, std::max(ext.y, ext.z));
  vtkAMRDualMesh* field = this->scene.field;
  this->dualBytes = double(field->GetTotalBytes());
  std::printf("read %.2f s, dual mesh built in %.2f s: %lld leaf cells, %.2f MB, %.2f B/leaf cell; "
              "finest level %s cells over the bounds\n",
    this->scene.readSeconds,
    field->GetBuildSeconds(),
    static_cast<long long>(field->GetNumberOfLeafCells()),
    field->GetTotalBytes() / 1e6,
    field->GetBytesPerLeafCell(),
    dimsText(this->scene.finestDims).c_str());
  return true;
}

glm::ivec3 SetBenchmark::fineRes(int cells) const
{
  return glm::clamp((this->scene.finestDims + cells - 1) / cells, glm::ivec3(1), glm::ivec3(256));
}

void SetBenchmark::pathTracerReference()
{
  const amrdm::DualMesh& mesh = *this->scene.field->GetDualMesh();
  const amrdm::TransferFunction& tf = this->scene.tf;
  this->pt = this->scene.params;
  this->base.reset(new DualSetup(mesh, tf, this->exact, glm::ivec3(0), this->threads));
  this->defaultRes = this->base->majorants.res;
  this->ptProbeMs = probeMs(this->base->medium, this->base->majorants, this->pt, 2);

  this->refSetup.reset(new DualSetup(mesh, tf, this->exact, this->fineRes(4), this->threads));
  const double refProbe = probeMs(this->refSetup->medium, this->refSetup->majorants, this->pt, 2);
  this->refSpp = std::clamp(floorPow2(this->mode.ptRefBudget * 1e3 / std::max(refProbe, 1e-3)),
    this->mode.ptRefMinSpp,
    this->mode.ptRefMaxSpp);
  amrdm::RenderParams refParams = this->pt;
  refParams.seed = 1000;
  const auto t0 = std::chrono::steady_clock::now();
  this->ptRef =
    runFrames(this->refSetup->medium, this->refSetup->majorants, refParams, this->refSpp).image;
  this->ptRefSeconds = seconds(t0);
  this->writeImages("ref-pt-" + this->spec.name, this->pt, this->ptRef, true);
  std::printf("path-traced reference: %d spp in %.1f s (majorant grid %s)\n",
    this->refSpp,
    this->ptRefSeconds,
    dimsText(this->refSetup->majorants.res).c_str());

  this->K = framesFor(this->ptProbeMs, this->mode.knobFrames, this->mode.knobBudget);
  const int sppMax =
    std::clamp(floorPow2(this->mode.sppBudget * 1e3 / std::max(this->ptProbeMs, 1e-3)),
      std::max(16, this->K),
      this->mode.sppMax);
  CurveRequest curve;
  curve.ref = &this->ptRef;
  curve.curve = &this->o.curves;
  curve.label.set = this->spec.name;
  curve.label.knob = "spp";
  curve.label.setting = "dual mesh, defaults";
  curve.label.integrator = "pt";
  const std::size_t curvesBefore = this->o.curves.size();
  this->baseImage =
    runFrames(this->base->medium, this->base->majorants, this->pt, sppMax, &curve, this->K).imageAt;
  this->writeImages("pt-" + this->spec.name + "-dual", this->pt, this->baseImage);
  const std::vector<float> oneSpp =
    runFrames(this->base->medium, this->base->majorants, this->pt, 1).image;
  this->refNoise = this->o.curves.size() > curvesBefore
                     ? rmseRGB(oneSpp, this->ptRef) / std::sqrt(double(this->refSpp))
                     : kNaN;
  std::printf("spp curve: 1..%d spp (%d frames per knob setting); reference noise ~%.5f RMSE\n",
    sppMax,
    this->K,
    this->refNoise);
}

void SetBenchmark::shippedRenderer()
{
  std::printf(
    "-- renderer (path tracer, --device %s)\n", amrdm::renderDeviceName(this->mode.device));
  this->addBase("renderer", "benchmark loop (cpu)", this->dualBytes);
  std::unique_ptr<amrdm::Renderer> renderer = amrdm::createRenderer(this->mode.device,
    [](const std::string& line) { std::printf("amrdm-bench: %s\n", line.c_str()); });
  renderer->setMesh(this->scene.field->GetDualMesh(), this->pt.majorantResolution, this->threads);
  renderer->setTransferFunction(this->scene.tf, this->threads);
  amrdm::RenderParams p = this->pt;
  p.samplesPerPass = 1;
  p.threads = this->threads;
  renderer->renderPass(p); // warm-up (caches, device buffers), then the same K frames
  renderer->reset();
  std::vector<double> ms;
  for (int f = 0; f < this->K; ++f)
  {
    const auto f0 = std::chrono::steady_clock::now();
    renderer->renderPass(p);
    ms.push_back(1e3 * seconds(f0));
  }
  Row r;
  r.knob = "renderer";
  r.setting = std::string(amrdm::renderDeviceName(renderer->device())) + " renderer";
  r.integrator = "pt";
  r.msPerFrame = median(ms);
  r.frames = this->K;
  r.bytes = this->dualBytes;
  r.buildSeconds = this->scene.field->GetBuildSeconds();
  this->addRow(r, renderer->image(), this->ptRef, &this->baseImage);
}

void SetBenchmark::addRow(Row r,
  const std::vector<float>& image,
  const std::vector<float>& ref,
  const std::vector<float>* baseImg)
{
  r.set = this->spec.name;
  r.rmse = rmseRGB(image, ref);
  r.psnr = psnr(r.rmse);
  const TailErrors tail = tailErrorsRGB(image, ref);
  r.p99 = tail.p99;
  r.maxError = tail.max;
  r.rmseVsBaseline = baseImg ? rmseRGB(image, *baseImg) : kNaN;
  printRow(r);
  this->o.rows.push_back(r);
}

void SetBenchmark::addPtRow(const std::string& knob,
  const std::string& setting,
  const RunOutput& run,
  double bytes,
  double buildSeconds)
{
  Row r;
  r.knob = knob;
  r.setting = setting;
  r.integrator = "pt";
  r.msPerFrame = median(run.frameMs);
  r.frames = this->K;
  r.bytes = bytes;
  r.buildSeconds = buildSeconds;
  this->addRow(r, run.image, this->ptRef, &this->baseImage);
}

// The baseline is re-timed next to each knob's other settings (its image is the same: same
// seed, same frames), so that a change of machine load between knobs does not bias the table.
void SetBenchmark::addBase(const std::string& knob, const std::string& setting, double bytes)
{
  Row r;
  r.knob = knob;
  r.setting = setting;
  r.integrator = "pt";
  r.msPerFrame = probeMs(this->base->medium, this->base->majorants, this->pt, this->K);
  r.frames = this->K;
  r.bytes = bytes;
  r.buildSeconds = this->scene.field->GetBuildSeconds();
  r.baseline = true;
  this->addRow(r, this->baseImage, this->ptRef, &this->baseImage);
}

void SetBenchmark::writeImages(const std::string& name,
  const amrdm::RenderParams& p,
  const std::vector<float>& image,
  bool exr,
  bool raw) const
{
  const std::string path = this->out + "/" + name;
  std::string error;
  const double black[3] = { 0, 0, 0 };
  amrdm_vtk::WritePNG(path + ".png", p.width, p.height, image.data(), black, error);
  if (exr)
    amrdm_vtk::WriteEXR(path + ".exr", p.width, p.height, image.data(), error);
  if (raw)
  {
    std::ofstream f(path + ".f32", std::ios::binary);
    f.write(
      reinterpret_cast<const char*>(image.data()), std::streamsize(image.size() * sizeof(float)));
  }
}

} // namespace amrdm_bench
