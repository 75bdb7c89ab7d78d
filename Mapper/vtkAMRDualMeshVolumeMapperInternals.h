// The private state of vtkAMRDualMeshVolumeMapper, shared by its implementation files:
// vtkAMRDualMeshVolumeMapper.cxx (API, Render(), PrintSelf), ...Upload.cxx (the renderer, its
// mesh and transfer function) and ...Frame.cxx (render parameters, accumulation, passes).
#pragma once

#include "vtkAMRDualMeshVolumeMapper.h"

#include "AMRDualMeshAccumulation.h"
#include "AMRDualMeshArraySelection.h"
#include "AMRDualMeshCompositor.h"
#include "AMRDualMeshImageIO.h"
#include "AMRDualMeshInteraction.h"
#include "AMRDualMeshProjection.h"
#include "AMRDualMeshRegion.h"
#include "AMRDualMeshSceneConversion.h"
#include "vtkAMRDualMesh.h"
#include "vtkCallbackCommand.h"
#include "vtkCamera.h"
#include "vtkCellData.h"
#include "vtkColorTransferFunction.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkDataSetAttributes.h"
#include "vtkInformation.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderPass.h"
#include "vtkOutputWindow.h"
#include "vtkOverlappingAMR.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPlane.h"
#include "vtkPlaneCollection.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkUniformGrid.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include "mesh/DualMesh.h"
#include "render/RendererFactory.h"

#include <algorithm>
#include <chrono>
#include <cstring>
#include <exception>
#include <mutex>
#include <set>
#include <string>
#include <vector>

struct vtkAMRDualMeshVolumeMapper::Internals
{
  vtkNew<vtkAMRDualMesh> Mesh;
  vtkNew<vtkCallbackCommand> ProgressForwarder;
  vtkNew<vtkCallbackCommand> ErrorCatcher;
  std::string MeshError;  ///< last error reported by the dual mesh
  std::string InputError; ///< the last point-data refusal (said once per array)

  std::unique_ptr<amrdm::Renderer> Renderer; ///< created for Device by UpdateRenderer()
  int RendererDevice = -1;                   ///< the Device it was created for
  std::string DeviceError;                   ///< why the last creation failed (said once)
  std::string DeviceReport;                  ///< the factory's last line (device chosen, why)
  amrdm_vtk::Compositor Compositor;
  const amrdm::DualMesh* MeshInRenderer = nullptr;
  vtkMTimeType MeshBuildTime = 0;

  // Transfer function currently in the renderer, and what it was sampled from.
  amrdm::TransferFunction Tf;
  bool HasTf = false;
  vtkVolumeProperty* TfProperty = nullptr;
  const void* TfFunctions[2] = { nullptr, nullptr };
  std::string TfWarning; ///< the last transfer-function warning (said once)

  amrdm_vtk::Accumulation Accum; ///< what the current accumulation was rendered with
  int ViewSamples = 0;           ///< samples of the last untiled view: what screenshot tiles get
  int ViewSize[2] = { 0, 0 };    ///< its size

  std::vector<float> Image; ///< mean premultiplied RGBA of the accumulation
  int ImageSize[2] = { 0, 0 };

  amrdm_vtk::RegionClip Region;                     ///< data-parallel rendering: the box drawn
  vtkSmartPointer<vtkOverlappingAMR> ProxyInput;    ///< the region's proxy (SetRegionProxy)
  vtkNew<vtkAMRDualMesh> ProxyMesh;                 ///< its dual mesh
  const amrdm::DualMesh* ProxyInRenderer = nullptr; ///< the proxy last given to the renderer
  bool ProxyAccepted = false;                       ///< ... and the renderer took it
  vtkMTimeType ProxyBuildTime = 0;
  double ProxyBox[6] = { 0, 0, 0, 0, 0, 0 }; ///< the region it was given to the renderer for
  std::string ProxyError;                    ///< why the renderer refused it (said once)
  amrdm_vtk::InteractionPolicy Interaction;  ///< interactive frames: reduction from timed passes
  bool LastRenderInteractive = false;
  int InteractiveReduction = 1; ///< of the last interactive frame

  int SampleLimit = 0; ///< > 0 during RenderUntil(): no pass goes beyond it
  int RenderCount = 0; ///< Render() calls (RenderUntil() notices when none happens)
  bool LastRenderOk = false;
  bool LastRenderAborted = false; ///< VTK's abort check stopped the last pass
  bool WarnedLights = false;
  std::string BlendWarning; ///< the last blend-mode warning (AMRDualMeshBlendMode.h): said once

  static void ForwardProgress(vtkObject*, unsigned long, void* clientData, void* callData)
  {
    auto* self = static_cast<vtkAMRDualMeshVolumeMapper*>(clientData);
    if (callData)
    {
      self->UpdateProgress(*static_cast<double*>(callData));
    }
  }
  static void CatchError(vtkObject*, unsigned long, void* clientData, void* callData)
  {
    auto* self = static_cast<Internals*>(clientData);
    self->MeshError = callData ? static_cast<const char*>(callData) : "unknown error";
  }
};
