// Media the integrators walk: the dual-mesh field seen through a transfer function, and small
// analytic media for tests. Every medium offers, at a world point p:
//   MediumSample sample(p, counters)  extinction + albedo (for delta / ratio tracking),
//   bool value(p, v, counters)        the scalar (false = no data; ray marcher, gradients),
//   glm::vec4 rgba(p, counters)       transfer-function colour and table opacity (ray marcher),
//   float unitDistance()              the opacity unit distance, world units.
// Host/device code.
#pragma once

#include "transport/DeltaTracking.h"
#include "sampling/FieldSampler.h"
#include "sampling/TransferFunction.h"

namespace amrdm
{

/// rgba() and sample() of a field medium: its value(p) through the transfer function `tf`
/// (DualMeshMedium, LinearFieldMedium, CompositeMedium).
template<typename Field>
AMRDM_HD glm::vec4 fieldRgba(const Field& field,
  const TransferFunctionView& tf,
  const glm::vec3& p,
  TraceCounters& counters)
{
  float v;
  return field.value(p, v, counters) ? tfLookup(tf, v) : glm::vec4(0.0f);
}
template<typename Field>
AMRDM_HD MediumSample fieldSample(const Field& field,
  const TransferFunctionView& tf,
  const glm::vec3& p,
  TraceCounters& counters)
{
  MediumSample s;
  float v;
  if (field.value(p, v, counters))
  {
    const glm::vec4 c = tfLookup(tf, v);
    s.sigmaT = opacityToExtinction(c.w, tf.unitDistance);
    s.albedo = glm::vec3(c);
  }
  return s;
}

/// The dual-mesh field (grid space) through a transfer function. world = origin + spacing *
/// grid. A point no primitive claims has zero density.
struct DualMeshMedium
{
  DualMeshView mesh;
  TransferFunctionView tf;
  ElementTestParams elementTest;
  glm::vec3 origin{ 0.0f };
  glm::vec3 invSpacing{ 1.0f };     ///< 1 / finestSpacing per axis
  bool countPrimitiveTests = false; ///< heat map: add the primitive tests to the counters

  AMRDM_HD glm::vec3 toGrid(const glm::vec3& p) const
  {
    return (p - this->origin) * this->invSpacing;
  }

  /// The field at world point p; false where no primitive claims it. The primitive that
  /// claimed the path's previous sample (TraceCounters::lastPrimitive) is tested first: any
  /// primitive that claims a point gives the dual-mesh value there, so this only skips the BVH
  /// descent for the next sample of a ray, which mostly lies in the same gridlet or element.
  /// Next, where a ray-marched sample names its slot of the tile's ray-hint table
  /// (TraceCounters::rayHints, hintSlot), the primitive that claimed the previous ray's sample
  /// of that slot: at the automatic step most samples leave the previous one's gridlet, but lie
  /// in the neighbouring ray's. The slot then holds what claimed this sample.
  AMRDM_HD AMRDM_FORCE_INLINE bool value(const glm::vec3& p,
    float& v,
    TraceCounters& counters,
    SampleHit* hit = nullptr) const
  {
    const glm::vec3 g = this->toGrid(p);
    std::uint32_t found = ~0u;
    int cell = -1;
    float result = 0.0f;
    std::uint32_t tests = 0;
    const std::uint32_t last = counters.lastPrimitive;
    if (last != ~0u)
    {
      ++tests;
      if (samplePrimitive(this->mesh, last, g, this->elementTest, result, &cell))
      {
        found = last;
      }
    }
    const std::uint32_t slot = counters.hintSlot;
    if (found == ~0u && slot != ~0u)
    {
      const std::uint32_t neighbour = counters.rayHints[slot];
      if (neighbour != ~0u && neighbour != last)
      {
        ++tests;
        if (samplePrimitive(this->mesh, neighbour, g, this->elementTest, result, &cell))
        {
          found = neighbour;
        }
      }
    }
    if (found == ~0u)
    {
      bvhPointQuery(this->mesh.bvh,
        g,
        [&](std::uint32_t ref)
        {
          ++tests;
          if (samplePrimitive(this->mesh, ref, g, this->elementTest, result, &cell))
          {
            found = ref;
            return true;
          }
          return false;
        });
    }
    if (this->countPrimitiveTests)
    {
      counters.primitiveTests += tests;
    }
    if (hit)
    {
      hit->prim = found;
      hit->cell = cell;
    }
    // A point no primitive claims (outside the mesh, or in primitives culled as invisible) drops
    // the hint: the next sample would otherwise pay one test for a primitive it has left, on
    // every step through a culled region.
    counters.lastPrimitive = found;
    if (slot != ~0u)
    {
      counters.rayHints[slot] = found;
    }
    if (found == ~0u)
    {
      return false;
    }
    v = result;
    return true;
  }
  AMRDM_HD glm::vec4 rgba(const glm::vec3& p, TraceCounters& counters) const
  {
    return fieldRgba(*this, this->tf, p, counters);
  }
  AMRDM_HD MediumSample sample(const glm::vec3& p, TraceCounters& counters) const
  {
    return fieldSample(*this, this->tf, p, counters);
  }
  AMRDM_HD float unitDistance() const { return this->tf.unitDistance; }
};

/// Test medium: constant extinction and albedo inside the box [lo, hi], vacuum outside.
struct HomogeneousMedium
{
  glm::vec3 lo{ 0.0f }, hi{ 1.0f };
  float sigmaT = 1.0f;
  glm::vec3 albedo{ 1.0f };

