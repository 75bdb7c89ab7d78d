// The accumulation of vtkAMRDualMeshVolumeMapper and its reset key: everything the accumulated
// image depends on, gathered and compared in one place. The mapper restarts the accumulation when
// the key of a frame differs from the one it was started with; a process that does not render
// (ParaView's client of a render server) asks the mapper for the same key without the parts only
// a render has (vtkAMRDualMeshVolumeMapper::GetAccumulationKey).
#pragma once

#include "vtkTimeStamp.h"
#include "vtkType.h"

#include "render/RenderParams.h"

#include <vector>

class vtkObject;
class vtkPlaneCollection;
class vtkVolume;
namespace amrdm
{
class Renderer;
}

namespace amrdm_vtk
{
/// What the accumulation follows.
struct AccumulationKey
{
  vtkMTimeType ConfigTime = 0;   ///< MTime of the mapper, the volume property, the clipping planes
  vtkMTimeType SlotTime = 0;     ///< the renderer slot's last change (renderer, mesh, proxy, TF)
  amrdm::RenderParams Params;    ///< the view: camera rays, size, lights, shading coefficients
  std::vector<float> TMin, TMax; ///< per-pixel ray intervals (opaque depth, clipping planes)
  float Tolerance = 0.0f;        ///< intervals this close are the same (re-read depth's last bits)
};

/// The key's time part: the latest MTime of `mapper`, `vol`'s property and each of `planes`.
vtkMTimeType AccumulationConfigTime(vtkObject* mapper, vtkVolume* vol, vtkPlaneCollection* planes);

/// The running accumulation: its key, its sample count and when it was last restarted.
class Accumulation
{
public:
  /// Restarts the accumulation (resets `renderer`, keeps `key`, zero samples) when there is none
  /// or `key` differs from its own; returns whether it did.
  bool Update(AccumulationKey& key, amrdm::Renderer& renderer);

  /// The renderer's accumulation is no longer this one (a renderer, mesh, proxy or transfer
  /// function changed, an interactive frame drew into it, a pass failed): the next Update()
  /// restarts. The one place that ends an accumulation.
  void Invalidate() { this->Valid = false; }

  /// For a process that does not render: the stamp of the last change of `key`'s view or
  /// configuration time (its slot time and intervals are not compared), by the rule of Update().
  vtkMTimeType ClientKey(const AccumulationKey& key);

  const amrdm::RenderParams& GetParams() const { return this->Key.Params; }
  float* GetTMin() { return this->Key.TMin.data(); }
  float* GetTMax() { return this->Key.TMax.data(); }
  vtkMTimeType GetTime() const { return this->Time.GetMTime(); }

  int Samples = 0; ///< samples per pixel accumulated since the last restart

private:
  bool Valid = false;
  AccumulationKey Key;
  vtkTimeStamp Time; ///< when the accumulation was last restarted
  AccumulationKey Client;
  bool HasClient = false;
  vtkTimeStamp ClientTime;
};
}
