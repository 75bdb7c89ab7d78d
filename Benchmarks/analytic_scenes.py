"""Analytic AMR scenes for the benchmark truth: fields known in closed form, sampled at cell
centres on an AMReX-like hierarchy, written as .vthb through VTK and read back.

Nothing here uses our renderer's code: the hierarchy is built with numpy and VTK only, so the
truth images of analytic_truth.py owe nothing to the dual mesh or its interpolant.

Hierarchy (domain [0, 1]^3, refinement ratio 2, `levels` levels (3), base `base` cells a side (32)):
  * every level is tiled into boxes of `box` cells a side (<= 32, as AMReX's max_grid_size);
  * a box of level l + 1 exists where some level-l cell under it is flagged (the field changes
    by more than `threshold` over the cell: |grad f| h > threshold), and the box grown by one
    level-l cell is covered by level-l boxes (proper nesting, as AMReX keeps a buffer);
  * cell values are the field at the cell centres (cell data, one array).

    /usr/bin/python3 Benchmarks/analytic_scenes.py OUT_DIR      # writes every scene's .vthb
"""
import os
import sys

import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonDataModel import vtkAMRBox, vtkAMRUtilities, vtkOverlappingAMR, vtkUniformGrid
from vtkmodules.vtkIOXML import vtkXMLUniformGridAMRReader, vtkXMLUniformGridAMRWriter

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from bench_vtk import XYZ_GRID  # noqa: E402

ARRAY = "f"


class Field:
    """A scalar field on [0, 1]^3: value(x, y, z) and gradient magnitude, vectorised."""

    def __init__(self, name, value, grad_norm, doc):
        self.name, self.value, self.grad_norm, self.doc = name, value, grad_norm, doc


def constant_field(c=1.0):
    return Field("constant", lambda x, y, z: np.full(np.broadcast(x, y, z).shape, c),
                 lambda x, y, z: np.zeros(np.broadcast(x, y, z).shape),
                 "f = %g everywhere (closed-form transmittance)" % c)


def gaussian_blob(centre=(0.5, 0.5, 0.5), sigma=0.12):
    cx, cy, cz = centre

    def value(x, y, z):
        r2 = (x - cx) ** 2 + (y - cy) ** 2 + (z - cz) ** 2
        return np.exp(-r2 / (2 * sigma ** 2))

    def grad(x, y, z):
        r = np.sqrt((x - cx) ** 2 + (y - cy) ** 2 + (z - cz) ** 2)
        return r / sigma ** 2 * value(x, y, z)

    return Field("blob", value, grad, "f = exp(-|x - c|^2 / (2 s^2)), c = (%g, %g, %g), s = %g"
                 % (cx, cy, cz, sigma))


def thin_shell(centre=(0.5, 0.5, 0.5), radius=0.3, width=0.03):
    cx, cy, cz = centre

    def value(x, y, z):
        r = np.sqrt((x - cx) ** 2 + (y - cy) ** 2 + (z - cz) ** 2)
        return np.exp(-((r - radius) / width) ** 2)

    def grad(x, y, z):
        r = np.sqrt((x - cx) ** 2 + (y - cy) ** 2 + (z - cz) ** 2)
        d = (r - radius) / width
        return np.abs(2 * d / width) * np.exp(-d * d)

    return Field("shell", value, grad, "f = exp(-((|x - c| - R) / w)^2), R = %g, w = %g (thin feature)"
                 % (radius, width))


SCENES = {"constant": constant_field, "blob": gaussian_blob, "shell": thin_shell}


def _centres(lo, n, h):
    """Cell-centre coordinate arrays (ij indexing) of an n[0] x n[1] x n[2] box from index lo."""
    ax = [(lo[a] + np.arange(n[a]) + 0.5) * h for a in range(3)]
    return np.meshgrid(ax[0], ax[1], ax[2], indexing="ij")


