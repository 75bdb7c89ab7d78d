// The scene and pass frame every renderer backend shares. See SceneRenderer.h.
#include "render/SceneRenderer.h"

namespace amrdm
{

void SceneRenderer::setMesh(const DualMesh* mesh, glm::ivec3 majorantResolution, int threads)
{
  this->Scene.setMesh(mesh, majorantResolution, threads);
  this->changed(SceneChange::Mesh);
}

void SceneRenderer::setTransferFunction(const TransferFunction& tf, int threads)
{
  this->Scene.setTransferFunction(tf, threads);
  this->changed(SceneChange::TransferFunction);
}

void SceneRenderer::setProxy(const DualMesh* proxy,
  const glm::vec3& lo,
  const glm::vec3& hi,
  int threads)
{
  this->Scene.setProxy(proxy, lo, hi, threads);
  this->changed(SceneChange::Proxy);
}

void SceneRenderer::changed(SceneChange what)
{
  this->sceneChanged(what);
  this->reset();
}

void SceneRenderer::reset()
{
  this->clearAccumulation();
  this->Passes = 0;
}

bool SceneRenderer::renderPass(const RenderParams& userParams,
  const float* depthMaxT,
  const float* minT)
{
  if (!this->Scene.ready() || userParams.width <= 0 || userParams.height <= 0)
  {
    return true;
  }
  if (userParams.width != this->Width || userParams.height != this->Height)
  {
    this->Width = this->Height = 0; // until the new buffers exist
    this->resizeAccumulation(userParams.width, userParams.height);
    this->Width = userParams.width;
    this->Height = userParams.height;
    this->reset();
  }
  if (this->Scene.updateMajorantResolution(userParams))
  {
    this->changed(SceneChange::MajorantResolution);
  }
  const RenderParams params = this->Scene.resolve(userParams);
  this->Cancellation.begin();
  this->runPass(params, depthMaxT, minT);
  ++this->Passes;
  return !this->Cancellation.end();
}

} // namespace amrdm
