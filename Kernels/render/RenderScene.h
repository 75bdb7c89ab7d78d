// The host scene every renderer draws (pbrt-v4: one scene; the backends differ only in where the
// accumulation lives and how a pass is launched): the dual mesh (not owned), the transfer
// function, the majorant grid, the culling ranges and masks, the proxy of a data-parallel region
// with its composite majorant grid, and the resolution of the "0 = automatic" parameters (one
// step formula, from the mesh's domain box, for the mapper and the command line alike). It hands
// out the medium and majorant-grid views a pass runs with: CpuRenderer runs them as they are,
// CudaRenderer swaps the host pointers for its device copies, the benchmark's loop uses them too.
// Host code.
#pragma once

#include "accel/MajorantGrid.h"
#include "accel/PrimitiveCulling.h"
#include "mesh/DualMesh.h"
#include "render/RenderParams.h"
#include "sampling/CompositeMedium.h"
#include "sampling/TransferFunction.h"

#include <cstdint>

namespace amrdm
{

/// The automatic ray-marching step is at least this fraction of the domain's diagonal: half
/// the finest cell of a deep hierarchy (Enzo: 2048^3 finest cells over the bounds) would take
/// thousands of samples per ray where most of the volume is coarse.
constexpr double kAutoStepDiagonalFraction = 1e-3;
/// The automatic step of composite ray marching adds at most this opacity per step where the
/// transfer function is most opaque: the step is where the Riemann sum's error per step, which
/// grows with the opacity a step adds, stays small, whatever the unit distance.
constexpr double kAutoStepOpacity = 0.1;
/// ... and is at most this fraction of the domain's diagonal (at least 32 samples across the
/// domain, also for a nearly transparent transfer function).
constexpr double kAutoStepMaxDiagonalFraction = 1.0 / 32.0;

/// The automatic ray-marching step (world units). Without a transfer function (and for the
/// blend modes, which see values, not opacity): half the finest cell's smallest spacing, but at
/// least kAutoStepDiagonalFraction of the diagonal of the mesh's domain box (domainLower ..
/// domainUpper: the whole AMR domain, also for the mesh of one data-parallel region; the bounds
/// of what can be sampled for a mesh built without one). With `tf`: the step at which the
/// table's largest opacity alpha_max adds kAutoStepOpacity, unitDistance ln(1 -
/// kAutoStepOpacity) / ln(1 - alpha_max), clamped to [that floor, max(floor,
/// kAutoStepMaxDiagonalFraction x diagonal)]. The table, not the data's range through it, so
/// that every region of a data-parallel render takes the same step (one lattice).
double autoStepSize(const DualMesh& mesh, const TransferFunction* tf = nullptr);

/// Resolves the "0 = automatic" parameters (ray-marching step, gradient offsets, samples per
/// pass) from the mesh and, for the step of Composite blending, the transfer function (null:
/// none). Every renderer launches with the resolved copy.
RenderParams resolveRenderParams(const RenderParams& userParams,
  const DualMesh& mesh,
  const TransferFunction* tf = nullptr);

/// Whether invisible primitives are skipped: on request, except where gradients need the field
/// on both sides of a culled primitive (render/IntegratorList.h: gradientShading), and where a
/// blend mode reads values the transfer function hides (blendModeSeesHiddenValues).
inline bool cullingEnabled(const RenderParams& params)
{
  const IntegratorInfo& info = integratorInfo(params.integrator);
  return params.cullInvisiblePrimitives && !(info.gradientShading && params.gradientShading) &&
         !(info.blendModes && blendModeSeesHiddenValues(params.blendMode));
}

class RenderScene
{
public:
  /// The mesh (not owned; must outlive its use): builds the majorant ranges at
  /// `majorantResolution` (<= 0: automatic) and the culling ranges, and their majorants and masks
  /// when a transfer function is set. Null clears the scene's mesh. Throws std::invalid_argument
  /// (DualMesh::validate) for an inconsistent mesh, keeping the old one.
  void setMesh(const DualMesh* mesh, glm::ivec3 majorantResolution, int threads);
  /// Copies the transfer function; recomputes majorants and culling masks only.
  void setTransferFunction(const TransferFunction& tf, int threads);
  /// The proxy outside the region's box [lo, hi] (Renderer.h). Its composite majorant grid
  /// (accel/CompositeMajorantGrid.h) spans the proxy's bounds at about the mesh's macrocell size.
  /// Throws std::invalid_argument for an empty box with a proxy or an inconsistent proxy.
  void setProxy(const DualMesh* proxy, const glm::vec3& lo, const glm::vec3& hi, int threads);
  /// Rebuilds the majorant grids when params.majorantResolution is not the one they were built
  /// at (with params.threads): the one route by which a pass changes the scene. True when it did.
  bool updateMajorantResolution(const RenderParams& params);

  /// A mesh and a transfer function are set: there is something to render.
  bool ready() const { return this->Mesh && this->HasTf; }
  /// resolveRenderParams() with this scene's mesh and transfer function (ready() required).
  RenderParams resolve(const RenderParams& userParams) const;
  /// Whether a pass with (resolved) `params` sees the proxy: one is set and the integrator
  /// scatters (render/IntegratorList.h; the others follow only camera rays, clipped to the box).
  bool seesProxy(const RenderParams& params) const;
  /// The region's medium for (resolved) `params`: host pointers, culling applied when enabled.
  DualMeshMedium medium(const RenderParams& params) const;
  /// medium() inside the region's box and the proxy outside it (seesProxy() required).
  CompositeMedium compositeMedium(const RenderParams& params) const;
  /// Calls pass(medium, majorantGridView) with what a pass with (resolved) `params` runs on:
  /// the composite medium and grid when it sees the proxy, else the mesh's.
  template<typename Pass>
  void withMedium(const RenderParams& params, Pass&& pass) const
  {
    if (this->seesProxy(params))
    {
      pass(this->compositeMedium(params), this->Composite.view());
    }
    else
    {
      pass(this->medium(params), this->Majorants.view());
    }
  }

  const DualMesh* mesh() const { return this->Mesh; }
  const DualMesh* proxy() const { return this->Proxy; }
  const TransferFunction& transferFunction() const { return this->Tf; }
  bool hasTransferFunction() const { return this->HasTf; }
  const MajorantGrid& majorantGrid() const { return this->Majorants; }
  /// The composite grid (empty without a proxy).
  const MajorantGrid& compositeMajorantGrid() const { return this->Composite; }
  const PrimitiveCulling& primitiveCulling() const { return this->Culling; }
  /// Host bytes of what the scene derives from the meshes (Renderer::accelerationBytes).
  std::uint64_t accelerationBytes() const
  {
    return this->Majorants.bytes() + this->Culling.bytes() + this->Composite.bytes();
  }

private:
  void updateComposite(int threads);

  const DualMesh* Mesh = nullptr;
  TransferFunction Tf;
  bool HasTf = false;
  MajorantGrid Majorants;
  glm::ivec3 Resolution{ 0 };      ///< what Majorants was built at (as requested: 0 = automatic)
  PrimitiveCulling Culling;        ///< value ranges per BVH slot/node; visibility from the TF
  const DualMesh* Proxy = nullptr; ///< DistributionMode Proxy: the whole domain, coarse
  glm::vec3 ProxyLo{ 0.0f }, ProxyHi{ 0.0f };
  MajorantGrid Composite; ///< the majorants of mesh-in-the-box + proxy-outside
};

} // namespace amrdm
