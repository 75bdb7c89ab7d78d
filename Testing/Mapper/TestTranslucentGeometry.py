"""Translucent geometry with the volume (issue 13), plain VTK with depth peeling on (as ParaView
has it): the AMReX advection set (phi), RAY_MARCH, and a sphere of opacity 0.4 partly inside
the slab, 160 x 120, no multisampling. Renders (A) the volume alone, (B) the volume and the
translucent sphere, (C) the sphere alone, all with the renderer's depth peeling on.
Asserts: outside the sphere's pixels (where C differs from the background, grown by 1 pixel),
A and B agree (mean |difference| per channel < 0.01, 99.5th percentile < 0.1: jitter noise);
inside them B differs from A (the sphere is visible, mean > 0.02); depth peeling was used; and
no OpenGL error and no VTK error is reported (vtkStringOutputWindow). As with VTK's own volume
mappers without UseDepthPeelingForVolumes, the volume is composited after the translucent pass,
over it (only opaque depth clips the rays). Note: with multisampling on, this Mesa's
vtkDualDepthPeelingPass itself reports glBindFramebuffer errors and drops translucent
geometry, with or without a volume in the scene; that is VTK's, so the test runs without MSAA.
Writes TestTranslucentGeometry-{A,B,C}.png to the folder given with -T."""
import os
import sys

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkOutputWindow, vtkStringOutputWindow
from vtkmodules.vtkCommonDataModel import vtkPiecewiseFunction
from vtkmodules.vtkFiltersSources import vtkSphereSource
from vtkmodules.vtkIOAMR import vtkAMReXGridReader
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingCore import (vtkActor, vtkColorTransferFunction, vtkPolyDataMapper,
                                         vtkRenderer, vtkRenderWindow, vtkVolume,
                                         vtkVolumeProperty, vtkWindowToImageFilter)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401

from amrdualmesh import vtkAMRDualMeshVolumeMapper

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "Support"))
from amrdm_testing import TEST_DATA  # noqa: E402

W, H, SAMPLES = 160, 120, 4
MEAN_MAX, P995_MAX, VISIBLE_MIN = 0.01, 0.1, 0.02
TEMP = None
for i, arg in enumerate(sys.argv):
    if arg == "-T" and i + 1 < len(sys.argv):
        TEMP = sys.argv[i + 1]
log = vtkStringOutputWindow()
vtkOutputWindow.SetInstance(log)

reader = vtkAMReXGridReader()
reader.SetFileName(os.path.join(TEST_DATA, "amrex-advection-amrcore3d", "plt00040"))
reader.UpdateInformation()
reader.SetMaxLevel(99)
reader.GetCellDataArraySelection().EnableAllArrays()
reader.Update()
amr = reader.GetOutputDataObject(0)
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


def render(with_volume, with_sphere, name):
    window = vtkRenderWindow()
    window.SetSize(W, H)
    window.SetMultiSamples(0)
    window.SetAlphaBitPlanes(1)
    ren = vtkRenderer()
    ren.SetBackground(0.1, 0.1, 0.1)
    ren.SetUseDepthPeeling(1)
    window.AddRenderer(ren)
    mapper = vtkAMRDualMeshVolumeMapper()
    if with_volume:
        mapper.SetInputData(amr)
        mapper.SelectScalarArray("phi")
        mapper.SetIntegrator(vtkAMRDualMeshVolumeMapper.RAY_MARCH)
        mapper.SetStepSize(0.01)
        mapper.SetSamplesPerRender(2)
        volume = vtkVolume()
        volume.SetMapper(mapper)
        volume.SetProperty(prop)
        ren.AddVolume(volume)
    if with_sphere:
        sphere = vtkSphereSource()
        sphere.SetCenter(0.64, 0.52, 0.25)
        sphere.SetRadius(0.15)
        sphere.SetThetaResolution(32)
        sphere.SetPhiResolution(32)
        sphereMapper = vtkPolyDataMapper()
        sphereMapper.SetInputConnection(sphere.GetOutputPort())
        actor = vtkActor()
        actor.SetMapper(sphereMapper)
        actor.GetProperty().SetColor(0.2, 0.9, 0.2)
        actor.GetProperty().SetOpacity(0.4)
        ren.AddActor(actor)
    cam = ren.GetActiveCamera()
    cam.SetFocalPoint(0.5, 0.5, 0.12)
    cam.SetPosition(1.2, -0.6, 1.0)
    cam.SetViewUp(0.0, 0.0, 1.0)
    cam.SetClippingRange(0.3, 3.0)
    if with_volume:
        mapper.RenderUntil(window, SAMPLES)
    else:
        window.Render()
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.ShouldRerenderOff()
    grab.ReadFrontBufferOff()
    grab.Update()
    if TEMP:
        writer = vtkPNGWriter()
        writer.SetInputData(grab.GetOutput())
        writer.SetFileName(os.path.join(TEMP, f"TestTranslucentGeometry-{name}.png"))
        writer.Write()
    pixels = vtk_to_numpy(grab.GetOutput().GetPointData().GetScalars()).reshape(H, W, -1)
    samples = mapper.GetNumberOfSamples() if with_volume else SAMPLES
    return pixels[:, :, :3].astype(np.float64) / 255.0, ren.GetLastRenderingUsedDepthPeeling(), \
        samples


a, _, samplesA = render(True, False, "A")
b, peeled, samplesB = render(True, True, "B")
c, _, _ = render(False, True, "C")
mask = np.abs(c - 0.1).max(axis=2) > 2.0 / 255.0
grown = mask.copy()
grown[1:, :] |= mask[:-1, :]
grown[:-1, :] |= mask[1:, :]
grown[:, 1:] |= mask[:, :-1]
grown[:, :-1] |= mask[:, 1:]
outside = np.abs(a - b)[~grown].ravel()
inside = np.abs(a - b)[mask].mean() if mask.any() else 0.0
mean, p995 = outside.mean(), np.percentile(outside, 99.5)
messages = log.GetOutput()
glErrors = "OpenGL error" in messages or "Invalid operation" in messages
vtkErrors = "ERROR" in messages
print(f"sphere covers {mask.mean():.3f} of the image; outside it volume-only vs with sphere: mean "
      f"|difference| {mean:.4f} (< {MEAN_MAX}), 99.5th percentile {p995:.4f} (< {P995_MAX}); "
      f"inside: {inside:.4f} (> {VISIBLE_MIN}); depth peeling used: {peeled}; samples "
      f"{samplesA}, {samplesB}; OpenGL errors: {glErrors}; VTK errors: {vtkErrors}")
ok = (mask.mean() > 0.02 and mean < MEAN_MAX and p995 < P995_MAX and inside > VISIBLE_MIN and
      peeled and samplesA == SAMPLES and samplesB == SAMPLES and not glErrors and not vtkErrors)
if not ok and messages:
    print(messages[:2000])
print("PASS" if ok else "FAIL")
sys.exit(0 if ok else 1)
