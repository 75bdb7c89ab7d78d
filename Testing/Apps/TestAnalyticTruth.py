"""The benchmark's analytic truth (Benchmarks/analytic_truth.py, analytic_scenes.py), validated
before anything is scored against it:
  1. constant field: the quadrature equals the closed-form transmittance (1 - alpha)^(L / u) and
     colour rgb (1 - T), for axis-aligned rays (L = 1 exactly) and for perspective rays of every
     chord length, with a table value between entries;
  2. smooth field: the quadrature converges as h^2 and its error estimate is small;
  3. the AMR scene written as .vthb through VTK and read back has AMReX-like boxes (<= 32 cells),
     properly nested levels, cell-centre values of the analytic field and the expected leaves;
  4. bad input gives a clear error.
Runs in a few seconds with /usr/bin/python3 (numpy, vtkmodules); no build products needed.
"""
import os
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "Benchmarks"))
import analytic_scenes as scenes  # noqa: E402
import analytic_truth as truth  # noqa: E402
from vtkmodules.util.numpy_support import vtk_to_numpy  # noqa: E402

failures = []


def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what)
    if not ok:
        failures.append(what)


# --- 1. constant field against the closed form ------------------------------------------------
rgb = np.array([1.0, 0.5, 0.25])
u = 0.25
# Two entries over [0, 1]: opacity 0.1 -> 0.5, so f = 0.25 reads alpha = 0.2 (between entries).
tf = truth.TransferFunction([[1.0, 0.5, 0.25, 0.1], [1.0, 0.5, 0.25, 0.5]], 0.0, 1.0, u)
field = scenes.constant_field(0.25)
alpha = 0.2

# Parallel camera straight down z over the unit square: every ray inside has chord exactly 1.
cam = truth.Camera((0.5, 0.5, 3.0), (0.5, 0.5, 0.5), up=(0, 1, 0), parallel=True, parallel_scale=0.6)
img, est = truth.truth_image(field, tf, cam, 24, 24, steps=16, ss=1)
o, d = cam.rays(24, 24, 0.5, 0.5)
inside = (np.abs(o[..., 0] - 0.5) < 0.5) & (np.abs(o[..., 1] - 0.5) < 0.5)
T = (1.0 - alpha) ** (1.0 / u)
err_in = np.abs(img[inside][:, :3] - rgb * (1 - T)).max()
err_a = np.abs(img[inside][:, 3] - (1 - T)).max()
check(inside.sum() > 200 and err_in < 1e-9 and err_a < 1e-9,
      "axis rays, L = 1: colour and opacity equal rgb (1 - T), 1 - T with T = 0.8^4 (max err %.2e, %.2e)"
      % (err_in, err_a))
check(np.abs(img[~inside]).max() == 0.0, "rays missing the domain stay black and transparent")
check(abs((1 - T) - 0.5904) < 1e-12, "closed form itself: 1 - 0.8^4 = 0.5904")

# Perspective (the benchmark's default view): chords of every length through corners and faces.
cam = truth.default_camera()
o, d = cam.rays(40, 32, 0.5, 0.5)
o, d = o.reshape(-1, 3), d.reshape(-1, 3)
t0, t1 = truth.box_chords(o, d)
L = np.maximum(t1 - t0, 0.0)
got = truth.integrate(field, tf, o, d, steps=7)
want_a = 1 - (1 - alpha) ** (L / u)
e = max(np.abs(got[:, 3] - want_a).max(), np.abs(got[:, :3] - want_a[:, None] * rgb).max())
check(L.max() > 1.2 and L.max() <= np.sqrt(3) + 1e-9 and (L == 0).any(),
      "default view: chords from 0 to %.3f (<= sqrt 3)" % L.max())
check(e < 1e-9, "perspective rays: opacity 1 - (1 - alpha)^(L/u) and colour, max err %.2e" % e)

