"""The vtkVolume's matrix (issue 13): Position, Orientation, Scale and Origin, the Translation,
Orientation, Scale and Origin of ParaView's Display panel. The AMReX advection set (phi),
RAY_MARCH, no shading (no lights involved), 160 x 120, 8 samples. For each matrix M (a
translation; a rotation about an off-centre origin; a uniform scale of 1.7 with a translation; a
rotation, scale and translation together; a parallel camera with all of them), the transformed
volume seen by camera C must equal the untransformed volume seen by M^-1 C (eye, focal point and
view up moved by the inverse; a parallel scale divided by the scale): the rays then agree in the
data frame, where the mapper samples (a scaled volume keeps its optical depth: extinction is
per unit of the data's own length, as a scaled prop's contents scale with it). Tolerances: mean
|difference| per channel < 0.01, 99.5th percentile < 0.1 (jitter noise); the transformed
render must also differ from the untransformed one seen by C (mean > 0.02), so an ignored
matrix fails. Writes TestVolumeTransform-*.png to the folder given with -T."""
import os
import sys

import numpy as np
from vtkmodules.vtkCommonMath import vtkMatrix4x4

from amrdualmesh import vtkAMRDualMeshVolumeMapper

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "Support"))
from amrdm_testing import (COOL_WARM, ErrorRecorder, aim, dual_mesh_volume, grab,  # noqa: E402
                           read_amrex, render_window, rgb, temp_dir, volume_property, write_png)

SAMPLES = 8
W, H = 160, 120
MEAN_MAX, P995_MAX, MOVED_MIN = 0.01, 0.1, 0.02
TEMP = temp_dir()

amr = read_amrex()
prop = volume_property(COOL_WARM, ((1.0, 0.0), (1.02, 0.01), (1.3, 0.3), (2.0, 0.9)), 0.02,
                       shade=False)

EYE, FOCAL, UP = (0.98, -0.24, 0.82), (0.55, 0.5, 0.12), (0.0, 0.0, 1.0)


def render(transform, eye, focal, up, parallel_scale=None):
    window, ren = render_window((W, H), (0.1, 0.1, 0.1), multisamples=0)
    mapper, volume = dual_mesh_volume(amr, "phi", prop,
                                      Integrator=vtkAMRDualMeshVolumeMapper.RAY_MARCH,
                                      SamplesPerRender=2, StepSize=0.01)
    errors = ErrorRecorder(mapper)
    if transform:
        transform(volume)
    ren.AddVolume(volume)
    cam = aim(ren.GetActiveCamera(), eye, focal, up)
    if parallel_scale:
        cam.ParallelProjectionOn()
        cam.SetParallelScale(parallel_scale)
    ren.ResetCameraClippingRange()
    mapper.RenderUntil(window, SAMPLES)
    image = grab(window)
    return image, rgb(image), volume, errors


def inverse_point(m, p):
    v = m.MultiplyPoint((p[0], p[1], p[2], 1.0))
    return [v[i] / v[3] for i in range(3)]


def inverse_vector(m, d):
    v = m.MultiplyPoint((d[0], d[1], d[2], 0.0))
    n = np.linalg.norm(v[:3])
    return [v[i] / n for i in range(3)]


cases = [
    ("translate", lambda v: v.SetPosition(0.2, -0.1, 0.15), 1.0, None),
    ("rotate", lambda v: (v.SetOrigin(0.5, 0.5, 0.1), v.SetOrientation(20.0, -35.0, 50.0)),
     1.0, None),
    ("scale", lambda v: (v.SetScale(1.7), v.SetPosition(-0.4, -0.3, -0.05)), 1.7, None),
    ("all", lambda v: (v.SetOrigin(0.3, 0.6, 0.0), v.SetOrientation(-15.0, 10.0, 80.0),
                       v.SetScale(0.8), v.SetPosition(0.1, 0.2, -0.1)), 0.8, None),
    ("all-parallel", lambda v: (v.SetOrigin(0.3, 0.6, 0.0), v.SetOrientation(-15.0, 10.0, 80.0),
                                v.SetScale(0.8), v.SetPosition(0.1, 0.2, -0.1)), 0.8, 0.4),
]
failures = []
_, plainImage, _, _ = render(None, EYE, FOCAL, UP)
_, plainParallel, _, _ = render(None, EYE, FOCAL, UP, 0.4)
for name, transform, scale, parallel_scale in cases:
    image, moved, volume, errors = render(transform, EYE, FOCAL, UP, parallel_scale)
    inverse = vtkMatrix4x4()
    vtkMatrix4x4.Invert(volume.GetMatrix(), inverse)
    refImage, ref, _, _ = render(None, inverse_point(inverse, EYE), inverse_point(inverse, FOCAL),
                                 inverse_vector(inverse, UP),
                                 parallel_scale / scale if parallel_scale else None)
    if TEMP:
        for img, suffix in ((image, ""), (refImage, "-camera")):
            write_png(img, os.path.join(TEMP, f"TestVolumeTransform-{name}{suffix}.png"))
    d = np.abs(moved - ref).ravel()
    mean, p995 = d.mean(), np.percentile(d, 99.5)
    against_plain = np.abs(moved - (plainParallel if parallel_scale else plainImage)).mean()
    ok = (mean < MEAN_MAX and p995 < P995_MAX and against_plain >= MOVED_MIN and
          not errors.errors)
    print(f"{name}: transformed vs moved camera mean |difference| {mean:.4f} (< {MEAN_MAX}), "
          f"99.5th percentile {p995:.4f} (< {P995_MAX}); vs untransformed {against_plain:.4f} "
          f"(>= {MOVED_MIN}) {'ok' if ok else 'FAIL'} {errors.errors or ''}")
    if not ok:
        failures.append(name)

if failures:
    print("FAIL:", ", ".join(failures))
    sys.exit(1)
print("PASS")
