// The blend modes, one row each: how a camera ray turns the field into a pixel, with the values
// and meanings of vtkVolumeMapper::BlendModes (COMPOSITE_BLEND = 0 ... SLICE_BLEND = 6), so the
// mapper passes VTK's value through unchanged. Composite is the integrator's own estimate; the
// others are drawn by the integrators with the `blendModes` trait (render/IntegratorList.h: the
// ray marcher) in transport/BlendModes.h; a front-end hands a non-composite frame of another
// integrator to the ray marcher and prints blendModeLimitation()'s sentence once. Host/device.
#pragma once

#include "render/IntegratorList.h"

// clang-format off
// X(Mode, CLI name, VTK constant)
#define AMRDM_BLEND_MODES(X)                                                                       \
  /* the integrator's estimate (emission-absorption, path tracing, ...) */                         \
  X(Composite, "composite", "COMPOSITE_BLEND")                                                     \
  /* colour map and opacity of the largest value along the ray */                                  \
  X(MaximumIntensity, "mip", "MAXIMUM_INTENSITY_BLEND")                                            \
  /* ... of the smallest value */                                                                  \
  X(MinimumIntensity, "minip", "MINIMUM_INTENSITY_BLEND")                                          \
  /* grey: mean of opacity(v) * v' over the samples in the average range (v' in 0..1) */          \
  X(AverageIntensity, "average", "AVERAGE_INTENSITY_BLEND")                                        \
  /* grey: integral of opacity(v) * v' per unit distance, clamped to 1 */                         \
  X(Additive, "additive", "ADDITIVE_BLEND")                                                        \
  /* exact isosurfaces of the interpolant, composited front to back */                             \
  X(Isosurface, "iso", "ISOSURFACE_BLEND")                                                         \
  /* the interpolant on a plane, coloured by the colour map */                                     \
  X(Slice, "slice", "SLICE_BLEND")
// clang-format on

namespace amrdm
{

enum class BlendMode : int
{
#define AMRDM_BLEND_ENUM(mode, ...) mode,
  AMRDM_BLEND_MODES(AMRDM_BLEND_ENUM)
#undef AMRDM_BLEND_ENUM
};

struct BlendModeInfo
{
  BlendMode mode;
  const char* name;    ///< amrdm-render --blend
  const char* vtkName; ///< vtkVolumeMapper's constant
};

constexpr BlendModeInfo kBlendModes[] = {
#define AMRDM_BLEND_INFO(mode, name, vtkName) { BlendMode::mode, name, vtkName },
  AMRDM_BLEND_MODES(AMRDM_BLEND_INFO)
#undef AMRDM_BLEND_INFO
};

constexpr int kBlendModeCount = int(sizeof(kBlendModes) / sizeof(kBlendModes[0]));

/// Most isosurface values one frame draws (vtkContourValues may hold more; the front-ends say
/// so and draw the first kMaxIsoValues).
constexpr int kMaxIsoValues = 8;
/// Most isosurface crossings composited along one camera ray.
constexpr int kMaxIsoLayers = 32;

/// The row of `mode`; a value outside the list is Composite.
constexpr const BlendModeInfo& blendModeInfo(BlendMode mode)
{
  return int(mode) >= 0 && int(mode) < kBlendModeCount ? kBlendModes[int(mode)] : kBlendModes[0];
}

/// Whether `mode` reads values whose opacity is zero (the extreme and the average of the
/// values): then primitive culling, which hides them, is off (cullingEnabled, RenderScene.h).
constexpr bool blendModeSeesHiddenValues(BlendMode mode)
{
  return mode == BlendMode::MaximumIntensity || mode == BlendMode::MinimumIntensity ||
         mode == BlendMode::AverageIntensity;
}

/// Whether `integrator` can draw `mode`: nullptr when it can, else one sentence for the
/// front-ends to print once when they hand the frame to the ray marcher (every layer does: the
/// blend mode the user set is what renders).
constexpr const char* blendModeLimitation(IntegratorType integrator, BlendMode mode)
{
  const IntegratorInfo& info = integratorInfo(integrator);
  if (mode == BlendMode::Composite || info.blendModes ||
      (mode == BlendMode::Isosurface && info.litIsosurfaces))
  {
    return nullptr;
  }
  return "this blend mode is drawn by the ray-march integrator (the selected one draws Composite "
         "only)";
}

/// Whether `integrator` draws RenderParams::embedIsosurfaces (its `embedsIsosurfaces` trait):
/// nullptr when it does or when `embed` is off, else one sentence for the front-ends to print once
/// (the integrator draws the volume alone; the kernels ignore the flag for it).
constexpr const char* embedIsosurfacesLimitation(IntegratorType integrator, bool embed)
{
  if (!embed || integratorInfo(integrator).embedsIsosurfaces)
  {
    return nullptr;
  }
  return "EmbedIsosurfaces is drawn by the path-tracer and ray-march integrators (the selected "
         "one draws the volume alone)";
}

} // namespace amrdm
