"""amrdm-render's command line (issue 19): one-line option errors, the output folder and format
checked before rendering (.png + .exr, .exr, .jpg), unknown arrays listed, progress as whole lines
into a file, the default array / log scale / range said on stderr, --exposure, the default
exposure of the path tracer, the cost view over its own range, and the default step
of ray marching (the table's). Argument 1: the amrdm-render executable."""
import glob
import math
import os
import subprocess
import sys
import tempfile
import time

from vtkmodules.vtkIOImage import vtkJPEGReader, vtkPNGReader
from vtkmodules.util.numpy_support import vtk_to_numpy

APP = sys.argv[1]
DATA = os.environ.get("AMRDM_TEST_DATA", os.path.join(os.path.dirname(__file__), "..", "Data"))
ENZO = os.path.join(DATA, "enzo-moving7_DD0010", "moving7_0010.hierarchy")
ADVECTION = os.path.join(DATA, "amrex-advection-amrcore3d", "plt00040")
SMALL = ["--size", "64", "64", "--spp", "2", "--threads", "2"]
failures = []


def check(condition, message):
    print(("ok:   " if condition else "FAIL: ") + message)
    if not condition:
        failures.append(message)


def run(*args):
    """Runs amrdm-render with stderr and stdout as pipes (not terminals)."""
    t0 = time.time()
    p = subprocess.run([APP] + list(args), stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                       universal_newlines=True, timeout=300)
    return p.returncode, p.stdout, p.stderr, time.time() - t0


def read_image(path):
    reader = vtkJPEGReader() if path.endswith(".jpg") else vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    return vtk_to_numpy(image.GetPointData().GetScalars()).astype(float)


def srgb_to_linear(v):
    v = v / 255.0
    return v / 12.92 if v <= 0.04045 else ((v + 0.055) / 1.055) ** 2.4


tmp = tempfile.mkdtemp(prefix="amrdm-cli-")

# 1. Option errors: one line, naming the option, pointing at --help; exit code 1.
for args, fragment in ((["--spp", "-5"], "--spp: expected an integer in [1, 1048576], got '-5'"),
                       (["--bogus"], "unknown option '--bogus'"),
                       (["--size", "3"], "--size: expected W H"),
                       (["--range", "2", "1"], "--range: expected LO < HI"),
                       (["--integrator", "xx"], "--integrator: unknown 'xx'")):
    rc, out, err, _ = run(*args)
    lines = err.strip().splitlines()
    check(rc == 1 and len(lines) == 1 and fragment in lines[0] and "see amrdm-render --help" in lines[0],
          "%s -> exit %d, %d line(s): %s" % (" ".join(args), rc, len(lines), lines[:2]))

# 2. Output: the folder and format are checked before anything is read or rendered.
rc, out, err, seconds = run(ENZO, "-o", "/nonexistent/dir/x.png", *SMALL)
check(rc == 1 and "the folder '/nonexistent/dir' does not exist" in err and "frame" not in err,
      "a missing output folder fails before rendering (%.2f s): %s" % (seconds, err.strip()))
rc, out, err, _ = run(ENZO, "-o", os.path.join(tmp, "x.tif"), *SMALL)
check(rc == 1 and "unknown image format '.tif'" in err and ".jpg" in err and "frame" not in err,
      "an unknown extension fails before rendering: %s" % err.strip())
rc, out, err, _ = run(ENZO, "-o", os.path.join(tmp, "noext"), *SMALL)
check(rc == 1 and "no file extension" in err, "no extension fails: %s" % err.strip())
rc, out, err, _ = run(ENZO, "-o", os.path.join(tmp, "x.jpg"), *SMALL)
with open(os.path.join(tmp, "x.jpg"), "rb") as f:
    magic = f.read(3)
check(rc == 0 and magic == b"\xff\xd8\xff" and not glob.glob(os.path.join(tmp, "x.jpg.*")),
      "-o x.jpg writes a JPEG named x.jpg and nothing else (%r)" % sorted(os.listdir(tmp)))
