"""VTK's abort check stops a vtkAMRDualMeshVolumeMapper pass in the middle.

An AbortCheckEvent observer on the render window plays the interactor (which sets AbortRender
when an event is pending). AMReX advection set, path tracing, 400 x 400, 8 samples per render:
- without an abort request, renders complete (LastRenderAborted false, 8 more samples each);
- with it, the render stops between tiles: LastRenderAborted is true, the sample count does not
  grow, and the picture is still the accumulated mean (luminance within 3 % of the one before,
  no black tiles: finished tiles keep exact samples, the others keep their old mean);
- the next render without the request continues the accumulation (8 more samples).
The observer is called from the mapper's poll while its pass runs; the render times are printed,
never asserted. Run: TestVolumeMapperAbort.py (AMRDM_TEST_DATA points at Testing/Data)."""
import os
import sys
import time

from vtkmodules.vtkCommonCore import vtkCommand

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "Support"))
from amrdm_testing import TEST_DATA, ErrorRecorder  # noqa: E402
from TestVolumeMapperInteraction import luminance, pixels, scene  # noqa: E402

SAMPLES = 8


def main():
    if not os.path.isdir(os.path.join(TEST_DATA, "amrex-advection-amrcore3d")):
        print("SKIP: the AMReX advection set is missing")
        return 125
    mapper, ren, window = scene()
    recorder = ErrorRecorder(mapper)
    window.SetSize(400, 400)
    mapper.SetSamplesPerRender(SAMPLES)
    state = {"abort": False, "calls": 0}

    def abort_check(obj, event):
        state["calls"] += 1
        if state["abort"]:
            obj.SetAbortRender(1)

    window.AddObserver(vtkCommand.AbortCheckEvent, abort_check)
    failures = []

    def render(abort):
        state["abort"], state["calls"] = abort, 0
        start = time.perf_counter()
        window.Render()
        seconds = time.perf_counter() - start
        print("abort requested %-5s: aborted %d, samples %d, %.3f s, %d abort checks" %
              (abort, mapper.GetLastRenderAborted(), mapper.GetNumberOfSamples(), seconds,
               state["calls"]))

    render(False)  # builds the mesh
    render(False)
    if mapper.GetLastRenderAborted() or mapper.GetNumberOfSamples() != 2 * SAMPLES:
        failures.append("renders without an abort request must complete (%d samples)" %
                        mapper.GetNumberOfSamples())
    before = pixels(window)

    render(True)
    if not mapper.GetLastRenderAborted():
        failures.append("the render with an abort request was not aborted")
    if state["calls"] == 0:
        failures.append("the abort check was never called")
    if mapper.GetNumberOfSamples() != 2 * SAMPLES:
        failures.append("an aborted render counted its pass (%d samples)" %
                        mapper.GetNumberOfSamples())
    after = pixels(window)
    lb, la = luminance(before), luminance(after)
    print("mean luminance before %.2f, after the aborted render %.2f" % (lb, la))
    if abs(la - lb) > 0.03 * lb:
        failures.append("the aborted render's picture is not the accumulated mean (%.2f vs %.2f)"
                        % (la, lb))
    lit_before = (before.sum(axis=1) > 0).sum()
    lit_after = (after.sum(axis=1) > 0).sum()
    if lit_after < 0.99 * lit_before:
        failures.append("pixels went dark after the abort (%d lit, %d before)" %
                        (lit_after, lit_before))

    render(False)
    if mapper.GetLastRenderAborted() or mapper.GetNumberOfSamples() != 3 * SAMPLES:
        failures.append("the render after the abort did not continue the accumulation (%d)" %
                        mapper.GetNumberOfSamples())
    if recorder.errors:
        failures.append("errors: %s" % recorder.errors)
    for f in failures:
        print("FAILED: " + f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
