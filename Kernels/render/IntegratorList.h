// The integrators, one row each: the single place an integrator is registered. The enum
// IntegratorType, the run-time dispatch of every renderer (CPU tiles, CUDA launch), the CUDA
// instantiations, the names of the CLI, the device check and the VTK mapper's PrintSelf all come
// from this list; the integrator itself is a specialization Integrate<IntegratorType::X> in its
// own header (transport/), included by transport/Integrators.h. Rows are in IntegratorType
// order and the values are stored in scene files, ParaView state and scripts: append, never
// reorder. Host/device code.
//
// X(Type, short CLI name, long name, VTK mapper constant, own CUDA translation unit 0/1)
//   own CUDA unit 1: cuda/CudaRender<Type>.cu instantiates it (the big kernels compile in
//   parallel); 0: cuda/CudaRenderOtherIntegrators.cu does.
#pragma once

#define AMRDM_INTEGRATORS(X)                                                                       \
  /* multiple scattering: delta tracking, NEE with ratio-tracked shadow rays */                    \
  X(PathTracer, "pt", "path-tracer", "PATH_TRACER", 1)                                             \
  /* first real collision, direct light from lights and ambient only */                            \
  X(SingleScatter, "ss", "single-scatter", "SINGLE_SCATTER", 1)                                    \
  /* emission-absorption ray marching (VTK volume-mapper conventions) */                           \
  X(RayMarch, "rm", "ray-march", "RAY_MARCH", 1)                                                   \
  /* colour by the primitive at the first collision (gridlet checkerboard, tet red, pyramid */     \
  /* green, wedge blue, hex orange) */                                                             \
  X(DebugPrimitive, "prims", "debug-primitive", "DEBUG_PRIMITIVES", 0)                             \
  /* heat map of the path tracer's work (steps + primitive tests) */                               \
  X(DebugCost, "cost", "debug-cost", "DEBUG_COST", 0)

namespace amrdm
{

/// Which estimator renders the image (run-time choice, no rebuild).
enum class IntegratorType : int
{
#define AMRDM_INTEGRATOR_ENUM(type, shortName, name, vtkName, ownCudaUnit) type,
  AMRDM_INTEGRATORS(AMRDM_INTEGRATOR_ENUM)
#undef AMRDM_INTEGRATOR_ENUM
};

/// One integrator's names.
struct IntegratorInfo
{
  IntegratorType type;
  const char* shortName; ///< CLI (--integrator pt)
  const char* name;      ///< CLI long form, device check, scene-file reports
  const char* vtkName;   ///< vtkAMRDualMeshVolumeMapper's constant
};

constexpr IntegratorInfo kIntegrators[] = {
#define AMRDM_INTEGRATOR_INFO(type, shortName, name, vtkName, ownCudaUnit)                         \
  { IntegratorType::type, shortName, name, vtkName },
  AMRDM_INTEGRATORS(AMRDM_INTEGRATOR_INFO)
#undef AMRDM_INTEGRATOR_INFO
};

constexpr int kIntegratorCount = int(sizeof(kIntegrators) / sizeof(kIntegrators[0]));

/// One sample along a camera ray with integrator I: a specialization per integrator, in the
/// integrator's own header, with
///   template <typename Medium> AMRDM_HD static SampleResult sample(const Medium&,
///     const MajorantGridView&, const RenderParams&, const Ray&, float maxT, Rng&,
///     TraceCounters&);
template<IntegratorType I>
struct Integrate;

} // namespace amrdm
