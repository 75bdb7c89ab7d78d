"""vtkAMRDualMeshProbeFilter and vtkAMRDualMesh from Python: probe values and mask, the memory
report, and that a linear field is reproduced through the VTK pipeline."""
import json
import math
import sys

from vtkmodules.vtkCommonDataModel import vtkImageData
from amrdualmesh import vtkAMRDualMesh, vtkAMRDualMeshProbeFilter

import os
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "Support"))
from amrdm_testing import make_amr, read_enzo  # noqa: E402

failures = []


def check(condition, message):
    if not condition:
        failures.append(message)
        print("FAIL:", message)


# 1. Probe the Enzo set on a 24^3 image that sticks out of the domain on one side.
amr = read_enzo()
points = vtkImageData()
points.SetDimensions(24, 24, 24)
points.SetOrigin(0.02, 0.02, 0.02)
points.SetSpacing(0.05, 0.04, 0.04)  # x reaches 1.17 > 1: outside the domain
probe = vtkAMRDualMeshProbeFilter()
probe.SetInputData(points)
probe.SetSourceData(amr)
probe.SetArrayName("Density")
probe.Update()
out = probe.GetOutput()
values = out.GetPointData().GetArray("Density")
mask = out.GetPointData().GetArray("vtkValidPointMask")
check(values is not None and mask is not None, "probe output has Density and vtkValidPointMask")
check(mask.GetDataTypeAsString() == "char", "mask is a char array like vtkProbeFilter's")
field = probe.GetDualMesh()
inside = outside = 0
for i in range(out.GetNumberOfPoints()):
    x = out.GetPoint(i)
    direct = field.Sample(*x)
    valid = mask.GetTuple1(i) != 0  # char arrays give str from GetValue()
    if valid:
        inside += 1
        check(abs(values.GetValue(i) - direct) <= 1e-6 * abs(direct), "probe == Sample at %s" % (x,))
    else:
        outside += 1
        check(math.isnan(direct), "masked point %s has no value" % (x,))
    if x[0] > 1.0:
        check(not valid, "point %s outside the domain is masked" % (x,))
print("probe: %d points inside, %d masked" % (inside, outside))
check(inside > 0 and outside > 0, "both valid and masked points")

# 1b. BVHLeafSize reaches the probe filter's mesh: same values, a smaller BVH at 16 than at 1.
bvh = {}
for leaf in (1, 16):
    p2 = vtkAMRDualMeshProbeFilter()
    p2.SetInputData(points)
    p2.SetSourceData(amr)
    p2.SetArrayName("Density")
    p2.SetBVHLeafSize(leaf)
    p2.Update()
    check(p2.GetDualMesh().GetBVHLeafSize() == leaf, "BVHLeafSize %d reaches the dual mesh" % leaf)
    bvh[leaf] = p2.GetDualMesh().GetBVHBytes()
    v2 = p2.GetOutput().GetPointData().GetArray("Density")
    same = all(v2.GetValue(i) == values.GetValue(i) or (math.isnan(v2.GetValue(i)) and
               math.isnan(values.GetValue(i))) for i in range(out.GetNumberOfPoints()))
    check(same, "BVHLeafSize %d: the same probed values" % leaf)
check(bvh[16] < bvh[1], "BVH bytes at leaf size 16 (%d) < at 1 (%d)" % (bvh[16], bvh[1]))

# 2. Memory report from Python.
report = json.loads(field.GetReportJSON())
parts = [field.GetGridletScalarBytes(), field.GetGridletHeaderBytes(), field.GetElementVertexBytes(),
         field.GetElementIndexBytes(), field.GetBVHBytes()]
check(sum(parts) == field.GetTotalBytes(), "categories add up to the total")
check(report["memory"]["total"] == field.GetTotalBytes(), "JSON total matches")
check(report["counts"]["leafCells"] == 27077, "Enzo has 27077 visible leaf cells (as VTK's own test)")
print("memory:", report["memory"])
print("counts:", report["counts"])

# 3. Re-running the probe with new points does not rebuild the dual mesh.
builds = field.GetBuildCount()
points.SetOrigin(0.03, 0.03, 0.03)
probe.Update()
check(field.GetBuildCount() == builds, "new probe points do not rebuild the dual mesh")

# 4. A linear field on a two-level hand-made AMR, through the pipeline.
lin = lambda c: 2.0 * c[0] - 0.5 * c[1] + 0.25 * c[2] + 1.0
amr2 = make_amr([[((0, 0, 0), (7, 7, 7))], [((4, 4, 4), (11, 9, 11))]], origin=(-1.0, 2.0, 0.5),
                spacing0=(0.5, 0.25, 1.0), field=lin)
mesh = vtkAMRDualMesh()
mesh.SetInputData(amr2)
mesh.SetArrayName("f")
check(mesh.Update(), "anisotropic two-level AMR builds")
worst = 0.0
for i in range(2000):
    t = [(i * 0.6180339) % 1.0, (i * 0.4142135) % 1.0, (i * 0.7320508) % 1.0]
    x = [-1.0 + 0.5 + t[0] * 3.0, 2.0 + 0.25 + t[1] * 1.5, 0.5 + 1.0 + t[2] * 6.0]
    v = mesh.Sample(*x)
    check(not math.isnan(v), "hand-made AMR point %s is covered" % (x,))
    worst = max(worst, abs(v - lin(x)))
print("linear, anisotropic, offset origin: worst error %.3g (range about 8)" % worst)
check(worst < 1e-4, "linear field reproduced")
check(mesh.GetNumberOfTets() + mesh.GetNumberOfPyramids() + mesh.GetNumberOfWedges() + mesh.GetNumberOfHexes() > 0,
      "two levels need stitching elements")

print("%d failures" % len(failures))
sys.exit(1 if failures else 0)
