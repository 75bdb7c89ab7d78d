"""Scale series: how the dual mesh's build time, memory and frame time grow with the number of
leaf cells, on realistic block-structured hierarchies made in memory, driven as a new user would
through the Python package (vtkAMRDualMesh, vtkAMRDualMeshVolumeMapper).

Hierarchy (numpy + VTK only): a cube of n0^3 level-0 cells over [0, 1]^3 tiled into AMReX-like
boxes of at most 32 cells a side; levels 1 and 2 (ratio 2) are boxes of 32^3 cells placed on
the tiles (16 parent cells a side) where a smooth 3D field's gradient is largest: the top
REFINE[0] of level-0 tiles, then the top REFINE[1] of the level-1 tiles inside them (proper
nesting: a level-2 box's parent cells and a one-cell buffer lie in level-1 boxes). Values are
the field at the cell centres (float32). n0 is chosen for the requested leaf-cell count.

For each size: the build (seconds, leaf cells per second), the finished mesh's bytes by
category and per leaf cell, the first frame's peak resident memory above the input (the
process's peak, reset before it through /proc/self/clear_refs: build, transfer-function setup,
frame buffers), the transfer-function setup (majorants, culling) after the build, and the median
frame time of the path tracer and the ray marcher at 256^2 (each Render adds one sample).

    /usr/bin/python3 Benchmarks/scale_series.py OUT.json [--sizes 1e6,4e6,...] [--frames N]
        [--threads N]
Run under xvfb-run (the frames render in a VTK window). Not a test: it measures and writes JSON;
Benchmarks/scale_report.py turns it into tables, growth exponents and plots.
"""
import argparse
import json
import math
import os
import sys
import time

import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk
from vtkmodules.vtkCommonDataModel import vtkAMRBox, vtkOverlappingAMR, vtkUniformGrid

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from bench_vtk import XYZ_GRID, first_frame_peak, offscreen_volume, source_commit  # noqa: E402

BOX = 32                 # AMReX max_grid_size
TILE = BOX // 2          # parent cells under one refined box, a side
REFINE = (0.30, 0.27)    # fraction of level-0 tiles refined, of level-1 tiles refined again
ARRAY = "f"


def field(x, y, z):
    """Smooth, with sharp-ish features: two Gaussian shells and a plane wave."""
    r1 = np.sqrt((x - 0.35) ** 2 + (y - 0.4) ** 2 + (z - 0.5) ** 2)
    r2 = np.sqrt((x - 0.7) ** 2 + (y - 0.6) ** 2 + (z - 0.45) ** 2)
    return (np.exp(-((r1 - 0.2) / 0.04) ** 2) + 0.7 * np.exp(-((r2 - 0.15) / 0.03) ** 2)
            + 0.2 * (1 + np.sin(6.0 * x + 4.0 * y)) * 0.5).astype(np.float32)


def gradient_score(lo, h, n):
    """Largest finite-difference gradient over an n^3 block of cells of size h from index lo,
    sampled on a 4^3 lattice (tile selection needs only a ranking)."""
    s = (np.arange(4) + 0.5) / 4.0 * n
    ax = [(lo[a] + s) * h for a in range(3)]
    x, y, z = np.meshgrid(ax[0], ax[1], ax[2], indexing="ij")
    d = 0.5 * h
    g = sum((field(x + d * (a == 0), y + d * (a == 1), z + d * (a == 2)) -
             field(x - d * (a == 0), y - d * (a == 1), z - d * (a == 2))) ** 2 for a in range(3))
    return float(np.sqrt(g.max())) / h


def leaf_factor():
    f1, f2 = REFINE[0], REFINE[0] * REFINE[1]
    return (1 - f1) + 8 * (f1 - f2) + 64 * f2


def plan(target_leaf_cells):
    """(n0, box lower corners per level) for about `target_leaf_cells` leaf cells: n0 from the
    refinement fractions, corrected once by the leaf count of that plan (nesting trims level 2
    most on small domains)."""
    n0 = max(2 * TILE, int(round((target_leaf_cells / leaf_factor()) ** (1 / 3) / TILE)) * TILE)
    levels = plan_boxes(n0)
    n1 = max(2 * TILE, int(round(n0 * (target_leaf_cells / planned_leaf_cells(n0, levels))
                                 ** (1 / 3) / TILE)) * TILE)
    return (n1, plan_boxes(n1)) if n1 != n0 else (n0, levels)


