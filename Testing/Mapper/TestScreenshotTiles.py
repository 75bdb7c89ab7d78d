"""Screenshots at another size (issue 13): the AMReX advection set (phi) with an opaque sphere
half inside it, RAY_MARCH, a 100 x 75 view accumulated to 8 samples, then
1. vtkWindowToImageFilter SetScale(2): 200 x 150 in four tiles;
2. vtkRenderLargeImage SetMagnification(2): the same through VTK's other tiler;
3. vtkWindowToImageFilter SetScale(3, 2): 300 x 150, a non-square magnification;
4. a parallel projection grabbed at scale 2;
each against a native render of that size with the same camera and sample count: the mean
|difference| per channel must stay < 0.01 and the 99.5th percentile < 0.1 (jitter noise; a tiled
copy of the whole scene differs by ~0.1 mean). After a vtkWindowToImageFilter tiled grab the
mapper's sample count must be the view's (vtkRenderLargeImage gives no sign that it tiles: its
tiles get SamplesPerRender each). 5. A window centre of (0.3, -0.2) at 200 x 150 must shift the
whole picture (volume and sphere) by (-30, +15) pixels against the centred render (VTK's own
tilers do not keep a window centre across tiles, so this is checked natively). 6. A plain grab
at scale 1 (ShouldRerender on) must not reset the accumulation (the count grows from 8, it does
not drop to SamplesPerRender). Writes the images as TestScreenshotTiles-*.png to the folder
given with -T."""
import os
import sys

import numpy as np
from vtkmodules.vtkFiltersHybrid import vtkRenderLargeImage
from vtkmodules.vtkRenderingCore import vtkWindowToImageFilter

from amrdualmesh import vtkAMRDualMeshVolumeMapper

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "Support"))
from amrdm_testing import (COOL_WARM, ErrorRecorder, aim, dual_mesh_volume, grab,  # noqa: E402
                           read_amrex, render_window, rgb, sphere_actor, temp_dir,
                           volume_property, write_png)

SAMPLES = 8
MEAN_MAX, P995_MAX = 0.01, 0.1
TEMP = temp_dir()

amr = read_amrex()
prop = volume_property(COOL_WARM, ((1.0, 0.0), (1.02, 0.01), (1.3, 0.3), (2.0, 0.9)), 0.02,
                       shade=False)


def make_scene(width, height, camera_setup):
    window, ren = render_window((width, height), (0.1, 0.1, 0.1), multisamples=0)
    mapper, volume = dual_mesh_volume(amr, "phi", prop,
                                      Integrator=vtkAMRDualMeshVolumeMapper.RAY_MARCH,
                                      SamplesPerRender=2, StepSize=0.01, Seed=1)
    ren.AddVolume(volume)
    ren.AddActor(sphere_actor((0.64, 0.52, 0.25), 0.1, (0.9, 0.9, 0.9)))
    cam = aim(ren.GetActiveCamera(), (0.98, -0.24, 0.82), (0.68, 0.56, 0.12))
    camera_setup(cam)
    cam.SetClippingRange(0.3, 3.0)
    return window, ren, mapper


def save(image, name):
    if TEMP:
        write_png(image, os.path.join(TEMP, f"TestScreenshotTiles-{name}.png"))


def native(width, height, camera_setup):
    window, ren, mapper = make_scene(width, height, camera_setup)
    mapper.RenderUntil(window, SAMPLES)
    return grab(window), mapper.GetNumberOfSamples()


failures = []


def compare(name, tiled, reference):
    a, b = rgb(tiled), rgb(reference)
    if a.shape != b.shape:
        failures.append(f"{name}: size {a.shape} against {b.shape}")
        return
    d = np.abs(a - b).ravel()
    mean, p995 = d.mean(), np.percentile(d, 99.5)
    ok = mean < MEAN_MAX and p995 < P995_MAX
    print(f"{name}: {a.shape[1]} x {a.shape[0]}, mean |difference| {mean:.4f} (< {MEAN_MAX}), "
          f"99.5th percentile {p995:.4f} (< {P995_MAX}) {'ok' if ok else 'FAIL'}")
    if not ok:
        failures.append(name)


def plain(cam):
    pass


def centred(cam):
    cam.SetWindowCenter(0.3, -0.2)


def parallel(cam):
    cam.ParallelProjectionOn()
    cam.SetParallelScale(0.35)


cases = [("scale2", plain, "w2i", (2, 2)), ("large2", plain, "large", (2, 2)),
         ("scale3x2", plain, "w2i", (3, 2)), ("parallel2", parallel, "w2i", (2, 2))]
for name, setup, tiler, (sx, sy) in cases:
    window, ren, mapper = make_scene(100, 75, setup)
    errors = ErrorRecorder(mapper)
    mapper.RenderUntil(window, SAMPLES)
    if tiler == "w2i":
        tiling = vtkWindowToImageFilter()
        tiling.SetInput(window)
        tiling.SetScale(sx, sy)
        tiling.ReadFrontBufferOff()
    else:
        tiling = vtkRenderLargeImage()
        tiling.SetInput(ren)
        tiling.SetMagnification(sx)
    tiling.Update()
    tiled = tiling.GetOutput()
    save(tiled, name)
    if tiler == "w2i" and mapper.GetNumberOfSamples() != SAMPLES:
        failures.append(f"{name}: a tile has {mapper.GetNumberOfSamples()} samples, expected "
                        f"the view's {SAMPLES}")
    reference, count = native(100 * sx, 75 * sy, setup)
    save(reference, name + "-native")
    compare(name, tiled, reference)
    if errors.errors:
        failures.append(f"{name}: errors {errors.errors}")

# The window centre moves the picture by half the viewport per unit, against its sign.
moved, _ = native(200, 150, centred)
still, _ = native(200, 150, plain)
save(moved, "centre")
a, b = rgb(moved), rgb(still)
dx, dy = 30, 15  # 0.3 * 200 / 2 to the left, 0.2 * 150 / 2 up (rows from the bottom)
d = np.abs(a[dy:, :200 - dx] - b[:150 - dy, dx:]).ravel()
mean, p995 = d.mean(), np.percentile(d, 99.5)
unshifted = np.abs(a - b).mean()
print(f"window centre: shifted overlap mean |difference| {mean:.4f} (< {MEAN_MAX}), 99.5th "
      f"percentile {p995:.4f} (< {P995_MAX}); unshifted {unshifted:.4f}")
if not (mean < MEAN_MAX and p995 < P995_MAX):
    failures.append("window centre")

# A plain grab re-renders the window: the accumulation continues.
window, ren, mapper = make_scene(100, 75, plain)
mapper.RenderUntil(window, SAMPLES)
grab(window, rerender=True)
print(f"plain grab after {SAMPLES} samples: {mapper.GetNumberOfSamples()} samples")
if mapper.GetNumberOfSamples() < SAMPLES:
    failures.append(f"a plain grab reset the accumulation to {mapper.GetNumberOfSamples()}")

if failures:
    print("FAIL:", "; ".join(failures))
    sys.exit(1)
print("PASS")
