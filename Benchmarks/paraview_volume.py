"""ParaView's own AMR volume rendering of one benchmark scene, for the side-by-side comparison.

Run with pvpython under an X server (Benchmarks/run.sh uses xvfb-run):
    pvpython Benchmarks/paraview_volume.py SCENES.json SET OUT.json [--frames N] [--max-cells N]
        [--plugin AMRDualMeshPlugin.so]   (also our representation, same view, same loop)

SCENES.json comes from amrdm-bench (camera, transfer-function table, unit distance, image size,
and the path of our emission-absorption reference as raw float RGBA). The set is opened with
ParaView's reader (all levels, one cell array; log10 through a Calculator when the scene is log
scaled), shown with the "Volume" representation (vtkAMRStreamingVolumeRepresentation: donor-cell
resample into a uniform image, then vtkSmartVolumeMapper ray casting, emission-absorption, no
shading) with the same camera, colour and opacity table and unit distance, at two resample caps:
  default   NumberOfSamples 64 128 64 (ParaView's default)
  finest    the finest level's resolution over the bounds (ParaView clamps to it), reduced by
            powers of two only when it exceeds --max-cells
For each: the first render (resample + upload + draw), the median of --frames renders (the camera
nudged by 1e-4 degree so that every render draws), and the RMSE / PSNR of the captured 8-bit RGB
(linear, over black) against our reference. Results are written after every variant.
"""
import json
import math
import os
import statistics
import sys
import time

import numpy as np
from paraview.simple import (AMReXBoxLibGridReader, Calculator, ColorBy, CreateView, EnzoReader,
                             GetColorTransferFunction, GetOpacityTransferFunction, LoadPlugin,
                             Render, SaveScreenshot, Show)
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOImage import vtkPNGReader


def open_set(scene):
    from file_check import check_file
    check_file(scene["path"])  # issue 33: a damaged file is an error, before the reader sees it
    if scene["reader"] == "enzo":
        reader = EnzoReader(FileNames=[scene["path"]])
        reader.ConvertToCGS = 1  # as VTK's vtkAMREnzoReader (amrdm-bench); ParaView's default is 0
    else:
        reader = AMReXBoxLibGridReader(FileNames=[scene["path"]])
    reader.UpdatePipelineInformation()
    reader.Level = 1 << 20  # every level (the default reads level 1 only)
    reader.CellArrayStatus = [scene["array"]]
    array = scene["array"]
    source = reader
    if scene["log_scale"]:
        array = "log10_" + scene["array"]
        source = Calculator(Input=reader, AttributeType="Cell Data", ResultArrayName=array,
                            Function="log10(%s)" % scene["array"])
    return source, array


def option(args, name, default):
    """Removes `name VALUE` from the argument list `args` and returns VALUE; `default` when the
    option is absent."""
    if name in args:
        i = args.index(name)
        value = args[i + 1]
        del args[i:i + 2]
        return value
    return default


def black_view(width, height):
    """A RenderView of width x height on black, without the orientation axes."""
    view = CreateView("RenderView")
    view.ViewSize = [width, height]
    view.OrientationAxesVisibility = 0
    if hasattr(view, "UseColorPaletteForBackground"):
        view.UseColorPaletteForBackground = 0
    view.Background = [0.0, 0.0, 0.0]
    return view


def camera_setter(view, position, focal_point, view_up, view_angle):
    """set_camera(nudge=0.0): puts the view's perspective camera there, turned by `nudge` degrees
    of azimuth (a nudge of 1e-4 makes a render draw without moving a pixel)."""
    def set_camera(nudge=0.0):
        view.CameraPosition = list(position)
        view.CameraFocalPoint = list(focal_point)
        view.CameraViewUp = list(view_up)
        view.CameraViewAngle = view_angle
        view.CameraParallelProjection = 0
        if nudge:
            view.GetActiveCamera().Azimuth(nudge)
    return set_camera


def volume_view(scene, source, array):
    """(view, display, set_camera) of a benchmark scene: its image size on black, `source` shown
    with ParaView's "Volume" representation and the scene's transfer function, its camera."""
    view = black_view(scene["width"], scene["height"])
    cam = scene["camera"]
    set_camera = camera_setter(view, cam["position"], cam["focal_point"], cam["view_up"],
                               cam["view_angle"])
    display = Show(source, view)
    display.SetRepresentationType("Volume")
    apply_transfer_function(display, array, scene["tf"])
    return view, display, set_camera


def apply_transfer_function(display, array, tf):
    lo, hi, table = tf["lo"], tf["hi"], tf["table"]
    n = len(table)
    values = [lo + (hi - lo) * i / (n - 1) for i in range(n)]
    ColorBy(display, ("CELLS", array))
    lut = GetColorTransferFunction(array)
    lut.AutomaticRescaleRangeMode = "Never"
    lut.ColorSpace = "RGB"
    lut.RGBPoints = [c for v, e in zip(values, table) for c in (v, e[0], e[1], e[2])]
    pwf = GetOpacityTransferFunction(array)
    pwf.Points = [c for v, e in zip(values, table) for c in (v, e[3], 0.5, 0.0)]
    lut.ScalarRangeInitialized = 1
    pwf.ScalarRangeInitialized = 1
    display.LookupTable = lut
    display.ScalarOpacityFunction = pwf
    display.ScalarOpacityUnitDistance = tf["unit_distance"]


def read_png_rgb(path, unit=255.0):
    """A PNG's RGB as floats divided by `unit`, (rows from the bottom, columns, 3)."""
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    img = reader.GetOutput()
    w, h, _ = img.GetDimensions()
    a = vtk_to_numpy(img.GetPointData().GetScalars()).reshape(h, w, -1)
    return a[:, :, :3].astype(np.float64) / unit


