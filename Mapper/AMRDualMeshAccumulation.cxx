#include "AMRDualMeshAccumulation.h"

#include "AMRDualMeshAbortablePass.h"
#include "AMRDualMeshBlendMode.h"
#include "AMRDualMeshImageIO.h"
#include "AMRDualMeshInteraction.h"
#include "AMRDualMeshProjection.h"
#include "vtkCollection.h"
#include "vtkPlane.h"
#include "vtkPlaneCollection.h"
#include "vtkRenderWindow.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include "render/Renderer.h"

#include <algorithm>
#include <chrono>
#include <exception>

namespace amrdm_vtk
{
namespace
{
bool SameView(const amrdm::RenderParams& a, const amrdm::RenderParams& b)
{
  if (!amrdm_vtk::SameRays(a.camera, b.camera) || a.width != b.width || a.height != b.height ||
      a.numLights != b.numLights || a.gradientShading != b.gradientShading ||
      a.ambientCoefficient != b.ambientCoefficient ||
      a.diffuseCoefficient != b.diffuseCoefficient ||
      a.specularCoefficient != b.specularCoefficient || a.specularPower != b.specularPower ||
      !SameBlend(a, b))
  {
    return false;
  }
  for (int i = 0; i < a.numLights; ++i)
  {
    const amrdm::Light &la = a.lights[i], &lb = b.lights[i];
    if (la.type != lb.type || la.direction != lb.direction || la.position != lb.position ||
        la.color != lb.color || la.intensity != lb.intensity)
    {
      return false;
    }
  }
  return true;
}
}

//------------------------------------------------------------------------------
vtkMTimeType AccumulationConfigTime(vtkObject* mapper, vtkVolume* vol, vtkPlaneCollection* planes)
{
  // Parameters and property by MTime (the view, lights, size and intervals are compared by value).
  vtkMTimeType time = std::max(mapper->GetMTime(), vol->GetProperty()->GetMTime());
  if (planes)
  {
    vtkCollectionSimpleIterator it;
    planes->InitTraversal(it);
    while (vtkPlane* plane = planes->GetNextPlane(it))
    {
      time = std::max(time, plane->GetMTime());
    }
  }
  return time;
}

//------------------------------------------------------------------------------
bool Accumulation::Update(AccumulationKey& key, amrdm::Renderer& renderer)
{
  const vtkMTimeType started = this->Time.GetMTime();
  const bool reset =
    !this->Valid || key.ConfigTime > started || key.SlotTime > started ||
    !SameView(key.Params, this->Key.Params) ||
    !amrdm_vtk::SameIntervals(key.TMin, key.TMax, this->Key.TMin, this->Key.TMax, key.Tolerance);
  if (reset)
  {
    renderer.reset();
    this->Samples = 0;
    std::swap(this->Key, key);
    this->Valid = true;
    this->Time.Modified();
  }
  return reset;
}

//------------------------------------------------------------------------------
vtkMTimeType Accumulation::ClientKey(const AccumulationKey& key)
{
  if (!this->HasClient || key.ConfigTime > this->ClientTime.GetMTime() ||
      !SameView(key.Params, this->Client.Params))
  {
    this->Client.Params = key.Params;
    this->HasClient = true;
    this->ClientTime.Modified();
  }
  return this->ClientTime.GetMTime();
}

//------------------------------------------------------------------------------
bool Accumulation::AddSamples(amrdm::Renderer& renderer,
  amrdm::RenderParams params,
  bool reset,
  int limit,
  int samplesPerRender,
  vtkRenderWindow* window,
  InteractionPolicy& interaction,
  bool& aborted,
  std::string& error)
{
  if (this->Samples >= limit && !reset)
  {
    return true; // converged: only re-composite
  }
  params.samplesPerPass = std::max(1, std::min(samplesPerRender, limit - this->Samples));
  try
  {
    const auto start = std::chrono::steady_clock::now();
    if (RenderAbortablePass(
          renderer, params, this->Key.TMax.data(), this->Key.TMin.data(), window) ==
        PassOutcome::Completed)
    {
      this->Samples += params.samplesPerPass;
      // The cost per pixel sample sizes the next interactive frame.
      interaction.RecordPass(
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(),
        double(params.width) * params.height * params.samplesPerPass);
    }
    else
    {
      aborted = true; // finished tiles kept their samples: the mean stays valid
    }
    this->Image = renderer.image();
  }
  catch (const std::exception& e) // e.g. accumulation buffers larger than the free memory
  {
    error = e.what();
    this->Invalidate();
    this->Image.clear();
    return false;
  }
  this->ImageSize[0] = params.width;
  this->ImageSize[1] = params.height;
  return true;
}

//------------------------------------------------------------------------------
bool Accumulation::MatchView(amrdm::Renderer& renderer,
  const amrdm::RenderParams& params,
  bool reset,
  bool tiled,
  int limit,
  int samplesPerRender,
  InteractionPolicy& interaction,
  bool& aborted,
  std::string& error)
{
  // A tile of a large screenshot (vtkWindowToImageFilter / vtkRenderLargeImage scale,
  // ParaView's SaveScreenshot at another resolution) is rendered to the sample count the view
  // had: each tile is a new view, and a screenshot must not be noisier than the view it copies.
  if (tiled)
  {
    while (this->Samples < this->ViewSamples)
    {
      const int before = this->Samples;
      if (!this->AddSamples(
            renderer, params, false, limit, samplesPerRender, nullptr, interaction, aborted, error))
      {
        return false;
      }
      if (this->Samples == before)
      {
        break; // at MaximumSamples
      }
    }
    return true;
  }
  // A resize alone (ParaView shrinks the view before it tiles a screenshot) keeps the count.
  const bool resized = params.width != this->ViewSize[0] || params.height != this->ViewSize[1];
  this->ViewSamples = reset && resized ? std::max(this->ViewSamples, this->Samples) : this->Samples;
  this->ViewSize[0] = params.width;
  this->ViewSize[1] = params.height;
  return true;
}
//------------------------------------------------------------------------------
bool Accumulation::RenderStill(AccumulationKey& key,
  amrdm::Renderer& renderer,
  const amrdm::RenderParams& params,
  int limit,
  int samplesPerRender,
  double budget,
  vtkRenderWindow* window,
  InteractionPolicy& interaction,
  bool& aborted,
  std::string& error)
{
  const auto start = std::chrono::steady_clock::now();
  const bool reset = this->Update(key, renderer);
  if (!this->AddSamples(
        renderer, params, reset, limit, samplesPerRender, window, interaction, aborted, error))
  {
    return false;
  }
  // A final frame (budget > 0) refines to its target: MaximumSamples, or the time budget.
  while (budget > 0.0 && !aborted && this->Samples < limit &&
         std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() < budget)
  {
    const int before = this->Samples;
    if (!this->AddSamples(
          renderer, params, false, limit, samplesPerRender, window, interaction, aborted, error))
    {
      return false;
    }
    if (this->Samples == before)
    {
      break;
    }
  }
  const int* tileScale = window->GetTileScale();
  return this->MatchView(renderer,
    params,
    reset,
    tileScale[0] > 1 || tileScale[1] > 1,
    limit,
    samplesPerRender,
    interaction,
    aborted,
    error);
}

bool Accumulation::WriteEXR(const char* fileName, std::string& error) const
{
  if (!fileName || this->Image.empty())
  {
    error = fileName ? "nothing rendered yet" : "no file name";
    return false;
  }
  return amrdm_vtk::WriteEXR(
    fileName, this->ImageSize[0], this->ImageSize[1], this->Image.data(), error);
}
}
