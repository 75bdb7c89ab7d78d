"""vtkAMRDualMeshVolumeMapper honours vtkVolumeMapper::SetBlendMode with VTK's meaning, on a
2-level AMR of the distance field f = |p - c| over the unit cube, seen along -z with a parallel
camera (pixel (i, j) looks down the line x = (i + 0.5) / N, y = (j + 0.5) / N):
- ISOSURFACE_BLEND (vtkVolumeProperty::GetIsoSurfaceValues()): the covered pixels are the disk
  of radius R around c (intersection over union >= 0.9), coloured by the map at R;
- SLICE_BLEND (a vtkPlane z = 0.5): every pixel, grey = the map at the distance in the plane;
- MAXIMUM / MINIMUM_INTENSITY_BLEND: grey = the map at the largest / smallest value on the line;
- AVERAGE_INTENSITY_BLEND, ADDITIVE_BLEND: every pixel covered, grey within (0, 1];
- a mode the integrator cannot draw (the path tracer) is drawn by the ray marcher (the mode the
  user set is what renders), said once.
With -I DIR the shaded isosurface image is written to DIR/blend-isosurface.png."""
import math
import os
import sys

from vtkmodules.vtkRenderingVolume import vtkVolumeMapper

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "Support"))
from amrdm_testing import blend_mode_scene, checker, grab, rgb, write_png  # noqa: E402

from amrdualmesh import vtkAMRDualMeshVolumeMapper  # noqa: E402

N = 64
C = (0.5, 0.5, 0.5)
R = 0.3
TOP = 0.9  # grey ramp 0 .. 1 over [0, TOP]
failures = []
check = checker(failures, "ok    ", "FAIL  ")


# Level 0: 16^3 cells over [0, 1]^3; level 1 refines the middle half. Slice plane z = 0.5.
scene = blend_mode_scene(N, C, R, TOP, 0.5, unit_distance=10.0)
mapper, recorder, prop, plane = scene.mapper, scene.recorder, scene.prop, scene.plane
window, ren, camera = scene.window, scene.ren, scene.camera
color, opacity = prop.GetRGBTransferFunction(), prop.GetScalarOpacity()
ren.ResetCameraClippingRange()


def render(mode):
    mapper.SetBlendMode(mode)
    window.Render()
    return rgb(grab(window, rerender=True))  # rows from the bottom: rgb[j][i]


def centre(i, j):
    return ((i + 0.5) / N, (j + 0.5) / N)


def in_plane(x, y):
    """Distance to c's z line from (x, y), the boundary layer's clamp (the outermost cell
    centres, 1/32 from the faces) applied."""
    clamp = lambda v: min(max(v, 1.0 / 32), 31.0 / 32)
    return math.hypot(clamp(x) - 0.5, clamp(y) - 0.5)


# Isosurface: coverage against the analytic disk, colour = the map at R.
iso = render(vtkVolumeMapper.ISOSURFACE_BLEND)
inter = union = 0
colour_err = 0.0
for j in range(N):
    for i in range(N):
        x, y = centre(i, j)
        disk = (x - 0.5) ** 2 + (y - 0.5) ** 2 < R * R
        covered = iso[j][i].max() > 0.02
        inter += disk and covered
        union += disk or covered
        if covered:
            colour_err = max(colour_err, abs(iso[j][i][0] - R / TOP))
check(union > 0 and inter / union >= 0.9, "isosurface coverage IoU %.3f against the disk" % (inter / max(union, 1)))
check(colour_err < 0.03, "isosurface colour = map at R (worst %.3f, flat shading)" % colour_err)

# Slice z = 0.5: grey = the map at the in-plane distance.
slice_img = render(vtkVolumeMapper.SLICE_BLEND)
worst = 0.0
for j in range(N):
    for i in range(N):
        x, y = centre(i, j)
        worst = max(worst, abs(slice_img[j][i][0] - in_plane(x, y) / TOP))
check(worst < 0.03, "slice grey = map at the interpolant on the plane (worst %.3f)" % worst)