rc, out, err, _ = run(ENZO, "-o", os.path.join(tmp, "y.exr"), *SMALL)
with open(os.path.join(tmp, "y.exr"), "rb") as f:
    magic = f.read(4)
check(rc == 0 and magic == b"\x76\x2f\x31\x01" and not glob.glob(os.path.join(tmp, "y.png")),
      "-o y.exr writes only an OpenEXR file")
rc, out, err, _ = run(ENZO, "-o", os.path.join(tmp, "z.png"), *SMALL)
check(rc == 0 and os.path.exists(os.path.join(tmp, "z.png")) and os.path.exists(os.path.join(tmp, "z.exr")),
      "-o z.png writes z.png and z.exr")

# 3. An unknown array lists the arrays there are (with ranges).
rc, out, err, _ = run(ADVECTION, "--array", "Phi", *SMALL)
check(rc == 1 and "no cell array named 'Phi'" in err and "'phi' [" in err and len(err.strip().splitlines()) == 1,
      "an unknown array lists the arrays: %s" % err.strip())
rc, out, err, _ = run(ENZO, "--list-arrays")
check(rc == 0 and "Density\t" in out and "Dark_Matter_Density\t" in out, "--list-arrays prints the arrays")

# 4. Progress into a file or pipe: whole lines, every 5 %, no carriage returns.
rc, out, err, _ = run(ENZO, "--size", "16", "16", "--spp", "200", "--threads", "2")
frames = [l for l in err.splitlines() if "frame " in l]
check(rc == 0 and "\r" not in err and 10 <= len(frames) <= 21 and "frame 200/200" in frames[-1],
      "progress into a pipe: %d whole lines, the last '%s'" % (len(frames), frames[-1] if frames else ""))

# 5. Defaults that show the data: Enzo picks Density (not Dark_Matter_Density), log10, a range from
#    the bulk, and says so with how to change each.
rc, out, err, _ = run(ENZO, "-o", os.path.join(tmp, "enzo.png"), "--size", "96", "96", "--spp", "4",
                      "--threads", "2")
check(rc == 0 and "array 'Density' (the density" in err and "--array NAME" in err,
      "the Enzo default array is Density, said on stderr")
check("log10 scale (positive values span" in err and "--linear" in err, "log10 scale chosen and said")
check("volume-weighted median" in err and "--range LO HI" in err, "the range is said with how to change it")
rgb = read_image(os.path.join(tmp, "enzo.png"))
lum = rgb.mean(axis=1)
covered = (lum > 8).mean()
check(lum.max() > 100 and 0.01 < covered < 0.6,
      "the default Enzo image shows structure: max %.0f, %.1f %% of pixels lit (not black, not a fog cube)"
      % (lum.max(), 100 * covered))

# The flame is two values (burnt, unburnt) with a thin front: the bulk opacity fades, said on
# stderr; --opaque-bulk keeps it (more of the image covered).
FLAME = os.path.join(DATA, "amrex-pelelmex-flame3d_plt")
rc1, _, err1, _ = run(FLAME, *SMALL, "-o", os.path.join(tmp, "flame.png"))
rc2, _, err2, _ = run(FLAME, *SMALL, "-o", os.path.join(tmp, "flame-bulk.png"), "--opaque-bulk")
faded = read_image(os.path.join(tmp, "flame.png")).mean()
kept = read_image(os.path.join(tmp, "flame-bulk.png")).mean()
check(rc1 == 0 and rc2 == 0 and "array 'density'" in err1 and "faded in" in err1 and "--opaque-bulk" in err1
      and "faded in" not in err2 and kept > 1.2 * faded,
      "flame: bulk opacity faded by default (mean %.1f), kept with --opaque-bulk (mean %.1f)" % (faded, kept))

