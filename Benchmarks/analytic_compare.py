"""Every renderer against the analytic truth, in one VTK script on one clock.

    /usr/bin/python3 Benchmarks/analytic_compare.py OUT.json [--quick]
    (PYTHONPATH must hold the amrdualmesh package: BUILD/lib/python3/dist-packages; run under an
    X server, e.g. xvfb-run)

For each analytic scene (analytic_scenes.py: written as .vthb, read back through VTK's
vtkXMLUniformGridAMRReader) the truth image comes from analytic_truth.py. Renderers, each with a
curve of settings, all in the same render window with the same camera, transfer function and
unit distance:
  ours        vtkAMRDualMeshVolumeMapper, RAY_MARCH, StepSize = finest spacing x {2, 1, 0.5, 0.25}
              and SamplesPerCell (level-adaptive) {1, 2}, 4 jittered samples a pixel a frame;
              then 1 and 16 samples a pixel at SamplesPerCell 1
  vtk-amr     vtkAMRVolumeMapper (what ParaView's "Volume" representation of AMR draws with):
              its default resample (NumberOfSamples 128^3 voxels over the data) and the finest
              level's resolution over the domain ("largest resample that fits")
  resample    vtkResampleToImage at N^3 + vtkSmartVolumeMapper, N in RESAMPLE_N (up to the finest
              level's resolution of the scenes, 128^3: full fidelity)
  ug-*        the dual mesh as a vtkUnstructuredGrid (vtkAMRDualMeshToUnstructuredGrid) through
              VTK's unstructured volume mappers, same window (analytic_peers.py)
  yt          yt 4.1 volume rendering of the same boxes and values (yt_volume.py), its own image;
              skipped with the reason printed when yt cannot be imported
Timing (time.perf_counter around renderWindow.Render()): `first` is the first render after the
settings change (mesh build / resample / upload included), `frame` the median of 5 renders after
it, each with the camera nudged by 1e-4 degree so that every render draws from scratch.
Scoring: the captured 8-bit framebuffer (VTK writes the linear composite straight into it, which
is what a user sees) against the truth quantised the same way, as RMSE / p99 / max in 8-bit
units; `floor` is the quantised truth against the float truth. Renderers that also give a float
image (ours: WriteLastImageEXR; yt) are scored in float too (float_rmse ..., x 255 units).
Memory per leaf cell: ours the dual mesh's GetTotalBytes; vtk-amr / resample the float voxels
they request; ug-* the vtkUnstructuredGrid's GetActualMemorySize; yt its bricks' bytes.
"""
import json
import os
import statistics
import sys
import tempfile
import time

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import analytic_peers as peers  # noqa: E402
import analytic_scenes as scenes  # noqa: E402
import exr_read  # noqa: E402
import analytic_truth as truth  # noqa: E402
from vtkmodules.util.numpy_support import vtk_to_numpy  # noqa: E402
from vtkmodules.vtkCommonDataModel import vtkPiecewiseFunction  # noqa: E402
from vtkmodules.vtkFiltersCore import vtkResampleToImage  # noqa: E402
from vtkmodules.vtkRenderingCore import (vtkColorTransferFunction, vtkRenderer,  # noqa: E402
                                         vtkRenderWindow, vtkVolume, vtkVolumeProperty,
                                         vtkWindowToImageFilter)
from vtkmodules.vtkRenderingVolumeAMR import vtkAMRVolumeMapper  # noqa: E402
from vtkmodules.vtkRenderingVolumeOpenGL2 import vtkSmartVolumeMapper  # noqa: E402
import vtkmodules.vtkRenderingOpenGL2  # noqa: E402,F401
import vtkmodules.vtkRenderingVolumeOpenGL2  # noqa: E402,F401

TABLE = [[0.2, 0.3, 1.0, 0.0], [1.0, 1.0, 0.3, 0.6], [1.0, 0.2, 0.1, 0.9]]  # over [0, 1]
UNIT = {"constant": 0.25, "blob": 0.1, "shell": 0.05}
FRAMES = 5
# vtkResampleToImage over the AMR data: 128^3 is the finest level's resolution of the multi-level
# scenes (full fidelity). 256^3 (twice finer than the data) took 92-158 s a scene to resample in the
# run of 2026-12-02 02:24 (7 of run.sh's 30 minutes) and is left out; its errors there: 0.42 /
# 0.24 / 1.87 against 128^3's 0.54 / 0.39 / 2.68 (constant / blob / shell, 8-bit RMSE).
RESAMPLE_N = [32, 64, 128]
OURS_SPP = [1, 16]  # besides 4, at the level-adaptive step of 1 sample a cell


