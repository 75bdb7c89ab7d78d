"""Equal clock: our representation next to ParaView's "Volume" in one pvpython script, timed by
the same loop (time.perf_counter around paraview.simple.Render(view)), on the analytic scenes and
scored against the same analytic truth as analytic_compare.py.

    pvpython Benchmarks/paraview_equal_clock.py OUT.json --plugin AMRDualMeshPlugin.so [--quick]
    (under an X server, e.g. xvfb-run)

Per scene: the .vthb of analytic_scenes.py opened with ParaView's XMLUniformGridAMRReader (every
level), one render view with analytic_compare's camera, colour / opacity table and unit
distance, black background; the same source shown as
  pv-volume     representation "Volume" (ParaView's AMR volume: resample + GPU ray cast) at
                NumberOfSamples 64 128 64 (ParaView's default) and at the finest level's
                resolution ("largest resample": ParaView clamps to it)
  ours-pv       representation "Dual-Mesh Path Tracer", Rendering Method "Ray Marching",
                at its defaults (StepSize 0: the automatic step) at 1 sample a pixel,
                StepSize = finest spacing x {2, 1} at 4 samples a pixel, and level-adaptive
                1 sample a cell at 1, 4 and 16 samples a pixel (as analytic_compare's "ours")
Each setting: the first Render(view) after the change, then the median of FRAMES renders, the
camera nudged by 1e-4 degree between them so each draws from scratch; then SaveScreenshot at the
view size, scored in 8 bits against the truth quantised the same way. The truth comes from
TRUTH_DIR/truth-NAME.npy when analytic_compare.py left it there (same size), else is computed.
"""
import json
import os
import sys
import tempfile
import time

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import analytic_scenes as scenes  # noqa: E402
import analytic_truth as truth  # noqa: E402
from paraview import simple  # noqa: E402
from paraview_volume import (black_view, camera_setter, median_frame_seconds,  # noqa: E402
                             read_png_rgb)

TABLE = [[0.2, 0.3, 1.0, 0.0], [1.0, 1.0, 0.3, 0.6], [1.0, 0.2, 0.1, 0.9]]  # analytic_compare's
UNIT = {"constant": 0.25, "blob": 0.1, "shell": 0.05}
FRAMES = 5


def get_truth(name, field, tf, cam, width, height, truth_dir, quick):
    path = os.path.join(truth_dir, "truth-%s.npy" % name)
    if os.path.exists(path):
        ref = np.load(path)
        if ref.shape[:2] == (height, width):
            return ref
    return truth.truth_image(field, tf, cam, width, height, steps=256 if quick else 1024, ss=2)[0]


