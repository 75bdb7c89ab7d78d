// Every knob of the renderer; the user-visible ones take their defaults from core/ParameterTable.h.
// Plain data: one copy is passed by value to every kernel (CPU or GPU); nothing is read from
// globals.
#pragma once

#include "core/Camera.h"
#include "core/ParameterTable.h"
#include "mesh/ElementTest.h"
#include "render/BlendModeList.h"
#include "render/IntegratorList.h"
#include "transport/Lights.h"

#include <cstdint>

namespace amrdm
{

static_assert(
  int(param::Integrator.maximum) == kIntegratorCount - 1 && param::Integrator.minimum == 0.0,
  "the parameter table's Integrator range (core/ParameterTable.h) must cover exactly the rows of "
  "render/IntegratorList.h");

struct RenderParams
{
  // --- Integrator ----------------------------------------------------------------------------
  /// Estimator; default PathTracer.
  IntegratorType integrator = IntegratorType(int(param::Integrator.defaultValue));
  /// Samples per pixel added by one renderPass(); 1..4096, default 1.
  int samplesPerPass = int(param::SamplesPerRender.defaultValue);
  /// Scattering events after which a path stops (light from deeper bounces is dropped);
  /// 0..100000, default 64. 0 = single scattering of the lights.
  int maxBounces = int(param::MaximumBounces.defaultValue);
  /// Russian roulette starts after this many scattering events; 0..maxBounces, default 3.
  /// Survival probability = min(1, max throughput component).
  int rouletteStartBounce = 3;
  /// Henyey-Greenstein anisotropy g; -0.99..0.99 (clamped), default 0 (isotropic).
  float anisotropy = float(param::ScatteringAnisotropy.defaultValue); ///< ScatteringAnisotropy
  /// Tentative collisions one majorant walk may take before it is cut (counted in
  /// TraceCounters::stepLimitHits); a cut walk finishes the rest of its ray by regular tracking
  /// over its non-empty majorant segments at the level-adaptive step (marchCutRemainder,
  /// DeltaTracking.h). 1..2^30, default 65536. Bounds the work of a huge majorant: at most
  /// maxStepsPerWalk + kCutFallbackSamples (4096) + one per non-empty macrocell crossed medium
  /// evaluations per walk. (The ray marcher stops compositing after this many samples, also
  /// counted.)
  int maxStepsPerWalk = 65536;
  /// Added to every random stream key; any value, default 0.
  std::uint32_t seed = std::uint32_t(int(param::Seed.defaultValue));

  // --- Ray marching (IntegratorType::RayMarch) ----------------------------------------------
  /// Step, world units; > 0. 0 (default) = automatic, from the mesh and (Composite blending) the
  /// transfer function (autoStepSize(), render/RenderScene.h, resolved by the renderer's scene
  /// before launch).
  float stepSize = float(param::StepSize.defaultValue);
  /// Level-adaptive step: > 0 samples every macrocell at max(stepSize, w / samplesPerCell),
  /// w = the smallest edge of the finest cell overlapping it (MajorantGridView::cellWidth), so
  /// coarse regions take as many samples per cell as the finest; each sample weighs the length
  /// of its stratum. 0 (default) = one uniform step everywhere. 0..1e6.
  float samplesPerCell = float(param::SamplesPerCell.defaultValue);
  /// Front-to-back compositing stops at this accumulated opacity; 0..1, default 0.99
  /// (1 = never stop early).
  float earlyTermination = 0.99f;
  /// Gradient (Phong) shading from central differences of the field; default off.
  bool gradientShading = false;
  /// Central-difference offset, world units; > 0. 0 (default) = half the finest spacing per
  /// axis (resolved by the renderer).
  glm::vec3 gradientDelta{ 0.0f };
  /// vtkVolumeProperty shading coefficients (defaults as VTK): ambient 0.1, diffuse 0.7,
  /// specular 0.2, specular power 10. Each >= 0.
  float ambientCoefficient = 0.1f;
  float diffuseCoefficient = 0.7f;
  float specularCoefficient = 0.2f;
  float specularPower = 10.0f;

