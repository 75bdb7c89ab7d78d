// What vtkAMRDualMeshRepresentation asks of the view for compositing several ranks' images.
#pragma once

class vtkInformation;

namespace amrdm_vtk
{
/// A client connected to a server of several ranks (whose views take the client's FXAA setting
/// with every render).
bool ClientOfSeveralRanks();

/// FXAA runs on each rank's image before IceT composites them: it blurs the hard edge where a
/// region's image ends, and the blur shows along every cut (measured: up to 15/255 off one
/// rank's image). Switched off on the view of `inInfo` (a view request's), said once per
/// process. Called for a distributed representation and on a client's view of several server
/// ranks, before the update and before each render.
void SwitchOffFXAA(vtkInformation* inInfo);
}
