// The removed names PathTracerScalarOpacityUnitDistance and PathTracerShade of
// vtkAMRDualMeshRepresentation (before 2026-12-03 the representation had its own unit distance
// and shading; now it uses the Volume representation's ScalarOpacityUnitDistance and Shade). Old
// state files and scripts still load: the values are remembered, compared with the volume
// property at each render, and a value that differs is said once per process (naming the
// property to set instead).
#pragma once

class vtkObject;
class vtkVolumeProperty;

class AMRDualMeshRemovedProperties
{
public:
  double UnitDistance = 0.0; ///< PathTracerScalarOpacityUnitDistance, 0: not set
  int Shade = -1;            ///< PathTracerShade, -1: not set

  /// Warns (as `reporter`, once per process and name) where a remembered value differs from
  /// `property`'s.
  void Report(vtkObject* reporter, vtkVolumeProperty* property) const;
};
