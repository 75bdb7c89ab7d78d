"""pvbatch SaveScreenshot at the representation's defaults, next to ParaView's "Volume".

    pvbatch Benchmarks/paraview_screenshots.py SCENES.json OUT_DIR --plugin PLUGIN.so
        [--sets enzo,flame] [--converged 1024]
    (under an X server, e.g. xvfb-run)

SCENES.json: amrdm-bench's scenes.json (camera, colour / opacity table, unit distance per set).
Per set, one render view at the scene's size, black background, the set shown once with the
scene's transfer function (paraview_volume.apply_transfer_function), then:
  volume     representation "Volume" (ParaView's defaults): Render(), SaveScreenshot, timed;
  ours       representation "Dual-Mesh Path Tracer" at its defaults (path tracer; a script's
             render is final: passes until MaximumSamples or FinalRenderTime): Render(),
             SaveScreenshot, timed from the Render() (the mesh is built by an untimed Render()
             before); the samples per pixel reached are read back;
  converged  the same view at MaximumSamples = --converged, FinalRenderTime unlimited,
             another Seed (a new accumulation, independent of the shot's samples).
RMSE over linear RGB in [0, 1] of the 8-bit screenshots, ours against converged; the converged
image's own noise is estimated from the shot's: its variance is (shot samples / converged
samples) of the shot's, and `rmse_corrected` subtracts it. Writes OUT_DIR/screenshot-SET-*.png
and OUT_DIR/screenshots.json.
"""
import json
import os
import sys
import time

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from paraview import simple  # noqa: E402
from paraview_volume import open_set, option, read_png_rgb, volume_view  # noqa: E402


def run_set(scene, out_dir, converged):
    name, width, height = scene["name"], scene["width"], scene["height"]
    source, array = open_set(scene)
    view, display, set_camera = volume_view(scene, source, array)
    set_camera()

    def shot(label):
        """Render() then SaveScreenshot, as a script does: (png, seconds of both)."""
        png = os.path.join(out_dir, "screenshot-%s-%s.png" % (name, label))
        t0 = time.perf_counter()
        simple.Render(view)
        simple.SaveScreenshot(png, view, ImageResolution=[width, height], TransparentBackground=0)
        return png, time.perf_counter() - t0

    simple.Render(view)  # Volume's resample, untimed as our build below
    volume_png, volume_s = shot("volume")
    display.SetRepresentationType("Dual-Mesh Path Tracer")
    budget, maximum = display.FinalRenderTime, display.MaximumSamples
    display.FinalRenderTime = 0.0
    t0 = time.perf_counter()
    simple.Render(view)  # the mesh build and one pass, untimed
    build_s = time.perf_counter() - t0
    display.FinalRenderTime = budget
    angle = scene["camera"]["view_angle"]
    view.CameraViewAngle = angle + 1e-6  # a new view: the shot starts from scratch
    view.CameraViewAngle = angle

    def samples():
        display.UpdatePropertyInformation()
        return display.SMProxy.GetProperty("AccumulatedSamples").GetElement(0)

    ours_png, ours_s = shot("ours")
    ours_spp = samples()
    display.MaximumSamples = converged
    display.FinalRenderTime = 1e9
    display.Seed = 12345  # independent of the shot's samples (a new accumulation)
    ref_png, ref_s = shot("converged")
    ref_spp = samples()
    display.MaximumSamples, display.FinalRenderTime = maximum, budget
    ours, ref = read_png_rgb(ours_png), read_png_rgb(ref_png)
    mse = float(np.mean((ours - ref) ** 2))
    # The converged image's noise variance is about ours_spp / ref_spp of the shot's.
    ratio = float(ours_spp) / float(ref_spp) if ref_spp else 0.0
    corrected = max(mse / (1.0 + ratio), 0.0) if ratio < 1.0 else mse
    row = {"set": name, "width": width, "height": height, "build_s": build_s,
           "volume_s": volume_s, "volume_image": volume_png,
           "ours_s": ours_s, "ours_spp": ours_spp, "ours_image": ours_png,
           "final_render_time": budget, "maximum_samples": maximum,
           "converged_s": ref_s, "converged_spp": ref_spp, "converged_image": ref_png,
           "rmse": mse ** 0.5, "rmse_corrected": corrected ** 0.5, "image_mean": float(ref.mean())}
    print("  %-9s volume %.2f s | ours %.2f s, %d spp, RMSE %.5f (converged noise removed %.5f) "
          "| converged %d spp in %.0f s, mean %.4f" % (
              name, volume_s, ours_s, ours_spp, row["rmse"], row["rmse_corrected"], ref_spp, ref_s,
              row["image_mean"]), flush=True)
    simple.Delete(display)
    simple.Delete(view)
    return row


def main():
    args = sys.argv[1:]
    plugin = option(args, "--plugin", None)
    sets = option(args, "--sets", None)
    converged = int(option(args, "--converged", "1024"))
    if len(args) != 2 or not plugin:
        sys.exit(__doc__)
    scenes_path, out_dir = args
    os.makedirs(out_dir, exist_ok=True)
    simple.LoadPlugin(plugin, remote=False, ns=globals())
    scenes = json.load(open(scenes_path))
    if sets:
        scenes = [s for s in scenes if s["name"] in sets.split(",")]
    result = {"date": time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime()),
              "load_start": os.getloadavg(), "converged_samples": converged, "sets": []}
    for scene in scenes:
        result["sets"].append(run_set(scene, out_dir, converged))
        result["load_end"] = os.getloadavg()
        with open(os.path.join(out_dir, "screenshots.json"), "w") as f:
            json.dump(result, f, indent=1)


if __name__ == "__main__":
    main()
