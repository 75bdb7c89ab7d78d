"""Memory by category on the real sets: the dual mesh's bytes (gridlet scalars and headers,
stitching-element corners and indices, BVH), the renderer's majorant grid and culling, all per
leaf cell, and the build's peak resident memory above the input, through the Python package as a
user would drive it (vtkAMRDualMeshVolumeMapper, path tracer, one 64^2 frame).

The majorant grid's bytes are the acceleration bytes at the default resolution less those at one
macrocell (16 B): what is left is the culling (ranges and masks per BVH slot and node).

    xvfb-run -a /usr/bin/python3 Benchmarks/memory_sets.py OUT.json [--data DIR] [--threads N]
        [--sets enzo,flame,advection,vortex]
    /usr/bin/python3 Benchmarks/memory_sets.py --report BEFORE.json AFTER.json OUT.md [--timing T.md]
Not a test: it measures and writes JSON, and prints one line per set; --report writes the
before -> after table by category (docs/BENCHMARKS-MEMORY.md), with an optional timing section.
"""
import argparse
import json
import os
import sys
import time

SETS = {
    "enzo": ("enzo-moving7_DD0010/moving7_0010.hierarchy", "Density"),
    "flame": ("amrex-pelelmex-flame3d_plt", "temp"),
    "advection": ("amrex-advection-amrcore3d/plt00040", "phi"),
    "vortex": ("amrex-singlevortex3d-128/plt00040", "phi"),
}


def rss_bytes(key):
    with open("/proc/self/status") as f:
        for line in f:
            if line.startswith(key + ":"):
                return int(line.split()[1]) * 1024
    return 0


def reset_peak():
    """Resets VmHWM to the current RSS (Linux >= 4.0); False when the kernel refuses."""
    try:
        with open("/proc/self/clear_refs", "w") as f:
            f.write("5")
        return True
    except OSError:
        return False


def read_set(path, array):
    from vtkmodules.vtkIOAMR import vtkAMREnzoReader
    from vtkmodules.vtkIOAMR import vtkAMReXGridReader
    reader = vtkAMREnzoReader() if path.endswith(".hierarchy") else vtkAMReXGridReader()
    reader.SetFileName(path)
    reader.UpdateInformation()
    reader.SetMaxLevel(100)
    reader.GetCellDataArraySelection().DisableAllArrays()
    reader.GetCellDataArraySelection().EnableArray(array)
    reader.Update()
    return reader.GetOutput()


def measure(name, path, array, threads):
    from vtkmodules.vtkCommonDataModel import vtkPiecewiseFunction
    from vtkmodules.vtkRenderingCore import (vtkColorTransferFunction, vtkRenderer,
                                             vtkRenderWindow, vtkVolume, vtkVolumeProperty)
    import vtkmodules.vtkRenderingOpenGL2  # noqa: F401
    from amrdualmesh import vtkAMRDualMeshVolumeMapper
    amr = read_set(path, array)
    mapper = vtkAMRDualMeshVolumeMapper()
    mapper.SetInputData(amr)
    mapper.SetScalarModeToUseCellFieldData()
    mapper.SelectScalarArray(array)
    mapper.SetNumberOfThreads(threads)
    mapper.SetIntegrator(vtkAMRDualMeshVolumeMapper.PATH_TRACER)
    color = vtkColorTransferFunction()
    color.AddRGBPoint(0.0, 0.2, 0.3, 0.9)
    color.AddRGBPoint(1.0, 0.9, 0.3, 0.1)
    opacity = vtkPiecewiseFunction()
    opacity.AddPoint(0.0, 0.0)
    opacity.AddPoint(1.0, 0.5)
    prop = vtkVolumeProperty()
    prop.SetColor(color)
    prop.SetScalarOpacity(opacity)
    volume = vtkVolume()
    volume.SetMapper(mapper)
    volume.SetProperty(prop)
    ren = vtkRenderer()
    ren.AddVolume(volume)
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.AddRenderer(ren)
    window.SetSize(64, 64)
    ren.ResetCamera()
    volume.SetVisibility(0)
    window.Render()  # the OpenGL context before the peak is reset
    volume.SetVisibility(1)
    input_rss = rss_bytes("VmRSS")
    peak_ok = reset_peak()
    window.Render()  # build, majorants, culling, one frame
    peak = rss_bytes("VmHWM") if peak_ok else 0
    mesh = mapper.GetDualMesh()
    accel = mapper.GetAccelerationBytes()
    mapper.SetMajorantResolution(1)
    window.Render()
    culling = mapper.GetAccelerationBytes() - 16
    leaf = mesh.GetNumberOfLeafCells()
    b = {"gridlet_scalars": mesh.GetGridletScalarBytes(),
         "gridlet_headers": mesh.GetGridletHeaderBytes(),
         "element_vertices": mesh.GetElementVertexBytes(),
         "element_indices": mesh.GetElementIndexBytes(),
         "bvh": mesh.GetBVHBytes(), "majorants": accel - culling, "culling": culling}
    b["mesh"] = mesh.GetTotalBytes()
    b["all_in"] = b["mesh"] + accel
    row = {"set": name, "leaf_cells": leaf, "bytes": b,
           "per_leaf_cell": {k: v / max(leaf, 1) for k, v in b.items()},
           "build_s": mesh.GetBuildSeconds(),
           "first_frame_peak_above_input": (peak - input_rss) if peak_ok else None}
    p = row["per_leaf_cell"]
    print("%-10s %9d leaf: scalars %.2f headers %.2f vertices %.2f indices %.2f bvh %.2f | mesh %.2f"
          " majorants %.2f culling %.2f | all-in %.2f B/leaf; first-frame peak above input %.2f x mesh"
          % (name, leaf, p["gridlet_scalars"], p["gridlet_headers"], p["element_vertices"],
             p["element_indices"], p["bvh"], p["mesh"], p["majorants"], p["culling"], p["all_in"],
             (row["first_frame_peak_above_input"] or 0) / max(b["mesh"], 1)), flush=True)
    return row


