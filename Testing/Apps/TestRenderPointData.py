"""amrdm-render --array finds point (vertex-centred) arrays too and says which association it
used (issue 35): the AMReX advection set through vtkCellDataToPointData is written as a .vthb
with the point array 'phi' only; --list-arrays lists it as points, --array phi renders it (exit
0, a non-blank PNG) and says "point data" on stderr; the cell-centred twin (the plotfile's cell
array 'phi') covers the same pixels (IoU >= 0.9 over pixels brighter than 0.05)."""
import os
import subprocess
import sys
import tempfile

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkFiltersCore import vtkCellDataToPointData
from vtkmodules.vtkIOAMR import vtkAMReXGridReader
from vtkmodules.vtkIOImage import vtkPNGReader
from vtkmodules.vtkIOXML import vtkXMLUniformGridAMRWriter

render = sys.argv[1]
data = os.environ.get("AMRDM_TEST_DATA", os.path.join(os.path.dirname(__file__), "..", "Data"))
plotfile = os.path.join(data, "amrex-advection-amrcore3d", "plt00040")
tmp = tempfile.mkdtemp(prefix="amrdm-points-")
reader = vtkAMReXGridReader()
reader.SetFileName(plotfile)
reader.UpdateInformation()
reader.SetMaxLevel(99)
reader.GetCellDataArraySelection().EnableAllArrays()
toPoints = vtkCellDataToPointData()
toPoints.SetInputConnection(reader.GetOutputPort())
writer = vtkXMLUniformGridAMRWriter()
writer.SetInputConnection(toPoints.GetOutputPort())
vthb = os.path.join(tmp, "advection-points.vthb")
writer.SetFileName(vthb)
writer.Write()

failures = []


def check(ok, what):
    print(f"{what}: {'ok' if ok else 'FAIL'}")
    if not ok:
        failures.append(what)


listing = subprocess.run([render, vthb, "--list-arrays"], capture_output=True, text=True)
check(listing.returncode == 0 and any(line.startswith("phi") and line.endswith("points")
                                      for line in listing.stdout.splitlines()),
      f"--list-arrays: {listing.stdout.strip()!r}")

common = ["--size", "160", "120", "--spp", "4", "--range", "1", "2", "--linear",
          "--eye", "1.2", "-0.6", "1.0", "--focal", "0.5", "0.5", "0.12", "--threads", "2"]
images = {}
for label, path in (("points", vthb), ("cells", plotfile)):
    png = os.path.join(tmp, f"{label}.png")
    run = subprocess.run([render, path, "--array", "phi", "-o", png] + common,
                         capture_output=True, text=True)
    said = [line for line in run.stderr.splitlines() if "array 'phi'" in line]
    print(label, run.returncode, said)
    expect = "point data" if label == "points" else "cell data"
    check(run.returncode == 0 and any(expect in line for line in said),
          f"{label}: exit {run.returncode}, says '{expect}' {run.stderr[-300:] if run.returncode else ''}")
    if run.returncode == 0:
        r = vtkPNGReader()
        r.SetFileName(png)
        r.Update()
        images[label] = vtk_to_numpy(r.GetOutput().GetPointData().GetScalars())[:, :3] / 255.0
if len(images) == 2:
    covered = {k: v.sum(axis=1) > 0.05 for k, v in images.items()}
    iou = (np.logical_and(covered["points"], covered["cells"]).sum() /
           max(1, np.logical_or(covered["points"], covered["cells"]).sum()))
    print(f"coverage points {covered['points'].mean():.3f}, cells {covered['cells'].mean():.3f}, "
          f"IoU {iou:.3f}; images in {tmp}")
    check(covered["cells"].mean() > 0.02 and iou >= 0.9, "coverage IoU >= 0.9")
if failures:
    print("FAIL:", "; ".join(failures))
    sys.exit(1)
print("PASS")
