"""Geometry extremes through the VTK layer (see docs/ROBUSTNESS.md, "Geometry extremes"):
1. an AMR whose origin is (1e6, 1e6, 1e6) with finest cells of 1e-3 ... 1e-6, probed with
   vtkAMRDualMeshProbeFilter: a linear field is reproduced as well as at the origin;
2. the same scene rendered by vtkAMRDualMeshVolumeMapper at the origin and at (1e6, 1e6, 1e6),
   camera and lights moved with it: the images agree (mean absolute difference < 1e-3). Float
   world coordinates resolve about 0.06 at 1e6, so this needs the scene origin (double) that
   the intake keeps and the camera, lights and clipping planes are taken relative to;
3. strongly anisotropic spacing, (1, 1e-3, 1e3) and (1e3, 1, 1e-3): the probe reproduces a
   linear field with no masked point inside the data;
4. a domain one cell thick: the clamped boundary layer fills the slab (no warning).
Each case prints its numbers; the test fails on any error above its tolerance."""
import os
import sys

from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkPolyData
from vtkmodules.vtkRenderingCore import vtkLight, vtkWindowToImageFilter
from vtkmodules.util.numpy_support import vtk_to_numpy

from amrdualmesh import vtkAMRDualMeshProbeFilter, vtkAMRDualMeshVolumeMapper

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "Support"))
from amrdm_testing import (ErrorRecorder, aim, checker, dual_mesh_volume, halton,  # noqa: E402
                           make_amr, probe_points, render_window, volume_property)

# The tolerance for linear reproduction, relative to the field's range.
RELATIVE_TOLERANCE = 1e-5
failures = []
check = checker(failures)


# Three levels, ratio 2: an 8^3 root, a refined centre and a refined box inside it that reaches
# the level-1 box's edge on one side (so there are stitching elements between all levels).
LEVELS = [[((0, 0, 0), (7, 7, 7))],
          [((4, 4, 4), (11, 11, 11))],
          [((10, 10, 10), (17, 15, 19))]]
ROOT_CELLS = 8


def probe_linear(origin, spacing0, gradient, count=3000):
    """Probes a linear field (relative to `origin`) at `count` points one root cell inside the
    domain; returns (misses, worst error / range, errors)."""
    def field(c):
        return sum(gradient[d] * (c[d] - origin[d]) for d in range(3)) + 1.0
    amr = make_amr(LEVELS, origin=origin, spacing0=spacing0, field=field)
    points = vtkPoints()
    points.SetDataTypeToDouble()
    rel = []
    for i in range(count):
        u = (halton(i + 1, 2), halton(i + 1, 3), halton(i + 1, 5))
        r = [spacing0[d] * (1.0 + u[d] * (ROOT_CELLS - 2)) for d in range(3)]
        rel.append(r)
        points.InsertNextPoint([origin[d] + r[d] for d in range(3)])
    values, mask, rec = probe_points(points, amr, "f")
    if values is None or mask is None:
        return count, float("inf"), rec.errors
    value_range = sum(abs(gradient[d]) * spacing0[d] * ROOT_CELLS for d in range(3))
    misses, worst = 0, 0.0
    for i in range(count):
        if mask.GetTuple1(i) == 0:
            misses += 1
            continue
        expect = sum(gradient[d] * rel[i][d] for d in range(3)) + 1.0
        worst = max(worst, abs(values.GetValue(i) - expect) / value_range)
    return misses, worst, rec.errors


# 1. Probe at the origin and at 1e6 for finest cells of 1e-3 ... 1e-6 (root cells 4x finer).
for finest in (1e-3, 1e-4, 1e-5, 1e-6):
    h0 = 4.0 * finest
    gradient = (1.0 / h0, -0.5 / h0, 0.25 / h0)  # about one unit per root cell
    for origin in ((0.0, 0.0, 0.0), (1e6, 1e6, 1e6)):
        misses, worst, errors = probe_linear(origin, (h0, h0, h0), gradient)
        check(not errors and misses == 0 and worst <= RELATIVE_TOLERANCE,
              "probe, origin %g, finest cell %g: %d misses, worst error / range %.3g%s"
              % (origin[0], finest, misses, worst, (" (" + errors[-1] + ")") if errors else ""))

# 3. Strongly anisotropic spacing.
for spacing0 in ((1.0, 1e-3, 1e3), (1e3, 1.0, 1e-3)):
    gradient = tuple(1.0 / s for s in spacing0)
    misses, worst, errors = probe_linear((0.5, -2.0, 3.0), spacing0, gradient)
    check(not errors and misses == 0 and worst <= RELATIVE_TOLERANCE,
          "probe, spacing %s: %d misses, worst error / range %.3g" % (spacing0, misses, worst))


