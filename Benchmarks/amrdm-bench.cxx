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
// random numbers and differ only by the knob ("rmse_vs_baseline"). SetBenchmark measures a set.
#include "SetBenchmark.h"
#include "SceneExport.h"

#include "core/ParallelFor.h"
#include "core/ParameterTable.h"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <sys/stat.h>

using namespace amrdm_bench;

namespace
{

bool exists(const std::string& path)
{
  struct stat st;
  return stat(path.c_str(), &st) == 0;
}

void makeDirectories(const std::string& dir)
{
  for (std::size_t slash = dir.find('/', 1); slash != std::string::npos;
       slash = dir.find('/', slash + 1))
    mkdir(dir.substr(0, slash).c_str(), 0755); // the parents, as mkdir -p
  mkdir(dir.c_str(), 0755);
}

/// Scene files of the benchmark's scenes (camera, lights, transfer function, mode size).
int exportScenes(const std::vector<SetSpec>& sets,
  const Mode& mode,
  int threads,
  const std::string& dir)
{
  makeDirectories(dir);
  int failed = 0;
  for (const SetSpec& s : sets)
  {
    Scene scene;
    std::string error;
    const bool ok = loadScene(s, mode.width, mode.height, threads, scene, error) &&
                    amrdm_app::ExportScene(dir + "/" + s.name + ".amrdmscene",
                      s.name + ": " + s.path + " (" + s.array + (s.logScale ? ", log10" : "") + ")",
                      scene.amr,
                      s.array,
                      -1,
                      s.logScale,
                      int(amrdm::param::GridletSize.defaultValue),
                      int(amrdm::param::BVHLeafSize.defaultValue),
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

} // namespace

int main(int argc, char* argv[])
{
  CLI::App app{ "amrdm-bench: speed against accuracy for every knob of the dual-mesh volume "
                "renderer, and its memory, on the real AMR sets (Benchmarks/run.sh runs it)" };
  bool quick = false;
  std::string out = "bench", exportDir, device = "auto";
  std::string shared = std::string(AMRDM_SOURCE_DIR) + "/../shared/amr-data";
  std::vector<std::string> only;
  std::vector<int> size;
  int threads = 0;
  app.add_flag("--quick", quick, "the smoke-test mode: 64x64, short budgets, few settings");
  app.add_option("--out", out, "output folder")->capture_default_str();
  app.add_option("--sets", only, "sets to run: enzo, flame, advection, vortex (default: all)")
    ->delimiter(',')
    ->check(CLI::IsMember({ "enzo", "flame", "advection", "vortex" }));
  app.add_option("--size", size, "image width and height (default 256 256, quick 64 64)")
    ->expected(2)
    ->check(CLI::PositiveNumber);
  app.add_option("--threads", threads, "worker threads (0: all cores)")
    ->check(CLI::NonNegativeNumber);
  app.add_option("--shared-data", shared, "folder of the large sets (the vortex set)")
    ->capture_default_str();
  app.add_option("--device", device, "the renderer timed in the \"renderer\" rows")
    ->check(CLI::IsMember({ "auto", "cpu", "cuda" }))
    ->capture_default_str();
  app.add_option("--export-scenes",
    exportDir,
    "write DIR/SET.amrdmscene per set (scene files for amrdm-devcheck) and exit");
  CLI11_PARSE(app, argc, argv);

  Mode mode = quick ? quickMode() : Mode();
  if (size.size() == 2)
  {
    mode.width = size[0];
    mode.height = size[1];
  }
  amrdm::parseRenderDevice(device, mode.device);
  std::string reason;
  if (mode.device == amrdm::RenderDevice::Cuda && !amrdm::cudaRenderingAvailable(&reason))
  {
    std::fprintf(
      stderr, "amrdm-bench: --device cuda: CUDA rendering was requested, but %s\n", reason.c_str());
    return 1;
  }

  const std::string data = std::string(AMRDM_SOURCE_DIR) + "/Testing/Data/";
  std::vector<SetSpec> all = {
    { "enzo", data + "enzo-moving7_DD0010/moving7_0010.hierarchy", "Density", true, "enzo" },
    { "flame", data + "amrex-pelelmex-flame3d_plt", "temp", false, "amrex" },
    { "advection", data + "amrex-advection-amrcore3d/plt00040", "phi", false, "amrex" },
  };
  const std::string vortex = shared + "/amrex-singlevortex3d-128/plt00040";
  if (exists(vortex))
    all.push_back({ "vortex", vortex, "phi", false, "amrex" });
  else
    std::printf("(no %s: the 6.7M-cell set is skipped)\n", vortex.c_str());
  std::vector<SetSpec> sets;
  for (const SetSpec& s : all)
    if (only.empty() || std::find(only.begin(), only.end(), s.name) != only.end())
      sets.push_back(s);

  if (!exportDir.empty())
    return exportScenes(sets, mode, threads, exportDir);
  makeDirectories(out);
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
    SetBenchmark(s, mode, threads, out, o).run();
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
