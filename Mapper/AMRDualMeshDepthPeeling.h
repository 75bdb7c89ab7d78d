// vtkAMRDualMeshVolumeMapper and depth peeling. Not wrapped.
#pragma once

class vtkRenderer;
class vtkVolume;

namespace amrdm_vtk
{
/// Depth peeling for volumes (ParaView's default) makes VTK run its peeling passes, volumes
/// inside, whenever the flag is on: our composite would land in the peeling buffers (stripes).
/// As by VTK's default the volume is drawn over translucent geometry: the flag is switched off,
/// silently, and a notice says so once per process where translucent geometry is in the scene.
/// False for a frame already inside the peeling pass: it draws nothing, the next one does.
bool DrawOutsideDepthPeeling(vtkRenderer* ren, vtkVolume* vol);
}