def build_boxes(field, base=32, levels=3, box=16, threshold=0.05):
    """Per level, the list of box lower indices (in that level's index space, each box box^3)."""
    if box > 32 or box < 2:
        raise ValueError("box size %d: expected 2 .. 32 cells a side (AMReX-like)" % box)
    if base % box:
        raise ValueError("base %d: expected a multiple of the box size %d" % (base, box))
    boxes = [[(i, j, k) for i in range(0, base, box) for j in range(0, base, box)
              for k in range(0, base, box)]]
    for level in range(1, levels):
        n_coarse = base << (level - 1)
        h = 1.0 / n_coarse
        covered = np.zeros((n_coarse,) * 3, bool)
        flagged = np.zeros((n_coarse,) * 3, bool)
        for lo in boxes[level - 1]:
            s = tuple(slice(lo[a], lo[a] + box) for a in range(3))
            covered[s] = True
            x, y, z = _centres(lo, (box,) * 3, h)
            flagged[s] = field.grad_norm(x, y, z) * h > threshold
        fine = []
        half = box // 2  # a fine box spans box/2 coarse cells a side
        for i in range(0, n_coarse, half):
            for j in range(0, n_coarse, half):
                for k in range(0, n_coarse, half):
                    if not flagged[i:i + half, j:j + half, k:k + half].any():
                        continue
                    g = tuple(slice(max(c - 1, 0), min(c + half + 1, n_coarse)) for c in (i, j, k))
                    if covered[g].all():
                        fine.append((2 * i, 2 * j, 2 * k))
        if not fine:
            break
        boxes.append(fine)
    return boxes


def make_amr(field, base=32, levels=3, box=16, threshold=0.05):
    """The vtkOverlappingAMR of `field` (cell data ARRAY at cell centres, blanking set)."""
    boxes = build_boxes(field, base, levels, box, threshold)
    amr = vtkOverlappingAMR()
    amr.Initialize(len(boxes), [len(b) for b in boxes])
    amr.SetOrigin([0.0, 0.0, 0.0])
    amr.SetGridDescription(XYZ_GRID)
    for level, level_boxes in enumerate(boxes):
        h = 1.0 / (base << level)
        amr.SetSpacing(level, [h, h, h])
        if level + 1 < len(boxes):
            amr.SetRefinementRatio(level, 2)
        for b, lo in enumerate(level_boxes):
            hi = [lo[a] + box - 1 for a in range(3)]
            amr.SetAMRBox(level, b, vtkAMRBox(list(lo), hi))
            grid = vtkUniformGrid()
            grid.SetOrigin(lo[0] * h, lo[1] * h, lo[2] * h)
            grid.SetSpacing(h, h, h)
            grid.SetDimensions(box + 1, box + 1, box + 1)
            x, y, z = _centres(lo, (box,) * 3, h)
            v = field.value(x, y, z).astype(np.float64)
            arr = numpy_to_vtk(np.ascontiguousarray(v.transpose(2, 1, 0)).ravel(), deep=True)
            arr.SetName(ARRAY)
            grid.GetCellData().AddArray(arr)
            grid.GetCellData().SetActiveScalars(ARRAY)
            amr.SetDataSet(level, b, grid)
    amr.GenerateParentChildInformation()
    vtkAMRUtilities.BlankCells(amr)
    return amr


def write_vthb(amr, path):
    w = vtkXMLUniformGridAMRWriter()
    w.SetFileName(path)
    w.SetInputData(amr)
    if not w.Write():
        raise RuntimeError("vtkXMLUniformGridAMRWriter could not write %s" % path)


def read_vthb(path):
    from file_check import check_file
    check_file(path)
    r = vtkXMLUniformGridAMRReader()
    r.SetFileName(path)
    r.SetMaximumLevelsToReadByDefault(0)  # every level
    r.Update()
    amr = r.GetOutput()
    if amr is None or amr.GetNumberOfLevels() == 0:
        raise RuntimeError("%s: VTK read no AMR levels" % path)
    return amr


def leaf_cells(amr):
    """Number of unblanked (leaf) cells."""
    n = 0
    for level in range(amr.GetNumberOfLevels()):
        for b in range(amr.GetNumberOfDataSets(level)):
            g = amr.GetDataSet(level, b)
            ghost = g.GetCellGhostArray()
            if ghost is None:
                n += g.GetNumberOfCells()
            else:
                n += int((vtk_to_numpy(ghost) & 8 == 0).sum())  # vtkDataSetAttributes::HIDDENCELL
    return n


def write_scene(name, out_dir, **kw):
    path = os.path.join(out_dir, "analytic-%s.vthb" % name)
    write_vthb(make_amr(SCENES[name](), **kw), path)
    return path


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit("usage: analytic_scenes.py OUT_DIR")
    os.makedirs(sys.argv[1], exist_ok=True)
    for name in SCENES:
        p = write_scene(name, sys.argv[1])
        amr = read_vthb(p)
        print("%s: %d levels, %s boxes, %d leaf cells -> %s" % (
            name, amr.GetNumberOfLevels(),
            [amr.GetNumberOfDataSets(l) for l in range(amr.GetNumberOfLevels())], leaf_cells(amr), p))
