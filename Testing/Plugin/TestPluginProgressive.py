"""ParaView plugin test: progressive refinement while the view is idle, restart on change.

With an interactor (as in the GUI), one Render() adds SamplesPerRender samples and the
representation's idle timer keeps rendering until MaximumSamples; a camera change restarts
the accumulation, which then refines again. Without processing interactor events nothing
refines on its own (scripts stay deterministic).

  pvpython TestPluginProgressive.py --plugin AMRDualMeshPlugin.so
"""
import argparse
import os
import sys
import time

from paraview import simple

HERE = os.path.dirname(os.path.abspath(__file__))
DATA = os.path.join(os.path.dirname(HERE), "Data")
MAXIMUM = 6

parser = argparse.ArgumentParser(description=__doc__)
parser.add_argument("--plugin", required=True)
args = parser.parse_args()

simple.LoadPlugin(args.plugin, remote=False, ns=globals())
reader = simple.AMReXBoxLibGridReader(
    FileNames=[os.path.join(DATA, "amrex-advection-amrcore3d", "plt00040")])
reader.UpdatePipelineInformation()
reader.Level = 100
reader.CellArrayStatus = ["phi"]
view = simple.CreateView("RenderView")
view.ViewSize = [160, 120]
display = simple.Show(reader, view)
display.SetRepresentationType("Dual-Mesh Path Tracer")
simple.ColorBy(display, ("CELLS", "phi"))
display.SamplesPerRender = 1
display.MaximumSamples = MAXIMUM
view.SMProxy.MakeRenderWindowInteractor(True)  # what the GUI has: an interactor + its timers
interactor = view.GetInteractor()
interactor.Initialize()


def samples():
    display.UpdatePropertyInformation()
    return display.SMProxy.GetProperty("AccumulatedSamples").GetElement(0)


def idle(seconds):
    """Lets the interactor's timers run, as the GUI's event loop does, until refined."""
    end = time.time() + seconds
    while time.time() < end and samples() < MAXIMUM:
        interactor.ProcessEvents()
        time.sleep(0.01)
    return samples()


failures = []
simple.Render(view)
first = samples()
if first != 1:
    failures.append("one render should give 1 sample per pixel, got %d" % first)
time.sleep(0.3)
if samples() != first:
    failures.append("refined without the event loop (%d -> %d samples)" % (first, samples()))
refined = idle(60)
print("after idling: %d samples per pixel" % refined)
if refined != MAXIMUM:
    failures.append("idle refinement reached %d of %d samples" % (refined, MAXIMUM))
view.CameraPosition = [0.5, -1.0, 1.0]  # an interaction: the accumulation restarts
simple.Render(view)
restarted = samples()
print("after a camera change: %d samples per pixel" % restarted)
if restarted != 1:
    failures.append("a camera change should restart at 1 sample, got %d" % restarted)
refined = idle(60)
if refined != MAXIMUM:
    failures.append("refinement after the change reached %d of %d samples" % (refined, MAXIMUM))
display.RefineWhileIdle = 0
view.CameraPosition = [0.5, -1.2, 1.0]
simple.Render(view)
interactor.ProcessEvents()
time.sleep(0.3)
interactor.ProcessEvents()
if samples() != 1:
    failures.append("RefineWhileIdle=0 still refined (%d samples)" % samples())

simple.Delete(display)
simple.Delete(view)  # before exit: a live view at exit gives GLXBadContext
for f in failures:
    print("FAILED: " + f)
print("PASSED" if not failures else "FAILED")
sys.exit(1 if failures else 0)
