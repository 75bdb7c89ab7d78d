// The private state of vtkAMRDualMeshVolumeMapper, shared by its implementation files:
// vtkAMRDualMeshVolumeMapper.cxx (API, Render(), PrintSelf) and ...Frame.cxx (still and
// interactive frames, read-backs). The concepts are classes of their own: the input slot (input,
// array, dual meshes), the renderer slot, the frame builder and the accumulation.
#pragma once

#include "vtkAMRDualMeshVolumeMapper.h"

#include "AMRDualMeshAccumulation.h"
#include "AMRDualMeshArraySelection.h"
#include "AMRDualMeshFrameBuilder.h"
#include "AMRDualMeshInputSlot.h"
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
#include "vtkImageData.h"
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
    : Input(self)
    , Slot(self)
    , Frames(self)
  {
  }

  AMRDualMeshInputSlot Input;       ///< input, array, dual mesh and the region's proxy (first:
                                    ///< the renderer below holds its meshes)
  AMRDualMeshRendererSlot Slot;     ///< renderer, device, uploads and their time stamps
  AMRDualMeshFrameBuilder Frames;   ///< VTK's view -> kernel parameters and the reset key
  amrdm_vtk::Accumulation Accum;    ///< the running accumulation, its key and image
  amrdm_vtk::Compositor Compositor; ///< opaque depth in, the image drawn over the scene

  amrdm_vtk::RegionClip Region; ///< data-parallel rendering: the box drawn

  amrdm_vtk::InteractionPolicy Interaction; ///< interactive frames: reduction from timed passes
  bool LastRenderInteractive = false;
  int InteractiveReduction = 1; ///< of the last interactive frame

  int SampleLimit = 0; ///< > 0 during RenderUntil(): no pass goes beyond it
  int RenderCount = 0; ///< Render() calls (RenderUntil() notices when none happens)
  bool LastRenderOk = false;
  bool LastRenderAborted = false; ///< VTK's abort check stopped the last pass
};
