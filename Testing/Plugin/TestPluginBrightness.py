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
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "Support"))
from pv_testing import (ADVECTION, amrex_source, bare_view, load_plugin, luminance,  # noqa: E402
                        plugin_args, png_rgb)

SIZE = [300, 300]
SAMPLES = 64


def render(simple, reader, representation, preset, png):
    view = bare_view(simple, SIZE)
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
    return float(luminance(png_rgb(png, unit=1.0)).mean()), unit


def main():
    args = plugin_args(__doc__, lambda p: p.add_argument("--factor", type=float, default=2.0))
    if not os.path.isdir(ADVECTION):
        print("SKIP: the AMReX advection set is missing")
        return 125
    simple = load_plugin(args.plugin)  # both representations get the camera below
    reader = amrex_source(simple, ADVECTION, "phi")
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