def run_scene(name, width, height, quick, truth_dir, out_dir):
    field = scenes.SCENES[name]()
    path = scenes.write_scene(name, tempfile.mkdtemp())
    amr = scenes.read_vthb(path)
    levels = amr.GetNumberOfLevels()
    n_fine = 32 << (levels - 1)
    finest = 1.0 / n_fine
    tf = truth.TransferFunction(TABLE, 0.0, 1.0, UNIT[name])
    cam = truth.default_camera()
    ref8 = np.round(np.clip(get_truth(name, field, tf, cam, width, height, truth_dir, quick)[..., :3],
                            0, 1) * 255.0)

    reader = simple.XMLUniformGridAMRReader(FileName=[path])
    reader.DefaultNumberOfLevels = 0  # every level (ParaView's default reads one)
    reader.CellArrayStatus = [scenes.ARRAY]
    view = black_view(width, height)
    set_camera = camera_setter(view, cam.position, cam.position + cam.direction, cam.up,
                               cam.view_angle)

    display = simple.Show(reader, view)
    simple.ColorBy(display, ("CELLS", scenes.ARRAY))
    lut = simple.GetColorTransferFunction(scenes.ARRAY)
    lut.AutomaticRescaleRangeMode = "Never"
    lut.ColorSpace = "RGB"
    values = [i / (len(TABLE) - 1) for i in range(len(TABLE))]
    lut.RGBPoints = [c for v, e in zip(values, TABLE) for c in (v, e[0], e[1], e[2])]
    pwf = simple.GetOpacityTransferFunction(scenes.ARRAY)
    pwf.Points = [c for v, e in zip(values, TABLE) for c in (v, e[3], 0.5, 0.0)]
    lut.ScalarRangeInitialized = 1
    pwf.ScalarRangeInitialized = 1
    display.LookupTable = lut
    display.ScalarOpacityFunction = pwf
    display.ScalarOpacityUnitDistance = UNIT[name]
    rows = []

    def score(renderer, setting):
        set_camera()
        t = time.perf_counter()
        simple.Render(view)
        first = time.perf_counter() - t
        frame = median_frame_seconds(view, set_camera, FRAMES)
        set_camera()
        png = os.path.join(out_dir, "equal-clock-%s-%s-%d.png" % (name, renderer, len(rows)))
        simple.SaveScreenshot(png, view, ImageResolution=[width, height], TransparentBackground=0)
        row = {"renderer": renderer, "setting": setting, "first_s": first,
               "frame_s": frame, "image": png}
        row.update(truth.errors(read_png_rgb(png, unit=1.0), ref8))
        rows.append(row)
        print("  %-9s %-26s rmse %6.2f p99 %6.1f max %5.0f  first %.3fs frame %.3fs" % (
            renderer, setting, row["rmse"], row["p99"], row["max"], first, row["frame_s"]),
            flush=True)

    display.SetRepresentationType("Volume")
    for label, cap in (("default 64x128x64", [64, 128, 64]),
                       ("finest %d^3" % n_fine, [n_fine] * 3)):
        display.NumberOfSamples = cap
        score("pv-volume", label)
    display.SetRepresentationType("Dual-Mesh Path Tracer")
    display.Integrator = "Ray Marching"
    # The representation's own unit distance (ParaView exposes it under this name).
    display.ScalarOpacityUnitDistance = UNIT[name]
    def ours(setting, step, samples_per_cell, spp):
        display.StepSize = step
        display.SamplesPerCell = samples_per_cell
        display.SamplesPerRender = spp
        display.MaximumSamples = spp
        score("ours-pv", setting)

    ours("defaults (automatic step), 1 spp", 0.0, 0.0, 1)  # what a user gets
    for k in ([2.0] if quick else [2.0, 1.0]):
        ours("step %.2g h_fine, 4 spp" % k, k * finest, 0.0, 4)
    for spp in ([4] if quick else [1, 4, 16]):
        ours("adaptive 1/cell, %d spp" % spp, 0.25 * finest, 1.0, spp)
    simple.Delete(display)
    simple.Delete(view)
    simple.Delete(reader)
    return {"name": name, "levels": levels, "leaf_cells": scenes.leaf_cells(amr), "rows": rows}


def main():
    args = sys.argv[1:]
    if len(args) < 3 or args[1] != "--plugin":
        sys.exit("usage: paraview_equal_clock.py OUT.json --plugin AMRDualMeshPlugin.so [--quick]")
    out, plugin = args[0], args[2]
    quick = "--quick" in args[3:]
    global FRAMES
    if quick:
        FRAMES = 2  # a smoke test
    simple.LoadPlugin(plugin, remote=False, ns=globals())
    width, height = (96, 72) if quick else (256, 192)
    out_dir = os.path.dirname(os.path.abspath(out))
    result = {"date": time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime()), "width": width,
              "height": height, "quick": quick, "frames": FRAMES, "load_start": os.getloadavg(),
              "scenes": []}
    for name in (["constant", "blob"] if quick else list(scenes.SCENES)):
        print("== equal clock (pvpython): %s" % name, flush=True)
        result["scenes"].append(run_scene(name, width, height, quick, out_dir, out_dir))
        result["load_end"] = os.getloadavg()
        with open(out, "w") as f:
            json.dump(result, f, indent=1)


if __name__ == "__main__":
    main()