# The advection blob fills a fraction of the domain: the default camera frames it and says so;
# an explicit camera is left alone.
rc1, _, err1, _ = run(ADVECTION, *SMALL, "-o", os.path.join(tmp, "adv-framed.png"))
rc2, _, err2, _ = run(ADVECTION, *SMALL, "-o", os.path.join(tmp, "adv-whole.png"),
                      "--focal", "0.5", "0.5", "0.125")  # the domain's centre: frames the domain
near = (read_image(os.path.join(tmp, "adv-framed.png")).mean(axis=1) > 8).mean()
far = (read_image(os.path.join(tmp, "adv-whole.png")).mean(axis=1) > 8).mean()
check(rc1 == 0 and rc2 == 0 and "the camera frames the cells above a tenth of the range" in err1
      and "the camera frames" not in err2 and near > 2 * far,
      "advection: the default camera frames the blob (%.0f %% of the pixels lit; %.0f %% framing the "
      "domain with --focal)" % (100 * near, 100 * far))

# 6. --exposure scales RGB by 2^stops; the path tracer's default exposure is the documented one.
def rm_image(name, *extra):
    path = os.path.join(tmp, name + ".png")
    rc, _, err, _ = run(ADVECTION, "--integrator", "rm", "--size", "64", "64", "--spp", "1",
                        "--threads", "2", "-o", path, *extra)
    return read_image(path) if rc == 0 else None


base, brighter = rm_image("e0"), rm_image("e1", "--exposure", "1")
ratios = []
for a, b in zip(base.ravel(), brighter.ravel()):
    la, lb = srgb_to_linear(a), srgb_to_linear(b)
    if 0.05 < la < 0.4:
        ratios.append(lb / la)
ratios.sort()
median = ratios[len(ratios) // 2] if ratios else float("nan")
check(len(ratios) > 50 and abs(median - 2.0) < 0.05,
      "--exposure 1 doubles the linear RGB (median ratio %.3f over %d pixels)" % (median, len(ratios)))
check(rm_image("edef") is not None and (rm_image("edef") == base).all(), "ray marching's default exposure is 0")
pt = [os.path.join(tmp, n) for n in ("pt-default.png", "pt-explicit.png")]
rc1, _, err1, _ = run(ENZO, *SMALL, "-o", pt[0])
with open(os.path.join(os.path.dirname(__file__), "..", "..", "Apps", "RenderCommandLine.h")) as f:
    declared = [l for l in f if "constexpr double kPathTracedExposure" in l][0]
stops = declared.split("=")[1].strip().rstrip(";")
rc2, _, _, _ = run(ENZO, *SMALL, "-o", pt[1], "--exposure", stops)
check(rc1 == 0 and rc2 == 0 and (read_image(pt[0]) == read_image(pt[1])).all() and ("exposure %s stops" % stops) in err1,
      "the path tracer's default exposure is kPathTracedExposure = %s stops, said on stderr" % stops)

# 7. The cost view is scaled to its own range: white is reached, and it is not black.
rc, out, err, _ = run(ENZO, "--integrator", "cost", *SMALL, "-o", os.path.join(tmp, "cost.png"))
cost = read_image(os.path.join(tmp, "cost.png"))
check(rc == 0 and cost.max() >= 250 and "cost view: black = 0, white =" in err,
      "the cost view reaches white (max %.0f): %s" % (cost.max(), [l for l in err.splitlines() if "cost" in l]))

# 8. Ray marching's default is the parameter table's SamplesPerCell (0: the uniform step), as in
#    the mapper; --samples-per-cell 1 (level-adaptive) gives another picture.
check((rm_image("spc0", "--samples-per-cell", "0") == base).all(),
      "ray marching's default equals --samples-per-cell 0 (the table's default)")
check(not (rm_image("spc1", "--samples-per-cell", "1") == base).all(),
      "--samples-per-cell 1 (the level-adaptive step) differs from the default")

if failures:
    print("%d failure(s)" % len(failures))
    sys.exit(1)
print("all passed")
