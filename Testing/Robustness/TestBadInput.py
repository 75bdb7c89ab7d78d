"""Bad input gives a clear vtkErrorMacro message and no crash: no input, no levels, unknown array,
non-integer ratio, inconsistent spacing, empty blocks, non-AMR input to the probe."""
import math
import sys

from vtkmodules.vtkCommonDataModel import vtkAMRBox, vtkImageData, vtkOverlappingAMR
from amrdualmesh import vtkAMRDualMesh, vtkAMRDualMeshProbeFilter

import os
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "Support"))
from amrdm_testing import ErrorRecorder, make_amr  # noqa: E402

failures = []


def expect_error(name, amr, array, fragment):
    mesh = vtkAMRDualMesh()
    rec = ErrorRecorder(mesh)
    mesh.SetInputData(amr)
    if array is not None:
        mesh.SetArrayName(array)
    ok = mesh.Update()
    message = rec.errors[-1] if rec.errors else ""
    print("%-22s -> %s" % (name, message.strip().splitlines()[-1] if message else "(no error)"))
    if ok or fragment not in message:
        failures.append(name)
        print("FAIL: expected an error containing %r" % fragment)
    if not math.isnan(mesh.Sample(0.5, 0.5, 0.5)):
        failures.append(name + " sample")


good = [[((0, 0, 0), (3, 3, 3))], [((2, 2, 2), (5, 5, 5))]]
expect_error("no input", None, "f", "no input")
empty = vtkOverlappingAMR()
expect_error("no levels", empty, "f", "no levels")
expect_error("no array selected", make_amr(good), None, "no scalar array")
expect_error("unknown array", make_amr(good), "nope", "no numeric cell-data array named 'nope'")
bad_ratio = make_amr(good)
bad_ratio.SetSpacing(1, [1.0 / 1.5] * 3)
expect_error("non-integer ratio", bad_ratio, "f", "expected an integer refinement ratio")
aniso_ratio = make_amr(good)
aniso_ratio.SetSpacing(1, [0.5, 0.25, 0.5])
expect_error("ratio differs by axis", aniso_ratio, "f", "inconsistent spacing")
mismatch = make_amr(good, grid_spacing_override=(0.3, 0.3, 0.3))
expect_error("inconsistent spacing", mismatch, "f", "inconsistent spacing")
empty_block = make_amr(good)
empty_block.SetAMRBox(1, 0, vtkAMRBox((3, 3, 3), (2, 2, 2)))  # hi < lo: no cells
expect_error("empty block", empty_block, "f", "empty AMR box")

# The probe filter refuses image data as its source (the pipeline reports the type).
probe = vtkAMRDualMeshProbeFilter()
rec = ErrorRecorder(probe)
exec_rec = ErrorRecorder(probe.GetExecutive())
probe.SetInputData(vtkImageData())
probe.SetInputData(1, vtkImageData())  # bypasses SetSourceData's type check on purpose
probe.SetArrayName("f")
probe.Update()
errors = rec.errors + exec_rec.errors
print("%-22s -> %s" % ("probe image source", (errors or ["(no error)"])[-1].strip().splitlines()[-1]))
if not errors or "vtkOverlappingAMR" not in errors[-1]:
    failures.append("probe with image source")

print("%d failures" % len(failures))
sys.exit(1 if failures else 0)
