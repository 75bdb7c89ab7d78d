"""pvpython: SaveScreenshot at another resolution and the Display panel's Translation with the
"Dual-Mesh Path Tracer" representation (issue 13). The AMReX advection set (phi) through
ParaView's reader, Ray Marching, 8 samples per render and at most. A 200 x 150 view is saved
at ImageResolution [400, 300] (2 x 2 tiles) and [300, 150] (a non-square magnification); each
must equal the view resized to that size and saved natively (mean |difference| per channel
< 0.01, 99.5th percentile < 0.1; tiled copies of the scene differ by ~0.1). Then Translation
[0.3, 0, 0] must equal the untranslated data seen by a camera moved by -0.3 in x, and differ
from the untranslated view (mean > 0.02).

  pvpython TestPluginScreenshotTransform.py --plugin AMRDualMeshPlugin.so --temp-dir DIR
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "Support"))
from pv_testing import ADVECTION, bare_view, finish, load_plugin, plugin_args, png_rgb  # noqa: E402

MEAN_MAX, P995_MAX, MOVED_MIN = 0.01, 0.1, 0.02


def main():
    args = plugin_args()
    simple = load_plugin(args.plugin)
    reader = simple.AMReXBoxLibGridReader(FileNames=[ADVECTION])
    reader.CellArrayStatus = ["phi"]
    view = bare_view(simple, background=(0.1, 0.1, 0.1))
    display = simple.Show(reader, view)
    display.SetRepresentationType("Dual-Mesh Path Tracer")
    simple.ColorBy(display, ("CELLS", "phi"))
    display.SetScalarBarVisibility(view, False)
    display.Integrator = 2
    display.StepSize = 0.01
    display.SamplesPerRender = 8
    display.MaximumSamples = 8
    display.Seed = 1
    camera = ([0.98, -0.24, 0.82], [0.55, 0.5, 0.12], [0.0, 0.0, 1.0])

    def shot(name, size, resolution, eye=None):
        view.ViewSize = size
        c = camera if eye is None else (eye, [camera[1][0] - 0.3, camera[1][1], camera[1][2]],
                                        camera[2])
        view.CameraPosition, view.CameraFocalPoint, view.CameraViewUp = c
        view.CameraViewAngle = 30.0
        simple.Render(view)
        path = os.path.join(args.temp_dir, "TestPluginScreenshotTransform-%s.png" % name)
        simple.SaveScreenshot(path, view, ImageResolution=resolution)
        return png_rgb(path)

    failures = []

    def compare(name, a, b, want_equal=True):
        if a.shape != b.shape:
            failures.append("%s: sizes %s and %s" % (name, a.shape, b.shape))
            return
        d = np.abs(a - b).ravel()
        mean, p995 = d.mean(), np.percentile(d, 99.5)
        ok = (mean < MEAN_MAX and p995 < P995_MAX) if want_equal else mean > MOVED_MIN
        print("%s: mean |difference| %.4f, 99.5th percentile %.4f (%s) %s" % (
            name, mean, p995, "< %.2f, < %.2f" % (MEAN_MAX, P995_MAX) if want_equal else
            "> %.2f" % MOVED_MIN, "ok" if ok else "FAIL"))
        if not ok:
            failures.append(name)

    compare("SaveScreenshot [400, 300] from 200 x 150 vs native 400 x 300",
            shot("tiled400x300", [200, 150], [400, 300]), shot("native400x300", [400, 300], [400, 300]))
    compare("SaveScreenshot [300, 150] from 200 x 150 vs native 300 x 150",
            shot("tiled300x150", [200, 150], [300, 150]), shot("native300x150", [300, 150], [300, 150]))
    still = shot("still", [200, 150], [200, 150])
    display.Position = [0.3, 0.0, 0.0]
    moved = shot("translated", [200, 150], [200, 150])
    display.Position = [0.0, 0.0, 0.0]
    eye = [camera[0][0] - 0.3, camera[0][1], camera[0][2]]
    cameraMoved = shot("camera-moved", [200, 150], [200, 150], eye)
    compare("Translation [0.3, 0, 0] vs camera moved by -0.3", moved, cameraMoved)
    compare("Translation [0.3, 0, 0] vs untranslated", moved, still, want_equal=False)
    simple.Delete(display)
    simple.Delete(view)  # before exit: a live view at exit gives GLXBadContext
    simple.Delete(reader)
    return finish(failures)


if __name__ == "__main__":
    sys.exit(main())
