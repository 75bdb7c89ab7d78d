"""The mapper's exported accumulation key follows its own reset rule.

vtkAMRDualMeshVolumeMapper::GetAccumulationKey(renderer, volume) is what a process that does not
render (ParaView's client of a render server) asks to estimate the samples the server has. For
each change of the scene, the key must change exactly when the next Render() restarts the
accumulation (GetNumberOfSamples() back to SamplesPerRender): the camera, a light added, a
light's intensity, a clipping plane moved, the volume's matrix, the property, a mapper parameter
(the client's former copy of the rule missed lights, clipping planes and the matrix); and it
must stay the same for a render that changes nothing.
Run: TestVolumeMapperAccumulationKey.py (AMRDM_TEST_DATA points at Testing/Data)."""
import os
import sys

from vtkmodules.vtkCommonDataModel import vtkPlane
from vtkmodules.vtkRenderingCore import vtkLight

from amrdualmesh import vtkAMRDualMeshVolumeMapper

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "Support"))
from amrdm_testing import (amrex_reader, dual_mesh_volume, render_window,  # noqa: E402
                           volume_property)

prop = volume_property(((1.0, 0.2, 0.3, 1.0), (2.0, 1.0, 0.6, 0.1)), ((1.0, 0.0), (2.0, 0.9)),
                       0.05)
mapper, volume = dual_mesh_volume(amrex_reader(), "phi", prop,
                                  Integrator=vtkAMRDualMeshVolumeMapper.RAY_MARCH)
window, ren = render_window((48, 40), offscreen=True)
ren.AddVolume(volume)
ren.ResetCamera()
light = vtkLight()
plane = vtkPlane()
plane.SetOrigin(volume.GetCenter())
plane.SetNormal(1.0, 0.0, 0.0)
mapper.AddClippingPlane(plane)

failures = []
window.Render()
window.Render()
changes = [
    ("nothing", lambda: None, False),
    ("camera", lambda: ren.GetActiveCamera().Azimuth(5.0), True),
    ("nothing again", lambda: None, False),
    ("a light added", lambda: ren.AddLight(light), True),
    ("the light's intensity", lambda: light.SetIntensity(0.5), True),
    ("the clipping plane", lambda: plane.SetNormal(1.0, 0.3, 0.0), True),
    ("the volume's matrix", lambda: volume.SetScale(1.0, 1.2, 1.0), True),
    ("the property", lambda: prop.SetScalarOpacityUnitDistance(0.07), True),
    ("a mapper parameter", lambda: mapper.SetSeed(4), True),
    ("the window size", lambda: window.SetSize(50, 40), True),
]
for name, change, expected in changes:
    before_key = mapper.GetAccumulationKey(ren, volume)
    before_samples = mapper.GetNumberOfSamples()
    change()
    key = mapper.GetAccumulationKey(ren, volume)
    window.Render()
    samples = mapper.GetNumberOfSamples()
    reset = samples <= before_samples
    print("%-22s key changed %-5s reset %-5s (samples %d -> %d)"
          % (name, key != before_key, reset, before_samples, samples))
    if before_samples < 1:
        failures.append("%s: nothing accumulated before the change" % name)
    if reset != expected:
        failures.append("%s: the render %s the accumulation, expected %s"
                        % (name, "restarted" if reset else "continued",
                           "a restart" if expected else "none"))
    if (key != before_key) != expected:
        failures.append("%s: the key %s, expected %s"
                        % (name, "changed" if key != before_key else "stayed",
                           "a change" if expected else "none"))
if mapper.GetAccumulationKey(None, volume) != 0:
    failures.append("a key without a renderer: expected 0")
for f in failures:
    print("FAIL:", f)
sys.exit(1 if failures else 0)
