#include "AMRDualMeshDepthPeeling.h"

#include "vtkCollection.h"
#include "vtkInformation.h"
#include "vtkOpenGLRenderPass.h"
#include "vtkOutputWindow.h"
#include "vtkProp.h"
#include "vtkPropCollection.h"
#include "vtkRenderer.h"
#include "vtkVolume.h"

namespace amrdm_vtk
{
bool DrawOutsideDepthPeeling(vtkRenderer* ren, vtkVolume* vol)
{
  bool translucent = false;
  vtkCollectionSimpleIterator it;
  for (ren->GetViewProps()->InitTraversal(it);
       vtkProp* prop = ren->GetViewProps()->GetNextProp(it);)
  {
    translucent |= prop != vol && prop->GetVisibility() && prop->HasTranslucentPolygonalGeometry();
  }
  static bool said = false; // VTK renders on one thread
  if (translucent && ren->GetUseDepthPeeling() && !said)
  {
    said = true;
    vtkOutputWindowDisplayText("vtkAMRDualMeshVolumeMapper: translucent geometry in the scene is "
                               "drawn before the dual-mesh volume, not depth-sorted with it (as "
                               "by VTK's volume mappers without depth peeling).\n");
  }
  if (ren->GetUseDepthPeeling() && ren->GetUseDepthPeelingForVolumes())
  {
    ren->SetUseDepthPeelingForVolumes(false);
    vtkInformation* keys = vol->GetPropertyKeys(); // the peeling pass sets its render passes
    return !(keys && keys->Has(vtkOpenGLRenderPass::RenderPasses()));
  }
  return true;
}
}
