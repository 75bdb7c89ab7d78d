"""Translucent geometry with the volume (issue 13), plain VTK with depth peeling on (as ParaView
has it): the AMReX advection set (phi), RAY_MARCH, and a sphere of opacity 0.4 partly inside
the slab, 160 x 120, no multisampling. Renders (A) the volume alone, (B) the volume and the
translucent sphere, (C) the sphere alone, all with the renderer's depth peeling on.
Asserts: outside the sphere's pixels (where C differs from the background, grown by 1 pixel),
A and B agree (mean |difference| per channel < 0.01, 99.5th percentile < 0.1: jitter noise);
inside them B differs from A (the sphere is visible, mean > 0.02); depth peeling was used; and
no OpenGL error and no VTK error is reported (vtkStringOutputWindow). As with VTK's own volume
mappers without UseDepthPeelingForVolumes, the volume is composited after the translucent pass,
over it (only opaque depth clips the rays). Note: with multisampling on, this Mesa's
vtkDualDepthPeelingPass itself reports glBindFramebuffer errors and drops translucent
geometry, with or without a volume in the scene; that is VTK's, so the test runs without MSAA.
Writes TestTranslucentGeometry-{A,B,C}.png to the folder given with -T."""
import os
import sys

import numpy as np
from vtkmodules.vtkCommonCore import vtkOutputWindow, vtkStringOutputWindow

from amrdualmesh import vtkAMRDualMeshVolumeMapper

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "Support"))
from amrdm_testing import (COOL_WARM, aim, dual_mesh_volume, grab, read_amrex,  # noqa: E402
                           render_window, rgb, sphere_actor, temp_dir, volume_property,
                           write_png)

W, H, SAMPLES = 160, 120, 4
MEAN_MAX, P995_MAX, VISIBLE_MIN = 0.01, 0.1, 0.02
TEMP = temp_dir()
log = vtkStringOutputWindow()
vtkOutputWindow.SetInstance(log)

amr = read_amrex()
prop = volume_property((COOL_WARM[0], COOL_WARM[2]), ((1.0, 0.0), (1.3, 0.3), (2.0, 0.9)), 0.02)


def render(with_volume, with_sphere, name):
    window, ren = render_window((W, H), (0.1, 0.1, 0.1), multisamples=0)
    window.SetAlphaBitPlanes(1)
    ren.SetUseDepthPeeling(1)
    if with_volume:
        mapper, volume = dual_mesh_volume(amr, "phi", prop,
                                          Integrator=vtkAMRDualMeshVolumeMapper.RAY_MARCH,
                                          StepSize=0.01, SamplesPerRender=2)
        ren.AddVolume(volume)
    if with_sphere:
        actor = sphere_actor((0.64, 0.52, 0.25), 0.15, (0.2, 0.9, 0.2))
        actor.GetProperty().SetOpacity(0.4)
        ren.AddActor(actor)
    aim(ren.GetActiveCamera(), (1.2, -0.6, 1.0), (0.5, 0.5, 0.12)).SetClippingRange(0.3, 3.0)
    if with_volume:
        mapper.RenderUntil(window, SAMPLES)
    else:
        window.Render()
    image = grab(window)
    if TEMP:
        write_png(image, os.path.join(TEMP, f"TestTranslucentGeometry-{name}.png"))
    samples = mapper.GetNumberOfSamples() if with_volume else SAMPLES
    return rgb(image), ren.GetLastRenderingUsedDepthPeeling(), samples


a, _, samplesA = render(True, False, "A")
b, peeled, samplesB = render(True, True, "B")
c, _, _ = render(False, True, "C")
mask = np.abs(c - 0.1).max(axis=2) > 2.0 / 255.0
grown = mask.copy()
grown[1:, :] |= mask[:-1, :]
grown[:-1, :] |= mask[1:, :]
grown[:, 1:] |= mask[:, :-1]
grown[:, :-1] |= mask[:, 1:]
outside = np.abs(a - b)[~grown].ravel()
inside = np.abs(a - b)[mask].mean() if mask.any() else 0.0
mean, p995 = outside.mean(), np.percentile(outside, 99.5)
messages = log.GetOutput()
glErrors = "OpenGL error" in messages or "Invalid operation" in messages
vtkErrors = "ERROR" in messages
print(f"sphere covers {mask.mean():.3f} of the image; outside it volume-only vs with sphere: mean "
      f"|difference| {mean:.4f} (< {MEAN_MAX}), 99.5th percentile {p995:.4f} (< {P995_MAX}); "
      f"inside: {inside:.4f} (> {VISIBLE_MIN}); depth peeling used: {peeled}; samples "
      f"{samplesA}, {samplesB}; OpenGL errors: {glErrors}; VTK errors: {vtkErrors}")
ok = (mask.mean() > 0.02 and mean < MEAN_MAX and p995 < P995_MAX and inside > VISIBLE_MIN and
      peeled and samplesA == SAMPLES and samplesB == SAMPLES and not glErrors and not vtkErrors)
if not ok and messages:
    print(messages[:2000])
print("PASS" if ok else "FAIL")
sys.exit(0 if ok else 1)
