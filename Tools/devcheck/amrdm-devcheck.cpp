// amrdm-devcheck: the device check, on scene files (Kernels/io/SceneFile.h), with no VTK. Per
// scene:
// 1. the dual mesh is built from the stored hierarchy;
// 2. agreement: for every integrator, a CPU reference and the checked device each render batch
//    means with independent seeds; StatisticalImageTest.h (Welch per pixel with Sidak, plus the
//    image-wide z-test, as TestPathTracerStatistics) must accept that they estimate one image,
//    at a level that keeps the whole run's false-failure chance at --alpha (Sidak over scenes x
//    integrators); no majorant violation is allowed. Power: the same comparison is run against
//    the device rendering a 1.5x denser medium, which it must reject (a failure with
//    --require-power, as scripts/device-check.sh runs the GPU protocol; reported otherwise);
// 3. frames per second: path tracer, 1 spp, fpsSize^2, the mean of frames 11..fpsFrames (the
//    authors' protocol), capped at fpsSeconds of wall time (then over the frames rendered);
// 4. memory: the counted bytes by category next to, on CUDA, the drop of the device's free
//    memory across the upload (free before the mesh upload, free after the last frame).
// Writes a JSON summary (--json) and exits 1 on any failure. See `amrdm-devcheck --help`.
#include "BatchEstimate.h"
#include "DevCheckOptions.h"

#include "render/CpuRenderer.h"
#include "mesh/DualMeshBuilder.h"
#include "render/RendererFactory.h"
#include "io/SceneFile.h"
#include "mesh/PrepareHierarchy.h"

#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>

using nlohmann::json;

