"""Point (vertex-centred) AMR arrays (issue 35; issue 13 refused them): rendered and sampled as
they are, without conversion. The AMReX advection set through vtkCellDataToPointData gives a
point array 'phi' (the reader's cell array 'phi' is its cell-centred twin). Checks:
1. the mapper with ScalarMode UsePointFieldData + SelectScalarArray('phi') (what ParaView passes
   for ColorBy(('POINTS', 'phi'))) renders without error, and its image covers what the
   cell-centred twin's covers (coverage IoU >= 0.9; both images are written to the temp folder);
2. the default scalar mode with a name that exists only as point data renders the point array;
3. the remaining refusals: UseCellFieldData with a point array's name (one error naming 'phi'
   and the scalar mode to use, nothing drawn), and a point array with the wrong number of
   tuples (an error naming the level and block);
4. vtkAMRDualMesh.SetInputArrayToProcess(0, 0, 0, FIELD_ASSOCIATION_POINTS, 'phi') builds the
   vertex mesh (no stitching elements, "association": "points" in the report),
   vtkAMRDualMeshProbeFilter.SetInputArrayToProcess(0, 1, 0, ...) samples the same field, and
   vtkAMRDualMeshToUnstructuredGrid gives one hexahedron per leaf cell within the AMR's bounds."""
import argparse
import json
import os
import sys

import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonDataModel import vtkDataObject
from vtkmodules.vtkFiltersCore import vtkCellDataToPointData
from vtkmodules.vtkFiltersSources import vtkLineSource

from amrdualmesh import (vtkAMRDualMesh, vtkAMRDualMeshProbeFilter,
                         vtkAMRDualMeshToUnstructuredGrid, vtkAMRDualMeshVolumeMapper)

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "Support"))
from amrdm_testing import (COOL_WARM, ErrorRecorder, aim, dual_mesh_volume,  # noqa: E402
                           grab as grab_image, read_amrex, render_window, rgb, volume_property,
                           write_png)

parser = argparse.ArgumentParser()
parser.add_argument("-T", dest="temp", default=".")
args = parser.parse_args()
os.makedirs(args.temp, exist_ok=True)

cellAmr = read_amrex()
toPoints = vtkCellDataToPointData()
toPoints.SetInputData(cellAmr)
toPoints.Update()
pointAmr = toPoints.GetOutputDataObject(0)
print("vtkCellDataToPointData gives a", pointAmr.GetClassName(), "with point arrays",
      [pointAmr.GetDataSet(0, 0).GetPointData().GetArrayName(i)
       for i in range(pointAmr.GetDataSet(0, 0).GetPointData().GetNumberOfArrays())])

prop = volume_property((COOL_WARM[0], COOL_WARM[2]), ((1.0, 0.0), (1.3, 0.3), (2.0, 0.9)), 0.02)

failures = []


def check(ok, what):
    print(f"{what}: {'ok' if ok else 'FAIL'}")
    if not ok:
        failures.append(what)


def scene(data, mode):
    window, ren = render_window((160, 120), multisamples=0)
    mapper, volume = dual_mesh_volume(data, "phi", prop,
                                      Integrator=vtkAMRDualMeshVolumeMapper.RAY_MARCH,
                                      StepSize=0.005, MaximumSamples=2)
    if mode == "points":
        mapper.SetScalarModeToUsePointFieldData()
    elif mode == "cells":
        mapper.SetScalarModeToUseCellFieldData()
    errors = ErrorRecorder(mapper)
    ren.AddVolume(volume)
    aim(ren.GetActiveCamera(), (1.2, -0.6, 1.0), (0.5, 0.5, 0.12))
    ren.ResetCameraClippingRange()
    return window, mapper, errors


def grab(window, name):
    image = grab_image(window)
    write_png(image, os.path.join(args.temp, name))
    return rgb(image)


# 1. Point array vs its cell-centred twin.
images = {}
for label, data, mode in (("points", pointAmr, "points"), ("cells", cellAmr, "default")):
    window, mapper, errors = scene(data, mode)
    mapper.RenderUntil(window, 2)
    images[label] = grab(window, f"TestPointData-{label}.png")
    check(not errors.errors and mapper.GetNumberOfSamples() == 2,
          f"{label}: {mapper.GetNumberOfSamples()} samples, errors {errors.errors}")
covered = {k: v.sum(axis=2) > 0.05 for k, v in images.items()}
inter = np.logical_and(covered["points"], covered["cells"]).sum()
union = np.logical_or(covered["points"], covered["cells"]).sum()
iou = inter / max(union, 1)
diff = np.abs(images["points"] - images["cells"]).mean()
print(f"coverage: points {covered['points'].mean():.3f}, cells {covered['cells'].mean():.3f} of "
      f"the image, IoU {iou:.3f}; mean |difference| {diff:.4f}; images in {args.temp}")
