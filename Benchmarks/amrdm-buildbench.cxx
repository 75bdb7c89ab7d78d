// amrdm-buildbench: the dual-mesh build alone, as the mapper runs it (vtkAMRDualMesh::Update:
// intake of the VTK arrays, then the Kernels build), on one AMR file. Per repeat it prints one
// JSON line: build and intake seconds, the build's CPU seconds (all threads; under load the
// honest measure: M leaf cells per CPU second, times 2 is the rate 2 free cores would reach),
// M leaf cells per wall second, the peak resident memory above
// the input during the build (/proc/self/clear_refs + VmHWM; every temporary included) as a
// multiple of the final mesh, the budget's estimate of that peak, and a 64-bit FNV-1a hash of
// every built array (gridlets, scalars, vertices, element indices, BVH) so that two builds of
// the same input can be compared for bit identity, and the build's phases (PhaseLog: when each
// phase ended, and the resident and peak bytes then). Not a test (Benchmarks/build_rate.py runs
// it).
//
//   amrdm-buildbench FILE ARRAY [--threads N] [--repeats R]
#include "AMRFileReader.h"

#include "mesh/DualMesh.h"
#include "vtkAMRDualMesh.h"
#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkOverlappingAMR.h"
#include "vtkSmartPointer.h"

#include <CLI/CLI.hpp>

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <sys/resource.h>
#include <iostream>
#include <string>
#include <vector>

namespace
{
std::uint64_t statusBytes(const char* key)
{
  std::ifstream f("/proc/self/status");
  std::string line;
  const std::string k = std::string(key) + ":";
  while (std::getline(f, line))
  {
    if (line.compare(0, k.size(), k) == 0)
    {
      return std::stoull(line.substr(k.size())) * 1024;
    }
  }
  return 0;
}

/// User plus system CPU seconds of the whole process so far (every thread).
double cpuSeconds()
{
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return double(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
         1e-6 * double(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

bool resetPeak()
{
  std::ofstream f("/proc/self/clear_refs");
  f << "5";
  f.flush();
  return static_cast<bool>(f);
}

/// The build's progress events (vtkAMRDualMesh forwards the Kernels build's: 0.2 work items and
/// budget, 0.4 dual-cell discovery, 0.6 stitching elements, 0.8 gridlets, 1.0 BVH): when each
/// came, seconds after Update() began, and the resident and peak bytes then.
struct PhaseLog
{
  struct Mark
  {
    double progress, seconds, rss, hwm;
  };
  std::chrono::steady_clock::time_point start;
  std::vector<Mark> marks;

  static void onProgress(vtkObject*, unsigned long, void* self, void* data)
  {
    auto* log = static_cast<PhaseLog*>(self);
    const double s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - log->start).count();
    log->marks.push_back({ *static_cast<double*>(data),
      s,
      double(statusBytes("VmRSS")),
      double(statusBytes("VmHWM")) });
  }
  /// JSON list [[progress, seconds, rss bytes, peak bytes], ...].
  std::string json() const
  {
    std::string out = "[";
    for (const Mark& m : this->marks)
    {
      char buf[128];
      std::snprintf(buf,
        sizeof buf,
        "%s[%.2f, %.4f, %.0f, %.0f]",
        out.size() > 1 ? ", " : "",
        m.progress,
        m.seconds,
        m.rss,
        m.hwm);
      out += buf;
    }
    return out + "]";
  }
};

struct Fnv
{
  std::uint64_t h = 1469598103934665603ull;
  template<typename V>
  void add(const V& v)
  {
    const auto* p = reinterpret_cast<const unsigned char*>(v.data());
    const std::size_t n = v.size() * sizeof(v[0]);
    for (std::size_t i = 0; i < n; ++i)
    {
      h = (h ^ p[i]) * 1099511628211ull;
    }
    const std::uint64_t size = n;
    for (int i = 0; i < 8; ++i)
    {
      h = (h ^ ((size >> (8 * i)) & 0xff)) * 1099511628211ull;
    }
  }
};
} // namespace

int main(int argc, char** argv)
{
  CLI::App app{ "amrdm-buildbench: dual-mesh build time, peak memory and a hash of the result" };
  std::string file, array;
  int threads = 2, repeats = 1;
  app.add_option("file", file, "AMR file (Enzo .hierarchy, AMReX plotfile, .vthb)")->required();
  app.add_option("array", array, "cell array to build on")->required();
  app.add_option("--threads", threads, "build threads");
  app.add_option("--repeats", repeats, "builds, one JSON line each");
  CLI11_PARSE(app, argc, argv);

  std::string error;
  vtkSmartPointer<vtkOverlappingAMR> amr = amrdm_app::ReadAMRFile(file, error);
  if (!amr)
  {
    std::cerr << "amrdm-buildbench: " << error << "\n";
    return 1;
  }
  for (int r = 0; r < repeats; ++r)
  {
    vtkNew<vtkAMRDualMesh> dm;
    dm->SetInputData(amr);
    dm->SetArrayName(array.c_str());
    dm->SetNumberOfThreads(threads);
    PhaseLog phases;
    vtkNew<vtkCallbackCommand> onProgress;
    onProgress->SetCallback(&PhaseLog::onProgress);
    onProgress->SetClientData(&phases);
    dm->AddObserver(vtkCommand::ProgressEvent, onProgress);
    const std::uint64_t before = statusBytes("VmRSS");
    const bool peakOk = resetPeak();
    const double cpu0 = cpuSeconds();
    phases.start = std::chrono::steady_clock::now();
    if (!dm->Update())
    {
      std::cerr << "amrdm-buildbench: the build failed\n";
      return 1;
    }
    const std::uint64_t peak = statusBytes("VmHWM");
    const double cpu = cpuSeconds() - cpu0;
    const amrdm::DualMesh& m = *dm->GetDualMesh();
    Fnv h;
    h.add(m.gridlets);
    h.add(m.gridletScalars);
    h.add(m.vertices);
    for (const auto& k : m.elementIndices)
    {
      h.add(k);
    }
    h.add(m.bvh.nodes);
    h.add(m.bvh.prims);
    const double mesh = static_cast<double>(dm->GetTotalBytes());
    const double leaf = static_cast<double>(dm->GetNumberOfLeafCells());
    std::printf("{\"file\": \"%s\", \"threads\": %d, \"leaf_cells\": %.0f, \"build_s\": %.4f, "
                "\"intake_s\": %.4f, \"cpu_s\": %.4f, \"mleaf_per_s\": %.3f, \"mleaf_per_cpu_s\": "
                "%.3f, \"mesh_bytes\": %.0f, "
                "\"peak_above_input\": %.0f, \"peak_x_mesh\": %.3f, \"hash\": \"%016llx\", "
                "\"phases\": %s}\n",
      file.c_str(),
      threads,
      leaf,
      dm->GetBuildSeconds(),
      dm->GetIntakeSeconds(),
      cpu,
      leaf / dm->GetBuildSeconds() * 1e-6,
      leaf / cpu * 1e-6,
      mesh,
      peakOk ? double(peak - before) : -1.0,
      peakOk ? double(peak - before) / mesh : -1.0,
      static_cast<unsigned long long>(h.h),
      phases.json().c_str());
    std::fflush(stdout);
  }
  return 0;
}
