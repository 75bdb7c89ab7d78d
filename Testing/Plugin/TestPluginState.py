"""ParaView plugin test: every property of the "Dual-Mesh Path Tracer" survives a .pvsm state.

  pvpython TestPluginState.py --plugin AMRDualMeshPlugin.so --temp-dir DIR [--pvpython PATH]

Phase 1 (this process) shows the AMReX advection set with the representation, sets every
path-tracer property to a value that is not its default (among them the unit distance 0.05 and
Shade, the Volume representation's own properties that ours renders with), renders a fixed number of
samples, saves a screenshot and SaveState(). Phase 2 runs this script again in a fresh pvpython
(--load): LoadState(), then every property must read back the saved value and the screenshot
must be the same image (the renderer is deterministic for a seed and a sample count).
Run under an X server (ctest runs under `xvfb-run -a`).
"""
import argparse
import json
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
DATA = os.path.join(os.path.dirname(HERE), "Data")
SIZE = [240, 200]

# name -> a value that is not the default (the XML defaults are in AMRDualMeshRepresentation.xml).
VALUES = {
    "Integrator": 1,                          # Single Scattering
    "Device": 1,                              # CPU
    "SamplesPerRender": 4,
    "MaximumSamples": 8,
    "RefineWhileIdle": 0,
    "ScalarOpacityUnitDistance": 0.05,        # Volume's property, linked to ours
    "ScatteringAnisotropy": 0.3,
    "EnvironmentRadiance": [0.5, 0.6, 0.7],
    "Shade": 1,
    "MaximumBounces": 7,
    "StepSize": 0.004,
    "SamplesPerCell": 1.5,
    "ElementTest": 1,
    "MaxNewtonIterations": 6,
    "GridletSize": 4,
    "MajorantResolution": 16,
    "NumberOfThreads": 2,
    "Seed": 7,
    "InteractiveFrameTime": 0.25,
}


def parse_args():
    p = argparse.ArgumentParser(description=__doc__)
    p.add_argument("--plugin", required=True)
    p.add_argument("--temp-dir", required=True)
    p.add_argument("--pvpython", default="pvpython", help="runs phase 2")
    p.add_argument("--load", action="store_true", help="phase 2: load the state and compare")
    return p.parse_args()


def value(display, name):
    prop = display.SMProxy.GetProperty(name)
    if prop is None:
        raise RuntimeError("the representation has no property %s" % name)
    return [float(prop.GetElement(i)) for i in range(prop.GetNumberOfElements())]


def render_to(simple, view, display, png):
    simple.Render(view)
    simple.Render(view)  # SamplesPerRender 4, MaximumSamples 8: two renders
    display.UpdatePropertyInformation()
    samples = display.GetPropertyValue("AccumulatedSamples")
    simple.SaveScreenshot(png, view, ImageResolution=SIZE)
    return samples


def pixels(png):
    from vtkmodules.vtkIOImage import vtkPNGReader
    from vtkmodules.util.numpy_support import vtk_to_numpy
    r = vtkPNGReader()
    r.SetFileName(png)
    r.Update()
    return vtk_to_numpy(r.GetOutput().GetPointData().GetScalars()).astype(int)


def main():
    args = parse_args()
    os.makedirs(args.temp_dir, exist_ok=True)
    state = os.path.join(args.temp_dir, "PluginState.pvsm")
    saved = os.path.join(args.temp_dir, "PluginState.json")
    from paraview import simple
    simple._DisableFirstRenderCameraReset()
    simple.LoadPlugin(args.plugin, remote=False, ns=globals())

    if not args.load:
        path = os.path.join(DATA, "amrex-advection-amrcore3d", "plt00040")
        if not os.path.isdir(path):
            print("SKIP: the AMReX advection set is missing")
            return 125
        view = simple.CreateView("RenderView")
        view.ViewSize = SIZE
        view.OrientationAxesVisibility = 0
        r = simple.AMReXBoxLibGridReader(FileNames=[path])
        r.UpdatePipelineInformation()
        r.Level = 100
        r.CellArrayStatus = ["phi"]
        d = simple.Show(r, view)
        d.SetRepresentationType("Dual-Mesh Path Tracer")
        simple.ColorBy(d, ("CELLS", "phi"))
        d.RescaleTransferFunctionToDataRange(True, False)
        simple.GetOpacityTransferFunction("phi").Points = [1.0, 0.0, 0.5, 0.0, 2.0, 0.8, 0.5, 0.0]
        defaults = {name: value(d, name) for name in VALUES}
        same = [n for n, v in VALUES.items() if defaults[n] == [float(x) for x in
                                                                 (v if isinstance(v, list) else [v])]]
        if same:
            print("FAILED: test values equal the defaults for %s" % same)
            return 1
        for name, v in VALUES.items():
            d.SetPropertyWithName(name, v)
        view.CameraPosition = [1.4, -0.5, 0.9]
        view.CameraFocalPoint = [0.5, 0.5, 0.12]
        view.CameraViewUp = [0, 0, 1]
        samples = render_to(simple, view, d, os.path.join(args.temp_dir, "PluginStateSaved.png"))
        if samples != 8:
            print("FAILED: %d samples before saving, expected 8" % samples)
            return 1
        simple.SaveState(state)
        with open(saved, "w") as f:
            json.dump({name: value(d, name) for name in VALUES}, f)
        simple.Delete(d)
        simple.Delete(view)
        # Phase 2 in a fresh process.
        rc = subprocess.call([args.pvpython, os.path.abspath(__file__), "--plugin", args.plugin,
                              "--temp-dir", args.temp_dir, "--load"])
        print("PASSED" if rc == 0 else "FAILED")
        return rc

    simple.LoadState(state)
    with open(saved) as f:
        expected = json.load(f)
    view = simple.GetActiveViewOrCreate("RenderView")
    source = list(simple.GetSources().values())[0]
    d = simple.GetDisplayProperties(source, view)
    ok = True
    for name, v in expected.items():
        got = value(d, name)
        if len(got) != len(v) or any(abs(a - b) > 1e-9 * max(1.0, abs(b)) for a, b in zip(got, v)):
            print("FAILED: %s is %s after LoadState, saved %s" % (name, got, v))
            ok = False
        else:
            print("ok: %s = %s" % (name, got))
    samples = render_to(simple, view, d, os.path.join(args.temp_dir, "PluginStateLoaded.png"))
    a = pixels(os.path.join(args.temp_dir, "PluginStateSaved.png"))
    b = pixels(os.path.join(args.temp_dir, "PluginStateLoaded.png"))
    diff = abs(a - b).max() if a.shape == b.shape else None
    print("image after LoadState: %d samples, max pixel difference %s" % (samples, diff))
    if samples != 8 or diff is None or diff > 1:
        print("FAILED: the reloaded state renders a different image")
        ok = False
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