# --- 2. smooth field: convergence order and error estimate ------------------------------------
blob = scenes.gaussian_blob()
tf2 = truth.TransferFunction([[0.2, 0.3, 1.0, 0.0], [1.0, 1.0, 0.3, 0.6], [1.0, 0.2, 0.1, 0.9]],
                             0.0, 1.0, 0.1)
ref = truth.integrate(blob, tf2, o, d, steps=2048)
e64 = np.abs(truth.integrate(blob, tf2, o, d, steps=64) - ref).max()
e128 = np.abs(truth.integrate(blob, tf2, o, d, steps=128) - ref).max()
check(3.0 < e64 / e128 < 5.0, "blob: midpoint error falls as h^2 (ratio %.2f for h / 2)" % (e64 / e128))
cam_small = truth.default_camera()
_, est = truth.truth_image(blob, tf2, cam_small, 20, 16, steps=512, ss=1)
check(est < 1e-4, "blob: truth error estimate at 512 steps %.1e < 1e-4" % est)

# --- 3. the .vthb round trip --------------------------------------------------------------------
with tempfile.TemporaryDirectory() as tmp:
    path = scenes.write_scene("blob", tmp)
    amr = scenes.read_vthb(path)
boxes = scenes.build_boxes(blob)
check(amr.GetNumberOfLevels() == 3 == len(boxes), "blob .vthb: 3 levels read back")
ok_boxes, ok_values, ok_nest = True, 0.0, True
for level in range(amr.GetNumberOfLevels()):
    check(amr.GetNumberOfDataSets(level) == len(boxes[level]),
          "level %d: %d boxes read back" % (level, len(boxes[level])))
    h = 1.0 / (32 << level)
    for b in range(amr.GetNumberOfDataSets(level)):
        g = amr.GetDataSet(level, b)
        dims = [n - 1 for n in g.GetDimensions()]
        ok_boxes &= max(dims) <= 32 and abs(g.GetSpacing()[0] - h) < 1e-12
        org = g.GetOrigin()
        ax = [org[a] + (np.arange(dims[a]) + 0.5) * h for a in range(3)]
        z, y, x = np.meshgrid(ax[2], ax[1], ax[0], indexing="ij")
        v = vtk_to_numpy(g.GetCellData().GetArray(scenes.ARRAY)).reshape(dims[2], dims[1], dims[0])
        ok_values = max(ok_values, float(np.abs(v - blob.value(x, y, z)).max()))
        if level > 0:  # nested: the box lies inside the union of the coarser level's boxes
            lo = [int(round(org[a] / (2 * h))) for a in range(3)]
            inside_one = any(all(c[a] <= lo[a] and lo[a] + dims[a] // 2 <= c[a] + 16 for a in range(3))
                             for c in boxes[level - 1])
            ok_nest &= inside_one
check(ok_boxes, "every box <= 32 cells a side, spacing halves per level")
check(ok_values < 1e-12, "cell values are the analytic field at cell centres (max err %.1e)" % ok_values)
check(ok_nest, "every fine box lies inside a coarser box")
expected_leaves = sum(16 ** 3 * len(b) for b in boxes) - sum(8 ** 3 * len(b) for b in boxes[1:])
check(scenes.leaf_cells(amr) == expected_leaves,
      "leaf cells %d == boxes minus covered (%d)" % (scenes.leaf_cells(amr), expected_leaves))

# --- 4. bad input ------------------------------------------------------------------------------
for what, fn in (("unit distance 0", lambda: truth.TransferFunction([[1, 1, 1, 1]], 0, 1, 0.0)),
                 ("box of 64 cells", lambda: scenes.build_boxes(blob, base=64, box=64))):
    try:
        fn()
        check(False, "%s is refused" % what)
    except ValueError as exc:
        check("expected" in str(exc), "%s is refused: %s" % (what, exc))

if failures:
    print("%d check(s) failed" % len(failures))
    sys.exit(1)
print("all checks passed")
