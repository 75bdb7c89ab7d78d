"""yt 4.1 volume rendering of the real benchmark sets (docs/BENCHMARKS.md), on amrdm-bench's
cameras and transfer functions, scored like ParaView's Volume (paraview_volume.py): RMSE of the
8-bit image (and of the float image) against our converged emission-absorption reference.

    /usr/bin/python3 Benchmarks/yt_real.py SCENES.json SET OUT.json [--frames N] [--max-cells N]

Every set is read with VTK's reader exactly as amrdm-bench reads it (vtkAMReXGridReader /
vtkAMREnzoReader, every level, the scene's array, log10 when the scene is log scaled) and handed
to yt through yt.load_amr_grids (all blocks, their cell values): the moving7 Enzo set is HDF4,
which yt's Enzo frontend cannot read, and one path for all sets keeps the values identical to
what the other renderers see. Transfer function and camera as in yt_volume.py (same residual
mismatch); yt's default (10 samples a cell, no ghost zones) and with ghost zones.
"""
import json
import os
import sys
import time

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import analytic_peers as peers  # noqa: E402
import analytic_truth as truth  # noqa: E402
import yt_volume  # noqa: E402
from vtkmodules.util.numpy_support import vtk_to_numpy  # noqa: E402


def read_amr(scene):
    from vtkmodules.vtkIOAMR import vtkAMREnzoReader, vtkAMReXGridReader
    from file_check import check_file
    check_file(scene["path"])
    r = vtkAMREnzoReader() if scene["reader"] == "enzo" else vtkAMReXGridReader()
    r.SetFileName(scene["path"])
    r.UpdateInformation()
    r.SetMaxLevel(64)
    r.GetCellDataArraySelection().DisableAllArrays()
    r.GetCellDataArraySelection().EnableArray(scene["array"])
    r.Update()
    return r.GetOutput()


def grids_of(amr, scene):
    """load_amr_grids' grid list, bounding box and level-0 dimensions of a vtkOverlappingAMR."""
    grids, lo, hi, base = [], np.full(3, np.inf), np.full(3, -np.inf), None
    for level in range(amr.GetNumberOfLevels()):
        for b in range(amr.GetNumberOfDataSets(level)):
            g = amr.GetDataSet(level, b)
            if g is None:
                continue
            a = g.GetCellData().GetArray(scene["array"])
            if a is None:
                raise RuntimeError("%s: no cell array %s in level %d block %d"
                                   % (scene["path"], scene["array"], level, b))
            v = vtk_to_numpy(a).astype(np.float64)
            if v.ndim > 1:
                v = np.linalg.norm(v, axis=1)
            if scene["log_scale"]:
                with np.errstate(divide="ignore", invalid="ignore"):
                    v = np.where(v > 0, np.log10(np.where(v > 0, v, 1.0)), np.nan)
            dims = [d - 1 for d in g.GetDimensions()]
            o, h = np.array(g.GetOrigin()), np.array(g.GetSpacing())
            v = v.reshape(dims[2], dims[1], dims[0]).transpose(2, 1, 0)
            grids.append({"left_edge": o, "right_edge": o + h * dims, "level": level,
                          "dimensions": dims, "f": np.ascontiguousarray(v)})
            lo, hi = np.minimum(lo, o), np.maximum(hi, o + h * dims)
            if level == 0:
                base = h
    return grids, np.stack([lo, hi], axis=1), np.rint((hi - lo) / base).astype(int)


def save_png(path, img, ref):
    """yt's image next to the reference (to look at), rows flipped to top-down."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    both = np.concatenate([np.clip(img, 0, 1), np.clip(ref[..., :3], 0, 1)], axis=1)[::-1]
    plt.imsave(path, np.ascontiguousarray(both))


def main():
    args = sys.argv[1:]
    frames, max_cells = 5, 1 << 62
    for flag in ("--frames", "--max-cells"):
        if flag in args:
            i = args.index(flag)
            val = int(args[i + 1])
            del args[i:i + 2]
            frames, max_cells = (val, max_cells) if flag == "--frames" else (frames, val)
    scenes_path, set_name, out_path = args
    scene = next(s for s in json.load(open(scenes_path)) if s["name"] == set_name)
    ok, why = yt_volume.available()
    result = {"set": set_name, "date": time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime()),
              "rows": [], "skipped": None if ok else why}
    if ok:
        import yt
        t = time.perf_counter()
        amr = read_amr(scene)
        grids, bbox, dims = grids_of(amr, scene)
        cells = sum(int(np.prod(g["dimensions"])) for g in grids)
        if cells > max_cells:
            result["skipped"] = "%d cells > --max-cells %d" % (cells, max_cells)
        else:
            yt.set_log_level(40)
            ds = yt.load_amr_grids(grids, dims, bbox=bbox, periodicity=(False,) * 3)
            result["read_s"] = time.perf_counter() - t
            w, h = scene["width"], scene["height"]
            c = scene["camera"]
            cam = truth.Camera(c["position"], c["focal_point"], c["view_up"], c["view_angle"])
            tf = truth.TransferFunction(scene["tf"]["table"], scene["tf"]["lo"], scene["tf"]["hi"],
                                        scene["tf"]["unit_distance"])
            ref = np.fromfile(scene["reference"], np.float32).reshape(h, w, 4).astype(np.float64)
            r = yt_volume.YtRenderer(ds, tf, cam, w, h)
            for ghost in (False, True):
                r.configure(10, ghost)
                first, frame = peers.timed_call(r.render, frames)
                img = r.render()
                img8 = np.round(np.clip(img, 0, 1) * 255.0) / 255.0
                row = {"setting": "10 samples/cell%s" % (", ghost zones" if ghost else " (default)"),
                       "first_render_s": first, "ms_per_frame": 1e3 * frame, "frames": frames,
                       "rmse": float(np.sqrt(np.mean((img8 - ref[..., :3]) ** 2))),
                       "p99": float(np.percentile(np.abs(img8 - ref[..., :3]), 99)),
                       "max": float(np.abs(img8 - ref[..., :3]).max()),
                       "rmse_float": float(np.sqrt(np.mean((img - ref[..., :3]) ** 2))),
                       "brick_bytes": r.memory_bytes()}
                png = os.path.join(os.path.dirname(os.path.abspath(out_path)),
                                   "yt-%s-%d.png" % (set_name, len(result["rows"])))
                save_png(png, img, ref)
                row["image"] = png
                result["rows"].append(row)
                print("  yt %-9s %-30s first render %7.2f s, %8.1f ms/frame, rmse %.5f (float %.5f)"
                      % (set_name, row["setting"], first, row["ms_per_frame"], row["rmse"],
                         row["rmse_float"]), flush=True)
    elif not ok:
        print("  yt %s skipped: %s" % (set_name, why))
    if result["skipped"] and ok:
        print("  yt %s skipped: %s" % (set_name, result["skipped"]))
    with open(out_path, "w") as f:
        json.dump(result, f, indent=1)


if __name__ == "__main__":
    main()
