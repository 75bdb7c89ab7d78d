// Interactive frames of vtkAMRDualMeshVolumeMapper. See AMRDualMeshInteraction.h.
#include "AMRDualMeshInteraction.h"

#include "AMRDualMeshCompositor.h"
#include "AMRDualMeshProjection.h"
#include "AMRDualMeshSceneConversion.h"
#include "render/Renderer.h"
#include "vtkCamera.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>

namespace amrdm_vtk
{

bool InteractionPolicy::IsInteractive(vtkRenderWindow* window, double updateRate)
{
  return window && updateRate > 0.0 && window->GetDesiredUpdateRate() >= updateRate;
}

void InteractionPolicy::RecordPass(double seconds, double pixelSamples)
{
  if (!(seconds > 0.0) || !(pixelSamples > 0.0))
  {
    return;
  }
  const double cost = seconds / pixelSamples;
  this->SecondsPerPixelSample =
    this->SecondsPerPixelSample > 0.0 ? 0.5 * (this->SecondsPerPixelSample + cost) : cost;
}

int InteractionPolicy::Reduction(double budget, int width, int height) const
{
  if (!(budget > 0.0))
  {
    return 1;
  }
  if (!(this->SecondsPerPixelSample > 0.0))
  {
    return kInitialInteractiveReduction;
  }
  const double predicted = this->SecondsPerPixelSample * double(width) * double(height);
  const double f = std::ceil(std::sqrt(predicted / budget));
  return int(std::clamp(f, 1.0, double(kMaxInteractiveReduction)));
}

void InteractionPolicy::ReducedSize(int width, int height, int f, int& rw, int& rh)
{
  f = std::max(1, f);
  rw = std::max(1, (width + f - 1) / f);
  rh = std::max(1, (height + f - 1) / f);
}

void InteractionPolicy::ReduceDepth(const std::vector<float>& depth,
  int width,
  int height,
  int f,
  std::vector<float>& reduced)
{
  int rw = 0, rh = 0;
  ReducedSize(width, height, f, rw, rh);
  reduced.assign(static_cast<std::size_t>(rw) * rh, 1.0f);
  if (depth.size() != static_cast<std::size_t>(width) * height)
  {
    return; // no depth: nothing drawn
  }
  for (int y = 0; y < height; ++y)
  {
    const float* row = depth.data() + static_cast<std::size_t>(y) * width;
    float* out = reduced.data() + static_cast<std::size_t>(y / f) * rw;
    for (int x = 0; x < width; ++x)
    {
      out[x / f] = std::min(out[x / f], row[x]);
    }
  }
}

bool InteractionPolicy::RenderFrame(vtkRenderer* ren,
  amrdm::Renderer& renderer,
  Compositor& compositor,
  amrdm::RenderParams params,
  const int viewport[4],
  vtkPlaneCollection* planes,
  vtkMatrix4x4* model,
  const glm::dvec3& sceneOrigin,
  double budget,
  int& reduction,
  std::string& error)
{
  const auto start = std::chrono::steady_clock::now();
  const int x0 = viewport[0], y0 = viewport[1], width = viewport[2], height = viewport[3];
  reduction = this->Reduction(budget, width, height);
  int rw = 0, rh = 0;
  ReducedSize(width, height, reduction, rw, rh);

  // Ray intervals at the reduced size: the nearest opaque depth of each block, the clipping
  // planes as for a still frame. The camera keeps the viewport's aspect (MakeRenderParams).
  std::vector<float> depth, reducedDepth, tMin, tMax;
  compositor.ReadDepth(ren, x0, y0, width, height, depth);
  ReduceDepth(depth, width, height, reduction, reducedDepth);
  // The projection's NDC does not depend on the pixel count: the full frame's camera and
  // unprojection serve the reduced grid (AMRDualMeshProjection.h).
  double ndcToScene[16];
  const bool invertible = NdcToScene(ren, model, sceneOrigin, ndcToScene);
  ComputeRayIntervals(params.camera,
    rw,
    rh,
    invertible ? reducedDepth.data() : nullptr,
    ndcToScene,
    planes,
    model,
    sceneOrigin,
    tMin,
    tMax);

  params.width = rw;
  params.height = rh;
  params.samplesPerPass = 1;
  std::vector<float> image;
  try
  {
    renderer.reset();
    renderer.renderPass(params, tMax.data(), tMin.data());
    image = renderer.image();
  }
  catch (const std::exception& e)
  {
    error = e.what();
    return false;
  }
  if (image.size() == std::size_t(4) * rw * rh)
  {
    compositor.Draw(ren, rw, rh, image.data());
  }
  const double seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  this->RecordPass(seconds, double(rw) * double(rh));
  return true;
}
}