check(covered["cells"].mean() > 0.05 and iou >= 0.9, "coverage IoU >= 0.9")

# 2. The default mode with a name that only point data has.
window, mapper, errors = scene(pointAmr, "default")
mapper.RenderUntil(window, 1)
check(not errors.errors and mapper.GetNumberOfSamples() == 1,
      f"default mode, point-only name: {mapper.GetNumberOfSamples()} sample, {errors.errors}")

# 3. Refusals.
window, mapper, errors = scene(pointAmr, "cells")
window.Render()
check(len(errors.errors) >= 1 and "'phi'" in errors.errors[0] and
      "SetScalarModeToUsePointFieldData" in errors.errors[0] and
      mapper.GetNumberOfSamples() == 0,
      f"UseCellFieldData with a point array: {errors.errors[:1]}")
# 4. vtkAMRDualMesh and the probe filter.
mesh = vtkAMRDualMesh()
mesh.SetInputData(pointAmr)
mesh.SetInputArrayToProcess(0, 0, 0, vtkDataObject.FIELD_ASSOCIATION_POINTS, "phi")
built = mesh.Update()
report = json.loads(mesh.GetReportJSON()) if built else {}
print("vertex mesh:", report.get("counts"), report.get("memory", {}).get("bytesPerLeafCell"))
check(built and mesh.GetBuiltAssociation() == vtkDataObject.FIELD_ASSOCIATION_POINTS and
      report.get("association") == "points" and mesh.GetNumberOfHexes() == 0 and
      mesh.GetNumberOfTets() == 0 and mesh.GetNumberOfGridlets() > 0,
      "vtkAMRDualMesh builds the point array")
line = vtkLineSource()
line.SetPoint1(0.05, 0.1, 0.1)
line.SetPoint2(0.95, 0.9, 0.2)
line.SetResolution(200)
probe = vtkAMRDualMeshProbeFilter()
probe.SetInputConnection(line.GetOutputPort())
probe.SetSourceData(pointAmr)
probe.SetInputArrayToProcess(0, 1, 0, vtkDataObject.FIELD_ASSOCIATION_POINTS, "phi")
probe.Update()
out = probe.GetOutput()
values = vtk_to_numpy(out.GetPointData().GetArray("phi"))
mask = vtk_to_numpy(out.GetPointData().GetArray("vtkValidPointMask"))
direct = np.array([mesh.Sample(*out.GetPoint(i)) for i in range(out.GetNumberOfPoints())])
check(mask.all() and np.allclose(values, direct, rtol=0, atol=1e-6) and
      probe.GetDualMesh().GetBuiltAssociation() == vtkDataObject.FIELD_ASSOCIATION_POINTS,
      f"probe filter: {int(mask.sum())}/{len(mask)} valid, equal to vtkAMRDualMesh.Sample")

# vtkAMRDualMeshToUnstructuredGrid of the point array (a name only point data has): one hexahedron
# per leaf cell, with its corners at the cell corners (the bounds are the AMR's).
conv = vtkAMRDualMeshToUnstructuredGrid()
conv.SetInputDataObject(pointAmr)
conv.SetArrayName("phi")
conv.Update()
ug = conv.GetOutput()
amrBounds = [0.0] * 6
pointAmr.GetBounds(amrBounds)
ugBounds = ug.GetBounds()
check(ug.GetNumberOfCells() == mesh.GetNumberOfLeafCells() and
      max(abs(a - b) for a, b in zip(amrBounds, ugBounds)) < 1e-9,
      f"as an unstructured grid: {ug.GetNumberOfCells()} cells for {mesh.GetNumberOfLeafCells()} "
      f"leaves, bounds {ugBounds} vs {amrBounds}")

# The last check changes a block of pointAmr in place.
lid = next(i for i in range(pointAmr.GetNumberOfDataSets(1)) if pointAmr.GetDataSet(1, i))
grid = pointAmr.GetDataSet(1, lid)
phi = vtk_to_numpy(grid.GetPointData().GetArray("phi"))
short = numpy_to_vtk(phi[:-1].copy(), deep=1)
short.SetName("phi")
grid.GetPointData().RemoveArray("phi")
grid.GetPointData().AddArray(short)
pointAmr.Modified()
window, mapper, errors = scene(pointAmr, "points")
window.Render()
check(len(errors.errors) >= 1 and f"level 1 block {lid}" in errors.errors[0] and
      "tuples" in errors.errors[0] and mapper.GetNumberOfSamples() == 0,
      f"wrong tuple count: {errors.errors[:1]}")

if failures:
    print("FAIL:", "; ".join(failures))
    sys.exit(1)
print("PASS")