namespace
{
constexpr int kNumIntegrators = amrdm::kIntegratorCount; // every row of render/IntegratorList.h
constexpr std::uint32_t kReferenceSeed = 1000000;        // the device's seeds start at 1
constexpr double kPowerDensity = 1.5;                    // the error the comparison must see

double secondsSince(std::chrono::steady_clock::time_point t0)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

/// Free device memory from a renderer's memory report (CUDA); null on the CPU.
json deviceFree(const amrdm::Renderer& r)
{
  const std::string report = r.deviceMemoryJson();
  return report.empty() ? json() : json::parse(report).value("deviceFreeBytes", json());
}

/// One scene; returns its JSON record, with "passed".
/// `alpha` is the significance of each comparison (main() splits the run's level over them).
json checkScene(const std::string& path, const amrdm_devcheck::DevCheckOptions& opt, double alpha)
{
  using namespace amrdm;
  json out = { { "file", path }, { "passed", false } };
  std::vector<std::string> failures;
  const auto t0 = std::chrono::steady_clock::now();
  SceneDescription scene = readSceneFile(path);
  out["name"] = scene.name;
  out["readSeconds"] = secondsSince(t0);
  prepareHierarchy(scene.hierarchy); // the one pipeline (readSceneFile checked it already)
  DualMeshBuildOptions build;
  build.gridletSize = scene.gridletSize;
  build.bvhLeafSize = scene.bvhLeafSize;
  build.threads = opt.threads;
  const auto t1 = std::chrono::steady_clock::now();
  const DualMesh mesh = buildDualMesh(scene.hierarchy, build);
  const MemoryReport counted = mesh.memoryReport();
  out["buildSeconds"] = secondsSince(t1);
  out["leafCells"] = counted.leafCells;
  std::printf("%s: %s, %lld leaf cells, dual mesh %.2f MB, built in %.2f s\n",
    path.c_str(),
    scene.name.c_str(),
    (long long)counted.leafCells,
    counted.total() / 1e6,
    out["buildSeconds"].get<double>());

  std::unique_ptr<Renderer> device = createRenderer(
    opt.device, [](const std::string& line) { std::printf("amrdm-devcheck: %s\n", line.c_str()); });
  out["device"] = renderDeviceName(device->device());
  const json freeBefore = deviceFree(*device);
  device->setMesh(&mesh, scene.params.majorantResolution, opt.threads);
  device->setTransferFunction(scene.tf, opt.threads);
  CpuRenderer reference;
  reference.setMesh(&mesh, scene.params.majorantResolution, opt.threads);
  reference.setTransferFunction(scene.tf, opt.threads);

  // --- Agreement, every integrator --------------------------------------------------------
  json agreement = json::array();
  ImageEstimate pathTracerReference;
  for (int i = 0; i < kNumIntegrators; ++i)
  {
    RenderParams p = scene.params;
    p.integrator = IntegratorType(i);
    p.width = p.height = opt.compareSize;
    p.threads = opt.threads;
    const auto ref =
      amrdm_devcheck::renderBatchMeans(reference, p, kReferenceSeed, opt.batches, opt.batchSpp);
    const auto dev = amrdm_devcheck::renderBatchMeans(*device, p, 1, opt.batches, opt.batchSpp);
    const ImageVerdict v = compareImages(dev.image, ref.image, alpha);
    if (i == int(IntegratorType::PathTracer))
      pathTracerReference = ref.image;
    const bool passed = !v.rejected() && ref.majorantViolations == 0 && dev.majorantViolations == 0;
    std::printf("  %-15s %s vs cpu, %dx%d, %d spp each: %zu of %zu pixels rejected (p < %.3g), "
                "image z = %+.2f %+.2f %+.2f %+.2f, min p %.3g; %.2f s vs %.2f s -> %s\n",
      amrdm::kIntegrators[i].name,
      renderDeviceName(device->device()),
      p.width,
      p.height,
      dev.image.spp,
      v.rejectedPixels,
      v.tests / 4,
      v.pixelThreshold,
      v.imageZ[0],
      v.imageZ[1],
      v.imageZ[2],
      v.imageZ[3],
      v.minP,
      dev.seconds,
      ref.seconds,
      passed ? "agree" : "DIFFER");
    if (!passed)
      failures.push_back(std::string(amrdm::kIntegrators[i].name) + " images differ");
    agreement.push_back({ { "integrator", amrdm::kIntegrators[i].name },
      { "passed", passed },
      { "size", p.width },
      { "spp", dev.image.spp },
      { "batches", opt.batches },
      { "rejectedPixels", v.rejectedPixels },
      { "pixels", v.tests / 4 },
      { "pixelThreshold", v.pixelThreshold },
      { "minP", v.minP },
      { "imageZ", { v.imageZ[0], v.imageZ[1], v.imageZ[2], v.imageZ[3] } },
      { "rejectedChannels", v.rejectedChannels },
      { "majorantViolations",
        { { "device", dev.majorantViolations }, { "cpu", ref.majorantViolations } } },
      { "stepLimitHits", dev.stepLimitHits },
      { "deviceSeconds", dev.seconds },
      { "cpuSeconds", ref.seconds } });
  }
  out["agreement"] = agreement;

  // --- Power: the same comparison must tell a 1.5x denser medium on the device apart ---------
  {
    TransferFunction denser = scene.tf;
    denser.unitDistance /= float(kPowerDensity);
    device->setTransferFunction(denser, opt.threads);
    RenderParams p = scene.params;
    p.integrator = IntegratorType::PathTracer;
    p.width = p.height = opt.compareSize;
    p.threads = opt.threads;
    const auto biased = amrdm_devcheck::renderBatchMeans(*device, p, 1, opt.batches, opt.batchSpp);
    const ImageVerdict v = compareImages(biased.image, pathTracerReference, alpha);
    std::printf("  power: path tracer, %.1fx denser medium on %s: %zu pixels rejected, image z = "
                "%+.1f %+.1f %+.1f %+.1f -> %s\n",
      kPowerDensity,
      renderDeviceName(device->device()),
      v.rejectedPixels,
      v.imageZ[0],
      v.imageZ[1],
      v.imageZ[2],
      v.imageZ[3],
      v.rejected() ? "rejected (as it must be)" : "NOT REJECTED: too few samples to see it");
    out["power"] = { { "densityScale", kPowerDensity },
      { "rejected", v.rejected() },
      { "required", opt.requirePower },
      { "rejectedPixels", v.rejectedPixels },
      { "rejectedChannels", v.rejectedChannels },
      { "imageZ", { v.imageZ[0], v.imageZ[1], v.imageZ[2], v.imageZ[3] } } };
    if (!v.rejected() && opt.requirePower)
      failures.push_back("the comparison did not reject a 1.5x denser medium: no power at "
                         "--compare-size " +
                         std::to_string(opt.compareSize) + " with these batches");
    device->setTransferFunction(scene.tf, opt.threads);
  }

  // --- Frames per second: path tracer, 1 spp, mean of frames 11..N, capped --------------------
  RenderParams p = scene.params;
  p.integrator = IntegratorType::PathTracer;
  p.width = p.height = opt.fpsSize;
  p.samplesPerPass = 1;
  p.threads = opt.threads;
  device->reset();
  std::vector<double> ms;
  const auto fps0 = std::chrono::steady_clock::now();
  while (int(ms.size()) < opt.fpsFrames)
  {
    const auto f0 = std::chrono::steady_clock::now();
    device->renderPass(p);
    ms.push_back(1e3 * secondsSince(f0));
    if (secondsSince(fps0) > opt.fpsSeconds)
      break;
  }
  const std::size_t first = ms.size() > 10 ? 10 : 0;
  double total = 0.0;
  for (std::size_t f = first; f < ms.size(); ++f)
    total += ms[f];
  const double mean = total / double(ms.size() - first);
  const bool capped = int(ms.size()) < opt.fpsFrames;
  std::printf("  fps: %s %dx%d path tracer 1 spp, mean of frames %zu..%zu: %.2f ms, %.2f FPS%s\n",
    renderDeviceName(device->device()),
    p.width,
    p.height,
    first + 1,
    ms.size(),
    mean,
    1e3 / mean,
    capped ? " (capped by --fps-seconds)" : "");
  out["fps"] = { { "size", opt.fpsSize },
    { "firstFrame", first + 1 },
    { "lastFrame", ms.size() },
    { "requestedFrames", opt.fpsFrames },
    { "capped", capped },
    { "meanMs", mean },
    { "fps", 1e3 / mean },
    { "majorantViolations", device->stats().majorantViolations } };
  if (device->stats().majorantViolations != 0)
    failures.push_back("majorant violations in the frames-per-second run");

  // --- Memory ---------------------------------------------------------------------------------
  json memory = { { "countedMeshBytes", counted.total() },
    { "counted",
      { { "gridletScalars", counted.gridletScalars },
        { "gridletHeaders", counted.gridletHeaders },
        { "elementVertices", counted.elementVertices },
        { "elementIndices", counted.elementIndices },
        { "bvh", counted.bvh } } } };
  const std::string report = device->deviceMemoryJson();
  if (!report.empty())
  {
    const json r = json::parse(report);
    memory["device"] = r;
    memory["freeBefore"] = freeBefore;
    memory["freeAfter"] = r.value("deviceFreeBytes", json());
    if (freeBefore.is_number() && memory["freeAfter"].is_number())
      memory["measuredDrop"] =
        freeBefore.get<std::int64_t>() - memory["freeAfter"].get<std::int64_t>();
    std::printf("  gpu memory: counted %llu B (all buffers), free memory dropped by %lld B\n",
      (unsigned long long)r.value("computedTotal", 0ull),
      (long long)memory.value("measuredDrop", 0ll));
  }
  else
    memory["device"] = nullptr; // the CPU: no device memory to measure
  out["memory"] = memory;
  out["failures"] = failures;
  out["passed"] = failures.empty();
  out["seconds"] = secondsSince(t0);
  return out;
}
} // namespace

