"""amrdm-render --blend, --iso, --slice (issue 34): option errors in one line naming the option,
what each mode needs, ray marching chosen for a non-composite mode and said on stderr, the path
tracer's limitation said when --integrator names it, and images: the isosurface covers part of the
advection set's view, the slice through its middle covers the slab's cut where the opacity
function shows it, MIP differs from composite. Argument 1: the amrdm-render executable."""
import os
import subprocess
import sys
import tempfile

from vtkmodules.vtkIOImage import vtkPNGReader
from vtkmodules.util.numpy_support import vtk_to_numpy

APP = sys.argv[1]
DATA = os.environ.get("AMRDM_TEST_DATA", os.path.join(os.path.dirname(__file__), "..", "Data"))
ADVECTION = os.path.join(DATA, "amrex-advection-amrcore3d", "plt00040")
SMALL = ["--size", "64", "64", "--spp", "1", "--threads", "2"]
failures = []


def check(condition, message):
    print(("ok:   " if condition else "FAIL: ") + message)
    if not condition:
        failures.append(message)


def run(*args):
    p = subprocess.run([APP] + list(args), stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                       universal_newlines=True, timeout=300)
    return p.returncode, p.stdout, p.stderr


def read_image(path):
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    return vtk_to_numpy(image.GetPointData().GetScalars()).astype(float)


tmp = tempfile.mkdtemp(prefix="amrdm-blend-")

# 1. Option errors: one line naming the option; what a mode needs.
for args, fragment in ((["--blend", "xx"], "--blend: unknown 'xx'; expected one of composite|mip|"),
                       (["--iso", "1,a"], "--iso: "),
                       (["--iso", ",".join(["1"] * 9)], "--iso: more than 8 values"),
                       (["--slice", "0", "0", "0", "0", "0", "0"], "--slice: the normal (NX NY NZ) is zero"),
                       ([ADVECTION, "--blend", "iso"], "--blend iso needs --iso V[,V...]"),
                       ([ADVECTION, "--blend", "slice"], "--blend slice needs --slice")):
    rc, out, err = run(*args)
    lines = err.strip().splitlines()
    check(rc == 1 and len(lines) == 1 and fragment in lines[0],
          "%s -> exit %d, %d line(s): %s" % (" ".join(args), rc, len(lines), lines[:2]))


def image(name, *extra):
    path = os.path.join(tmp, name + ".png")
    rc, _, err = run(ADVECTION, "--array", "phi", *SMALL, "-o", path, *extra)
    return rc, err, (read_image(path) if rc == 0 else None)


# 2. Isosurface: ray marching is chosen and said; the surface covers part of the view.
rc, err, iso = image("iso", "--blend", "iso", "--iso", "1.5", "--shade")
lit = (iso[:, :3].max(axis=1) > 10).mean() if iso is not None else 0.0
check(rc == 0 and "--blend iso: ray marching draws it" in err and 0.02 < lit < 0.98,
      "--blend iso --iso 1.5: exit %d, covered fraction %.3f, said: %s"
      % (rc, lit, [l for l in err.splitlines() if "blend" in l]))

# 3. Slice through the middle of the slab ([0, 1]^2 x [0, 0.25]), seen from above: with an opacity
#    ramp that leaves the bulk visible it covers the slab's cut; with the default map (the bulk
#    transparent) only the blob shows: colour times opacity, VTK's meaning.
view = ["--slice", "0.5", "0.5", "0.125", "0", "0", "1", "--eye", "0.5", "0.5", "3",
        "--focal", "0.5", "0.5", "0.125", "--up", "0", "1", "0"]
rc1, _, sl = image("slice", "--blend", "slice", "--range", "0.5", "2", "--opaque-bulk", *view)
rc2, _, blob = image("slice-blob", "--blend", "slice", *view)
lit = (sl[:, :3].max(axis=1) > 0).mean() if sl is not None else 0.0
lit_blob = (blob[:, :3].max(axis=1) > 0).mean() if blob is not None else 0.0
check(rc1 == 0 and rc2 == 0 and lit > 0.3 and 0.01 < lit_blob < 0.5 * lit,
      "--blend slice: covered fraction %.3f with the bulk visible, %.3f with it transparent"
      % (lit, lit_blob))

# 4. MIP differs from composite; with the path tracer named by --integrator the ray marcher still
#    draws the MIP (the blend mode asked for is what renders), said on stderr.
rc1, _, mip = image("mip", "--blend", "mip")
rc2, _, comp = image("comp", "--integrator", "rm")
check(rc1 == 0 and rc2 == 0 and not (mip == comp).all(), "--blend mip differs from composite ray marching")
rc, err, ptmip = image("pt-mip", "--blend", "mip", "--integrator", "pt")
check(rc == 0 and "--blend mip: this blend mode is drawn by the ray-march integrator" in err,
      "--integrator pt --blend mip: said on stderr: %s" % [l for l in err.splitlines() if "blend" in l])
check(rc == 0 and rc1 == 0 and (ptmip == mip).all(),
      "--integrator pt --blend mip draws the same MIP as ray marching")

if failures:
    print("%d failure(s)" % len(failures))
    sys.exit(1)
print("all passed")
