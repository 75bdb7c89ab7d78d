"""Interactive renders of vtkAMRDualMeshVolumeMapper are cheap, still renders refine.

The render window's DesiredUpdateRate tells the mapper that the user interacts (VTK's
interactor sets 15 frames/s while a button is down, 0.0001 otherwise; ParaView's interactive
renders set 5). Checked on the AMReX advection set, path tracing, 300 x 300:
- an interactive Render() is flagged, uses a reduced resolution (reduction > 1 with a budget of a
  quarter of the measured full pass) and adds no samples (its times are printed, not asserted);
- its picture is the still picture at a lower resolution (mean luminance within 15 %);
- the still Render() after it restarts at full resolution: its image is bit-identical to the
  first still frame of a mapper that never saw an interactive render;
- InteractiveUpdateRate 0 never counts as interactive; InteractiveFrameTime 0 keeps the full
  resolution.
Run: TestVolumeMapperInteraction.py (AMRDM_TEST_DATA points at Testing/Data)."""
import os
import statistics
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "Support"))
from amrdm_testing import (ADVECTION, COOL_WARM, ErrorRecorder, aim,  # noqa: E402
                           amrex_reader, dual_mesh_volume, grab, mean_luminance, render_window,
                           rgb, volume_property)

SIZE = 300
INTERACTIVE = 15.0  # vtkRenderWindowInteractor's DesiredUpdateRate
STILL = 0.0001      # its StillUpdateRate


def scene():
    prop = volume_property(COOL_WARM, ((1.0, 0.0), (1.1, 0.2), (2.0, 0.9)), 0.02)
    mapper, volume = dual_mesh_volume(amrex_reader(), "phi", prop, Seed=11)
    window, ren = render_window((SIZE, SIZE), offscreen=True)
    ren.AddVolume(volume)
    aim(ren.GetActiveCamera(), (1.3, -0.6, 0.9), (0.5, 0.5, 0.12))
    ren.ResetCamera()
    return mapper, ren, window


def pixels(window):
    return rgb(grab(window), unit=1.0)


luminance = mean_luminance


def main():
    if not os.path.isdir(ADVECTION):
        print("SKIP: the AMReX advection set is missing")
        return 125
    ok = True

    def fail(message):
        nonlocal ok
        print("FAILED: " + message)
        ok = False

    # A reference: the first still frame of a mapper that never interacts.
    ref_mapper, ref_ren, ref_window = scene()
    ref_window.SetDesiredUpdateRate(STILL)
    for _ in range(3):  # the first builds the mesh; the cost of a full pass is measured after
        ref_window.Render()
    full_seconds = ref_mapper.GetLastRenderSeconds()
    ref_window.Render()
    for _ in range(8):  # the same camera moves as the interaction below, without rendering
        ref_ren.GetActiveCamera().Azimuth(1.25)
    ref_window.Render()  # 1 sample at the rotated view
    reference = pixels(ref_window)

    mapper, ren, window = scene()
    recorder = ErrorRecorder(mapper)
    # The budget is a quarter of the measured full pass, so that a reduction is needed on any
    # machine (timings are printed, never asserted: ctest holds no timing assertions).
    mapper.SetInteractiveFrameTime(0.25 * full_seconds)
    budget = mapper.GetInteractiveFrameTime()
    window.SetDesiredUpdateRate(STILL)
    for _ in range(3):
        window.Render()
    still_samples = mapper.GetNumberOfSamples()
    still_picture = luminance(pixels(window))
    if mapper.GetLastRenderInteractive() or still_samples != 3:
        fail("still renders: interactive=%d, samples %d (expected 0, 3)" %
             (mapper.GetLastRenderInteractive(), still_samples))

    window.SetDesiredUpdateRate(INTERACTIVE)
    times, reductions = [], []
    for _ in range(8):
        ren.GetActiveCamera().Azimuth(1.25)
        window.Render()
        times.append(mapper.GetLastRenderSeconds())
        reductions.append(mapper.GetInteractiveReduction())
        if not mapper.GetLastRenderInteractive():
            fail("a render at DesiredUpdateRate %g is not interactive" % INTERACTIVE)
        if mapper.GetNumberOfSamples() != 0:
            fail("an interactive render accumulated %d samples" % mapper.GetNumberOfSamples())
    interactive_picture = luminance(pixels(window))
    median = statistics.median(times[2:])
    print("full-resolution pass %.1f ms; interactive frames %s ms (median %.1f, budget %.0f), "
          "reductions %s" % (1e3 * full_seconds, ["%.1f" % (1e3 * t) for t in times],
                             1e3 * median, 1e3 * budget, reductions))
    if not max(reductions[2:]) > 1:
        fail("interactive frames kept the full resolution (reductions %s)" % reductions)
    if not abs(interactive_picture - still_picture) <= 0.15 * still_picture:
        fail("the interactive picture's mean %.2f differs from the still one's %.2f" %
             (interactive_picture, still_picture))

    # Mouse-up: the still render starts a fresh full-resolution accumulation.
    window.SetDesiredUpdateRate(STILL)
    window.Render()
    if mapper.GetLastRenderInteractive() or mapper.GetNumberOfSamples() != 1:
        fail("the still render after interaction: interactive=%d, samples %d (expected 0, 1)" %
             (mapper.GetLastRenderInteractive(), mapper.GetNumberOfSamples()))
    settled = pixels(window)
    if settled.shape != reference.shape or abs(settled - reference).max() != 0:
        fail("the first still frame after interaction differs from a mapper that never "
             "interacted (max difference %g)" % abs(settled - reference).max())

    # The switches.
    mapper.SetInteractiveUpdateRate(0.0)
    window.SetDesiredUpdateRate(INTERACTIVE)
    window.Render()
    if mapper.GetLastRenderInteractive():
        fail("InteractiveUpdateRate 0 still counts renders as interactive")
    mapper.SetInteractiveUpdateRate(1.0)
    mapper.SetInteractiveFrameTime(0.0)
    ren.GetActiveCamera().Azimuth(1.0)
    window.Render()
    if not mapper.GetLastRenderInteractive() or mapper.GetInteractiveReduction() != 1:
        fail("InteractiveFrameTime 0: interactive=%d, reduction %d (expected 1, 1)" %
             (mapper.GetLastRenderInteractive(), mapper.GetInteractiveReduction()))
    if recorder.errors or recorder.warnings:
        fail("messages: %s" % (recorder.errors + recorder.warnings))
    print("PASSED" if ok else "FAILED")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
