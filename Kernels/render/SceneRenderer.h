// What every renderer backend shares (pbrt-v4: one scene, thin backends): the RenderScene it draws
// (render/RenderScene.h), the forwarding of setMesh / setTransferFunction / setProxy to it, the
// scene accessors, and the frame of a pass (nothing to draw, image size change, majorant
// resolution change, resolution of the automatic parameters, cancellation, pass count). A backend
// (CpuRenderer, CudaRenderer) supplies only where the accumulation lives and how a pass runs:
// resizeAccumulation, clearAccumulation, runPass and, for its copies of the scene (CUDA's device
// buffers), sceneChanged. Host code.
#pragma once

#include "render/PassCancellation.h"
#include "render/RenderScene.h"
#include "render/Renderer.h"

#include <cstdint>

namespace amrdm
{

class SceneRenderer : public Renderer
{
public:
  /// RenderScene::setMesh, then sceneChanged(Mesh) and reset().
  void setMesh(const DualMesh* mesh,
    glm::ivec3 majorantResolution = glm::ivec3(0),
    int threads = 0) final;
  /// RenderScene::setTransferFunction, then sceneChanged(TransferFunction) and reset().
  void setTransferFunction(const TransferFunction& tf, int threads = 0) final;
  /// The proxy outside the region's box (Renderer.h, RenderScene::setProxy), then
  /// sceneChanged(Proxy) and reset().
  void setProxy(const DualMesh* proxy,
    const glm::vec3& lo,
    const glm::vec3& hi,
    int threads = 0) final;
  /// clearAccumulation() and the pass count.
  void reset() final;
  /// Nothing (true) without a mesh and a transfer function or for an empty image. Else:
  /// resizeAccumulation() and reset() when params' image size changed, the scene's majorant grids
  /// rebuilt (sceneChanged(MajorantResolution), reset()) when params.majorantResolution changed,
  /// then runPass() with the resolved parameters. False when cancel() stopped it. depthMaxT and
  /// minT: see CpuRenderer.h.
  bool renderPass(const RenderParams& params,
    const float* depthMaxT = nullptr,
    const float* minT = nullptr) final;
  /// Asks the running pass to stop (thread safe); no effect when no pass runs
  /// (PassCancellation.h).
  void cancel() final { this->Cancellation.request(); }
  /// The host copies of the majorant grids and the culling ranges and masks (Renderer.h).
  std::uint64_t accelerationBytes() const final { return this->Scene.accelerationBytes(); }

  /// The scene (majorant, composite and culling grids, transfer function) this renderer draws.
  const RenderScene& scene() const { return this->Scene; }
  const MajorantGrid& majorantGrid() const { return this->Scene.majorantGrid(); }
  const MajorantGrid& compositeMajorantGrid() const { return this->Scene.compositeMajorantGrid(); }
  const PrimitiveCulling& primitiveCulling() const { return this->Scene.primitiveCulling(); }
  const TransferFunction& transferFunction() const { return this->Scene.transferFunction(); }

protected:
  /// What changed in the scene.
  enum class SceneChange
  {
    Mesh,              ///< the mesh and every grid and mask derived from it
    TransferFunction,  ///< the table, the majorants and the culling masks
    Proxy,             ///< the proxy mesh and the composite grid
    MajorantResolution ///< the majorant grids' ranges and cell widths (not the masks)
  };
  /// Called after the scene changed, before the reset: a backend with its own copies of the
  /// scene (CudaRenderer) updates them here. The default does nothing.
  virtual void sceneChanged(SceneChange /*what*/) {}
  /// (Re)allocates the accumulation buffers for a width x height image (their contents are
  /// cleared next). Throws, having freed the old buffers or not, when they do not fit.
  virtual void resizeAccumulation(int width, int height) = 0;
  /// Zeroes the accumulation buffers and the work counters.
  virtual void clearAccumulation() = 0;
  /// Adds params.samplesPerPass samples to every pixel with (resolved) `params`; frame passes().
  virtual void runPass(const RenderParams& params, const float* depthMaxT, const float* minT) = 0;

  /// Passes since the last reset().
  int passes() const { return this->Passes; }
  /// The running pass's cancellation (begun and ended by renderPass).
  PassCancellation Cancellation;

private:
  void changed(SceneChange what);

  RenderScene Scene;
  int Width = 0, Height = 0; ///< the accumulation buffers' image size
  int Passes = 0;
};

} // namespace amrdm
