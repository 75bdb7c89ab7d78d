// The interaction policy of vtkAMRDualMeshVolumeMapper. A render is interactive when the render
// window's desired update rate is at least the mapper's InteractiveUpdateRate: VTK's
// vtkRenderWindowInteractor sets 15 frames/s while a button is down (0.0001 otherwise) and
// ParaView's vtkPVRenderView::InteractiveRender() sets 5 (StillRender(): 0.002). An interactive
// frame takes one sample per pixel at a reduced resolution chosen from the measured cost of the
// earlier passes so that it fits the mapper's InteractiveFrameTime; it does not touch the
// accumulation's sample count (the next still render starts a fresh accumulation at full
// resolution). Private to the mapper; not wrapped.
#ifndef AMRDualMeshInteraction_h
#define AMRDualMeshInteraction_h

#include "render/RenderParams.h" // amrdm::RenderParams (and glm)

#include <string>
#include <vector>

class vtkMatrix4x4;
class vtkPlaneCollection;
class vtkRenderWindow;
class vtkRenderer;

namespace amrdm
{
class Renderer;
}

namespace amrdm_vtk
{
class Compositor;

/// The largest per-axis resolution reduction of an interactive frame.
constexpr int kMaxInteractiveReduction = 16;
/// The reduction of an interactive frame before any pass has been timed.
constexpr int kInitialInteractiveReduction = 4;

class InteractionPolicy
{
public:
  /// True when `window` asks for at least `updateRate` frames per second (updateRate > 0).
  static bool IsInteractive(vtkRenderWindow* window, double updateRate);

  /// Records a timed pass: `seconds` for `pixelSamples` = width * height * samples per pixel.
  void RecordPass(double seconds, double pixelSamples);

  /// Per-axis reduction 1..kMaxInteractiveReduction under which a width x height frame of one
  /// sample per pixel is predicted to take at most `budget` seconds; 1 when budget <= 0 (no
  /// reduction), kInitialInteractiveReduction before any pass was timed.
  int Reduction(double budget, int width, int height) const;

  /// Seconds per pixel sample measured so far (0 before any pass).
  double GetSecondsPerPixelSample() const { return this->SecondsPerPixelSample; }

  /// Reduced image size: ceil(width / f) x ceil(height / f).
  static void ReducedSize(int width, int height, int f, int& rw, int& rh);

  /// The nearest depth of each f x f block of `depth` (width x height, rows from the bottom), so
  /// a reduced camera ray stops at the nearest surface of the pixels it stands for.
  static void ReduceDepth(const std::vector<float>& depth,
    int width,
    int height,
    int f,
    std::vector<float>& reduced);

  /// Renders and draws one interactive frame: `params` is the full-size frame (camera, lights,
  /// integrator; `model` is the vtkVolume's matrix, null for the identity, as for a still
  /// frame); it is rendered at the Reduction(budget) size with one sample per pixel (the
  /// renderer's accumulation is reset), drawn stretched over the viewport and timed. Returns
  /// false with `error` set when the renderer fails. `reduction` receives the factor used.
  bool RenderFrame(vtkRenderer* ren,
    amrdm::Renderer& renderer,
    Compositor& compositor,
    amrdm::RenderParams params,
    const int viewport[4],
    vtkPlaneCollection* planes,
    vtkMatrix4x4* model,
    const glm::dvec3& sceneOrigin,
    double budget,
    int& reduction,
    std::string& error);

private:
  double SecondsPerPixelSample = 0.0; ///< running mean (weight 1/2 for the newest pass)
};
}

#endif