CATEGORIES = [("gridlet_scalars", "gridlet scalars"), ("gridlet_headers", "gridlet headers"),
              ("element_vertices", "element vertices"), ("element_indices", "element indices"),
              ("bvh", "BVH"), ("mesh", "**mesh**"), ("majorants", "majorant grid"),
              ("culling", "culling"), ("all_in", "**all-in**")]


def report(before_path, after_path, out_path, timing_path):
    with open(before_path) as f:
        before = json.load(f)
    with open(after_path) as f:
        after = json.load(f)
    sets = [r["set"] for r in after["rows"]]
    b = {r["set"]: r for r in before["rows"]}
    a = {r["set"]: r for r in after["rows"]}
    w = []
    w.append("# Memory by category on the real sets: before -> after")
    w.append("")
    w.append("Generated by `Benchmarks/memory_sets.py --report` (do not edit by hand) from two runs of "
             "`Benchmarks/memory_sets.py` on this machine (2 cores, shared): before %s (commit %s), "
             "after %s (commit %s). Bytes per visible leaf cell, through the Python package "
             "(`vtkAMRDualMesh` getters; majorant grid = the mapper's acceleration bytes at the default "
             "resolution less those at one macrocell; culling = the rest). `peak` = the first frame's "
             "peak resident memory above the input (build, majorants, culling, frame buffers; "
             "`/proc/self/clear_refs`), as a multiple of the final mesh."
             % (before["date"], before.get("commit", "?"), after["date"], after.get("commit", "?")))
    w.append("")
    w.append("| B / leaf cell | " + " | ".join("%s (%s leaf cells)" % (n, "{:,}".format(a[n]["leaf_cells"]))
                                              for n in sets) + " |")
    w.append("|---|" + "---|" * len(sets))
    for key, label in CATEGORIES:
        cells = []
        for n in sets:
            x0 = b[n]["per_leaf_cell"][key] if n in b else float("nan")
            x1 = a[n]["per_leaf_cell"][key]
            cells.append("%.2f" % x1 if abs(x1 - x0) < 0.005 else "%.2f -> %.2f" % (x0, x1))
        w.append("| %s | %s |" % (label, " | ".join(cells)))
    cells = []
    for n in sets:
        p0 = (b[n]["first_frame_peak_above_input"] or 0) / max(b[n]["bytes"]["mesh"], 1) if n in b else 0
        p1 = (a[n]["first_frame_peak_above_input"] or 0) / max(a[n]["bytes"]["mesh"], 1)
        cells.append("%.2fx -> %.2fx" % (p0, p1))
    w.append("| peak / mesh | %s |" % " | ".join(cells))
    w.append("")
    if timing_path:
        with open(timing_path) as f:
            w.append(f.read().rstrip())
            w.append("")
    with open(out_path, "w") as f:
        f.write("\n".join(w))
    return 0


def main(argv):
    if argv and argv[0] == "--report":
        if len(argv) not in (4, 6):
            print("usage: memory_sets.py --report BEFORE.json AFTER.json OUT.md [--timing T.md]")
            return 2
        return report(argv[1], argv[2], argv[3], argv[5] if len(argv) == 6 else None)
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("out")
    ap.add_argument("--data", default="/work/shared/amr-data")
    ap.add_argument("--sets", default=",".join(SETS))
    ap.add_argument("--threads", type=int, default=2)
    a = ap.parse_args(argv)
    rows = []
    for name in a.sets.split(","):
        rel, array = SETS[name]
        path = os.path.join(a.data, rel)
        if not os.path.exists(path):
            print("%s: skipped, %s does not exist" % (name, path))
            continue
        rows.append(measure(name, path, array, a.threads))
    import subprocess
    try:
        commit = subprocess.run(["git", "-C", os.path.dirname(os.path.abspath(__file__)), "describe",
                                 "--always", "--dirty"], capture_output=True, text=True,
                                check=True).stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        commit = None
    with open(a.out, "w") as f:
        json.dump({"date": time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime()), "commit": commit,
                   "rows": rows}, f, indent=1)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
