// SetBenchmark: samplers other than the dual mesh, under the path tracer: the nearest finest
// cell, and uniform resamples (donor cell like ParaView, incl. its default cap, and from the
// dual mesh). The ray marcher reuses them (SetBenchmarkRayMarch.cxx).
#include "SetBenchmark.h"

#include "MediumMajorants.h"

#include <cstdio>

namespace amrdm_bench
{

namespace
{

std::string dimsText(const glm::ivec3& d)
{
  return std::to_string(d.x) + "x" + std::to_string(d.y) + "x" + std::to_string(d.z);
}

} // namespace

glm::ivec3 SetBenchmark::uniformDims(int n) const
{
  const glm::dvec3 ext = this->scene.hi - this->scene.lo;
  glm::ivec3 d;
  for (int a = 0; a < 3; ++a)
    d[a] = std::max(
      2, std::min(this->scene.finestDims[a], int(std::lround(n * ext[a] / this->longest))));
  return d;
}

bool SetBenchmark::nearestSampler()
{
  std::string error;
  const auto t0 = std::chrono::steady_clock::now();
  if (!convertHierarchy(this->scene, this->nearest.amr, error))
  {
    std::fprintf(stderr, "amrdm-bench: %s\n", error.c_str());
    return false;
  }
  this->nearest.init();
  this->nearestBuild = seconds(t0);
  this->nearestMedium.field = &this->nearest;
  this->nearestMedium.tf = this->scene.tf.view();
  this->nearestMaj =
    buildNearestCellMajorants(this->nearest, this->defaultRes, this->scene.tf.view());
  const RunOutput r = runFrames(this->nearestMedium, this->nearestMaj, this->pt, this->K);
  this->addPtRow(
    "sampler", "nearest finest cell", r, double(this->nearest.bytes()), this->nearestBuild);
  this->writeImages("pt-" + this->spec.name + "-nearest", this->pt, r.image);
  return true;
}

void SetBenchmark::addUniform(const std::string& label, glm::ivec3 dims, bool fromDual)
{
  if (double(dims.x) * dims.y * dims.z > 70e6)
  {
    std::printf("  (skipped %s: %s values)\n", label.c_str(), dimsText(dims).c_str());
    return;
  }
  Uniform u;
  u.label = label;
  u.grid.reset(new UniformGrid());
  const glm::vec3 lo(this->scene.lo), hi(this->scene.hi);
  const NearestCellField& nearestField = this->nearest;
  const auto t = std::chrono::steady_clock::now();
  if (fromDual)
  {
    const amrdm::DualMeshMedium& full = this->samplerSetup->medium;
    u.grid->fill(
      lo,
      hi,
      dims,
      [&](const glm::vec3& p, float& v)
      {
        amrdm::TraceCounters c;
        return full.value(p, v, c) || nearestField.value(p, v);
      },
      this->threads);
  }
  else
  {
    u.grid->fill(
      lo,
      hi,
      dims,
      [&](const glm::vec3& p, float& v) { return nearestField.value(p, v); },
      this->threads);
  }
  u.buildSeconds = seconds(t);
  u.majorants = buildUniformGridMajorants(*u.grid, this->defaultRes, this->scene.tf.view());
  this->uniforms.push_back(std::move(u));
}

void SetBenchmark::uniformSamplers()
{
  const amrdm::DualMesh& mesh = *this->scene.field->GetDualMesh();
  this->samplerSetup.reset(
    new DualSetup(mesh, this->scene.tf, this->exact, glm::ivec3(0), this->threads));
  // Every primitive: resampling must see the whole field, not only what the TF shows.
  this->samplerSetup->medium.mesh.bvh = mesh.view().bvh;
  const glm::ivec3 cap = glm::min(this->scene.finestDims, glm::ivec3(64, 128, 64));
  this->addUniform("ParaView default cap, donor " + dimsText(cap), cap, false);
  for (int n : this->mode.uniformN)
  {
    const glm::ivec3 d = this->uniformDims(n);
    this->addUniform("uniform " + dimsText(d) + ", donor", d, false);
    this->addUniform("uniform " + dimsText(d) + ", from dual", d, true);
  }
  for (std::size_t i = 0; i < this->uniforms.size(); ++i)
  {
    UniformGridMedium m;
    m.field = this->uniforms[i].grid.get();
    m.tf = this->scene.tf.view();
    const RunOutput r = runFrames(m, this->uniforms[i].majorants, this->pt, this->K);
    this->addPtRow("sampler",
      this->uniforms[i].label,
      r,
      double(this->uniforms[i].grid->bytes()),
      this->uniforms[i].buildSeconds);
    if (i == 0)
      this->writeImages("pt-" + this->spec.name + "-pvcap", this->pt, r.image);
  }
}

} // namespace amrdm_bench
