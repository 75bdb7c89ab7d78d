// The shared part of the renderer suite (TestRenderer*.cxx, one executable): the synthetic
// scene, the statistical image comparison, the command runner and the timing loop that the
// CPU cases (TestRendererCpu.cxx) and the CUDA cases (TestRendererCuda.cxx) use; main and the
// device selection are in TestRenderer.cxx.
#pragma once

#include <doctest/doctest.h>

#include "core/ParallelFor.h"
#include "mesh/DualMeshBuilder.h"
#include "render/CpuRenderer.h"
#include "render/RendererFactory.h"
#include "SyntheticAmr.h"
#ifdef AMRDM_TEST_CUDA
#include "cuda/CudaLauncher.h"
#include "cuda/CudaRenderer.h"
#endif

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <thread>

#include <sys/wait.h>

namespace amrdm::rendertest
{
inline std::string gRenderApp; ///< amrdm-render, from argv (the CUDA cases run it)
inline bool gHaveDevice = false;
inline std::string gNoDeviceReason;

inline DualMesh syntheticMesh(int levels, glm::ivec3 rootCells)
{
  amrdm_test::SyntheticOptions opt;
  opt.levels = levels;
  opt.rootCells = rootCells;
  opt.boxesPerLevel = 4;
  opt.maxBoxCells = 8;
  AmrHierarchy amr = amrdm_test::makeSynthetic(7,
    opt,
    [](const glm::dvec3& p)
    {
      return static_cast<float>(
        0.5 + 0.5 * std::sin(0.15 * p.x) * std::cos(0.2 * p.y) * std::sin(0.1 * p.z + 1.0));
    });
  amr.origin = glm::dvec3(-1.0, 2.0, 0.5);
  amr.finestSpacing = glm::dvec3(0.1, 0.1, 0.12);
  amr.validate();
  amr.finalizeCellStates();
  return buildDualMesh(amr);
}

inline TransferFunction testTf(float unitDistance)
{
  TransferFunction tf;
  tf.table = { glm::vec4(0.2f, 0.3f, 0.9f, 0.0f),
    glm::vec4(0.3f, 0.8f, 0.4f, 0.1f),
    glm::vec4(0.9f, 0.9f, 0.2f, 0.5f),
    glm::vec4(0.9f, 0.3f, 0.1f, 0.9f) };
  tf.lo = 0.2f;
  tf.hi = 1.0f;
  tf.unitDistance = unitDistance;
  return tf;
}

inline RenderParams viewOf(const DualMesh& mesh, int size)
{
  glm::vec3 lo, hi;
  mesh.gridBounds(lo, hi);
  const glm::vec3 wlo = glm::vec3(mesh.origin) + glm::vec3(mesh.finestSpacing) * lo;
  const glm::vec3 whi = glm::vec3(mesh.origin) + glm::vec3(mesh.finestSpacing) * hi;
  const glm::vec3 centre = 0.5f * (wlo + whi);
  const float radius = 0.5f * glm::length(whi - wlo);
  RenderParams p;
  p.width = p.height = size;
  p.camera.direction = glm::normalize(glm::vec3(-0.4f, -0.3f, -1.0f));
  p.camera.position = centre - p.camera.direction * (radius * 2.5f);
  p.camera.viewAngle = 30.0f;
  p.numLights = 2;
  p.lights[0].direction = glm::normalize(glm::vec3(1.0f, 1.0f, 0.5f));
  p.lights[0].intensity = 2.0f;
  p.lights[1].type = LightType::Point;
  p.lights[1].position = centre + glm::vec3(0.0f, radius, 0.0f);
  p.lights[1].intensity = radius * radius;
  p.ambient = glm::vec3(0.3f);
  p.anisotropy = 0.4f;
  return p;
}
/// Fraction of pixels whose four channels all satisfy |a - b| <= 4 sqrt(varA + varB) + eps.
inline double agreeingPixels(const std::vector<float>& a,
  const std::vector<float>& va,
  const std::vector<float>& b,
  const std::vector<float>& vb,
  double eps,
  double* worstZ)
{
  std::size_t good = 0;
  *worstZ = 0.0;
  const std::size_t pixels = a.size() / 4;
  for (std::size_t i = 0; i < pixels; ++i)
  {
    bool ok = true;
    for (int c = 0; c < 4; ++c)
    {
      const std::size_t k = 4 * i + c;
      const double d = std::fabs(double(a[k]) - double(b[k]));
      const double sigma = std::sqrt(double(va[k]) + double(vb[k]));
      ok = ok && d <= 4.0 * sigma + eps;
      if (d > eps)
        *worstZ = std::max(*worstZ, d / std::max(sigma, 1e-30));
    }
    good += ok;
  }
  return double(good) / double(pixels);
}

/// Runs a command, returns its exit status and its output (stdout and stderr).
inline int runCommand(const std::string& command, std::string& output)
{
  output.clear();
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  if (!pipe)
    return -1;
  char buffer[4096];
  while (std::fgets(buffer, sizeof(buffer), pipe))
    output += buffer;
  const int status = pclose(pipe);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

inline std::size_t countOccurrences(const std::string& text, const std::string& what)
{
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1))
    ++n;
  return n;
}

/// Prints per-integrator timings of `passes` 1-spp passes at size^2 after `warmup` passes.
template<typename R>
inline void printTimings(const char* where, int size, int warmup, int passes)
{
  const DualMesh mesh = syntheticMesh(4, glm::ivec3(16, 16, 16));
  MESSAGE("mesh: ", mesh.counts.toJson());
  const char* names[] = {
    "path tracer", "single scatter", "ray march", "debug primitive", "debug cost"
  };
  for (int integrator = 0; integrator <= 4; ++integrator)
  {
    R r;
    r.setMesh(&mesh);
    r.setTransferFunction(testTf(0.05f));
    RenderParams p = viewOf(mesh, size);
    p.integrator = static_cast<IntegratorType>(integrator);
    for (int i = 0; i < warmup; ++i)
      r.renderPass(p);
    const auto t0 = std::chrono::steady_clock::now();
    for (int i = 0; i < passes; ++i)
      r.renderPass(p);
    const double ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    const RenderStats s = r.stats();
    MESSAGE(std::string(names[integrator]),
      ": ",
      ms / passes,
      " ms per 1-spp ",
      size,
      "^2 pass on ",
      where,
      ", steps/sample ",
      double(s.steps) / double(s.samples),
      ", step-limit hits ",
      s.stepLimitHits,
      ", majorant violations ",
      s.majorantViolations);
    CHECK(s.majorantViolations == 0);
  }
}
} // namespace amrdm::rendertest
