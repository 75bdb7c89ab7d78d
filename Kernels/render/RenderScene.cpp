// The host scene of every renderer. See RenderScene.h.
#include "render/RenderScene.h"

#include "accel/CompositeMajorantGrid.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace amrdm
{

namespace
{
/// The mesh's BVH by reference (an empty one without a mesh): the culling's node masks follow it.
const Bvh& meshBvh(const DualMesh* mesh)
{
  static const Bvh none;
  return mesh ? mesh->bvh : none;
}
} // namespace

double autoStepSize(const DualMesh& mesh, const TransferFunction* tf)
{
  glm::dvec3 lo(mesh.domainLower), hi(mesh.domainUpper);
  if (!glm::all(glm::lessThan(lo, hi)))
  {
    glm::vec3 flo, fhi; // a mesh built without a domain box: what can be sampled
    mesh.gridBounds(flo, fhi);
    lo = glm::dvec3(flo);
    hi = glm::dvec3(fhi);
  }
  const glm::dvec3 h = glm::abs(mesh.finestSpacing);
  const double diagonal = glm::length((hi - lo) * h);
  const double floor =
    std::max(0.5 * std::min(h.x, std::min(h.y, h.z)), kAutoStepDiagonalFraction * diagonal);
  if (!tf || tf->table.empty())
  {
    return floor;
  }
  const double ceiling = std::max(floor, kAutoStepMaxDiagonalFraction * diagonal);
  double alpha = 0.0;
  for (const glm::vec4& c : tf->table)
  {
    alpha = std::max(alpha, double(c.w));
  }
  alpha = std::min(alpha, double(kMaxTableOpacity));
  if (!(alpha > 0.0) || !(tf->unitDistance > 0.0f))
  {
    return ceiling; // transparent: nothing to composite, the step only finds colour
  }
  const double step = double(tf->unitDistance) * std::log1p(-kAutoStepOpacity) / std::log1p(-alpha);
  return std::clamp(step, floor, ceiling);
}

RenderParams resolveRenderParams(const RenderParams& userParams,
  const DualMesh& mesh,
  const TransferFunction* tf)
{
  RenderParams params = userParams;
  const glm::vec3 spacing(mesh.finestSpacing);
  if (!(params.stepSize > 0.0f))
  {
    params.stepSize =
      float(autoStepSize(mesh, params.blendMode == BlendMode::Composite ? tf : nullptr));
  }
  for (int a = 0; a < 3; ++a)
  {
    if (!(params.gradientDelta[a] > 0.0f))
    {
      params.gradientDelta[a] = 0.5f * spacing[a];
    }
  }
  params.samplesPerPass = std::max(1, params.samplesPerPass);
  return params;
}

void RenderScene::setMesh(const DualMesh* mesh, glm::ivec3 majorantResolution, int threads)
{
  if (mesh)
  {
    mesh->validate(); // before anything is built from it (the scene keeps its old mesh)
  }
  this->Mesh = mesh;
  this->Resolution = majorantResolution;
  this->Majorants = mesh ? buildMajorantRanges(*mesh, majorantResolution, threads) : MajorantGrid();
  this->Culling = mesh ? buildPrimitiveRanges(*mesh, threads) : PrimitiveCulling();
  if (this->HasTf)
  {
    updateMajorants(this->Majorants, this->Tf.view(), threads);
    updatePrimitiveVisibility(this->Culling, meshBvh(mesh), this->Tf.view(), threads);
  }
  this->updateComposite(threads);
}

void RenderScene::setTransferFunction(const TransferFunction& tf, int threads)
{
  this->Tf = tf;
  this->HasTf = true;
  updateMajorants(this->Majorants, this->Tf.view(), threads);
  updatePrimitiveVisibility(this->Culling, meshBvh(this->Mesh), this->Tf.view(), threads);
  if (!this->Composite.range.empty())
  {
    updateMajorants(this->Composite, this->Tf.view(), threads);
  }
}

void RenderScene::setProxy(const DualMesh* proxy,
  const glm::vec3& lo,
  const glm::vec3& hi,
  int threads)
{
  if (proxy && !glm::all(glm::lessThan(lo, hi)))
  {
    throw std::invalid_argument("setProxy: the region's box is empty; expected lo < hi on every "
                                "axis");
  }
  if (proxy)
  {
    proxy->validate();
  }
  this->Proxy = proxy;
  this->ProxyLo = lo;
  this->ProxyHi = hi;
  this->updateComposite(threads);
}

bool RenderScene::updateMajorantResolution(const RenderParams& params)
{
  if (!this->Mesh || params.majorantResolution == this->Resolution)
  {
    return false;
  }
  this->Resolution = params.majorantResolution;
  this->Majorants = buildMajorantRanges(*this->Mesh, this->Resolution, params.threads);
  if (this->HasTf)
  {
    updateMajorants(this->Majorants, this->Tf.view(), params.threads);
  }
  this->updateComposite(params.threads);
  return true;
}

void RenderScene::updateComposite(int threads)
{
  this->Composite = MajorantGrid();
  if (!this->Proxy || !this->Mesh || this->Majorants.range.empty())
  {
    return;
  }
  glm::vec3 glo, ghi;
  this->Proxy->gridBounds(glo, ghi);
  const glm::vec3 w0(this->Proxy->origin + this->Proxy->finestSpacing * glm::dvec3(glo));
  const glm::vec3 w1(this->Proxy->origin + this->Proxy->finestSpacing * glm::dvec3(ghi));
  const MajorantGrid outer = buildMajorantRanges(*this->Proxy,
    compositeMajorantResolution(this->Majorants, glm::min(w0, w1), glm::max(w0, w1)),
    threads);
  this->Composite = compositeMajorantRanges(outer, this->Majorants, this->ProxyLo, this->ProxyHi);
  if (this->HasTf)
  {
    updateMajorants(this->Composite, this->Tf.view(), threads);
  }
}

RenderParams RenderScene::resolve(const RenderParams& userParams) const
{
  return resolveRenderParams(userParams, *this->Mesh, this->HasTf ? &this->Tf : nullptr);
}

bool RenderScene::seesProxy(const RenderParams& params) const
{
  return !this->Composite.majorant.empty() && integratorInfo(params.integrator).scatters;
}

DualMeshMedium RenderScene::medium(const RenderParams& params) const
{
  DualMeshMedium medium;
  medium.mesh = this->Mesh->view();
  if (cullingEnabled(params))
  {
    medium.mesh.bvh = this->Culling.apply(medium.mesh.bvh);
  }
  medium.tf = this->Tf.view();
  medium.elementTest = params.elementTest;
  medium.origin = glm::vec3(this->Mesh->origin);
  medium.invSpacing = 1.0f / glm::vec3(this->Mesh->finestSpacing);
  medium.countPrimitiveTests = integratorInfo(params.integrator).countsPrimitiveTests;
  return medium;
}

CompositeMedium RenderScene::compositeMedium(const RenderParams& params) const
{
  CompositeMedium composite;
  composite.inner = this->medium(params);
  composite.outer = composite.inner;
  composite.outer.mesh = this->Proxy->view();
  composite.outer.origin = glm::vec3(this->Proxy->origin);
  composite.outer.invSpacing = 1.0f / glm::vec3(this->Proxy->finestSpacing);
  composite.lo = this->ProxyLo;
  composite.hi = this->ProxyHi;
  return composite;
}

} // namespace amrdm
