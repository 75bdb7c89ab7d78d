// The accumulation of vtkAMRDualMeshVolumeMapper and its reset key: everything the accumulated
// image depends on, gathered and compared in one place. The mapper restarts the accumulation when
// the key of a frame differs from the one it was started with; a process that does not render
// (ParaView's client of a render server) asks the mapper for the same key without the parts only
// a render has (vtkAMRDualMeshVolumeMapper::GetAccumulationKey).
#pragma once

#include "vtkTimeStamp.h"
#include "vtkType.h"

#include "render/RenderParams.h"

#include <string>
#include <vector>

class vtkObject;
class vtkPlaneCollection;
class vtkRenderWindow;
class vtkVolume;
namespace amrdm
{
class Renderer;
}

namespace amrdm_vtk
{
class InteractionPolicy;

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

/// The running accumulation: its key, its sample count, when it was last restarted, its image and
/// the sample count of the last untiled view (what a screenshot's tiles are rendered to).
class Accumulation
{
public:
  /// Restarts the accumulation (resets `renderer`, keeps `key`, zero samples) when there is none
  /// or `key` differs from its own; returns whether it did.
  bool Update(AccumulationKey& key, amrdm::Renderer& renderer);

  /// The renderer's accumulation is no longer this one (an interactive frame drew into it, a
  /// pass failed): the next Update() restarts. The one place that ends an accumulation other than
  /// the key (a renderer, mesh, proxy or transfer function change is the slot's stamp in it).
  void Invalidate() { this->Valid = false; }

  /// For a process that does not render: the stamp of the last change of `key`'s view or
  /// configuration time (its slot time and intervals are not compared), by the rule of Update().
  vtkMTimeType ClientKey(const AccumulationKey& key);

  /// Renders one pass of `samplesPerRender` samples per pixel (fewer where `limit` is reached;
  /// none when the accumulation is at `limit` and was not `reset`: only the image stays), with
  /// VTK's abort check on `window` (null: none). A completed pass is timed into `interaction`;
  /// an aborted one sets `aborted` and keeps its finished tiles. False with `error` when the
  /// renderer throws (the accumulation ends, the image is cleared).
  bool AddSamples(amrdm::Renderer& renderer,
    amrdm::RenderParams params,
    bool reset,
    int limit,
    int samplesPerRender,
    vtkRenderWindow* window,
    InteractionPolicy& interaction,
    bool& aborted,
    std::string& error);

  /// After a still frame's pass: a tile of a screenshot magnification (`tiled`) is rendered to the
  /// sample count of the untiled view (these passes do not poll the abort check); an untiled
  /// frame records that count (a resize alone, as before ParaView tiles a screenshot, keeps it).
  /// False with `error` as AddSamples().
  bool MatchView(amrdm::Renderer& renderer,
    const amrdm::RenderParams& params,
    bool reset,
    bool tiled,
    int limit,
    int samplesPerRender,
    InteractionPolicy& interaction,
    bool& aborted,
    std::string& error);

  /// A still frame: Update() with `key`, AddSamples() (abort check on `window`), repeated while
  /// the accumulation is below `limit` and less than `budget` seconds have passed since the frame
  /// began (0: one pass; the pass that crosses the budget finishes), then MatchView() for a tile
  /// of a screenshot magnification (`window`'s TileScale > 1).
  bool RenderStill(AccumulationKey& key,
    amrdm::Renderer& renderer,
    const amrdm::RenderParams& params,
    int limit,
    int samplesPerRender,
    double budget,
    vtkRenderWindow* window,
    InteractionPolicy& interaction,
    bool& aborted,
    std::string& error);

  /// Writes the image to an OpenEXR file; false with `error` without a file name or an image, or
  /// when writing fails.
  bool WriteEXR(const char* fileName, std::string& error) const;

  vtkMTimeType GetTime() const { return this->Time.GetMTime(); }
  /// The mean premultiplied RGBA of the accumulation (ImageSize), empty after an error.
  const std::vector<float>& GetImage() const { return this->Image; }
  const int* GetImageSize() const { return this->ImageSize; }

  int Samples = 0; ///< samples per pixel accumulated since the last restart

private:
  bool Valid = false;
  AccumulationKey Key;
  vtkTimeStamp Time; ///< when the accumulation was last restarted
  std::vector<float> Image;
  int ImageSize[2] = { 0, 0 };
  int ViewSamples = 0;        ///< samples of the last untiled view: what screenshot tiles get
  int ViewSize[2] = { 0, 0 }; ///< its size
  AccumulationKey Client;
  bool HasClient = false;
  vtkTimeStamp ClientTime;
};
}
