"""Side by side on a shared machine: ParaView's "Volume" and our representation in one pvpython
script, one view, one clock, alternating, so that a load that comes and goes weighs on both.

    pvpython Benchmarks/paraview_side_by_side.py SCENES.json OUT.json --plugin PLUGIN.so
        [--sets enzo,flame] [--rounds 5] [--frames 3] [--ours LABEL=STEP:SAMPLESPERCELL ...]
        [--no-error]
    (STEP in world units, or dN: the bounds' diagonal / N)
    (under an X server, e.g. xvfb-run)

SCENES.json: amrdm-bench's scenes.json (camera, transfer function per set; `reference` unused).
Per set: one render view at the scene's size, the set shown once. Each round times "Volume"
(ParaView's default NumberOfSamples 64 128 64) and then each of our settings (representation
"Dual-Mesh Path Tracer", Ray Marching, 1 sample a pixel a render; default: StepSize 0 and
SamplesPerCell 0, the shipped automatic step): an untimed Render after the switch, then FRAMES
renders with the camera nudged by 1e-4 degree between them, their median. A setting's time is
the median over the rounds of its round medians (the spread, min..max of those, is kept too).
Error: RMSE over linear RGB in [0, 1] of the SaveScreenshot (8 bits) against our own ray-marched
image at a quarter of the scene's base step (max(half the finest cell, longest edge / 1024)),
16 samples a pixel, saved the same way (cached as OUT_DIR/sbs-ref-SET.npy). --no-error: times
only (no reference render, which takes minutes on the vortex set; rmse is null).
"""
import json
import os
import statistics
import sys
import time

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from paraview.simple import Delete, LoadPlugin, Render, SaveScreenshot  # noqa: E402
from paraview_volume import (median_frame_seconds, open_set, option,  # noqa: E402
                             read_png_rgb, volume_view)


def main():
    args = sys.argv[1:]
    plugin = option(args, "--plugin", None)
    sets = option(args, "--sets", None)
    rounds = int(option(args, "--rounds", "5"))
    frames = int(option(args, "--frames", "3"))
    with_error = "--no-error" not in args
    if not with_error:
        args.remove("--no-error")
    ours = []
    while "--ours" in args:
        label, spec = option(args, "--ours", None).split("=")
        step, spc = spec.split(":")
        ours.append((label, step, float(spc)))
    if not ours:
        ours = [("ours default", "0", 0.0)]
    if len(args) != 2 or not plugin:
        sys.exit(__doc__)
    scenes_path, out_path = args
    out_dir = os.path.dirname(os.path.abspath(out_path))
    LoadPlugin(plugin, remote=False, ns=globals())
    scenes = json.load(open(scenes_path))
    if sets:
        scenes = [s for s in scenes if s["name"] in sets.split(",")]
    result = {"date": time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime()), "rounds": rounds,
              "frames": frames, "load_start": os.getloadavg(), "sets": []}
    for scene in scenes:
        result["sets"].append(run_set(scene, ours, rounds, frames, out_dir, with_error))
        result["load_end"] = os.getloadavg()
        with open(out_path, "w") as f:
            json.dump(result, f, indent=1)


def run_set(scene, ours, rounds, frames, out_dir, with_error=True):
    name, width, height = scene["name"], scene["width"], scene["height"]
    source, array = open_set(scene)
    view, display, set_camera = volume_view(scene, source, array)
    display.NumberOfSamples = [64, 128, 64]

    def use(setting):
        if setting is None:
            display.SetRepresentationType("Volume")
            return
        display.SetRepresentationType("Dual-Mesh Path Tracer")
        display.Integrator = "Ray Marching"
        display.ScalarOpacityUnitDistance = scene["tf"]["unit_distance"]
        display.StepSize = setting[0]
        display.SamplesPerCell = setting[1]
        display.SamplesPerRender = setting[2]
        display.MaximumSamples = setting[2]

    def timed():
        set_camera()
        Render(view)  # untimed: the switch, a resample
        return median_frame_seconds(view, set_camera, frames)

    def shot(label):
        set_camera()
        png = os.path.join(out_dir, "sbs-%s-%s.png" % (name, label.replace(" ", "_")))
        SaveScreenshot(png, view, ImageResolution=[width, height], TransparentBackground=0)
        return png, read_png_rgb(png)

    longest = max(scene["finest_dims"])  # in finest cells; the domain is their box
    ref_path = os.path.join(out_dir, "sbs-ref-%s.npy" % name)
    bounds = source.GetDataInformation().GetBounds()
    sides = [bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4]]
    edge, diagonal = max(sides), sum(s * s for s in sides) ** 0.5

    def world(step):  # "dN": the diagonal / N
        return diagonal / float(step[1:]) if step.startswith("d") else float(step)

    settings = [("Volume", None)] + [(label, (world(step), spc, 1)) for label, step, spc in ours]
    if with_error and not os.path.exists(ref_path):
        base = max(0.5 * edge / longest, edge / 1024.0)
        use((base / 4.0, 0.0, 16))
        set_camera()
        t0 = time.perf_counter()
        Render(view)
        print("  %s reference: step %.4g, 16 spp, %.1f s" % (name, base / 4, time.perf_counter() - t0),
              flush=True)
        np.save(ref_path, shot("reference")[1])
    ref = np.load(ref_path) if with_error else None
    per = {label: [] for label, _ in settings}
    for r in range(rounds):
        for label, setting in settings:
            use(setting)
            per[label].append(timed())
        print("  %s round %d: %s" % (name, r + 1, ", ".join(
            "%s %.0f ms" % (label, 1e3 * per[label][-1]) for label, _ in settings)), flush=True)
    rows = []
    for label, setting in settings:
        use(setting)
        png, img = shot(label)
        rmse = float(np.sqrt(np.mean((img - ref) ** 2))) if with_error else float("nan")
        ms = [1e3 * t for t in per[label]]
        rows.append({"setting": label, "step": None if setting is None else setting[0],
                     "samples_per_cell": None if setting is None else setting[1],
                     "ms_per_frame": statistics.median(ms), "ms_min": min(ms), "ms_max": max(ms),
                     "rmse": rmse if with_error else None, "image": png})
        print("  %-9s %-22s %8.1f ms/frame (rounds %s), rmse %.5f" % (
            name, label, statistics.median(ms), "/".join("%.0f" % m for m in ms), rmse), flush=True)
    Delete(display)
    Delete(view)
    return {"set": name, "width": width, "height": height, "rows": rows}


if __name__ == "__main__":
    main()
