"""ParaView plugin test: the default path-traced image is about as bright as ParaView's Volume.

  pvpython TestPluginBrightness.py --plugin AMRDualMeshPlugin.so --temp-dir DIR [--factor F]

The AMReX advection set (all levels, phi) is shown with ParaView's "Volume" representation and
with the "Dual-Mesh Path Tracer" at its defaults (Path Tracing, ParaView's light kit, the default
Environment Light, the same unit distance), with the same colour map, opacity function, view
and a black background, for two colour maps: Cool to Warm and Inferno (whose dark low end used
to give black smoke). The mean luminance (Rec. 709, of the 8-bit screenshot) of the path-traced
image must be within a factor F (default 2, Plugin/README.md "Brightness") of Volume's. Screenshots are
left in DIR (PluginBrightness<map><representation>.png).
Run under an X server (ctest runs under `xvfb-run -a`).
"""
import argparse
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
DATA = os.path.join(os.path.dirname(HERE), "Data")
SIZE = [300, 300]
SAMPLES = 64


def parse_args():
    p = argparse.ArgumentParser(description=__doc__)
    p.add_argument("--plugin", required=True)
    p.add_argument("--temp-dir", required=True)
    p.add_argument("--factor", type=float, default=2.0)
    return p.parse_args()


def mean_luminance(png):
    from vtkmodules.vtkIOImage import vtkPNGReader
    from vtkmodules.util.numpy_support import vtk_to_numpy
    r = vtkPNGReader()
    r.SetFileName(png)
    r.Update()
    rgb = vtk_to_numpy(r.GetOutput().GetPointData().GetScalars())[:, :3].astype(float)
    return float((0.2126 * rgb[:, 0] + 0.7152 * rgb[:, 1] + 0.0722 * rgb[:, 2]).mean())


def render(simple, reader, representation, preset, png):
    view = simple.CreateView("RenderView")
    view.ViewSize = SIZE
    view.OrientationAxesVisibility = 0
    view.UseColorPaletteForBackground = 0
    view.Background = [0.0, 0.0, 0.0]
    d = simple.Show(reader, view)
    d.SetRepresentationType(representation)
    simple.ColorBy(d, ("CELLS", "phi"))
    lut = simple.GetColorTransferFunction("phi")
    lut.ApplyPreset(preset, True)
    lut.RescaleTransferFunction(1.0, 2.0)
    pwf = simple.GetOpacityTransferFunction("phi")
    pwf.Points = [1.0, 0.0, 0.5, 0.0, 2.0, 1.0, 0.5, 0.0]  # ParaView's default ramp
    if representation != "Volume":
        d.SamplesPerRender = SAMPLES
        d.MaximumSamples = SAMPLES
    unit = d.ScalarOpacityUnitDistance  # Volume's property, shared by both representations
    view.CameraPosition = [1.6, -0.7, 1.0]
    view.CameraFocalPoint = [0.5, 0.5, 0.125]
    view.CameraViewUp = [0, 0, 1]
    simple.Render(view)
    simple.SaveScreenshot(png, view, ImageResolution=SIZE)
    simple.Delete(d)
    simple.Delete(view)
    return mean_luminance(png), unit


def main():
    args = parse_args()
    os.makedirs(args.temp_dir, exist_ok=True)
    path = os.path.join(DATA, "amrex-advection-amrcore3d", "plt00040")
    if not os.path.isdir(path):
        print("SKIP: the AMReX advection set is missing")
        return 125
    from paraview import simple
    simple._DisableFirstRenderCameraReset()  # both representations get the camera below
    simple.LoadPlugin(args.plugin, remote=False, ns=globals())
    reader = simple.AMReXBoxLibGridReader(FileNames=[path])
    reader.UpdatePipelineInformation()
    reader.Level = 100
    reader.CellArrayStatus = ["phi"]
    ok = True
    for preset in ("Cool to Warm", "Inferno (matplotlib)"):
        tag = preset.split()[0]
        volume, vunit = render(simple, reader, "Volume", preset,
                               os.path.join(args.temp_dir, "PluginBrightness%sVolume.png" % tag))
        ours, ounit = render(simple, reader, "Dual-Mesh Path Tracer", preset,
                             os.path.join(args.temp_dir, "PluginBrightness%sPathTracer.png" % tag))
        ratio = ours / volume if volume > 0 else float("inf")
        print("%s: mean luminance Volume %.2f, path tracer %.2f, ratio %.2f "
              "(unit distance %.4g / %.4g)" % (preset, volume, ours, ratio, vunit, ounit))
        if abs(vunit - ounit) > 1e-9 * vunit:
            print("FAILED: the two representations have different unit distances")
            ok = False
        if not (volume > 1.0 and 1.0 / args.factor <= ratio <= args.factor):
            print("FAILED: %s: ratio %.2f outside [1/%.2f, %.2f]" %
                  (preset, ratio, args.factor, args.factor))
            ok = False
    print("PASSED" if ok else "FAILED")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
