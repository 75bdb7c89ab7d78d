// The renderers on a synthetic dual mesh (kernel only, no VTK), one suite for every device:
// `TestRenderer --device cpu` (ctest TestCpuRenderer): images are bit-identical for 1 and 2
// threads, progressive passes accumulate, cancellation keeps per-pixel counts exact, depth clipping
// removes the volume behind it, every integrator runs without majorant violations.
// `TestRenderer --device cuda [amrdm-render]` (ctest TestCudaRenderer, CUDA builds): the CUDA
// renderer runs the CPU's per-sample kernel: on a device, CPU and GPU images of the same scene
// agree statistically for every integrator (independent random streams; per pixel
// |a - b| <= 4 sqrt(varA + varB) + eps on every channel for >= 99% of pixels), progressive passes,
// depth clipping and the memory report are checked. Without a device the device-free cases still
// run (device choice, amrdm-render --device) and the run then skips (exit 125) saying why; in a
// build without CUDA it skips at once and says so. Without --device every device runs in turn.
// AMRDM_PT_TIMINGS=1 / AMRDM_CUDA_TIMINGS=1 print 256^2 (CPU) / 1024^2 (CUDA) 1-spp timings per
// integrator.
// The cases: TestRendererCpu.cxx, TestRendererCuda.cxx; their shared helpers: TestRendererSuite.h.
#define DOCTEST_CONFIG_IMPLEMENT
#include <doctest/doctest.h>

#include "TestRendererSuite.h"

using namespace amrdm;
using namespace amrdm::rendertest;

namespace
{
/// Runs one device's cases: 0 passed, 125 skipped (said why), else failed.
int runDevice(const std::string& device, int argc, char** argv)
{
  std::vector<char*> args(argv, argv + argc);
  doctest::Context context(int(args.size()), args.data());
  context.addFilter("test-suite", device.c_str());
  if (device == "cuda")
  {
#ifdef AMRDM_TEST_CUDA
    gHaveDevice = cuda::deviceAvailable(&gNoDeviceReason);
    if (!gHaveDevice)
      context.addFilter("test-case-exclude", "device:*");
#else
    std::printf(
      "SKIP: CUDA cases: this build has no CUDA (configure with -DAMRDM_ENABLE_CUDA=ON)\n");
    return 125;
#endif
  }
  const int result = context.run();
  if (result != 0 || context.shouldExit())
    return result;
  if (device == "cuda" && !gHaveDevice)
  {
    std::printf("SKIP: %s (device-free cases passed)\n", gNoDeviceReason.c_str());
    return 125;
  }
  return 0;
}
} // namespace

int main(int argc, char** argv)
{
  // --device cpu|cuda (default: every device in turn), then the optional amrdm-render path, then
  // doctest's own options.
  std::vector<std::string> devices = { "cpu", "cuda" };
  std::vector<char*> args = { argv[0] };
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    if (a == "--device" && i + 1 < argc)
    {
      devices = { argv[++i] };
      if (devices[0] != "cpu" && devices[0] != "cuda")
      {
        std::fprintf(stderr, "TestRenderer: --device: expected cpu or cuda, got '%s'\n", argv[i]);
        return 2;
      }
    }
    else if (gRenderApp.empty() && !a.empty() && a[0] != '-')
      gRenderApp = a;
    else
      args.push_back(argv[i]);
  }
  int status = 0;
  for (const std::string& device : devices)
  {
    const int rc = runDevice(device, int(args.size()), args.data());
    if (rc != 0 && rc != 125)
      return rc;
    // A skipped device skips the run only when it was the one asked for.
    status = rc == 125 && devices.size() == 1 ? 125 : status;
  }
  return status;
}
