"""Helpers shared by the ParaView plugin tests (Testing/Plugin, run with pvpython): the command
line, loading the plugin, a bare render view, screenshots as numbers, and the PASS / FAIL end.
paraview.simple is imported where a helper needs it, so that a test can print SKIP before."""
import argparse
import os

DATA = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "Data")
ADVECTION = os.path.join(DATA, "amrex-advection-amrcore3d", "plt00040")
ENZO = os.path.join(DATA, "enzo-moving7_DD0010", "moving7_0010.hierarchy")


def plugin_args(description=None, more=None):
    """--plugin and --temp-dir (created), and what more(parser) adds; the parsed arguments."""
    parser = argparse.ArgumentParser(description=description)
    parser.add_argument("--plugin", required=True)
    parser.add_argument("--temp-dir", required=True)
    if more:
        more(parser)
    args = parser.parse_args()
    os.makedirs(args.temp_dir, exist_ok=True)
    return args


def load_plugin(plugin):
    """paraview.simple with the plugin loaded in the client and ParaView's reset of the camera
    on the first render off (each test places its camera)."""
    from paraview import simple
    simple._DisableFirstRenderCameraReset()
    simple.LoadPlugin(plugin, remote=False, ns=globals())
    return simple


def bare_view(simple, size=None, background=(0.0, 0.0, 0.0)):
    """A RenderView without the orientation axes on a plain background (not the palette's)."""
    view = simple.CreateView("RenderView")
    if size:
        view.ViewSize = list(size)
    view.OrientationAxesVisibility = 0
    view.UseColorPaletteForBackground = 0
    view.Background = list(background)
    return view



def amrex_source(simple, path, array):
    """ParaView's AMReX reader of `path` with every level and only the cell array `array`."""
    reader = simple.AMReXBoxLibGridReader(FileNames=[path])
    reader.UpdatePipelineInformation()
    reader.Level = 100
    reader.CellArrayStatus = [array]
    return reader


def show_dual_mesh(simple, source, view, array, association="CELLS"):
    """`source` in `view` with the "Dual-Mesh Path Tracer" representation coloured by `array`;
    (the display, the array's colour transfer function)."""
    display = simple.Show(source, view)
    display.SetRepresentationType("Dual-Mesh Path Tracer")
    simple.ColorBy(display, (association, array))
    return display, simple.GetColorTransferFunction(array)


def ray_marching(display, samples):
    """Ray Marching (deterministic; emission-absorption, as Volume), `samples` per render and
    at most."""
    display.Integrator = 2
    display.SamplesPerRender = samples
    display.MaximumSamples = samples


def shoot(simple, view, camera, png, resolution):
    """Places the camera (position, focal point, view up), renders and saves the screenshot."""
    view.CameraPosition, view.CameraFocalPoint, view.CameraViewUp = [list(v) for v in camera]
    simple.Render(view)
    simple.SaveScreenshot(png, view, ImageResolution=resolution)
    return png

def png_rgb(path, unit=255.0):
    """A PNG's RGB as floats divided by `unit`, shape (rows from the bottom, columns, 3)."""
    from vtkmodules.util.numpy_support import vtk_to_numpy
    from vtkmodules.vtkIOImage import vtkPNGReader
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    w, h, _ = reader.GetOutput().GetDimensions()
    a = vtk_to_numpy(reader.GetOutput().GetPointData().GetScalars()).reshape(h, w, -1)
    return a[:, :, :3].astype(float) / unit


def luminance(rgb):
    """Rec. 709 luminance of each pixel (the last axis is R, G, B), in the pixels' unit."""
    return 0.2126 * rgb[..., 0] + 0.7152 * rgb[..., 1] + 0.0722 * rgb[..., 2]


def finish(failures):
    """Prints FAIL with the failures, or PASS; the exit status."""
    if failures:
        print("FAIL: " + "; ".join(failures))
        return 1
    print("PASS")
    return 0