# Moving the plane (the property's MTime does not change) restarts the accumulation.
plane.SetOrigin(0.5, 0.5, 0.2)
moved = render(vtkVolumeMapper.SLICE_BLEND)
check(abs(moved[N // 2][N // 2][0] - slice_img[N // 2][N // 2][0]) > 0.1,
      "moving the slice plane redraws (centre grey %.3f -> %.3f)"
      % (slice_img[N // 2][N // 2][0], moved[N // 2][N // 2][0]))
plane.SetOrigin(0.5, 0.5, 0.5)

# MIP / MinIP along z: the extreme of the line's values (the boundary layer holds the outermost
# cell centres' values up to the faces: z = 1/32 and 31/32).
for mode, name, expected in ((vtkVolumeMapper.MAXIMUM_INTENSITY_BLEND, "MIP",
                              lambda r: math.hypot(r, 0.5 - 1.0 / 32)),
                             (vtkVolumeMapper.MINIMUM_INTENSITY_BLEND, "MinIP", lambda r: r)):
    img = render(mode)
    worst = 0.0
    for j in range(N):
        for i in range(N):
            x, y = centre(i, j)
            r = in_plane(x, y)
            worst = max(worst, abs(img[j][i][0] - min(expected(r), TOP) / TOP))
    check(worst < 0.04, "%s grey = map at the line's extreme (worst %.3f)" % (name, worst))

for mode, name in ((vtkVolumeMapper.AVERAGE_INTENSITY_BLEND, "average"),
                   (vtkVolumeMapper.ADDITIVE_BLEND, "additive")):
    img = render(mode)
    lit = sum(1 for j in range(N) for i in range(N) if img[j][i][0] > 0.01)
    check(lit > 0.95 * N * N, "%s covers the cube's projection (%d of %d pixels)" % (name, lit, N * N))

check(not recorder.warnings and not recorder.errors,
      "the ray marcher draws every mode without a warning (%s)" % (recorder.warnings + recorder.errors))

# The path tracer cannot: the ray marcher draws the same MIP, said once (two renders).
rm_mip = render(vtkVolumeMapper.MAXIMUM_INTENSITY_BLEND)
mapper.SetIntegrator(vtkAMRDualMeshVolumeMapper.PATH_TRACER)
pt_mip = render(vtkVolumeMapper.MAXIMUM_INTENSITY_BLEND)
render(vtkVolumeMapper.MAXIMUM_INTENSITY_BLEND)
said = [w for w in recorder.warnings if "MAXIMUM_INTENSITY_BLEND" in w and "ray-march" in w]
check(len(said) == 1, "path tracer + MIP said once (%d warnings: %s)" % (len(said), recorder.warnings))
diff = float(abs(pt_mip - rm_mip).max())
check(diff < 1.0 / 255.0 + 1e-9, "path tracer + MIP draws the ray marcher's MIP (largest difference %.4f)" % diff)

# No isosurface value: said.
mapper.SetIntegrator(vtkAMRDualMeshVolumeMapper.RAY_MARCH)
prop.GetIsoSurfaceValues().SetNumberOfContours(0)
render(vtkVolumeMapper.ISOSURFACE_BLEND)
check(any("no isosurface value" in w for w in recorder.warnings), "no iso value is said")

if "-I" in sys.argv:
    # The docs image: two shaded isosurfaces of the same field, the outer one translucent.
    prop.GetIsoSurfaceValues().SetValue(0, 0.22)
    prop.GetIsoSurfaceValues().SetValue(1, 0.42)
    color.RemoveAllPoints()
    color.AddRGBPoint(0.22, 0.95, 0.55, 0.2)
    color.AddRGBPoint(0.42, 0.3, 0.6, 0.95)
    opacity.RemoveAllPoints()
    opacity.AddPoint(0.22, 1.0)
    opacity.AddPoint(0.42, 0.35)
    prop.ShadeOn()
    window.SetSize(384, 384)
    camera.ParallelProjectionOff()
    camera.SetPosition(2.2, -1.4, 1.9)
    camera.SetViewUp(0.0, 0.0, 1.0)
    ren.ResetCameraClippingRange()
    mapper.SetBlendMode(vtkVolumeMapper.ISOSURFACE_BLEND)
    mapper.SetMaximumSamples(16)
    mapper.SetSamplesPerRender(16)
    window.Render()
    write_png(grab(window, rerender=True),
              os.path.join(sys.argv[sys.argv.index("-I") + 1], "blend-isosurface.png"))

sys.exit(1 if failures else 0)