def volume_property(unit_distance):
    color, opacity = vtkColorTransferFunction(), vtkPiecewiseFunction()
    for i, e in enumerate(TABLE):
        v = i / (len(TABLE) - 1)
        color.AddRGBPoint(v, e[0], e[1], e[2])
        opacity.AddPoint(v, e[3])
    prop = vtkVolumeProperty()
    prop.SetColor(color)
    prop.SetScalarOpacity(opacity)
    prop.SetScalarOpacityUnitDistance(unit_distance)
    prop.SetInterpolationTypeToLinear()
    prop.ShadeOff()
    return prop


def attenuation_property(unit_distance, samples=256):
    """The same optical model for VTK's unstructured volume mappers, which read the scalar-opacity
    value as an attenuation coefficient per unit distance (vtkUnstructuredGridHomogeneousRayIntegrator:
    tau = opacity / unit distance, alpha = 1 - exp(-tau l)) where the image-data mappers and ours
    read it as the opacity of one unit distance (sigma = -ln(1 - alpha) / unit distance). The
    opacity table is resampled at `samples` values as -ln(1 - alpha(v)) / K and the unit distance
    divided by K (K = the largest -ln(1 - alpha), so every value stays in [0, 1], which the
    projected-tetrahedra mapper's 8-bit opacities need): tau(v) = sigma(v) for both. The colour
    table is unchanged."""
    prop = volume_property(unit_distance)
    xs = np.linspace(0.0, 1.0, len(TABLE))
    vs = np.linspace(0.0, 1.0, samples)
    tau = -np.log(np.maximum(1.0 - np.interp(vs, xs, [e[3] for e in TABLE]), 1e-6))
    k = max(float(tau.max()), 1.0)
    opacity = vtkPiecewiseFunction()
    for v, t in zip(vs, tau):
        opacity.AddPoint(float(v), float(t / k))
    prop.SetScalarOpacity(opacity)
    prop.SetScalarOpacityUnitDistance(unit_distance / k)
    return prop


def capture(window):
    w2i = vtkWindowToImageFilter()
    w2i.SetInput(window)
    w2i.SetInputBufferTypeToRGB()
    w2i.ReadFrontBufferOff()
    w2i.Update()
    img = w2i.GetOutput()
    nx, ny, _ = img.GetDimensions()
    return vtk_to_numpy(img.GetPointData().GetScalars()).reshape(ny, nx, 3)


def save_strip(images, out_dir, name):
    """One PNG per scene: the truth then every renderer's capture, left to right (to look at)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    cols = min(6, len(images))
    rows = (len(images) + cols - 1) // cols
    fig, axes = plt.subplots(rows, cols, figsize=(2.2 * cols, 2.0 * rows), squeeze=False)
    for ax in axes.ravel():
        ax.axis("off")
    for ax, (label, img) in zip(axes.ravel(), images.items()):
        ax.imshow(img[::-1], interpolation="nearest")
        ax.set_title(label, fontsize=6)
    fig.savefig(os.path.join(out_dir, "analytic-%s.png" % name), dpi=110, bbox_inches="tight")
    plt.close(fig)


def timed(window, camera, kernel=None):
    """(first s, median frame s, median kernel s or None): `kernel()` after each frame gives the
    renderer's own time of its last render (ours: LastRenderSeconds), a separate measure."""
    t = time.perf_counter()
    window.Render()
    first = time.perf_counter() - t
    frames, kernels = [], []
    for i in range(FRAMES):
        camera.Azimuth(1e-4 if i % 2 == 0 else -1e-4)
        t = time.perf_counter()
        window.Render()
        frames.append(time.perf_counter() - t)
        if kernel:
            kernels.append(kernel())
    return first, statistics.median(frames), statistics.median(kernels) if kernels else None


