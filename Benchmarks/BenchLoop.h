// The benchmark's timing loop: a medium (dual mesh, nearest cell, uniform grid) rendered for a
// number of 1-spp frames after one untimed warm-up, with frame times and, optionally, the error
// curve against a reference at every power of two. Every row of amrdm-bench is timed by it.
#pragma once

#include "BenchResults.h"
#include "ImageMetrics.h"
#include "ProgressiveRender.h"

#include "accel/MajorantGrid.h"
#include "mesh/DualMesh.h"
#include "render/RenderScene.h"
#include "sampling/Media.h"
#include "sampling/TransferFunction.h"

#include <algorithm>
#include <chrono>
#include <vector>

namespace amrdm_bench
{

inline double seconds(std::chrono::steady_clock::time_point t0)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

inline double median(std::vector<double> v)
{
  if (v.empty())
    return kNaN;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

inline int floorPow2(double x)
{
  int p = 1;
  while (2.0 * p <= x)
    p *= 2;
  return p;
}

inline bool isPow2(int n)
{
  return n > 0 && (n & (n - 1)) == 0;
}

/// Frames for one knob setting: `base` unless a frame is so slow that the budget would be
/// exceeded, never fewer than 5 (the median needs them).
inline int framesFor(double frameMs, int base, double budgetSeconds)
{
  const int byBudget = frameMs > 0.0 ? int(budgetSeconds * 1e3 / frameMs) : base;
  return std::max(5, std::min(base, byBudget));
}

/// The dual mesh of a scene as the kernels' medium, with its culling masks and majorant grid:
/// the renderers' own scene (render/RenderScene.h) and its medium for the path tracer.
/// Not copyable: the medium's BVH view points into the scene's culling arrays.
struct DualSetup
{
  amrdm::RenderScene scene;
  const amrdm::MajorantGrid& majorants;
  amrdm::DualMeshMedium medium;

  DualSetup(const amrdm::DualMesh& mesh,
    const amrdm::TransferFunction& tf,
    amrdm::ElementTestParams test,
    glm::ivec3 res,
    int threads)
    : majorants(scene.majorantGrid())
  {
    this->scene.setMesh(&mesh, res, threads);
    this->scene.setTransferFunction(tf, threads);
    amrdm::RenderParams params;
    params.integrator = amrdm::IntegratorType::PathTracer;
    params.elementTest = test;
    this->medium = this->scene.medium(params);
  }
  DualSetup(const DualSetup&) = delete;
  DualSetup& operator=(const DualSetup&) = delete;

  /// Bytes of the culling masks (ranges and visibility of slots and BVH nodes).
  std::uint64_t cullingBytes() const { return this->scene.primitiveCulling().bytes(); }
};

/// Frame times (ms) and images of one run.
struct RunOutput
{
  std::vector<double> frameMs;
  std::vector<float> image;
  std::vector<float> imageAt; ///< image after `keepAt` frames (when requested)
};

/// Where runFrames records its error curve: (spp, cumulative seconds, rmse vs ref) at every
/// power of two and at the end, labelled as `label`.
struct CurveRequest
{
  const std::vector<float>* ref = nullptr;
  std::vector<CurvePoint>* curve = nullptr;
  CurvePoint label;
};

/// Renders `frames` 1-spp passes after one untimed warm-up; keeps the image after `keepAt`.
template<typename Medium>
RunOutput runFrames(const Medium& medium,
  const amrdm::MajorantGrid& grid,
  amrdm::RenderParams params,
  int frames,
  const CurveRequest* curve = nullptr,
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
    if (curve && (isPow2(f) || f == frames))
    {
      CurvePoint c = curve->label;
      c.spp = f;
      c.seconds = total / 1e3;
      c.rmse = rmseRGB(render.image(), *curve->ref);
      curve->curve->push_back(c);
    }
  }
  out.image = render.image();
  return out;
}

/// Median frame time of a short probe run (frames chosen from it).
template<typename Medium>
double probeMs(const Medium& medium,
  const amrdm::MajorantGrid& grid,
  const amrdm::RenderParams& params,
  int frames)
{
  return median(runFrames(medium, grid, params, frames).frameMs);
}

} // namespace amrdm_bench
