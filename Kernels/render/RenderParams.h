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
#include <type_traits>

namespace amrdm
{

static_assert(
  int(param::Integrator.maximum) == kIntegratorCount - 1 && param::Integrator.minimum == 0.0,
  "the parameter table's Integrator range (core/ParameterTable.h) must cover exactly the rows of "
  "render/IntegratorList.h");

struct RenderParams
{
  // --- The user-visible parameters: one field per row of core/ParameterTable.h -------------
  // (the rows whose kernel field is RenderParams::<member>; ElementTest and MaxNewtonIterations
  // are elementTest's, below). Automatic values (0) are resolved on the host before launch:
  // stepSize and majorantResolution by the renderer's scene (render/RenderScene.h), threads by
  // the CPU backend; majorantResolution is read on the host only, samplesPerPass by renderPass().
  // BEGIN GENERATED render-params (Tools/generate_parameters.py; edit the table, then run it)
  // clang-format off
  /// Integrator: estimator: path tracer, single scatter, ray march, debug primitives, debug cost;
  /// 0..4, default 0.
  IntegratorType integrator = IntegratorType(int(param::Integrator.defaultValue));
  /// SamplesPerRender: samples per pixel added by each render; 1..4096, default 1.
  int samplesPerPass = int(param::SamplesPerRender.defaultValue);
  /// ScatteringAnisotropy: Henyey-Greenstein anisotropy g of the phase function; -0.99..0.99,
  /// default 0.
  float anisotropy = float(param::ScatteringAnisotropy.defaultValue);
  /// EnvironmentRadiance: uniform environment radiance (RGB) seen by scattered paths; >= 0,
  /// default (1, 1, 1).
  glm::vec3 ambient = glm::vec3{ float(param::EnvironmentRadiance.defaultValue) };
  /// EmbedIsosurfaces: draw the isosurface values inside the Composite volume (path tracer: lit,
  /// shadowed surfaces); 0..1, default 0.
  bool embedIsosurfaces = param::EmbedIsosurfaces.defaultValue != 0.0;
  /// MaximumBounces: scattering events after which a path stops; 0..100000, default 64.
  int maxBounces = int(param::MaximumBounces.defaultValue);
  /// StepSize: ray-marching step, world units (0: automatic, where the most opaque colour adds
  /// 0.1 opacity per step, within [half the finest cell, >= 1/1000 of the diagonal; 1/32 of it]);
  /// >= 0, default 0.
  float stepSize = float(param::StepSize.defaultValue);
  /// SamplesPerCell: level-adaptive ray marching: samples per finest cell of each macrocell, step
  /// >= StepSize (0: uniform step); 0..1000000, default 0.
  float samplesPerCell = float(param::SamplesPerCell.defaultValue);
  /// MajorantResolution: majorant macrocells per axis (0: automatic, 1 per 16 finest cells, <=
  /// 128, <= 1 per 64 leaf cells); 0..1024, default 0.
  glm::ivec3 majorantResolution = glm::ivec3{ int(param::MajorantResolution.defaultValue) };
  /// NumberOfThreads: threads for building, sampling and rendering (0: all cores, at most
  /// VTK_SMP_MAX_THREADS when that is set); results do not depend on it; 0..1024, default 0.
  int threads = int(param::NumberOfThreads.defaultValue);
  /// Seed: random seed; any, default 0.
  std::uint32_t seed = std::uint32_t(int(param::Seed.defaultValue));
  // clang-format on
  // END GENERATED render-params

  // --- Integrator ----------------------------------------------------------------------------
  /// Russian roulette starts after this many scattering events; 0..maxBounces, default 3.
  /// Survival probability = min(1, max throughput component).
  int rouletteStartBounce = 3;
  /// Tentative collisions one majorant walk may take before it is cut (counted in
  /// TraceCounters::stepLimitHits); a cut walk finishes the rest of its ray by regular tracking
  /// over its non-empty majorant segments at the level-adaptive step (marchCutRemainder,
  /// DeltaTracking.h). 1..2^30, default 65536. Bounds the work of a huge majorant: at most
  /// maxStepsPerWalk + kCutFallbackSamples (4096) + one per non-empty macrocell crossed medium
  /// evaluations per walk. (The ray marcher stops compositing after this many samples, also
  /// counted.)
  int maxStepsPerWalk = 65536;

  // --- Ray marching (IntegratorType::RayMarch) ----------------------------------------------
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
  /// embedIsosurfaces (above) draws the surfaces of isoValues inside the Composite volume, by
  /// the integrators with the `embedsIsosurfaces` trait (path tracer: lit surfaces in the
  /// medium, transport/SurfacePathTracer.h; ray marcher: surfaces and volume composited in depth
  /// order, transport/EmbeddedIsoMarch.h).
  /// Slice: the plane through sliceOrigin (scene frame) with normal sliceNormal (any length > 0).
  glm::vec3 sliceOrigin{ 0.0f };
  glm::vec3 sliceNormal{ 0.0f, 0.0f, 1.0f };
  /// AverageIntensity: only values in [averageRangeLo, averageRangeHi] are averaged
  /// (vtkVolumeMapper::AverageIPScalarRange); default everything.
  float averageRangeLo = -3.0e38f;
  float averageRangeHi = 3.0e38f;

  // --- Space skipping and sampling -------------------------------------------------------
  /// Element inside test and Newton iterations (see ElementTest.h).
  ElementTestParams elementTest;

  // --- Lights ------------------------------------------------------------------------------
  /// Directional / point lights used by NEE (and by gradient shading: the first directional
  /// light, or a headlight when there is none); numLights 0..kMaxLights, default 0.
  Light lights[kMaxLights];
  int numLights = 0;
  /// (ambient, above, is the environment radiance: camera rays that escape show the background
  /// instead, alpha 0.)

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

// One copy is passed by value to every kernel, on the CPU and the GPU (cudaMemcpy'd as bytes).
static_assert(std::is_trivially_copyable<RenderParams>::value,
  "RenderParams is copied to the GPU as bytes: every field must be trivially copyable");

} // namespace amrdm