def planned_leaf_cells(n0, levels):
    cells = [n0 ** 3] + [len(b) * BOX ** 3 for b in levels[1:]]
    return sum(c - (cells[i + 1] // 8 if i + 1 < len(cells) else 0) for i, c in enumerate(cells))


def plan_boxes(n0):
    """Box lower corners per level for a level 0 of n0^3 cells."""
    levels = [[(i, j, k) for i in range(0, n0, BOX) for j in range(0, n0, BOX)
               for k in range(0, n0, BOX)]]
    parents = [(i, j, k) for i in range(0, n0, TILE) for j in range(0, n0, TILE)
               for k in range(0, n0, TILE)]
    for level, fraction in enumerate(REFINE):
        h = 1.0 / (n0 << level)
        scores = np.array([gradient_score(t, h, TILE) for t in parents])
        keep = max(1, int(round(fraction * len(parents))))
        chosen = sorted(parents[i] for i in np.argsort(-scores, kind="stable")[:keep])
        if level + 1 < len(REFINE):
            # Proper nesting: refine a level-1 tile only when it and a one-cell buffer lie in
            # level-1 boxes (all its neighbours' parents chosen, or the domain edge).
            chosen_set = set(chosen)
            n1 = n0 << (level + 1)
            children = []
            for c in chosen:
                for o in [(a, b, d) for a in (0, TILE) for b in (0, TILE) for d in (0, TILE)]:
                    t = (2 * c[0] + o[0], 2 * c[1] + o[1], 2 * c[2] + o[2])
                    inside = True
                    for nb in [(a, b, d) for a in (-1, 0, 1) for b in (-1, 0, 1) for d in (-1, 0, 1)]:
                        q = [t[e] + nb[e] * TILE for e in range(3)]
                        if min(q) < 0 or max(q) >= n1:
                            continue
                        parent = tuple((q[e] // 2) // TILE * TILE for e in range(3))
                        inside = inside and parent in chosen_set
                    if inside:
                        children.append(t)
            parents_next = children
        levels.append([(2 * c[0], 2 * c[1], 2 * c[2]) for c in chosen])
        if level + 1 < len(REFINE):
            parents = parents_next
    return levels


def make_amr(n0, levels):
    amr = vtkOverlappingAMR()
    amr.Initialize(len(levels), [len(b) for b in levels])
    amr.SetOrigin([0.0, 0.0, 0.0])
    amr.SetGridDescription(XYZ_GRID)
    keep = []  # numpy buffers referenced by the VTK arrays (deep=False)
    for level, boxes in enumerate(levels):
        h = 1.0 / (n0 << level)
        amr.SetSpacing(level, [h, h, h])
        if level + 1 < len(levels):
            amr.SetRefinementRatio(level, 2)
        for b, lo in enumerate(boxes):
            n = [min(BOX, (n0 << level) - lo[a]) for a in range(3)]
            amr.SetAMRBox(level, b, vtkAMRBox(list(lo), [lo[a] + n[a] - 1 for a in range(3)]))
            grid = vtkUniformGrid()
            grid.SetOrigin(lo[0] * h, lo[1] * h, lo[2] * h)
            grid.SetSpacing(h, h, h)
            grid.SetDimensions(n[0] + 1, n[1] + 1, n[2] + 1)
            ax = [(lo[a] + np.arange(n[a], dtype=np.float32) + 0.5) * np.float32(h)
                  for a in range(3)]
            z, y, x = np.meshgrid(ax[2], ax[1], ax[0], indexing="ij")  # x fastest
            v = np.ascontiguousarray(field(x, y, z)).ravel()
            keep.append(v)
            arr = numpy_to_vtk(v, deep=False)
            arr.SetName(ARRAY)
            grid.GetCellData().AddArray(arr)
            amr.SetDataSet(level, b, grid)
    return amr, keep


def make_view(amr, threads):
    """The mapper in a 256^2 offscreen window, camera at azimuth 35, elevation 25."""
    mapper, window, ren, volume = offscreen_volume(amr, ARRAY, threads, 1.2, 0.6, 256, 0.05)
    mapper.SetMaximumSamples(100000)
    ren.GetActiveCamera().Azimuth(35)
    ren.GetActiveCamera().Elevation(25)
    return mapper, window, volume


def median_frame(mapper, window, count):
    """Median of `count` frames' LastRenderSeconds (each Render adds one sample)."""
    times = []
    for _ in range(count):
        window.Render()
        times.append(mapper.GetLastRenderSeconds())
    return float(np.median(times))


def measure(target, n_frames, threads):
    from amrdualmesh import vtkAMRDualMeshVolumeMapper
    t0 = time.perf_counter()
    n0, levels = plan(target)
    amr, keep = make_amr(n0, levels)
    generate_s = time.perf_counter() - t0
    mapper, window, volume = make_view(amr, threads)
    mapper.SetIntegrator(vtkAMRDualMeshVolumeMapper.PATH_TRACER)
    # the OpenGL context and window buffers, then (after the peak is reset) the build, the
    # transfer-function setup (majorants, culling), one frame
    input_rss, peak, peak_ok, first_s = first_frame_peak(window, volume)
    mesh = mapper.GetDualMesh()
    if mesh is None or mesh.GetNumberOfLeafCells() == 0:
        raise RuntimeError("the dual mesh of about %d leaf cells was not built" % target)
    row = {
        "target": target, "n0": n0, "blocks": [len(b) for b in levels],
        "leaf_cells": mesh.GetNumberOfLeafCells(), "generate_s": generate_s,
        "input_rss": input_rss, "build_s": mesh.GetBuildSeconds(),
        "intake_s": mesh.GetIntakeSeconds(), "first_frame_s": first_s,
        "bytes": {"gridlet_scalars": mesh.GetGridletScalarBytes(),
                  "gridlet_headers": mesh.GetGridletHeaderBytes(),
                  "element_vertices": mesh.GetElementVertexBytes(),
                  "element_indices": mesh.GetElementIndexBytes(),
                  "bvh": mesh.GetBVHBytes(), "total": mesh.GetTotalBytes(),
                  "acceleration": mapper.GetAccelerationBytes()},
        "first_frame_peak_above_input": (peak - input_rss) if peak_ok else None,
    }
    row["leaf_cells_per_s"] = row["leaf_cells"] / max(row["build_s"], 1e-9)
    row["bytes_per_leaf_cell"] = row["bytes"]["total"] / max(row["leaf_cells"], 1)
    row["all_in_bytes_per_leaf_cell"] = ((row["bytes"]["total"] + row["bytes"]["acceleration"])
                                         / max(row["leaf_cells"], 1))
    row["pt_frame_s"] = median_frame(mapper, window, n_frames)
    # Transfer-function setup after the build: the first frame less the build and one frame.
    row["tf_setup_s"] = max(0.0, first_s - row["build_s"] - row["pt_frame_s"])
    mapper.SetIntegrator(vtkAMRDualMeshVolumeMapper.RAY_MARCH)
    window.Render()  # the first ray-marched frame restarts the accumulation
    row["rm_frame_s"] = median_frame(mapper, window, n_frames)
    peak_text = ("%.2f B/leaf" % (row["first_frame_peak_above_input"] / row["leaf_cells"])
                 if peak_ok else "n/a")
    print("%11d leaf cells (n0 %d, blocks %s): build %.2f s (%.1f M/s), %.2f B/leaf cell "
          "(all-in %.2f), "
          "first-frame peak above input %s, TF setup %.2f s, pt %.3f s, rm %.3f s per frame"
          % (row["leaf_cells"], n0, row["blocks"], row["build_s"],
             row["leaf_cells_per_s"] / 1e6, row["bytes_per_leaf_cell"],
             row["all_in_bytes_per_leaf_cell"], peak_text,
             row["tf_setup_s"], row["pt_frame_s"], row["rm_frame_s"]), flush=True)
    return row


def fit_exponent(xs, ys):
    """Least-squares slope of log y against log x (the growth exponent)."""
    lx, ly = np.log(np.asarray(xs, float)), np.log(np.asarray(ys, float))
    return float(np.polyfit(lx, ly, 1)[0]) if len(xs) >= 2 else float("nan")


def main(argv):
    commit = source_commit()
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("out")
    ap.add_argument("--sizes", default="1e6,4e6,16e6,64e6",
                    help="target leaf-cell counts, comma separated (default %(default)s)")
    ap.add_argument("--frames", type=int, default=5, help="timed frames per integrator (median)")
    ap.add_argument("--threads", type=int, default=0, help="0: all cores")
    a = ap.parse_args(argv)
    rows = []
    for s in a.sizes.split(","):
        rows.append(measure(int(float(s)), a.frames, a.threads))
        with open(a.out, "w") as f:
            json.dump({"date": time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime()),
                       "commit": commit, "cores": os.cpu_count(), "refine": REFINE, "box": BOX,
                       "rows": rows}, f,
                      indent=1)
    if len(rows) >= 2:
        n = [r["leaf_cells"] for r in rows]
        for key in ("build_s", "pt_frame_s", "rm_frame_s"):
            print("growth exponent of %s: %.2f" % (key, fit_exponent(n, [r[key] for r in rows])))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
