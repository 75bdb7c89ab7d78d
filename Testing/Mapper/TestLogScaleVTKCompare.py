"""Log-scale transfer functions (ParaView's UseLogScale; vtkColorTransferFunction::SetScaleToLog10,
vtkPiecewiseFunction::UseLogScaleOn) on the Enzo set's Density (6.4 decades), against VTK's own
volume rendering. Left: our RAY_MARCH mode on the AMR with log-scale colour and opacity functions
defined in Density. Middle: the reference, vtkGPUVolumeRayCastMapper on the AMR resampled to
128^3 points (vtkResampleToImage), rendering log10(Density) with the same nodes at log10 of their
positions on a linear scale; this is what a log-scale map means, and it sidesteps VTK's own GPU
mapper, which looks a log-spaced colour table up linearly. Right: our mapper with the same
functions on a linear scale (what the mapper drew before it honoured log scale).
Asserts: coverage (max channel > 8/255) of ours and the reference overlap with IoU >= 0.85; the
mean |difference| per channel over the pixels either covers is < 0.03 (measured: see output);
the linear-scale render is far from the reference (IoU < 0.5), so the test sees a log scale
that is ignored. Writes TestLogScaleVTKCompare.png to the folder given with -T."""
import math
import os
import sys

import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonDataModel import vtkPiecewiseFunction
from vtkmodules.vtkFiltersCore import vtkResampleToImage
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingCore import (vtkColorTransferFunction, vtkRenderer, vtkRenderWindow,
                                         vtkVolume, vtkVolumeProperty, vtkWindowToImageFilter)
from vtkmodules.vtkRenderingVolume import vtkGPUVolumeRayCastMapper
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401
import vtkmodules.vtkRenderingVolumeOpenGL2  # noqa: F401

from amrdualmesh import vtkAMRDualMeshVolumeMapper

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "Support"))
from amrdm_testing import ErrorRecorder, read_enzo  # noqa: E402

IOU_MIN = 0.85
MEAN_DIFF_MAX = 0.03
LINEAR_IOU_MAX = 0.5
SIZE = 240
SAMPLES = 8

amr = read_enzo()
lo, hi = math.inf, -math.inf
peak, peakValue = None, -math.inf
for level in range(amr.GetNumberOfLevels()):
    for i in range(amr.GetNumberOfDataSets(level)):
        grid = amr.GetDataSet(level, i)
        values = vtk_to_numpy(grid.GetCellData().GetArray("Density")).astype(np.float64)
        lo, hi = min(lo, values.min()), max(hi, values.max())
        if values.max() > peakValue:
            peakValue = values.max()
            peak = grid.GetCell(int(values.argmax())).GetBounds()
print(f"Density range [{lo:.3g}, {hi:.3g}] ({math.log10(hi / lo):.1f} decades)")
if not lo > 0:
    print("FAIL: the Enzo Density is expected to be positive")
    sys.exit(1)

# Colour and opacity nodes in Density, meant on a log scale: blue -> white -> red over
# 1e-26 .. 1e-22, transparent below 1e-26.
colors = [(lo, (0.23, 0.30, 0.75)), (1e-26, (0.23, 0.30, 0.75)), (1e-24, (0.87, 0.87, 0.87)),
          (1e-22, (0.71, 0.02, 0.15)), (hi, (0.71, 0.02, 0.15))]
opacities = [(lo, 0.0), (1e-26, 0.0), (1e-24, 0.3), (hi, 1.0)]


def make_property(mode):
    """mode 'log': nodes in Density, log scale; 'linear': the same, linear scale; 'log10':
    nodes at log10 of their positions, linear scale (for log10(Density))."""
    color, opacity = vtkColorTransferFunction(), vtkPiecewiseFunction()
    at = (lambda x: math.log10(x)) if mode == "log10" else (lambda x: x)
    for x, rgb in colors:
        color.AddRGBPoint(at(x), *rgb)
    for x, a in opacities:
        opacity.AddPoint(at(x), a)
    if mode == "log":
        color.SetScaleToLog10()
        opacity.UseLogScaleOn()
    prop = vtkVolumeProperty()
    prop.SetColor(color)
    prop.SetScalarOpacity(opacity)
    prop.SetScalarOpacityUnitDistance(0.01)
    prop.SetInterpolationTypeToLinear()
    prop.ShadeOff()
    return prop


# The reference: resampled points, log10 after resampling (the GPU mapper interpolates it).
resample = vtkResampleToImage()
resample.SetInputDataObject(amr)
resample.SetSamplingDimensions(128, 128, 128)
resample.Update()
image = resample.GetOutput()
density = vtk_to_numpy(image.GetPointData().GetArray("Density")).astype(np.float64)
logDensity = numpy_to_vtk(np.log10(np.maximum(density, lo)), deep=1)
logDensity.SetName("logDensity")
image.GetPointData().AddArray(logDensity)
image.GetPointData().SetActiveScalars("logDensity")