  // --- Blend modes (render/BlendModeList.h, transport/BlendModes.h) ---------------------------
  /// vtkVolumeMapper's blend mode, same values; default Composite (the integrator's estimate).
  /// The non-composite modes are drawn by integrators with the `blendModes` trait (ray march).
  BlendMode blendMode = BlendMode::Composite;
  /// Isosurface: the values (raw field values, also with a log-scale transfer function),
  /// numIsoValues 0..kMaxIsoValues; each surface's colour and opacity are the transfer
  /// function's at its value (VTK's meaning).
  float isoValues[kMaxIsoValues] = {};
  int numIsoValues = 0;
  /// Isosurfaces embedded in the volume (beyond vtkVolumeMapper's modes): with BlendMode
  /// Composite, the surfaces of isoValues are drawn inside the volume by the integrators with
  /// the `embedsIsosurfaces` trait (path tracer: lit surfaces in the medium, shadowing it and
  /// shadowed by it, transport/SurfacePathTracer.h; ray marcher: surfaces and volume composited
  /// in depth order, transport/EmbeddedIsoMarch.h). Default off (today's image, byte for byte).
  bool embedIsosurfaces = param::EmbedIsosurfaces.defaultValue != 0.0;
  /// Slice: the plane through sliceOrigin (scene frame) with normal sliceNormal (any length > 0).
  glm::vec3 sliceOrigin{ 0.0f };
  glm::vec3 sliceNormal{ 0.0f, 0.0f, 1.0f };
  /// AverageIntensity: only values in [averageRangeLo, averageRangeHi] are averaged
  /// (vtkVolumeMapper::AverageIPScalarRange); default everything.
  float averageRangeLo = -3.0e38f;
  float averageRangeHi = 3.0e38f;

  // --- Space skipping and sampling -------------------------------------------------------
  /// Macrocells per axis of the majorant grid; any component <= 0 (default) = one macrocell
  /// per 8 finest cells, at most 128 per axis and one per 64 leaf cells (min 64 in all; see
  /// MajorantGrid.h). Host-side only.
  glm::ivec3 majorantResolution{ int(param::MajorantResolution.defaultValue) };
  /// Element inside test and Newton iterations (see ElementTest.h).
  ElementTestParams elementTest;

  // --- Lights ------------------------------------------------------------------------------
  /// Directional / point lights used by NEE (and by gradient shading: the first directional
  /// light, or a headlight when there is none); numLights 0..kMaxLights, default 0.
  Light lights[kMaxLights];
  int numLights = 0;
  /// Uniform environment radiance seen by escaping scattered paths, RGB >= 0; default 1
  /// (white). Camera rays that escape show the background instead (alpha 0).
  glm::vec3 ambient{ float(param::EnvironmentRadiance.defaultValue) }; ///< EnvironmentRadiance

  // --- Camera and image ----------------------------------------------------------------------
  CameraParams camera;
  /// Camera rays through a uniformly random point of each pixel (antialiasing; default true).
  /// false = through the pixel centre: one fixed ray per pixel (debugging, and tests that place
  /// rays exactly on cell faces). The random stream is the same either way.
  bool pixelJitter = true;
  /// Data-parallel rendering: each camera ray (after its sub-pixel jitter) is clipped to the
  /// box [clipLo, clipHi] (scene frame) of the region this process draws, so that the regions
  /// of N processes split every ray exactly at their common faces; scattered and shadow rays
  /// are not clipped. Off by default.
  bool clipToBox = false;
  glm::vec3 clipLo{ 0.0f };
  glm::vec3 clipHi{ 0.0f };
  /// Image size in pixels; each 1..16384, default 256 x 256.
  int width = 256;
  int height = 256;
  /// Render threads (CPU); 0 (default) = all cores. Images do not depend on it.
  int threads = int(param::NumberOfThreads.defaultValue);
  /// Tile edge in pixels (CPU work unit, cancellation granularity); 4..256, default 16.
  int tileSize = 16;

  /// Skip BVH nodes and primitives whose value range the transfer function maps to zero
  /// opacity (PrimitiveCulling.h); default on. Off only to measure what culling saves.
  bool cullInvisiblePrimitives = true;

  // --- Debug views -------------------------------------------------------------------------
  /// DebugCost: cost (steps + primitive tests per sample) mapped to full red-yellow-white;
  /// > 0, default 2000.
  float heatMapScale = 2000.0f;
};

} // namespace amrdm
