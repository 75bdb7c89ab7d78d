"""Set-up shared by the Python benchmarks that drive vtkAMRDualMeshVolumeMapper themselves
(memory_sets.py, scale_series.py): the process's resident memory, and an offscreen view of one
volume. Benchmarks import nothing from Testing/ (tests and benchmarks keep their own helpers)."""
from vtkmodules import vtkCommonDataModel as _dm

# The grid description of a 3-D AMR block: VTK 9.2's module constant VTK_XYZ_GRID became
# vtkStructuredData.VTK_STRUCTURED_XYZ_GRID in VTK 9.6 (same value, 8; the old name is gone
# from VTK 9.7's Python). analytic_scenes.py and scale_series.py build AMR with it.
XYZ_GRID = getattr(_dm, "VTK_XYZ_GRID", None)
if XYZ_GRID is None:
    XYZ_GRID = _dm.vtkStructuredData.VTK_STRUCTURED_XYZ_GRID


def rss_bytes(key):
    """/proc/self/status's `key` (VmRSS, VmHWM) in bytes; 0 where it is missing."""
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


def offscreen_volume(amr, array, threads, ramp_top, opacity_top, size, unit_distance=None):
    """vtkAMRDualMeshVolumeMapper of `amr`'s cell array `array` on `threads` threads, blue to
    orange and opacity 0 to `opacity_top` over [0, ramp_top], in an offscreen size^2 window with
    the camera reset. Returns (mapper, window, renderer, volume)."""
    from vtkmodules.vtkCommonDataModel import vtkPiecewiseFunction
    from vtkmodules.vtkRenderingCore import (vtkColorTransferFunction, vtkRenderer,
                                             vtkRenderWindow, vtkVolume, vtkVolumeProperty)
    import vtkmodules.vtkRenderingOpenGL2  # noqa: F401
    from amrdualmesh import vtkAMRDualMeshVolumeMapper
    mapper = vtkAMRDualMeshVolumeMapper()
    mapper.SetInputData(amr)
    mapper.SetScalarModeToUseCellFieldData()
    mapper.SelectScalarArray(array)
    mapper.SetNumberOfThreads(threads)
    volume = vtkVolume()
    volume.SetMapper(mapper)
    volume.SetProperty(vtkVolumeProperty())
    color = vtkColorTransferFunction()
    opacity = vtkPiecewiseFunction()
    for value, rgb, alpha in ((0.0, (0.2, 0.3, 0.9), 0.0),
                              (ramp_top, (0.9, 0.3, 0.1), opacity_top)):
        color.AddRGBPoint(value, *rgb)
        opacity.AddPoint(value, alpha)
    volume.GetProperty().SetColor(color)
    volume.GetProperty().SetScalarOpacity(opacity)
    if unit_distance is not None:
        volume.GetProperty().SetScalarOpacityUnitDistance(unit_distance)
    ren = vtkRenderer()
    ren.AddVolume(volume)
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.AddRenderer(ren)
    window.SetSize(size, size)
    ren.ResetCamera()
    return mapper, window, ren, volume


def first_frame_peak(window, volume):
    """Renders once without the volume (the OpenGL context and window buffers), then resets the
    peak and renders the frame that builds everything. Returns (input RSS, peak RSS or 0 where
    the kernel cannot reset it, whether it could, the frame's seconds)."""
    import time
    volume.SetVisibility(0)
    window.Render()
    volume.SetVisibility(1)
    input_rss = rss_bytes("VmRSS")
    peak_ok = reset_peak()
    t0 = time.perf_counter()
    window.Render()
    seconds = time.perf_counter() - t0
    return input_rss, rss_bytes("VmHWM") if peak_ok else 0, peak_ok, seconds


def source_commit():
    """`git describe --always --dirty` of the checkout the benchmark runs from, or None."""
    import os
    import subprocess
    try:
        return subprocess.run(["git", "-C", os.path.dirname(os.path.abspath(__file__)), "describe",
                               "--always", "--dirty"], capture_output=True, text=True,
                              check=True).stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        return None
