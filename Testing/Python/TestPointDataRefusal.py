"""Point (vertex-centred) AMR arrays (issue 13): the mapper renders cell data only, so a point
array must be refused by name with what works, never drawn as a silent blank. The AMReX
advection set through vtkCellDataToPointData gives a point array 'phi'. Checks:
1. ScalarMode UsePointFieldData + SelectScalarArray('phi') (what ParaView's "Dual-Mesh Path
   Tracer" passes for ColorBy(('POINTS', 'phi'))): one error naming 'phi' and the way out
   ("Point Data to Cell Data"), not repeated on the next render, and nothing drawn;
2. the default scalar mode with the name of an array that exists only as point data: the same
   error;
3. what the message says works: vtkPointDataToCellData back to cells renders a picture (mean
   brightness over the image > 0.02 on a black background, where a blank frame gives 0)."""
import os
import sys

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonDataModel import vtkPiecewiseFunction
from vtkmodules.vtkFiltersCore import vtkCellDataToPointData, vtkPointDataToCellData
from vtkmodules.vtkIOAMR import vtkAMReXGridReader
from vtkmodules.vtkRenderingCore import (vtkColorTransferFunction, vtkRenderer, vtkRenderWindow,
                                         vtkVolume, vtkVolumeProperty, vtkWindowToImageFilter)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401

from amrdualmesh import vtkAMRDualMeshVolumeMapper

from amrdm_testing import TEST_DATA, ErrorRecorder

reader = vtkAMReXGridReader()
reader.SetFileName(os.path.join(TEST_DATA, "amrex-advection-amrcore3d", "plt00040"))
reader.UpdateInformation()
reader.SetMaxLevel(99)
reader.GetCellDataArraySelection().EnableAllArrays()
toPoints = vtkCellDataToPointData()
toPoints.SetInputConnection(reader.GetOutputPort())
toPoints.Update()
pointAmr = toPoints.GetOutputDataObject(0)
print("vtkCellDataToPointData gives a", pointAmr.GetClassName())

color = vtkColorTransferFunction()
color.AddRGBPoint(1.0, 0.23, 0.30, 0.75)
color.AddRGBPoint(2.0, 0.71, 0.02, 0.15)
opacity = vtkPiecewiseFunction()
opacity.AddPoint(1.0, 0.0)
opacity.AddPoint(1.3, 0.3)
opacity.AddPoint(2.0, 0.9)
prop = vtkVolumeProperty()
prop.SetColor(color)
prop.SetScalarOpacity(opacity)
prop.SetScalarOpacityUnitDistance(0.02)

failures = []


def scene(data, point_mode):
    window = vtkRenderWindow()
    window.SetSize(120, 90)
    window.SetMultiSamples(0)
    ren = vtkRenderer()
    ren.SetBackground(0.0, 0.0, 0.0)
    window.AddRenderer(ren)
    mapper = vtkAMRDualMeshVolumeMapper()
    mapper.SetInputData(data)
    if point_mode:
        mapper.SetScalarModeToUsePointFieldData()
    mapper.SelectScalarArray("phi")
    mapper.SetIntegrator(vtkAMRDualMeshVolumeMapper.RAY_MARCH)
    mapper.SetStepSize(0.01)
    mapper.SetMaximumSamples(2)
    errors = ErrorRecorder(mapper)
    volume = vtkVolume()
    volume.SetMapper(mapper)
    volume.SetProperty(prop)
    ren.AddVolume(volume)
    cam = ren.GetActiveCamera()
    cam.SetFocalPoint(0.5, 0.5, 0.12)
    cam.SetPosition(1.2, -0.6, 1.0)
    cam.SetViewUp(0.0, 0.0, 1.0)
    ren.ResetCameraClippingRange()
    return window, mapper, errors


def brightness(window):
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.ShouldRerenderOff()
    grab.ReadFrontBufferOff()
    grab.Update()
    return vtk_to_numpy(grab.GetOutput().GetPointData().GetScalars())[:, :3].mean() / 255.0


for case, point_mode in (("UsePointFieldData", True), ("default scalar mode", False)):
    window, mapper, errors = scene(pointAmr, point_mode)
    window.Render()
    window.Render()
    ok = (len(errors.errors) == 1 and "'phi'" in errors.errors[0] and
          "Point Data to Cell Data" in errors.errors[0] and mapper.GetNumberOfSamples() == 0)
    print(f"{case}: {len(errors.errors)} error(s) over two renders: "
          f"{errors.errors[0] if errors.errors else '(none)'} {'ok' if ok else 'FAIL'}")
    if not ok:
        failures.append(case)

back = vtkPointDataToCellData()
back.SetInputData(pointAmr)
back.Update()
window, mapper, errors = scene(back.GetOutputDataObject(0), False)
mapper.RenderUntil(window, 2)
level = brightness(window)
ok = not errors.errors and mapper.GetNumberOfSamples() == 2 and level > 0.02
print(f"after vtkPointDataToCellData: {mapper.GetNumberOfSamples()} samples, mean brightness "
      f"{level:.3f} (> 0.02) {'ok' if ok else 'FAIL'} {errors.errors or ''}")
if not ok:
    failures.append("point data converted back to cells")

if failures:
    print("FAIL:", ", ".join(failures))
    sys.exit(1)
print("PASS")
