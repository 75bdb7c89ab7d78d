// The private state of vtkAMRDualMeshVolumeMapper, shared by its implementation files:
// vtkAMRDualMeshVolumeMapper.cxx (API, input, Render(), PrintSelf), ...Frame.cxx (still and
// interactive frames) and ...Region.cxx (data-parallel region and proxy). The concepts are
// classes of their own: the renderer slot, the frame builder and the accumulation.
#pragma once

#include "vtkAMRDualMeshVolumeMapper.h"

#include "AMRDualMeshAccumulation.h"
#include "AMRDualMeshArraySelection.h"
#include "AMRDualMeshFrameBuilder.h"
#include "AMRDualMeshRendererSlot.h"
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
  explicit Internals(vtkAMRDualMeshVolumeMapper* self)
    : Slot(self)
    , Frames(self)
  {
  }

  // The input's dual mesh (vtkAMRDualMesh::BuildTime follows the input, array and parameters).
  vtkNew<vtkAMRDualMesh> Mesh;
  vtkNew<vtkCallbackCommand> ProgressForwarder;
  vtkNew<vtkCallbackCommand> ErrorCatcher;
  std::string MeshError;  ///< last error reported by the dual mesh
  std::string InputError; ///< the last point-data refusal (said once per array)

  AMRDualMeshRendererSlot Slot;     ///< renderer, device, uploads and their time stamps
  AMRDualMeshFrameBuilder Frames;   ///< VTK's view -> kernel parameters and the reset key
  amrdm_vtk::Accumulation Accum;    ///< the running accumulation, its key and image
  amrdm_vtk::Compositor Compositor; ///< opaque depth in, the image drawn over the scene

  amrdm_vtk::RegionClip Region;                  ///< data-parallel rendering: the box drawn
  vtkSmartPointer<vtkOverlappingAMR> ProxyInput; ///< the region's proxy (SetRegionProxy)
  vtkNew<vtkAMRDualMesh> ProxyMesh;              ///< its dual mesh

  amrdm_vtk::InteractionPolicy Interaction; ///< interactive frames: reduction from timed passes
  bool LastRenderInteractive = false;
  int InteractiveReduction = 1; ///< of the last interactive frame

  int SampleLimit = 0; ///< > 0 during RenderUntil(): no pass goes beyond it
  int RenderCount = 0; ///< Render() calls (RenderUntil() notices when none happens)
  bool LastRenderOk = false;
  bool LastRenderAborted = false; ///< VTK's abort check stopped the last pass

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