int main(int argc, char* argv[])
{
  amrdm_devcheck::DevCheckOptions opt;
  std::string error;
  if (!amrdm_devcheck::parseDevCheckOptions(argc, argv, opt, error))
  {
    std::fprintf(
      stderr, "amrdm-devcheck: %s\n%s", error.c_str(), amrdm_devcheck::devCheckUsage().c_str());
    return 1;
  }
  if (opt.help)
  {
    std::cout << amrdm_devcheck::devCheckUsage();
    return 0;
  }
  const auto t0 = std::chrono::steady_clock::now();
  json summary = { { "requestedDevice", amrdm::renderDeviceName(opt.device) },
    { "cudaBuilt", amrdm::cudaSupportBuilt() },
    { "protocol",
      { { "compareSize", opt.compareSize },
        { "batches", opt.batches },
        { "batchSpp", opt.batchSpp },
        { "alpha", opt.alpha },
        { "fpsSize", opt.fpsSize },
        { "fpsFrames", opt.fpsFrames },
        { "fpsSeconds", opt.fpsSeconds } } } };
  // --alpha is the chance that an unbiased device fails any comparison of the run: Sidak over
  // every scene and integrator.
  const double comparisonAlpha =
    amrdm::sidak(opt.alpha, double(opt.scenes.size()) * double(kNumIntegrators));
  summary["comparisonAlpha"] = comparisonAlpha;
  json scenes = json::array();
  bool passed = true;
  for (const std::string& path : opt.scenes)
  {
    try
    {
      scenes.push_back(checkScene(path, opt, comparisonAlpha));
    }
    catch (const std::exception& e)
    {
      const std::string what = e.what();
      // Scene-file errors name the file already.
      const std::string where = what.compare(0, path.size(), path) == 0 ? "" : path + ": ";
      std::fprintf(stderr, "amrdm-devcheck: %s%s\n", where.c_str(), what.c_str());
      scenes.push_back({ { "file", path }, { "passed", false }, { "failures", { e.what() } } });
    }
    passed = passed && scenes.back()["passed"].get<bool>();
  }
  summary["scenes"] = scenes;
  summary["passed"] = passed;
  summary["seconds"] = secondsSince(t0);
  if (!opt.json.empty())
  {
    std::ofstream f(opt.json);
    f << summary.dump(2) << "\n";
    if (!f)
    {
      std::fprintf(stderr, "amrdm-devcheck: cannot write %s\n", opt.json.c_str());
      return 1;
    }
  }
  std::printf("amrdm-devcheck: %zu scene(s), %s in %.1f s\n",
    opt.scenes.size(),
    passed ? "all checks passed" : "FAILED",
    summary["seconds"].get<double>());
  return passed ? 0 : 1;
}
