// Emission-absorption ray marching with VTK volume-mapper conventions: samples every `step`
// world units from a jittered start (or, level-adaptive, a step that grows with the local cell
// size), table opacity corrected to the step (alpha_step = 1 - (1 - alpha)^(step /
// unitDistance)), front-to-back compositing C += (1 - A) alpha_step rgb, A += (1 - A) alpha_step,
// early termination at params.earlyTermination, optional gradient (Phong) shading. Macrocells
// with zero majorant (no data, or transparent over their whole value range) are skipped without
// samples. Host/device code, templated on the medium (see Media.h).
#pragma once

#include "transport/MarchLattice.h"
#include "transport/PathTracer.h"

#include <cmath>

namespace amrdm
{

/// Opacity of one step: 1 - (1 - alpha)^exponent for alpha in [0, 1), exponent >= 0 (the step
/// over the unit distance), to a relative error below 1e-5, also where alpha or the exponent
/// is tiny (density scale 1e-6: 1 - pow() would round to 0). Short series where the argument is
/// small, logf / expf elsewhere: the same value as -expm1(exponent * log1p(-alpha)) at a
/// fraction of the cost of those two (they were 13 % of a ray-marched frame's profile).
AMRDM_HD float stepOpacity(float alpha, float exponent)
{
  // ln(1 - alpha): -(a + a^2/2 + a^3/3 + a^4/4 + a^5/5) below 1/32 (next term a^6/6: 1.5e-10
  // relative), the logarithm of the exactly rounded 1 - alpha above (relative error 2^-24 / a).
  float lnT;
  if (alpha < 0.03125f)
  {
    const float a = alpha;
    lnT = -a * (1.0f + a * (0.5f + a * (1.0f / 3.0f + a * (0.25f + a * 0.2f))));
  }
  else
  {
    lnT = std::log(1.0f - alpha);
  }
  const float x = exponent * lnT; // <= 0
  // 1 - e^x: -(x + x^2/2 + x^3/6 + x^4/24 + x^5/120) above -1/32 (next term 2e-12 relative).
  if (x > -0.03125f)
  {
    return -x * (1.0f + x * (0.5f + x * (1.0f / 6.0f + x * (1.0f / 24.0f + x * (1.0f / 120.0f)))));
  }
  return 1.0f - std::exp(x);
}

/// Phong shading of a surface of colour rgb with world gradient `grad`: colour x (ka + kd |n.l|)
/// + ks |n.h|^p (two-sided, as VTK's volume shading; the first directional light or a
/// headlight). The ray marcher's (shadeGradient) and the isosurfaces' of the blend modes.
AMRDM_HD glm::vec3 shadeSurface(const RenderParams& params,
  const glm::vec3& grad,
  const glm::vec3& rgb,
  const glm::vec3& viewDir)
{
  const float len = glm::length(grad);
  if (!(len > 0.0f))
  {
    return rgb * (params.ambientCoefficient + params.diffuseCoefficient);
  }
  const glm::vec3 n = -grad / len;
  glm::vec3 l = -viewDir; // headlight
  for (int i = 0; i < params.numLights && i < kMaxLights; ++i)
  {
    if (params.lights[i].type == LightType::Directional)
    {
      l = glm::normalize(params.lights[i].direction);
      break;
    }
  }
  const glm::vec3 hv = glm::normalize(l - viewDir);
  const float diffuse = std::fabs(glm::dot(n, l));
  const float specular = std::pow(std::fabs(glm::dot(n, hv)), params.specularPower);
  return rgb * (params.ambientCoefficient + params.diffuseCoefficient * diffuse) +
         glm::vec3(params.specularCoefficient * specular);
}

/// The ray marcher's shading: shadeSurface with the field's central-difference gradient at p
/// (one-sided where one side has no data). Returns the shaded RGB.
template<typename Medium>
AMRDM_HD glm::vec3 shadeGradient(const Medium& medium,
  const RenderParams& params,
  const glm::vec3& p,
  const glm::vec3& rgb,
  const glm::vec3& viewDir,
  TraceCounters& counters)
{
  float centre = 0.0f;
  if (!medium.value(p, centre, counters))
  {
    return rgb;
  }
  glm::vec3 grad(0.0f);
  for (int a = 0; a < 3; ++a)
  {
    glm::vec3 h(0.0f);
    h[a] = params.gradientDelta[a];
    float vp = centre, vm = centre;
    const bool hp = medium.value(p + h, vp, counters);
    const bool hm = medium.value(p - h, vm, counters);
    // One-sided where the field has no data on one side.
    const float span = (hp ? h[a] : 0.0f) + (hm ? h[a] : 0.0f);
    grad[a] = span > 0.0f ? ((hp ? vp : centre) - (hm ? vm : centre)) / span : 0.0f;
  }
  return shadeSurface(params, grad, rgb, viewDir);
}

/// Marches the camera ray over [0, tmax] ∩ grid bounds on marchLattice()'s samples
/// (transport/MarchLattice.h). `jitter` in [0, 1) offsets the
/// samples. alpha = accumulated opacity (1 - transmittance of the Riemann sum).
/// Uniform step (params.samplesPerCell == 0): one lattice (k + jitter) * step measured from the
/// camera ray's true origin (ray.at(t) with t + ray.tCamera on the lattice), so neither skipped
/// macrocells nor a moved origin (clipping planes, a data-parallel region's box) shift the
/// samples: the regions' pieces of one ray sample exactly where the whole ray does. Level-adaptive
/// step (> 0): each non-empty macrocell segment [t0, t1] is cut into strata of h = max(step,
/// cellWidth / samplesPerCell) (the last one shorter), one sample at `jitter` inside each, opacity
/// corrected to the stratum's length.
template<typename Medium>
AMRDM_HD SampleResult rayMarch(const Medium& medium,
  const MajorantGridView& grid,
  const RenderParams& params,
  const Ray& ray,
  float tmax,
  float jitter,
  TraceCounters& counters)
{
  SampleResult out;
  const float step = params.stepSize;
  if (!(step > 0.0f))
  {
    return out;
  }
  const float unitDistance = medium.unitDistance();
  const float invStep = 1.0f / step;
  float A = 0.0f;
  glm::vec3 C(0.0f);
  int steps = 0;
  // One sample at t weighing `length` world units; false when the walk is over (opacity
  // reached earlyTermination, or the step limit).
  auto composite = [&](float t, float length) -> bool
  {
    if (steps >= params.maxStepsPerWalk)
    {
      ++counters.stepLimitHits;
      return false;
    }
    ++steps;
    ++counters.steps;
    const glm::vec3 p = ray.at(t);
    glm::vec4 c;
    {
      const RayHintSlot slot(counters, t + ray.tCamera, invStep);
      c = medium.rgba(p, counters);
    }
    if (!(c.w > 0.0f))
    {
      return true;
    }
    const float a = stepOpacity(glm::min(c.w, kMaxTableOpacity), length / unitDistance);
    glm::vec3 rgb(c);
    if (params.gradientShading)
    {
      rgb = shadeGradient(medium, params, p, rgb, ray.d, counters);
    }
    C += (1.0f - A) * a * rgb;
    A += (1.0f - A) * a;
    return A < params.earlyTermination;
  };
  marchLattice(
    grid,
    ray,
    tmax,
    step,
    params.samplesPerCell,
    jitter,
    [](const MajorantSegment& seg) { return !(seg.sigmaMaj > 0.0f); },
    composite);
  out.L = C;
  out.alpha = A;
  return out;
}

/// Ray marching as an integrator (render/IntegratorList.h): one jitter per sample, stratified
/// over the pixel's samples (its low-discrepancy pair kLdCameraVertex).
template<>
struct Integrate<IntegratorType::RayMarch>
{
  template<typename Medium>
  AMRDM_HD static SampleResult sample(const TraceContext<Medium>& ctx, const Ray& ray, float maxT)
  {
    return rayMarch(
      ctx.medium, ctx.grid, ctx.params, ray, maxT, ctx.rng.ld2(kLdCameraVertex).x, ctx.counters);
  }
};

} // namespace amrdm
