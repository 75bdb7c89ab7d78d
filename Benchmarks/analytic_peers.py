"""The peers of analytic_compare.py that are not VTK's AMR mappers: yt 4.1 volume rendering
(yt_volume.py) and the dual mesh handed to VTK as a plain vtkUnstructuredGrid
(vtkAMRDualMeshToUnstructuredGrid) through VTK's unstructured volume mappers. Each is timed on
the same clock (time.perf_counter), first render then the median of FRAMES renders, and scored
against the same truth at 8 bits (and at float where the renderer gives floats: yt).

Unstructured mappers (VTK 9.1), what each accepts:
  ug-raycast  vtkUnstructuredGridVolumeRayCastMapper (Bunyk): tetrahedra only ("only tetrahedra
              are supported"), so the grid is tetrahedralised first (vtkDataSetTriangleFilter);
  ug-zsweep   vtkUnstructuredGridVolumeZSweepMapper: takes the mixed cells as they are (CPU;
              about a minute a frame on the 90 k-cell blob at 96 x 72 on this machine, so it is
              run only on scenes up to ZSWEEP_MAX_CELLS leaf cells);
  ug-pt       vtkProjectedTetrahedraMapper (OpenGL): tetrahedra only ("Encountered
              non-tetrahedra cell!"), the tetrahedralised grid.
Memory: vtkDataObject::GetActualMemorySize of the grid the mapper draws (points, connectivity,
offsets, types, scalars), per leaf cell.
"""
import statistics
import time

import numpy as np

import analytic_scenes as scenes
import analytic_truth as truth
import yt_volume

ZSWEEP_MAX_CELLS = 40000
PT_ATTENUATION = True


def timed_call(render, frames):
    """(first s, median of `frames` s) of render(); `render` draws from scratch each call."""
    t = time.perf_counter()
    render()
    first = time.perf_counter() - t
    times = []
    for _ in range(frames):
        t = time.perf_counter()
        render()
        times.append(time.perf_counter() - t)
    return first, statistics.median(times)


def float_errors(img_linear, ref):
    """Errors of a float linear RGB image against the float truth, in 8-bit units (x 255)."""
    e = truth.errors(np.asarray(img_linear, np.float64) * 255.0, ref[..., :3] * 255.0)
    return {"float_" + k: v for k, v in e.items()}


def yt_rows(field, tf, cam, width, height, ref, ref8, leaves, quick, frames, log):
    """{"rows", "images", "skipped" (why, or None), "centre_ray_length"} for yt at num_samples x
    {no ghost zones (yt's default), ghost zones}."""
    ok, why = yt_volume.available()
    if not ok:
        log("  yt        skipped: %s" % why)
        return {"rows": [], "images": {}, "skipped": why, "centre_ray_length": None}
    rows, images = [], {}
    ds = yt_volume.load_scene(field)
    r = yt_volume.YtRenderer(ds, tf, cam, width, height)
    samples = [10] if quick else [2, 5, 10, 20]
    for ghost in (False, True):
        for n in samples:
            r.configure(n, ghost)
            first, frame = timed_call(r.render, frames)
            img = r.render()
            img8 = np.round(np.clip(img, 0.0, 1.0) * 255.0)
            setting = "%d samples/cell%s%s" % (n, ", ghost zones" if ghost else "",
                                               " (default)" if n == 10 and not ghost else "")
            row = {"renderer": "yt", "setting": setting, "first_s": first, "frame_s": frame,
                   "memory_bytes": r.memory_bytes(), "drawn": bool(img8.max() > 0)}
            row.update(truth.errors(img8, ref8))
            row.update(float_errors(img, ref))
            row["bytes_per_leaf"] = row["memory_bytes"] / leaves
            rows.append(row)
            images["yt " + setting] = img8.astype(np.uint8)
            log("  %-9s %-22s rmse %6.2f p99 %6.1f max %5.0f  first %.3fs frame %.3fs  float rmse %.2f"
                % ("yt", setting, row["rmse"], row["p99"], row["max"], first, frame, row["float_rmse"]))
    return {"rows": rows, "images": images, "skipped": None, "centre_ray_length": r.centre_ray_length}


def dual_unstructured_grids(amr):
    """(mixed-cell grid, tetrahedralised grid, seconds to export, seconds to tetrahedralise)."""
    from amrdualmesh import vtkAMRDualMeshToUnstructuredGrid
    from vtkmodules.vtkFiltersGeneral import vtkDataSetTriangleFilter
    t = time.perf_counter()
    conv = vtkAMRDualMeshToUnstructuredGrid()
    conv.SetInputDataObject(amr)
    conv.SetArrayName(scenes.ARRAY)
    conv.Update()
    export_s = time.perf_counter() - t
    t = time.perf_counter()
    tri = vtkDataSetTriangleFilter()
    tri.SetInputData(conv.GetOutput())
    tri.TetrahedraOnlyOn()
    tri.Update()
    return conv.GetOutput(), tri.GetOutput(), export_s, time.perf_counter() - t


def unstructured_mappers(leaves, quick):
    """[(renderer, setting, mapper factory, which grid: 'mixed' | 'tets', attenuation)] to run;
    attenuation: the mapper reads the scalar opacity as an attenuation coefficient, so it is given
    analytic_compare.attenuation_property (the same sigma as every other renderer)."""
    from vtkmodules.vtkRenderingVolume import (vtkProjectedTetrahedraMapper,
                                               vtkUnstructuredGridVolumeRayCastMapper,
                                               vtkUnstructuredGridVolumeZSweepMapper)
    import vtkmodules.vtkRenderingVolumeOpenGL2  # noqa: F401 - the OpenGL PT override

    def raycast(distance):
        def make():
            m = vtkUnstructuredGridVolumeRayCastMapper()
            m.SetImageSampleDistance(distance)
            m.AutoAdjustSampleDistancesOff()
            return m
        return make

    def zsweep():
        m = vtkUnstructuredGridVolumeZSweepMapper()
        m.SetImageSampleDistance(1.0)
        m.AutoAdjustSampleDistancesOff()
        return m

    out = [("ug-raycast", "tets, image sample distance 2", raycast(2.0), "tets", True)]
    if not quick:
        out.append(("ug-raycast", "tets, image sample distance 1", raycast(1.0), "tets", True))
    if not quick or leaves <= ZSWEEP_MAX_CELLS:  # seconds a frame on the blob: not in CI
        out.append(("ug-pt", "tets", vtkProjectedTetrahedraMapper, "tets", PT_ATTENUATION))
    if not quick and leaves <= ZSWEEP_MAX_CELLS:
        out.append(("ug-zsweep", "mixed cells", zsweep, "mixed", True))
    return out