  AMRDM_HD bool inside(const glm::vec3& p) const
  {
    return glm::all(glm::greaterThanEqual(p, this->lo)) &&
           glm::all(glm::lessThanEqual(p, this->hi));
  }
  AMRDM_HD MediumSample sample(const glm::vec3& p, TraceCounters&) const
  {
    MediumSample s;
    if (this->inside(p))
    {
      s.sigmaT = this->sigmaT;
      s.albedo = this->albedo;
    }
    return s;
  }
  AMRDM_HD bool value(const glm::vec3& p, float& v, TraceCounters&) const
  {
    v = 1.0f;
    return this->inside(p);
  }
  AMRDM_HD glm::vec4 rgba(const glm::vec3& p, TraceCounters&) const
  {
    // Opacity over one unit distance (1) that reproduces sigmaT.
    return this->inside(p) ? glm::vec4(this->albedo, 1.0f - std::exp(-this->sigmaT))
                           : glm::vec4(0.0f);
  }
  AMRDM_HD float unitDistance() const { return 1.0f; }
};

/// Test medium: scalar field v = dot(gradient, p) + offset inside the box [lo, hi], through a
/// transfer function (the analytic twin of DualMeshMedium).
struct LinearFieldMedium
{
  glm::vec3 lo{ 0.0f }, hi{ 1.0f };
  glm::vec3 gradient{ 1.0f, 0.0f, 0.0f };
  float offset = 0.0f;
  TransferFunctionView tf;

  AMRDM_HD bool value(const glm::vec3& p, float& v, TraceCounters&) const
  {
    if (!(glm::all(glm::greaterThanEqual(p, this->lo)) &&
          glm::all(glm::lessThanEqual(p, this->hi))))
    {
      return false;
    }
    v = glm::dot(this->gradient, p) + this->offset;
    return true;
  }
  AMRDM_HD glm::vec4 rgba(const glm::vec3& p, TraceCounters& c) const
  {
    return fieldRgba(*this, this->tf, p, c);
  }
  AMRDM_HD MediumSample sample(const glm::vec3& p, TraceCounters& c) const
  {
    return fieldSample(*this, this->tf, p, c);
  }
  AMRDM_HD float unitDistance() const { return this->tf.unitDistance; }
};

} // namespace amrdm