def median_frame_seconds(view, set_camera, frames):
    """The median seconds of `frames` Render(view) calls, the camera nudged by -+1e-4 degree
    before each so that every render draws from scratch."""
    times = []
    for k in range(frames):
        set_camera(1e-4 if k % 2 == 0 else -1e-4)
        t0 = time.perf_counter()
        Render(view)
        times.append(time.perf_counter() - t0)
    return statistics.median(times)


def errors_against(image_rgb, reference_path, width, height):
    """(RMSE, 99th percentile, max) of |image - reference| over R, G, B (linear, over black)."""
    ref = np.fromfile(reference_path, dtype=np.float32).reshape(height, width, 4)[:, :, :3]
    d = np.abs(image_rgb - ref.astype(np.float64))
    return float(np.sqrt(np.mean(d ** 2))), float(np.percentile(d, 99)), float(d.max())


def opengl_renderer(view):
    try:
        Render(view)
        caps = view.GetRenderWindow().ReportCapabilities()
        for line in caps.splitlines():
            if "renderer string" in line.lower():
                return line.split(":", 1)[1].strip()
    except Exception:  # noqa: BLE001 - informational only
        pass
    return "unknown"


def cap_for_finest(dims, max_cells):
    dims = list(dims)
    while dims[0] * dims[1] * dims[2] > max_cells:
        dims = [max(2, d // 2) for d in dims]
    return dims


def main():
    args = sys.argv[1:]
    frames = int(option(args, "--frames", "5"))
    plugin = option(args, "--plugin", None)
    max_cells = int(option(args, "--max-cells", "140000000"))
    scenes_path, set_name, out_path = args
    scene = next(s for s in json.load(open(scenes_path)) if s["name"] == set_name)
    width, height = scene["width"], scene["height"]
    out_dir = os.path.dirname(os.path.abspath(out_path))
    if plugin:  # before Show(), so that the representation has the plugin's properties
        LoadPlugin(plugin, remote=False, ns=globals())
    source, array = open_set(scene)

    view, display, set_camera = volume_view(scene, source, array)

    finest = [int(d) for d in scene["finest_dims"]]
    variants = [("default", [64, 128, 64])]
    fcap = cap_for_finest(finest, max_cells)
    if [min(c, f) for c, f in zip(fcap, finest)] != [min(c, f) for c, f in zip(variants[0][1], finest)]:
        variants.append(("finest", fcap))  # else the default cap already keeps the finest level
    results = {"set": set_name, "width": width, "height": height, "variants": [], "ours": []}

    def measure(label):
        """(first render s, median ms/frame, png, (rmse, p99, max)) of the view as it is set up."""
        set_camera()
        t0 = time.perf_counter()
        Render(view)
        first = time.perf_counter() - t0
        frame = median_frame_seconds(view, set_camera, frames)
        set_camera()
        png = os.path.join(out_dir, "paraview-%s-%s.png" % (set_name, label))
        SaveScreenshot(png, view, ImageResolution=[width, height], TransparentBackground=0)
        return (first, 1e3 * frame, png,
                errors_against(read_png_rgb(png), scene["reference"], width, height))

    def save():
        with open(out_path, "w") as f:
            json.dump(results, f, indent=1)

    for name, cap in variants:
        display.NumberOfSamples = cap
        resampled = [min(c, f) for c, f in zip(cap, finest)]
        first, ms, png, (err, p99, worst) = measure(name)
        entry = {
            "variant": name, "cap": cap, "resample_dims": resampled,
            "keeps_finest": resampled == finest,
            "resample_bytes": 4 * resampled[0] * resampled[1] * resampled[2],
            "first_render_s": first, "ms_per_frame": ms, "frames": frames, "rmse": err,
            "p99": p99, "max": worst, "psnr": (-20 * math.log10(err)) if err > 0 else None,
            "image": png,
        }
        results["variants"].append(entry)
        print("  paraview %-9s %-8s cap %-14s first render %7.2f s, %8.1f ms/frame, rmse %.5f" % (
            set_name, name, "x".join(map(str, resampled)), first, ms, err), flush=True)
        save()
    if plugin:
        # Ours in the same view and the same loop: the "Dual-Mesh Path Tracer" representation at
        # its defaults, except Ray Marching (the emission-absorption model of the reference) and
        # the scene's unit distance, at 1 and 4 samples a pixel a frame.
        display.SetRepresentationType("Dual-Mesh Path Tracer")
        display.Integrator = "Ray Marching"
        display.ScalarOpacityUnitDistance = scene["tf"]["unit_distance"]
        for spp in (1, 4):
            display.SamplesPerRender = spp
            display.MaximumSamples = spp
            first, ms, png, (err, p99, worst) = measure("ours-%dspp" % spp)
            results["ours"].append({"setting": "Ray Marching, defaults, %d spp" % spp, "spp": spp,
                                    "first_render_s": first, "ms_per_frame": ms, "frames": frames,
                                    "rmse": err, "p99": p99, "max": worst, "image": png})
            print("  ours-pv  %-9s %d spp, first render %7.2f s, %8.1f ms/frame, rmse %.5f" % (
                set_name, spp, first, ms, err), flush=True)
            save()
        display.SetRepresentationType("Volume")
    results["opengl_renderer"] = opengl_renderer(view)
    with open(out_path, "w") as f:
        json.dump(results, f, indent=1)


if __name__ == "__main__":
    main()
