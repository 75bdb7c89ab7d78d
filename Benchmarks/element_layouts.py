"""Stitching-element storage: what candidate layouts would cost on the real sets, measured on the
elements the builder makes today (issue 31: "stitching elements without stored vertices").

The dual mesh is exported with vtkAMRDualMeshToUnstructuredGrid (its stitching elements are the
cells with vtkDualCellSource 1-4, their points the distinct corner cells); per set it counts
elements E, corners C and distinct corner cells V, and prints bytes per leaf cell of:
  stored     today's layout: 16 B per distinct corner (twice its grid position as int32 x 3, and
             its value) + 4 B index per corner                          = 16 V + 4 C
  values     positions recomputed from the cell's level and index: a 4-byte value per distinct
             corner, a 4-byte index per corner, and what identifies the position: a base
             (twice the grid position of corner 0, 12 B) per element and one byte per corner
             (the corner's offset from the base in units of 2^shift, int8 per axis would need
             3 B; a level + octant code fits one byte when the offsets are octant steps)
                                                                        = 4 V + 4 C + 12 E + C
  inline     no sharing: each element stores its corner values, a base and a one-byte code per
             corner                                                     = 4 C + 12 E + C
  rel16      shared values, a 4-byte base vertex index per element and a 16-bit signed index
             offset per corner (needs vertex numbering where an element's corners lie within
             +-32767 of its first; the fraction that fits is measured on the export's numbering,
             which merges gridlet and element points, so it is a lower bound), positions as in
             `values`                                                   = 4 V + 4 E + 2 C + 12 E + C
and two feasibility checks: the fraction of elements whose corner offsets from corner 0, divided
by their greatest common power of two, fit int8 per axis, and the largest such offset.
Not a test: it measures and prints; the figures are quoted in docs/BENCHMARKS-MEMORY.md.

    /usr/bin/python3 Benchmarks/element_layouts.py [--data DIR] [--sets enzo,flame,...]
(PYTHONPATH must hold the build's lib/python3/dist-packages.)
"""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from memory_sets import SETS, available_sets, read_set  # noqa: E402


def pow2_gcd(a):
    """Largest power of two dividing every nonzero entry of the int array a (1 when all zero)."""
    nz = np.abs(a[a != 0])
    if nz.size == 0:
        return 1
    low = nz & -nz  # lowest set bit of each
    return int(low.min())


def measure(name, path, array):
    from amrdualmesh import vtkAMRDualMeshToUnstructuredGrid
    from vtkmodules.util.numpy_support import vtk_to_numpy
    amr = read_set(path, array)
    conv = vtkAMRDualMeshToUnstructuredGrid()
    conv.SetInputData(amr)
    conv.SetArrayName(array)
    conv.Update()
    ug = conv.GetOutput()
    dm = conv.GetDualMesh()
    leaf = dm.GetNumberOfLeafCells()
    src = vtk_to_numpy(ug.GetCellData().GetArray("vtkDualCellSource"))
    offsets = vtk_to_numpy(ug.GetCells().GetOffsetsArray())
    conn = vtk_to_numpy(ug.GetCells().GetConnectivityArray())
    pts = vtk_to_numpy(ug.GetPoints().GetData())
    # Twice the grid position on the finest level: the smallest spacing of the hierarchy.
    spacing = [0.0, 0.0, 0.0]
    amr.GetSpacing(amr.GetNumberOfLevels() - 1, spacing)
    h = np.array(spacing)
    elems = np.nonzero(src > 0)[0]
    E = elems.size
    C = 0
    used = set()
    fit8 = 0
    fit16 = 0
    max_off = 0
    for e in elems:
        ids = conn[offsets[e]:offsets[e + 1]]
        C += ids.size
        used.update(ids.tolist())
        rel = np.rint((pts[ids] - pts[ids[0]]) / h * 2.0).astype(np.int64)
        g = pow2_gcd(rel)
        scaled = rel // g
        m = int(np.abs(scaled).max())
        max_off = max(max_off, m)
        fit8 += m <= 127
        fit16 += int(np.abs(ids.astype(np.int64) - int(ids[0])).max()) <= 32767
    V = len(used)
    L = max(leaf, 1)
    rows = {
        "stored": 16 * V + 4 * C,
        "values": 4 * V + 4 * C + 12 * E + C,
        "inline": 4 * C + 12 * E + C,
        "rel16": 4 * V + 4 * E + 2 * C + 12 * E + C,
    }
    print("%-10s leaf %9d  elements %8d  corners %9d  distinct corners %8d  (%.2f corners/leaf,"
          " %.2f uses per corner)" % (name, leaf, E, C, V, C / L, C / max(V, 1)))
    print("           B/leaf: " + "  ".join("%s %.2f" % (k, v / L) for k, v in rows.items()))
    print("           offsets fit int8 after a power-of-two scale: %.1f %% (largest %d);"
          " 16-bit index offsets fit (export numbering): %.1f %%"
          % (100.0 * fit8 / max(E, 1), max_off, 100.0 * fit16 / max(E, 1)), flush=True)
    return rows


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--data", default=os.environ.get("AMRDM_SHARED_DATA", "/work/shared/amr-data"))
    ap.add_argument("--sets", default=",".join(SETS))
    args = ap.parse_args()
    for name, path, array in available_sets(args.data, args.sets):
        measure(name, path, array)


if __name__ == "__main__":
    main()
