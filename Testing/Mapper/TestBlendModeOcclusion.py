"""Isosurface and slice blend modes against opaque VTK geometry in the same scene: an opaque
sphere actor that pokes through the isosurface hides it where the sphere is nearer the camera,
and is hidden by it where the surface is nearer (both ways in one image), with no halo or gap
away from the intersection curve; the same with a slice plane through the sphere. The colours
come from the renderer's depth buffer (each ray stops at the opaque depth, Mapper/
AMRDualMeshProjection.h ComputeRayIntervals). The surfaces also write their depth
(Mapper/AMRDualMeshSurfaceDepth.h, AMRDualMeshCompositor::DrawDepth): after the frame the
z-buffer holds the surface's depth where it is nearest (within that of spheres R -+ 0.01, the
interpolant's tolerance here), the actor's where it is, and 1 on the background.

On a 2-level AMR of f = |p - c| over the unit cube (isosurface R = 0.3: a sphere about c), seen
along -z with a parallel camera; the actor is a sphere of radius 0.15 about (0.75, 0.5, 0.5),
pure red (ambient only). Each pixel (away from the curves where the depths are within 0.02) is
classified by the analytic depths: red where the actor is in front or alone, the surface's grey
where the surface is in front."""
import math
import os
import sys

from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkRenderingVolume import vtkVolumeMapper

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "Support"))
from amrdm_testing import (blend_mode_scene, checker, grab, rgb, sphere_actor,  # noqa: E402
                           write_png)

N = 96
C = (0.5, 0.5, 0.5)
R = 0.3
TOP = 0.9  # grey ramp 0 .. 1 over [0, TOP]
S, SR = (0.75, 0.5, 0.5), 0.15  # the actor
MARGIN = 0.02
failures = []
check = checker(failures, "ok    ", "FAIL  ")


scene = blend_mode_scene(N, C, R, TOP, 0.62)
mapper, recorder, plane = scene.mapper, scene.recorder, scene.plane
window, ren = scene.window, scene.ren
actor = sphere_actor(S, SR, (1.0, 0.0, 0.0), resolution=256)
actor.GetProperty().SetAmbient(1.0)
actor.GetProperty().SetDiffuse(0.0)
actor.GetProperty().SetSpecular(0.0)
ren.AddActor(actor)
scene.camera.SetClippingRange(1.0, 4.0)


def render(mode):
    mapper.SetBlendMode(mode)
    window.Render()
    return rgb(grab(window, rerender=True))


def front_z(x, y, centre, radius):
    """z of the sphere's near side along the pixel's line, or None."""
    q = radius * radius - (x - centre[0]) ** 2 - (y - centre[1]) ** 2
    return centre[2] + math.sqrt(q) if q > 0 else None


def classify(img, surface_z, surface_grey, name):
    counts = {"actor": [0, 0], "surface": [0, 0]}  # [pixels, right]
    for j in range(N):
        for i in range(N):
            x, y = (i + 0.5) / N, (j + 0.5) / N
            za, zs = front_z(x, y, S, SR), surface_z(x, y)
            if za is None or (zs is not None and abs(za - zs) < MARGIN):
                continue
            if za is not None and abs(math.hypot(x - S[0], y - S[1]) - SR) < MARGIN:
                continue  # the actor's silhouette (tessellation)
            r, g, b = img[j][i]
            if zs is None or za > zs:
                counts["actor"][0] += 1
                counts["actor"][1] += r > 0.9 and g < 0.1 and b < 0.1
            else:
                grey = surface_grey(x, y)
                counts["surface"][0] += 1
                counts["surface"][1] += (abs(r - grey) < 0.04 and abs(g - grey) < 0.04 and
                                         abs(b - grey) < 0.04)
    for what, (n, right) in counts.items():
        check(n > 50 and right == n, "%s: %d of %d pixels where the %s is in front show it"
              % (name, right, n, "actor" if what == "actor" else "surface"))


def display_depth(x, y, z):
    ren.SetWorldPoint(x, y, z, 1.0)
    ren.WorldToDisplay()
    return ren.GetDisplayPoint()[2]


def check_depth(surface_range, name):
    """The z-buffer after the frame: within the depths of the surface's z range where it is
    nearest, the actor's depth where it is, 1 where neither is near. surface_range(x, y): the
    surface's (low, high) z along the pixel's line (the analytic surface moved by the
    interpolant's tolerance), (None, None) where it surely is not, None where it may be."""
    from vtkmodules.vtkCommonCore import vtkFloatArray
    zbuf = vtkFloatArray()
    window.GetZbufferData(0, 0, N - 1, N - 1, zbuf)
    z = vtk_to_numpy(zbuf).reshape(N, N)
    counts = {"surface": [0, 0], "actor": [0, 0], "background": [0, 0]}
    for j in range(N):
        for i in range(N):
            x, y = (i + 0.5) / N, (j + 0.5) / N
            za, zs = front_z(x, y, S, SR), surface_range(x, y)
            if zs is None or abs(math.hypot(x - S[0], y - S[1]) - SR) < MARGIN:
                continue  # the actor's silhouette (tessellation, partly covered pixels)
            lo, hi = zs
            if lo is not None and (za is None or lo > za + MARGIN):
                a, b = display_depth(x, y, lo), display_depth(x, y, hi)
                key, ok = "surface", min(a, b) - 1e-6 <= z[j][i] <= max(a, b) + 1e-6
            elif za is not None and (lo is None or za > hi + MARGIN):
                key, ok = "actor", abs(z[j][i] - display_depth(x, y, za)) < 0.01
            elif za is None and lo is None:
                key, ok = "background", z[j][i] == 1.0
            else:
                continue
            counts[key][0] += 1
            counts[key][1] += ok
    for key, (n, ok) in counts.items():
        check((n > 50 or key == "background") and ok == n, "%s depth: %d of %d pixels where the "
              "%s is nearest hold its depth" % (name, ok, n, key))


def iso_range(x, y, tolerance=0.01):
    """The near side of spheres of radius R -+ tolerance about c (the interpolant's surface lies
    between them here): None at the rim, where it may or may not be hit."""
    inner, outer = front_z(x, y, C, R - tolerance), front_z(x, y, C, R + tolerance)
    if inner is not None:
        return inner, outer
    return (None, None) if outer is None else None


iso = render(vtkVolumeMapper.ISOSURFACE_BLEND)
classify(iso, lambda x, y: front_z(x, y, C, R), lambda x, y: R / TOP, "isosurface")
check_depth(iso_range, "isosurface")


def slice_z(x, y):
    return plane.GetOrigin()[2]


slice_img = render(vtkVolumeMapper.SLICE_BLEND)
classify(slice_img, slice_z,
         lambda x, y: math.hypot(x - C[0], y - C[1], plane.GetOrigin()[2] - C[2]) / TOP, "slice")
check_depth(lambda x, y: (slice_z(x, y) - 1e-3, slice_z(x, y) + 1e-3), "slice")
check(not recorder.errors, "no error (%s)" % recorder.errors)

if "-I" in sys.argv:  # the two images, for a look: DIR/occlusion-{isosurface,slice}.png
    out = sys.argv[sys.argv.index("-I") + 1]
    for mode, name in ((vtkVolumeMapper.ISOSURFACE_BLEND, "isosurface"),
                       (vtkVolumeMapper.SLICE_BLEND, "slice")):
        mapper.SetBlendMode(mode)
        window.Render()
        write_png(grab(window, rerender=True), os.path.join(out, "occlusion-%s.png" % name))

if failures:
    sys.exit("%d check(s) failed" % len(failures))
print("all checks passed")
