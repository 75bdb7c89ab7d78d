"""Robustness of the AMR intake and the field (see docs/ROBUSTNESS.md): a level without blocks,
wrong-typed, integer and vector arrays, NaN/Inf values, overlapping boxes, a memory limit,
constant fields and huge or tiny magnitudes. Each case: a clear message or a correct field,
never a crash."""
import math
import sys

from vtkmodules.vtkCommonCore import vtkIntArray, vtkStringArray, vtkDoubleArray
from amrdualmesh import vtkAMRDualMesh

import os
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "Support"))
from amrdm_testing import ErrorRecorder, checker, make_amr  # noqa: E402

failures = []
check = checker(failures)


def build(amr, array="f", component=-1, memory_limit=0):
    mesh = vtkAMRDualMesh()
    rec = ErrorRecorder(mesh)
    mesh.SetInputData(amr)
    mesh.SetArrayName(array)
    mesh.SetComponent(component)
    mesh.SetMemoryLimit(memory_limit)
    ok = mesh.Update()
    return mesh, ok, rec


def replace_array(amr, name, make):
    """Adds array `name` to every block; make(grid) returns the filled array."""
    for level in range(amr.GetNumberOfLevels()):
        for i in range(amr.GetNumberOfDataSets(level)):
            grid = amr.GetDataSet(level, i)
            a = make(grid)
            a.SetName(name)
            grid.GetCellData().AddArray(a)


two_levels = [[((0, 0, 0), (7, 7, 7))], [((4, 4, 4), (9, 9, 9))]]
lin = lambda c: 1.5 * c[0] - 0.5 * c[1] + 2.0 * c[2]

# A level without blocks (the finest level declared but empty).
amr = make_amr([[((0, 0, 0), (5, 5, 5))], []], field=lin)
mesh, ok, rec = build(amr)
# 6^3 cells: the 7^3 dual cells of the lattice extended by the clamped boundary layer's ghosts
# are all perfect or boundary cubes, in gridlets: no stitching element.
check(ok and mesh.GetNumberOfPerfectCubes() == 7 ** 3
      and mesh.GetNumberOfHexes() + mesh.GetNumberOfPyramids() + mesh.GetNumberOfWedges()
      + mesh.GetNumberOfTets() == 0,
      "a level without blocks builds one level of gridlets, its boundary layer included")
check(abs(mesh.Sample(2.2, 3.1, 2.9) - lin((2.2, 3.1, 2.9))) < 1e-5, "and samples the linear field")

# Wrong-typed array: a string array is not numeric.
amr = make_amr(two_levels, field=lin)
def strings(grid):
    s = vtkStringArray()
    s.SetNumberOfValues(grid.GetNumberOfCells())
    return s
replace_array(amr, "label", strings)
mesh, ok, rec = build(amr, "label")
check(not ok and rec.errors and "no numeric cell-data array named 'label'" in rec.errors[-1],
      "a string array is refused by name")

# Integer array: converted, the linear field of integers is reproduced.
amr = make_amr(two_levels, field=lin)
def integers(grid):
    a = vtkIntArray()
    n = grid.GetNumberOfCells()
    a.SetNumberOfTuples(n)
    f = grid.GetCellData().GetArray("f")
    for c in range(n):
        a.SetValue(c, int(round(1000 * f.GetValue(c))))
    return a
replace_array(amr, "ints", integers)
mesh, ok, rec = build(amr, "ints")
x = (3.3, 4.6, 5.1)
check(ok and abs(mesh.Sample(*x) - 1000 * lin(x)) < 1e-2, "an integer array is sampled (%.4f vs %.4f)" % (mesh.Sample(*x), 1000 * lin(x)))

# Vector array: magnitude by default, one component on request, a bad component refused.
def vectors(grid):
    a = vtkDoubleArray()
    a.SetNumberOfComponents(3)
    n = grid.GetNumberOfCells()
    a.SetNumberOfTuples(n)
    for c in range(n):
        a.SetTuple3(c, 3.0, 4.0, 12.0)
    return a
replace_array(amr, "v", vectors)
mesh, ok, rec = build(amr, "v")
check(ok and abs(mesh.Sample(*x) - 13.0) < 1e-5, "a vector array gives its magnitude (13)")
mesh, ok, rec = build(amr, "v", component=1)
check(ok and abs(mesh.Sample(*x) - 4.0) < 1e-6, "component 1 gives 4")
mesh, ok, rec = build(amr, "v", component=5)
check(not ok and "has 3 components" in rec.errors[-1], "component 5 of a 3-component array is refused")

# NaN and Inf: treated as empty with one warning, never a NaN sample inside valid cells.
amr = make_amr(two_levels, field=lin)
grid0 = amr.GetDataSet(0, 0)
f0 = grid0.GetCellData().GetArray("f")
f0.SetValue(0, float("nan"))
f0.SetValue(7 + 8 * 7 + 64 * 3, float("inf"))
mesh, ok, rec = build(amr)
check(ok and len(rec.warnings) == 1 and "2 NaN or infinite" in rec.warnings[0],
      "NaN/Inf values: one warning naming their count")
check(mesh.GetNumberOfNonFiniteValues() == 2, "the report counts them")
check(math.isnan(mesh.Sample(0.6, 0.6, 0.6)), "the dual cells touching a NaN cell are a hole")
check(abs(mesh.Sample(*x) - lin(x)) < 1e-5, "elsewhere the field is unchanged")

# Overlapping boxes on one level.
amr = make_amr([[((0, 0, 0), (5, 5, 5)), ((3, 3, 3), (7, 7, 7))]], field=lin)
mesh, ok, rec = build(amr)
check(not ok and "overlap" in rec.errors[-1], "overlapping boxes on one level are refused")

# A memory limit below what the build needs: a clear error before allocating.
amr = make_amr([[((0, 0, 0), (63, 63, 63))]], field=lin)
mesh, ok, rec = build(amr, memory_limit=1)
check(not ok and "MiB" in rec.errors[-1] and "available" in rec.errors[-1],
      "a build over the memory limit is refused before allocating")

# Constant field, huge and tiny magnitudes.
for scale in (1e-30, 1.0, 1e30):
    amr = make_amr(two_levels, field=lambda c, s=scale: s * (1.0 + 0.01 * lin(c)))
    mesh, ok, rec = build(amr)
    v = mesh.Sample(*x)
    expect = scale * (1.0 + 0.01 * lin(x))
    check(ok and abs(v - expect) <= 1e-6 * abs(expect), "magnitude %g: relative error %.2g" % (scale, abs(v - expect) / abs(expect)))
amr = make_amr(two_levels, field=lambda c: 42.0)
mesh, ok, rec = build(amr)
check(ok and mesh.Sample(*x) == 42.0 and mesh.Sample(5.01, 5.01, 5.01) == 42.0, "a constant field is exactly constant")

print("%d failures" % len(failures))
sys.exit(1 if failures else 0)