window = vtkRenderWindow()
window.SetSize(3 * SIZE, SIZE)
window.SetMultiSamples(0)
mappers = []
renderers = []
for i, mode in enumerate(("log", "log10", "linear")):
    if mode == "log10":
        mapper = vtkGPUVolumeRayCastMapper()
        mapper.SetInputData(image)
        mapper.AutoAdjustSampleDistancesOff()
        mapper.SetSampleDistance(0.001)
    else:
        mapper = vtkAMRDualMeshVolumeMapper()
        mapper.SetInputData(amr)
        mapper.SelectScalarArray("Density")
        mapper.SetIntegrator(vtkAMRDualMeshVolumeMapper.RAY_MARCH)
        mapper.SetMaximumSamples(SAMPLES)
    mappers.append(mapper)
    volume = vtkVolume()
    volume.SetMapper(mapper)
    volume.SetProperty(make_property(mode))
    ren = vtkRenderer()
    ren.SetViewport(i / 3.0, 0.0, (i + 1) / 3.0, 1.0)
    ren.SetBackground(0.0, 0.0, 0.0)
    ren.AddVolume(volume)
    window.AddRenderer(ren)
    renderers.append(ren)
errors = ErrorRecorder(mappers[0])
camera = renderers[0].GetActiveCamera()
center = [0.5 * (peak[2 * a] + peak[2 * a + 1]) for a in range(3)]
camera.SetFocalPoint(center)
camera.SetPosition(center[0] + 0.5, center[1] - 0.7, center[2] + 0.6)
camera.SetViewUp(0.0, 0.0, 1.0)
camera.SetViewAngle(30.0)
camera.SetClippingRange(0.05, 3.0)
for ren in renderers[1:]:
    ren.SetActiveCamera(camera)
mappers[0].RenderUntil(window, SAMPLES)
mappers[2].RenderUntil(window, SAMPLES)
if mappers[0].GetNumberOfSamples() != SAMPLES or mappers[2].GetNumberOfSamples() != SAMPLES:
    print(f"FAIL: expected {SAMPLES} samples, got {mappers[0].GetNumberOfSamples()}, "
          f"{mappers[2].GetNumberOfSamples()}")
    sys.exit(1)

grab = vtkWindowToImageFilter()
grab.SetInput(window)
grab.ShouldRerenderOff()
grab.ReadFrontBufferOff()
grab.Update()
for i, arg in enumerate(sys.argv):
    if arg == "-T" and i + 1 < len(sys.argv):
        writer = vtkPNGWriter()
        writer.SetInputConnection(grab.GetOutputPort())
        writer.SetFileName(os.path.join(sys.argv[i + 1], "TestLogScaleVTKCompare.png"))
        writer.Write()
pixels = vtk_to_numpy(grab.GetOutput().GetPointData().GetScalars())
pixels = pixels.reshape(SIZE, 3 * SIZE, -1)[:, :, :3].astype(np.float64) / 255.0
ours, ref, linear = pixels[:, :SIZE], pixels[:, SIZE:2 * SIZE], pixels[:, 2 * SIZE:]


def covered(img):
    return img.max(axis=2) > 8.0 / 255.0


def iou(a, b):
    return (a & b).sum() / max(1, (a | b).sum())


cOurs, cRef, cLinear = covered(ours), covered(ref), covered(linear)
union = cOurs | cRef
meanDiff = np.abs(ours - ref)[union].mean() if union.any() else 1.0
iouOurs, iouLinear = iou(cOurs, cRef), iou(cLinear, cRef)
print(f"coverage: ours {cOurs.mean():.4f}, reference {cRef.mean():.4f}, linear scale "
      f"{cLinear.mean():.4f} of the image")
print(f"ours vs reference: IoU {iouOurs:.3f} (>= {IOU_MIN}), mean |difference| {meanDiff:.4f} "
      f"(< {MEAN_DIFF_MAX}); linear scale vs reference: IoU {iouLinear:.3f} (< {LINEAR_IOU_MAX})")
ok = (cRef.mean() > 0.02 and iouOurs >= IOU_MIN and meanDiff < MEAN_DIFF_MAX and
      iouLinear < LINEAR_IOU_MAX and not errors.errors)
if errors.errors:
    print("FAIL: errors:", errors.errors)
print("PASS" if ok else "FAIL")
sys.exit(0 if ok else 1)
