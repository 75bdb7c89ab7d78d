"""A deep .vthb at a 1e6 offset, written and read by VTK's own XML AMR writer and reader, loads and
samples linear fields exactly (docs/ROBUSTNESS.md, "Bad input" and "Geometry extremes").

The .vthb stores each level's spacing as text with 6 significant digits (3.8147e-06 for
3.814697265625e-06), while every block's .vti stores its origin with 17. Multiplied by box indices
of 2^24, the rounded spacing puts a block 2e-4 away from its own origin, a hundred thousand finest
cells. The intake snaps each level's spacing to level 0's spacing over the refinement ratios and
checks origins against a tolerance relative to the domain, so:
1. 13 levels (the issue's case: level-12 spacing written as 0.00195312) and 23 levels (grid
   coordinates up to 2^27) at origin (1e6, 1e6, 1e6) build without error;
2. vtkAMRDualMeshProbeFilter reproduces a linear field at points in every level's box to 1e-5 of
   that box's own range (the finest box spans 1.5e-5 world units), with no masked point;
3. a block whose origin really disagrees with its box is refused, and the message's two numbers
   differ when printed."""
import os
import re
import sys
import tempfile

from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkIOXML import vtkXMLUniformGridAMRReader, vtkXMLUniformGridAMRWriter

from amrdualmesh import vtkAMRDualMesh

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "Support"))
from amrdm_testing import ErrorRecorder, checker, halton, make_amr, probe_points  # noqa: E402

OFFSET = 1.0e6
SPACING0 = 8.0
CELLS = 8  # every level is one 8^3 box
CENTRE = OFFSET + SPACING0 * CELLS / 2  # every box is centred here
GRADIENT = (1.0, 2.0, -0.5)
RELATIVE_TOLERANCE = 1e-5
POINTS_PER_LEVEL = 64
failures = []
check = checker(failures)


def chain(num_levels):
    """Nested boxes, ratio 2: each level's 8^3 box covers the middle half of the one above."""
    levels = [[((0, 0, 0), (CELLS - 1,) * 3)]]
    for _ in range(1, num_levels):
        lo = tuple(2 * c + CELLS // 2 for c in levels[-1][0][0])
        levels.append([(lo, tuple(c + CELLS - 1 for c in lo))])
    return levels


def linear(c):
    return sum(GRADIENT[d] * (c[d] - CENTRE) for d in range(3))


def write_and_read(amr, folder, name):
    path = os.path.join(folder, name + ".vthb")
    writer = vtkXMLUniformGridAMRWriter()
    writer.SetFileName(path)
    writer.SetInputData(amr)
    writer.Write()
    reader = vtkXMLUniformGridAMRReader()
    reader.SetFileName(path)
    reader.SetMaximumLevelsToReadByDefault(0)  # 0 = every level
    reader.Update()
    with open(path) as f:
        stored = re.findall(r'spacing="([^ "]+)', f.read())
    return reader.GetOutput(), stored


def probe_levels(amr, levels):
    """Per level: (misses, worst error / the box's range) at points inside the level's box."""
    points = vtkPoints()
    points.SetDataTypeToDouble()
    expected, owner = [], []
    for level, boxes in enumerate(levels):
        h = SPACING0 / 2 ** level
        lo, hi = boxes[0]
        for i in range(POINTS_PER_LEVEL):
            u = (halton(i + 1, 2), halton(i + 1, 3), halton(i + 1, 5))
            # inside the cell-centre hull of the box: [lo + 0.5, hi + 0.5] cells
            p = [OFFSET + (lo[d] + 0.5 + u[d] * (hi[d] - lo[d])) * h for d in range(3)]
            points.InsertNextPoint(p)
            expected.append(linear(p))
            owner.append(level)
    values, mask, rec = probe_points(points, amr, "f")
    if values is None or mask is None:
        return None, rec.errors
    result = [[0, 0.0] for _ in levels]
    for i in range(len(expected)):
        level = owner[i]
        box_range = sum(abs(g) for g in GRADIENT) * CELLS * SPACING0 / 2 ** level
        if not mask.GetValue(i):
            result[level][0] += 1
        else:
            result[level][1] = max(result[level][1], abs(values.GetValue(i) - expected[i]) / box_range)
    return result, rec.errors


with tempfile.TemporaryDirectory() as folder:
    for num_levels in (13, 23):
        levels = chain(num_levels)
        amr, stored = write_and_read(
            make_amr(levels, origin=(OFFSET,) * 3, spacing0=(SPACING0,) * 3, field=linear),
            folder, "deep%d" % num_levels)
        finest = SPACING0 / 2 ** (num_levels - 1)
        check(amr.GetNumberOfLevels() == num_levels,
              "%d levels written and read back by VTK (finest spacing stored as %s, exactly %r)"
              % (num_levels, stored[-1], finest))
        result, errors = probe_levels(amr, levels)
        check(result is not None and not errors,
              "%d levels at a 1e6 offset build: %s" % (num_levels, errors[-1] if errors else "no error"))
        if result is None:
            continue
        misses = sum(r[0] for r in result)
        worst = max(r[1] for r in result)
        worst_level = max(range(num_levels), key=lambda l: result[l][1])
        check(misses == 0, "%d levels: %d of %d probe points masked"
              % (num_levels, misses, num_levels * POINTS_PER_LEVEL))
        check(worst <= RELATIVE_TOLERANCE,
              "%d levels: linear field reproduced to %.2e of each box's range (worst: level %d; bound %g)"
              % (num_levels, worst, worst_level, RELATIVE_TOLERANCE))

    # A block that truly sits elsewhere than its box says: refused, with numbers that differ.
    levels = chain(13)
    shifted = make_amr(levels, origin=(OFFSET,) * 3, spacing0=(SPACING0,) * 3, field=linear)
    grid = shifted.GetDataSet(12, 0)
    o = list(grid.GetOrigin())
    o[1] += 3 * SPACING0 / 2 ** 12  # three level-12 cells
    grid.SetOrigin(o)
    amr, _ = write_and_read(shifted, folder, "shifted")
    mesh = vtkAMRDualMesh()
    rec = ErrorRecorder(mesh)
    mesh.SetInputData(amr)
    mesh.SetArrayName("f")
    ok = mesh.Update()
    message = rec.errors[-1].strip().splitlines()[-1] if rec.errors else ""
    print("shifted block -> " + message)
    numbers = re.findall(r"has origin (\S+) on axis 1; expected (\S+) ", message)
    check(not ok and "inconsistent origin" in message and "level 12 block 0" in message,
          "a block shifted by 3 cells on level 12 is refused, naming the block")
    check(len(numbers) == 1 and numbers[0][0] != numbers[0][1],
          "the message's origins differ as printed: %s" % (str(numbers[0]) if numbers else "(none)"))

if failures:
    print("%d failure(s)" % len(failures))
    sys.exit(1)
print("all passed")