def run_scene(name, width, height, quick, out_dir):
    field = scenes.SCENES[name]()
    tmp = tempfile.mkdtemp()  # the scene's .vthb and our float images
    amr = scenes.read_vthb(scenes.write_scene(name, tmp))
    leaves = scenes.leaf_cells(amr)
    finest = 1.0 / (32 << (amr.GetNumberOfLevels() - 1))
    tf = truth.TransferFunction(TABLE, 0.0, 1.0, UNIT[name])
    cam = truth.default_camera()
    t = time.perf_counter()
    ref, est = truth.truth_image(field, tf, cam, width, height, steps=256 if quick else 1024, ss=2)
    truth_s = time.perf_counter() - t
    ref8 = np.round(np.clip(ref[..., :3], 0, 1) * 255.0)
    np.save(os.path.join(out_dir, "truth-%s.npy" % name), ref)  # for paraview_equal_clock.py
    floor = truth.errors(ref8, ref[..., :3] * 255.0)

    window = vtkRenderWindow()
    window.SetSize(width, height)
    window.SetOffScreenRendering(1)
    ren = vtkRenderer()
    ren.SetBackground(0, 0, 0)
    window.AddRenderer(ren)
    vcam = ren.GetActiveCamera()
    vcam.SetPosition(*cam.position)
    vcam.SetFocalPoint(*(cam.position + cam.direction))
    vcam.SetViewUp(*cam.up)
    vcam.SetViewAngle(cam.view_angle)
    ren.ResetCameraClippingRange(0, 1, 0, 1, 0, 1)
    volume = vtkVolume()
    image_property = volume_property(UNIT[name])
    ug_property = attenuation_property(UNIT[name])
    volume.SetProperty(image_property)
    ren.AddVolume(volume)

    rows = []
    images = {"truth": ref8.astype(np.uint8)}

    def score(renderer, setting, mapper, memory=None, extra=None, prop=None):
        volume.SetProperty(prop or image_property)
        volume.SetMapper(mapper)
        first, frame, kernel = timed(window, vcam,
                                     mapper.GetLastRenderSeconds if renderer == "ours" else None)
        row = {"renderer": renderer, "setting": setting, "first_s": first, "frame_s": frame}
        if kernel is not None:
            row["kernel_s"] = kernel
        img = capture(window)
        row.update(truth.errors(img.astype(np.float64), ref8))
        images[renderer + " " + setting] = img
        row["drawn"] = bool(img.max() > 0)
        if renderer == "ours":
            exr = os.path.join(tmp, "ours.exr")
            if mapper.WriteLastImageEXR(exr):
                row.update(peers.float_errors(exr_read.read_exr(exr)[..., :3], ref))
            memory = mapper.GetDualMesh().GetTotalBytes()
        if memory is not None:
            row["memory_bytes"] = memory
            row["bytes_per_leaf"] = memory / leaves
        row.update(extra or {})
        rows.append(row)
        print("  %-10s %-30s rmse %6.2f p99 %6.1f max %5.0f  first %.3fs frame %.3fs%s"
              % (renderer, setting, row["rmse"], row["p99"], row["max"], first, frame,
                 "  float rmse %.2f" % row["float_rmse"] if "float_rmse" in row else ""),
              flush=True)

    from amrdualmesh import vtkAMRDualMeshVolumeMapper

    def ours(setting, step, samples_per_cell, spp):
        m = vtkAMRDualMeshVolumeMapper()
        m.SetInputDataObject(amr)
        m.SelectScalarArray(scenes.ARRAY)
        m.SetIntegratorToRayMarch()
        m.SetStepSize(step)
        m.SetSamplesPerCell(samples_per_cell)
        m.SetSamplesPerRender(spp)  # every frame draws from scratch: spp samples a pixel a frame
        m.SetMaximumSamples(spp)
        score("ours", setting, m)

    # The curve: the step (uniform, then level-adaptive) at 4 jittered samples a pixel, then the
    # samples a pixel at the level-adaptive step (the pixel footprint's noise dominates the error
    # of smooth scenes at 4; OURS_SPP).
    for k in ([2.0, 1.0] if quick else [2.0, 1.0, 0.5, 0.25]):
        ours("step %.2g h_fine, 4 spp" % k, k * finest, 0.0, 4)
    for spc in ([1.0] if quick else [1.0, 2.0]):
        ours("adaptive %g/cell, 4 spp" % spc, 0.25 * finest, spc, 4)
    for spp in ([1] if quick else OURS_SPP):
        ours("adaptive 1/cell, %d spp" % spp, 0.25 * finest, 1.0, spp)

    n_fine = 32 << (amr.GetNumberOfLevels() - 1)
    for label, dims in (("default 128^3", 128), ("finest %d^3" % n_fine, n_fine)):
        m = vtkAMRVolumeMapper()
        m.SetInputDataObject(amr)
        m.SetScalarModeToUseCellFieldData()
        m.SelectScalarArray(scenes.ARRAY)
        m.SetNumberOfSamples(dims, dims, dims)
        score("vtk-amr", label, m, memory=4 * dims ** 3)

    for n in ([32, 64] if quick else RESAMPLE_N):
        rs = vtkResampleToImage()
        rs.SetInputDataObject(amr)
        rs.SetSamplingDimensions(n, n, n)
        rs.UseInputBoundsOn()
        m = vtkSmartVolumeMapper()
        m.SetInputConnection(rs.GetOutputPort())
        m.SetScalarModeToUsePointFieldData()
        m.SelectScalarArray(scenes.ARRAY)
        score("resample", "%d^3" % n, m, memory=4 * n ** 3)

    # The dual mesh as a plain vtkUnstructuredGrid, VTK's unstructured mappers, same window.
    mixed, tets, export_s, tet_s = peers.dual_unstructured_grids(amr)
    grids = {"mixed": mixed, "tets": tets}
    ug_info = {"cells": mixed.GetNumberOfCells(), "points": mixed.GetNumberOfPoints(),
               "tets": tets.GetNumberOfCells(), "export_s": export_s, "tetrahedralise_s": tet_s}
    print("  dual mesh as vtkUnstructuredGrid: %d points, %d cells (%d tets after "
          "vtkDataSetTriangleFilter); export %.2fs, tetrahedralise %.2fs"
          % (ug_info["points"], ug_info["cells"], ug_info["tets"], export_s, tet_s), flush=True)
    for renderer, setting, make, which, attenuation in peers.unstructured_mappers(leaves, quick):
        m = make()
        m.SetInputData(grids[which])
        score(renderer, setting, m, memory=grids[which].GetActualMemorySize() * 1024,
              prop=ug_property if attenuation else None)

    yt = peers.yt_rows(field, tf, cam, width, height, ref, ref8, leaves, quick, FRAMES,
                       lambda line: print(line, flush=True))
    rows += yt["rows"]
    images.update(yt["images"])
    save_strip(images, out_dir, name)
    return {"name": name, "doc": field.doc, "leaf_cells": leaves, "levels": amr.GetNumberOfLevels(),
            "truth_error_estimate": est, "truth_seconds": truth_s, "quantisation_floor": floor,
            "unstructured_grid": ug_info, "yt_skipped": yt["skipped"],
            "yt_centre_ray_length": yt["centre_ray_length"], "rows": rows}


