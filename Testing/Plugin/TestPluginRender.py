"""ParaView plugin test: the "Dual-Mesh Path Tracer" representation on real AMR data.

Loads the plugin, opens the Enzo and AMReX test sets with ParaView's own readers (all levels,
one cell array), shows each with the representation, sets a colour map and an opacity
function, renders a fixed number of samples and compares SaveScreenshot() with a baseline
(vtkTesting::RegressionTest, threshold 0.05).

  pvpython TestPluginRender.py --plugin AMRDualMeshPlugin.so --baseline-dir DIR --temp-dir DIR
      [--client-server [--pvserver PATH]]

--client-server starts `pvserver` on a free localhost port, connects to it, loads the plugin on
both sides and renders remotely (the server draws, the client receives the image); pvserver is
stopped at the end whatever happens. Run under an X server (ctest runs under `xvfb-run -a`).
"""
import argparse
import os
import socket
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
DATA = os.path.join(os.path.dirname(HERE), "Data")
SAMPLES = 32  # samples per pixel of every baseline
SIZE = [320, 240]


def parse_args():
    p = argparse.ArgumentParser(description=__doc__)
    p.add_argument("--plugin", required=True, help="path of AMRDualMeshPlugin.so")
    p.add_argument("--baseline-dir", required=True)
    p.add_argument("--temp-dir", required=True)
    p.add_argument("--threshold", type=float, default=0.05)
    p.add_argument("--client-server", action="store_true")
    p.add_argument("--pvserver", default="pvserver")
    p.add_argument("--timeout", type=float, default=60.0, help="seconds to wait for pvserver")
    return p.parse_args()


def free_port():
    with socket.socket(socket.AF_INET, socket.SOCK_STREAM) as s:
        s.bind(("localhost", 0))
        return s.getsockname()[1]


def start_pvserver(exe, timeout, log_path):
    """Starts pvserver on a free port; returns (process, port) once it accepts connections."""
    port = free_port()
    log = open(log_path, "w")
    proc = subprocess.Popen([exe, "--server-port=%d" % port], stdout=log,
                            stderr=subprocess.STDOUT)
    deadline = time.time() + timeout
    while time.time() < deadline:
        if proc.poll() is not None:
            raise RuntimeError("pvserver exited with %d (log: %s)" % (proc.returncode, log_path))
        with open(log_path) as f:
            if "Accepting connection" in f.read():
                return proc, port
        time.sleep(0.2)
    proc.kill()
    raise RuntimeError("pvserver did not accept connections within %gs" % timeout)


def compare(png, baseline, temp_dir, threshold):
    from vtkmodules.vtkTestingRendering import vtkTesting
    t = vtkTesting()
    for a in ("-T", temp_dir, "-V", baseline):
        t.AddArgument(a)
    ok = t.RegressionTest(png, threshold) == vtkTesting.PASSED
    print("%s: %s against %s" % ("PASSED" if ok else "FAILED", png, baseline))
    return ok


def show(simple, reader, array, view, lut_range, opacity_points, camera):
    """Shows `reader` with the plugin's representation, coloured by the cell array `array`."""
    display = simple.Show(reader, view)
    display.SetRepresentationType("Dual-Mesh Path Tracer")
    simple.ColorBy(display, ("CELLS", array))
    lut = simple.GetColorTransferFunction(array)
    lut.ApplyPreset("Cool to Warm", True)
    lut.RescaleTransferFunction(*lut_range)
    pwf = simple.GetOpacityTransferFunction(array)
    pwf.Points = opacity_points
    display.SetScalarBarVisibility(view, True)
    display.Seed = 7
    display.SamplesPerRender = SAMPLES
    display.MaximumSamples = SAMPLES
    view.CameraPosition, view.CameraFocalPoint, view.CameraViewUp = camera
    view.CameraParallelProjection = 0
    simple.Render(view)
    display.UpdatePropertyInformation()
    samples = display.SMProxy.GetProperty("AccumulatedSamples").GetElement(0)
    return display, samples


def main():
    args = parse_args()
    os.makedirs(args.temp_dir, exist_ok=True)
    server = None
    suffix = "ClientServer" if args.client_server else ""
    try:
        from paraview import simple
        simple._DisableFirstRenderCameraReset()  # the cameras below are the baselines' cameras
        if args.client_server:
            server, port = start_pvserver(args.pvserver, args.timeout,
                                          os.path.join(args.temp_dir, "pvserver%s.log" % suffix))
            simple.Connect("localhost", port)
        simple.LoadPlugin(args.plugin, remote=False, ns=globals())
        if args.client_server:
            simple.LoadPlugin(args.plugin, remote=True, ns=globals())

        ok = True
        cases = [
            ("PluginEnzo", "Density",
             lambda: simple.EnzoReader(FileNames=[os.path.join(
                 DATA, "enzo-moving7_DD0010", "moving7_0010.hierarchy")]),
             # Density spans 0.1 .. 2.6e5 (code units); the refined clump sits near (0.75, 0.75,
             # 0.75): show it and its envelope.
             (0.1, 100.0), [0.1, 0.0, 0.5, 0.0, 10.0, 0.02, 0.5, 0.0, 100.0, 1.0, 0.5, 0.0],
             ([0.975, 0.885, 1.005], [0.72, 0.72, 0.72], [0.0, 1.0, 0.0])),
            ("PluginAMReX", "phi",
             lambda: simple.AMReXBoxLibGridReader(FileNames=[os.path.join(
                 DATA, "amrex-advection-amrcore3d", "plt00040")]),
             (1.0, 2.0), [1.0, 0.0, 0.5, 0.0, 1.3, 0.05, 0.5, 0.0, 2.0, 1.0, 0.5, 0.0],
             ([0.65, -0.5, 1.1], [0.65, 0.6, 0.125], [0.0, 0.0, 1.0])),
        ]
        for name, array, make_reader, lut_range, points, camera in cases:
            reader = make_reader()
            reader.UpdatePipelineInformation()
            reader.Level = 100  # all levels (the readers load level 0 only by default)
            reader.CellArrayStatus = [array]
            reader.UpdatePipeline()
            view = simple.CreateView("RenderView")
            view.ViewSize = SIZE
            view.OrientationAxesVisibility = 0
            view.Background = [0.1, 0.1, 0.15]
            # ParaView 5.11 uses the palette's background unless told otherwise.
            if "UseColorPaletteForBackground" in view.ListProperties():
                view.UseColorPaletteForBackground = 0
            display, samples = show(simple, reader, array, view, lut_range, points, camera)
            print("%s: %d samples per pixel" % (name, samples))
            if not args.client_server and samples != SAMPLES:
                print("FAILED: expected %d samples per pixel, got %d" % (SAMPLES, samples))
                ok = False
            png = os.path.join(args.temp_dir, name + suffix + ".png")
            simple.SaveScreenshot(png, view, ImageResolution=SIZE)
            ok = compare(png, os.path.join(args.baseline_dir, name + ".png"), args.temp_dir,
                         args.threshold) and ok
            simple.Delete(display)
            simple.Delete(view)  # before exit: a live view at exit gives GLXBadContext
            simple.Delete(reader)
        if args.client_server:
            simple.Disconnect()
        return 0 if ok else 1
    finally:
        if server is not None:
            server.kill()
            server.wait(timeout=30)


if __name__ == "__main__":
    sys.exit(main())
