// The integrators, one row each: the single place an integrator is registered. The enum
// IntegratorType, the run-time dispatch of every renderer (withIntegrator: CPU tiles, CUDA launch),
// the CUDA instantiations, the names of the CLI, the device check and the VTK mapper's PrintSelf
// all come from this list; the integrator itself is a specialization Integrate<IntegratorType::X>
// in its own header (transport/), included by transport/Integrators.h. Rows are in IntegratorType
// order and the values are stored in scene files, ParaView state and scripts: append, never
// reorder. Host/device code.
//
// X(Type, short CLI name, long name, VTK mapper constant, own CUDA translation unit 0/1,
//   scatters, jitterLattice, countsPrimitiveTests, costHeatMap, gradientShading, blendModes,
//   litIsosurfaces, embedsIsosurfaces)
//   own CUDA unit 1: cuda/CudaRender<Type>.cu instantiates it (the big kernels compile in
//   parallel); 0: cuda/CudaRenderOtherIntegrators.cu does.
//   The traits (IntegratorInfo) are what renderers and front-ends ask instead of naming rows:
//   scatters             follows scattered and shadow rays off the camera ray: sees the proxy
//                        outside a region's box (render/RenderScene.h) and is lit by the lights'
//                        intensity (amrdm-render's default exposure);
//   jitterLattice        samples a jittered lattice along the ray that the regions of a
//                        data-parallel image must share (one seed for all regions); 0: an
//                        independent Monte Carlo stream per region (the mapper's region seed);
//   countsPrimitiveTests the medium counts its primitive tests (TraceCounters::primitiveTests);
//   costHeatMap          the image is a heat map of work over RenderParams::heatMapScale
//                        (amrdm-render renders it unclamped and rescales it);
//   gradientShading      shades with field gradients when RenderParams::gradientShading is on:
//                        a gradient needs the field on both sides of a primitive, so culling of
//                        invisible primitives is off then (cullingEnabled, render/Renderer.h);
//   blendModes           draws RenderParams::blendMode's non-composite modes (MIP, MinIP,
//                        average, additive, isosurface, slice: transport/BlendModes.h,
//                        render/BlendModeList.h); a frame in such a mode is drawn by one
//                        of them, said once (blendModeLimitation);
//   litIsosurfaces       draws BlendMode Isosurface itself, as lit surfaces (a diffuse BRDF
//                        with next-event estimation, shadows and indirect light:
//                        transport/SurfacePathTracer.h), not by the ray marcher;
//   embedsIsosurfaces    draws RenderParams::embedIsosurfaces: the isosurfaces inside the
//                        Composite volume (path tracer: surfaces in the medium, shadowing it and
//                        shadowed by it; ray marcher: surfaces and volume composited in depth
//                        order); the others draw the volume alone, said once
//                        (embedIsosurfacesLimitation, render/BlendModeList.h).
// X macros take `...` after the columns they use, so a new column leaves them alone.
#pragma once

#include <type_traits>

// clang-format off
#define AMRDM_INTEGRATORS(X)                                                                       \
  /* multiple scattering: delta tracking, NEE with ratio-tracked shadow rays */                    \
  X(PathTracer, "pt", "path-tracer", "PATH_TRACER", 1,          1, 0, 0, 0, 0, 0, 1, 1)            \
  /* first real collision, direct light from lights and ambient only */                            \
  X(SingleScatter, "ss", "single-scatter", "SINGLE_SCATTER", 1, 1, 0, 0, 0, 0, 0, 0, 0)            \
  /* emission-absorption ray marching (VTK volume-mapper conventions) */                           \
  X(RayMarch, "rm", "ray-march", "RAY_MARCH", 1,                0, 1, 0, 0, 1, 1, 0, 1)            \
  /* colour by the primitive at the first collision (gridlet checkerboard, tet red, pyramid */     \
  /* green, wedge blue, hex orange) */                                                             \
  X(DebugPrimitive, "prims", "debug-primitive", "DEBUG_PRIMITIVES", 0, 0, 0, 0, 0, 0, 0, 0, 0)     \
  /* heat map of the path tracer's work (steps + primitive tests) */                               \
  X(DebugCost, "cost", "debug-cost", "DEBUG_COST", 0,           0, 0, 1, 1, 0, 0, 0, 0)