def main():
    if len(sys.argv) < 2:
        sys.exit("usage: analytic_compare.py OUT.json [--quick]")
    quick = "--quick" in sys.argv[2:]
    global FRAMES
    if quick:
        FRAMES = 2  # a smoke test: the timings of a quick run are not reported as results
    width, height = (96, 72) if quick else (256, 192)
    result = {"date": time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime()), "width": width,
              "height": height, "quick": quick, "cpu_count": os.cpu_count(), "frames": FRAMES,
              "load_start": os.getloadavg(), "scenes": []}
    for name in (["constant", "blob"] if quick else list(scenes.SCENES)):
        print("== %s" % name, flush=True)
        result["scenes"].append(run_scene(name, width, height, quick,
                                            os.path.dirname(os.path.abspath(sys.argv[1]))))
        result["load_end"] = os.getloadavg()
        with open(sys.argv[1], "w") as f:
            json.dump(result, f, indent=1)
    # Sanity (no timing): every renderer drew something finite; the truth is converged.
    bad = [(s["name"], r["renderer"], r["setting"]) for s in result["scenes"] for r in s["rows"]
           if not np.isfinite(r["rmse"]) or not r["drawn"]]
    bad += [(s["name"], "truth", "error estimate %.2g" % s["truth_error_estimate"])
            for s in result["scenes"] if not s["truth_error_estimate"] < 1e-3]
    if bad:
        sys.exit("analytic_compare: renderers that drew nothing or a non-finite error: %s" % bad)


if __name__ == "__main__":
    main()
