"""Every light of VTK's light kit lights the volume, silently.

vtkLightKit (ParaView's default lighting) puts five lights into the renderer. The mapper must
use all five without a warning: single scattering with no environment light is linear in the
lights, so the image mean with the whole kit equals the sum of the means with each light alone
(within Monte Carlo noise), and each light adds something. A renderer with more lights than the
kernel has slots (9 > 8) gets one warning that says how many are dropped.
Run: TestVolumeMapperLights.py (AMRDM_TEST_DATA points at Testing/Data)."""
import os
import sys

from vtkmodules.vtkRenderingCore import vtkLight, vtkLightKit

from amrdualmesh import vtkAMRDualMeshVolumeMapper

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "Support"))
from amrdm_testing import (ADVECTION, ErrorRecorder, aim, amrex_reader,  # noqa: E402
                           dual_mesh_volume, grab, mean_luminance, render_window, rgb,
                           volume_property)

SAMPLES = 32
SIZE = 96


def scene():
    white = ((1.0, 1.0, 1.0, 1.0), (2.0, 1.0, 1.0, 1.0))
    prop = volume_property(white, ((1.0, 0.0), (1.1, 0.2), (2.0, 0.9)), 0.05)
    mapper, volume = dual_mesh_volume(
        amrex_reader(), "phi", prop, Integrator=vtkAMRDualMeshVolumeMapper.SINGLE_SCATTER,
        EnvironmentRadiance=(0.0, 0.0, 0.0),  # lights only: the image is linear in them
        Seed=5)
    window, ren = render_window((SIZE, SIZE), offscreen=True)
    ren.AddVolume(volume)
    aim(ren.GetActiveCamera(), (1.3, -0.6, 0.9), (0.5, 0.5, 0.12))
    ren.ResetCamera()
    return mapper, ren, window


def render(mapper, window):
    window.Render()  # the first render resets the accumulation (the lights changed)
    reached = mapper.RenderUntil(window, SAMPLES)
    assert reached == SAMPLES, reached
    return mean_luminance(rgb(grab(window), unit=1.0))  # what the last Render() drew


def main():
    if not os.path.isdir(ADVECTION):
        print("SKIP: the AMReX advection set is missing")
        return 125
    mapper, ren, window = scene()
    recorder = ErrorRecorder(mapper)
    kit = vtkLightKit()
    kit.AddLightsToRenderer(ren)
    lights = [ren.GetLights().GetItemAsObject(i) for i in range(ren.GetLights().GetNumberOfItems())]
    ok = True
    if len(lights) != 5:
        print("FAILED: vtkLightKit gave %d lights, expected 5" % len(lights))
        return 1

    whole = render(mapper, window)
    alone = []
    for i, light in enumerate(lights):
        for j, other in enumerate(lights):
            other.SetSwitch(i == j)
        alone.append(render(mapper, window))
    for light in lights:
        light.SetSwitch(True)
    total = sum(alone)
    print("whole kit: %.3f; each light alone: %s; sum %.3f" %
          (whole, ", ".join("%.3f" % a for a in alone), total))
    if recorder.warnings or recorder.errors:
        print("FAILED: the light kit produced messages: %s" % (recorder.warnings + recorder.errors))
        ok = False
    if not abs(whole - total) <= 0.03 * total:
        print("FAILED: the kit's image mean %.3f is not the sum of its lights' %.3f" % (whole, total))
        ok = False
    for i, a in enumerate(alone):
        if not a > 0.02 * total:
            print("FAILED: light %d of the kit adds nothing (%.3f of %.3f)" % (i, a, total))
            ok = False

    # More lights than the kernel's eight slots: one warning with the counts.
    for k in range(4):
        extra = vtkLight()
        extra.SetLightTypeToSceneLight()
        extra.SetPosition(1.0, float(k), 1.0)
        extra.SetFocalPoint(0.5, 0.5, 0.1)
        extra.SetIntensity(0.1)
        ren.AddLight(extra)
    window.Render()
    window.Render()
    expected = "9 lights switched on; the first 8 are used, the other 1 are ignored"
    if len(recorder.warnings) != 1 or expected not in recorder.warnings[0]:
        print("FAILED: with 9 lights expected one warning containing '%s', got %s" %
              (expected, recorder.warnings))
        ok = False
    print("PASSED" if ok else "FAILED")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