// clang-format on

namespace amrdm
{

/// Which estimator renders the image (run-time choice, no rebuild).
enum class IntegratorType : int
{
#define AMRDM_INTEGRATOR_ENUM(type, ...) type,
  AMRDM_INTEGRATORS(AMRDM_INTEGRATOR_ENUM)
#undef AMRDM_INTEGRATOR_ENUM
};

/// One integrator's names and traits (the columns above).
struct IntegratorInfo
{
  IntegratorType type;
  const char* shortName; ///< CLI (--integrator pt)
  const char* name;      ///< CLI long form, device check, scene-file reports
  const char* vtkName;   ///< vtkAMRDualMeshVolumeMapper's constant
  bool scatters;
  bool jitterLattice;
  bool countsPrimitiveTests;
  bool costHeatMap;
  bool gradientShading;
  bool blendModes;
  bool litIsosurfaces;
  bool embedsIsosurfaces;
};

constexpr IntegratorInfo kIntegrators[] = {
#define AMRDM_INTEGRATOR_INFO(                                                                     \
  type, shortName, name, vtkName, ownCudaUnit, sc, jl, cp, hm, gs, bm, li, ei)                     \
  { IntegratorType::type,                                                                          \
    shortName,                                                                                     \
    name,                                                                                          \
    vtkName,                                                                                       \
    (sc) != 0,                                                                                     \
    (jl) != 0,                                                                                     \
    (cp) != 0,                                                                                     \
    (hm) != 0,                                                                                     \
    (gs) != 0,                                                                                     \
    (bm) != 0,                                                                                     \
    (li) != 0,                                                                                     \
    (ei) != 0 },
  AMRDM_INTEGRATORS(AMRDM_INTEGRATOR_INFO)
#undef AMRDM_INTEGRATOR_INFO
};

constexpr int kIntegratorCount = int(sizeof(kIntegrators) / sizeof(kIntegrators[0]));

/// The row of `type`; a value outside the list is the path tracer (as every renderer renders it).
constexpr const IntegratorInfo& integratorInfo(IntegratorType type)
{
  return int(type) >= 0 && int(type) < kIntegratorCount ? kIntegrators[int(type)] : kIntegrators[0];
}

/// The one run-time switch over the rows: calls f(IntegratorConstant<I>()) with `type` as the
/// compile-time I (a value outside the list runs as the path tracer, as integratorInfo says) and
/// returns what f returns. The CPU tiles (render/TiledPass.h) and the CUDA launch
/// (cuda/CudaRenderer.cu) both dispatch through it. Host code.
template<IntegratorType I>
using IntegratorConstant = std::integral_constant<IntegratorType, I>;
template<typename F>
decltype(auto) withIntegrator(IntegratorType type, F&& f)
{
  switch (type)
  {
#define AMRDM_INTEGRATOR_CASE(type, ...)                                                           \
  case IntegratorType::type:                                                                       \
    return f(IntegratorConstant<IntegratorType::type>());
    AMRDM_INTEGRATORS(AMRDM_INTEGRATOR_CASE)
#undef AMRDM_INTEGRATOR_CASE
  }
  return f(IntegratorConstant<IntegratorType::PathTracer>());
}

/// One sample along a camera ray with integrator I: a specialization per integrator, in the
/// integrator's own header (transport/), with
///   template <typename Medium> AMRDM_HD static SampleResult sample(
///     const TraceContext<Medium>& ctx, const Ray& ray, float maxT);
/// (transport/TraceContext.h: medium, majorant grid, params, random stream, counters).
template<IntegratorType I>
struct Integrate;

} // namespace amrdm