# 4. A domain one cell thick (2D data) has one layer of cell centres: no interior dual cells,
#    only the clamped boundary layer, which holds the cells' interpolant constant across the slab:
#    no warning, no error, and a probe point in the slab gets the field (f = x here).
flat = make_amr([[((0, 0, 0), (7, 7, 0))]], field=lambda c: c[0])
points = vtkPoints()
points.InsertNextPoint(4.0, 4.0, 0.5)
poly = vtkPolyData()
poly.SetPoints(points)
probe = vtkAMRDualMeshProbeFilter()
probe.SetInputData(poly)
probe.SetSourceData(flat)
probe.SetArrayName("f")
rec = ErrorRecorder(probe.GetDualMesh())
probe.Update()
mask = probe.GetOutput().GetPointData().GetArray("vtkValidPointMask")
value = probe.GetOutput().GetPointData().GetArray("f")
got = value.GetValue(0) if value is not None else float("nan")
check(not rec.errors and not rec.warnings and mask is not None and mask.GetTuple1(0) == 1
      and abs(got - 4.0) < 1e-5,
      "a domain one cell thick: the boundary layer fills the slab (f at x = 4: %g; warnings %s)"
      % (got, rec.warnings))


# 2. The volume mapper at the origin and at 1e6.
def render(origin, h0, integrator):
    """The 3-level scene of root spacing h0 at `origin`, camera and a positional light placed
    relative to it; returns the RGBA image as floats in [0, 1]."""
    def field(c):
        x = [(c[d] - origin[d]) / h0 for d in range(3)]  # root-cell units
        return 1.0 + 0.1 * x[0] + 0.05 * x[1] * x[2] / 8.0
    amr = make_amr(LEVELS, origin=origin, spacing0=(h0, h0, h0), field=field)
    prop = volume_property(((1.0, 0.2, 0.3, 0.9), (1.8, 0.95, 0.8, 0.2)),
                           ((1.0, 0.05), (1.8, 0.8)), 2.0 * h0)
    mapper, volume = dual_mesh_volume(amr, "f", prop, Integrator=integrator, Seed=5,
                                      EnvironmentRadiance=(0.3, 0.3, 0.3))
    rec = ErrorRecorder(mapper)
    window, ren = render_window((64, 64), offscreen=True)
    ren.AddVolume(volume)
    at = lambda r: [origin[d] + r[d] * h0 for d in range(3)]  # root-cell units -> world
    light = vtkLight()
    light.SetLightTypeToSceneLight()
    light.SetPositional(True)
    light.SetPosition(at((-4.0, 12.0, 14.0)))
    light.SetFocalPoint(at((4.0, 4.0, 4.0)))
    light.SetConeAngle(90)
    light.SetIntensity(2.0)
    ren.AddLight(light)
    cam = aim(ren.GetActiveCamera(), at((19.0, -9.0, 13.0)), at((4.0, 4.0, 4.0)))
    cam.SetViewAngle(30.0)
    cam.SetClippingRange(1e-3 * h0, 100.0 * h0)
    reached = mapper.RenderUntil(window, 16)
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.SetInputBufferTypeToRGBA()
    grab.ReadFrontBufferOff()
    grab.Update()
    image = vtk_to_numpy(grab.GetOutput().GetPointData().GetScalars()).astype(float) / 255.0
    window.Finalize()
    return image, reached, rec.errors


names = {vtkAMRDualMeshVolumeMapper.RAY_MARCH: "ray marching",
         vtkAMRDualMeshVolumeMapper.PATH_TRACER: "path tracing"}
for finest in (1e-3, 1e-6):
    h0 = 4.0 * finest
    for integrator in (vtkAMRDualMeshVolumeMapper.RAY_MARCH, vtkAMRDualMeshVolumeMapper.PATH_TRACER):
        ref, n0, e0 = render((0.0, 0.0, 0.0), h0, integrator)
        off, n1, e1 = render((1e6, 1e6, 1e6), h0, integrator)
        diff = abs(ref - off).mean()
        coverage = (ref[:, :3].max(axis=1) > 0.05).mean()
        check(not e0 and not e1 and n0 == 16 and n1 == 16 and coverage > 0.1 and diff < 1e-3,
              "volume mapper, %s, finest cell %g: the image at 1e6 equals the one at the origin "
              "(mean abs diff %.2g; the volume covers %.0f%% of the image)"
              % (names[integrator], finest, diff, 100 * coverage))

print("%d failures" % len(failures))
sys.exit(1 if failures else 0)
