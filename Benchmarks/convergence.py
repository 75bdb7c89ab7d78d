"""Time to a clean picture (issue 30): error against wall time of the path tracer, single
scattering and ray marching, rendered as a VTK user renders them — vtkAMRDualMeshVolumeMapper in a
VTK render window, VTK's light kit (ParaView's default lights), a cool-to-warm colour map, a
linear opacity ramp, one sample per pixel per Render() — on the shared AMR sets.

    /usr/bin/python3 Benchmarks/convergence.py OUT.json [--quick] [--size N] [--sets a,b]
        [--integrators pt,ss,rm] [--budget S] [--reference-samples N] [--threads N]
        [--build NAME=BUILD_DIR ...] [--scaling] [--spp N]
Run under xvfb-run. Every build is run in its own child process (its own Python package from
BUILD_DIR/lib/python3/dist-packages), one after the other on the same scenes, so a change is
measured next to the commit it started from (`--build before=../base/build --build after=build`).

Error: RMSE of the linear premultiplied RGB (over black) against a converged reference, with the
reference's own noise subtracted: the reference is the mean r = (a + b) / 2 of two independent
renders (seeds 1 and 2, --reference-seconds of Render() each, at most --reference-samples,
made by the LAST build given), so
E[(x - r)^2] = (x - truth)^2 + var(r) and var(r) is estimated per image as mean((a - b)^2) / 4.
The clock runs over Render() calls only; reading back the image at the checkpoints (1, 2, 4, ...
samples) is not timed. Time to RMSE 0.008 and 0.004: interpolated on the measured curve
(log-log), or extrapolated from its last two points with the Monte Carlo law RMSE ~ t^-1/2 when
the budget ends first (marked "extrapolated"). Also measured: the first Render() (dual-mesh build,
transfer function, first pass), the fixed cost of a Render() (its wall time minus the mapper's own
pass time, LastRenderSeconds), and with --scaling the pass time at 1 and 2 threads with an Amdahl
prediction for 16 and 64 threads (a prediction, said so in the report).

--spp N: error at fixed sample counts instead of a time budget (load-independent): every build
renders exactly N samples per pixel (one per Render()) and the RMSE is read at 1, 2, 4, ..., N;
the reference is --reference-samples per seed (default 256 with --spp), whatever the time.
"""
import argparse
import json
import math
import os
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
SHARED = os.environ.get("AMRDM_SHARED_DATA", os.path.join(ROOT, "..", "shared", "amr-data"))
TEST_DATA = os.path.join(ROOT, "Testing", "Data")

# name: (reader, path relative to a data folder, array, log colours, folders to look in)
SETS = {
    "enzo": ("enzo", "enzo-moving7_DD0010/moving7_0010.hierarchy", "Density", True,
             (TEST_DATA, SHARED)),
    "flame": ("amrex", "amrex-pelelmex-flame3d_plt", "density", False, (TEST_DATA, SHARED)),
    "advection": ("amrex", "amrex-advection-amrcore3d/plt00040", "phi", False,
                  (TEST_DATA, SHARED)),
    "vortex": ("amrex", "amrex-singlevortex3d-128/plt00040", "phi", False, (SHARED,)),
}
INTEGRATORS = {"pt": "PathTracer", "ss": "SingleScatter", "rm": "RayMarch"}
TARGETS = (0.008, 0.004)


def find_set(name):
    reader, rel, array, log, folders = SETS[name]
    for folder in folders:
        path = os.path.join(folder, rel)
        if os.path.exists(path):
            return {"name": name, "reader": reader, "path": os.path.abspath(path), "array": array,
                    "log": log}
    return None


# ---------------------------------------------------------------- child: one build, one scene
def build_scene(scene, size, threads):
    from vtkmodules.vtkCommonDataModel import vtkPiecewiseFunction
    from vtkmodules.vtkIOAMR import vtkAMREnzoReader, vtkAMReXGridReader
    from vtkmodules.vtkRenderingCore import (vtkColorTransferFunction, vtkLightKit, vtkRenderer,
                                             vtkRenderWindow, vtkVolume, vtkVolumeProperty)
    import vtkmodules.vtkRenderingOpenGL2  # noqa: F401
    from amrdualmesh import vtkAMRDualMeshVolumeMapper

    reader = vtkAMREnzoReader() if scene["reader"] == "enzo" else vtkAMReXGridReader()
    reader.SetFileName(scene["path"])
    reader.UpdateInformation()
    reader.SetMaxLevel(99)
    reader.GetCellDataArraySelection().EnableAllArrays()
    reader.Update()
    amr = reader.GetOutput()
    lo, hi = math.inf, -math.inf
    for level in range(amr.GetNumberOfLevels()):
        for i in range(amr.GetNumberOfDataSets(level)):
            grid = amr.GetDataSet(level, i)
            if grid is None:
                continue
            r = grid.GetCellData().GetArray(scene["array"]).GetRange()
            lo, hi = min(lo, r[0]), max(hi, r[1])
    if scene["log"]:
        lo = max(lo, hi * 1e-6)
    color, opacity, prop = vtkColorTransferFunction(), vtkPiecewiseFunction(), vtkVolumeProperty()
    # ParaView's "Cool to Warm": blue, white, red, diverging in Msh space.
    color.SetColorSpaceToDiverging()
    if scene["log"]:
        color.SetScaleToLog10()
        mid = math.sqrt(lo * hi)
    else:
        mid = 0.5 * (lo + hi)
    color.AddRGBPoint(lo, 0.231, 0.298, 0.753)
    color.AddRGBPoint(mid, 0.865, 0.865, 0.865)
    color.AddRGBPoint(hi, 0.706, 0.016, 0.150)
    opacity.AddPoint(lo, 0.0)
    opacity.AddPoint(hi, 1.0)
    if scene["log"]:
        # a linear ramp in log10 of the value, as a log colour map shows it
        for k in range(1, 16):
            v = lo * (hi / lo) ** (k / 16.0)
            opacity.AddPoint(v, k / 16.0)
    prop.SetColor(color)
    prop.SetScalarOpacity(opacity)
    b = [0.0] * 6
    amr.GetBounds(b)
    diagonal = math.sqrt(sum((b[2 * a + 1] - b[2 * a]) ** 2 for a in range(3)))
    # ParaView's default for Volume: the approximate cell length, diagonal / cells^(1/3)
    # (vtkSMBoundsDomain's "approximate_cell_length"), so the media are as dense as a user sees.
    prop.SetScalarOpacityUnitDistance(diagonal / amr.GetNumberOfCells() ** (1.0 / 3.0))
    mapper, volume, ren, window = (vtkAMRDualMeshVolumeMapper(), vtkVolume(), vtkRenderer(),
                                   vtkRenderWindow())
    mapper.SetInputData(amr)
    mapper.SelectScalarArray(scene["array"])
    mapper.SetSamplesPerRender(1)
    mapper.SetMaximumSamples(1 << 30)  # the default (256) would stop a long run's accumulation
    mapper.SetNumberOfThreads(threads)
    volume.SetMapper(mapper)
    volume.SetProperty(prop)
    ren.AddVolume(volume)
    vtkLightKit().AddLightsToRenderer(ren)
    window.SetSize(size, size)
    window.SetOffScreenRendering(True)
    window.AddRenderer(ren)
    ren.ResetCamera()
    cam = ren.GetActiveCamera()
    cam.Azimuth(35)
    cam.Elevation(25)
    ren.ResetCamera()
    return {"mapper": mapper, "window": window, "amr": amr, "keep": (reader, color, opacity,
            prop, volume, ren, cam)}


def read_image(mapper, path):
    sys.path.insert(0, HERE)
    from exr_read import read_exr
    if not mapper.WriteLastImageEXR(path):
        raise RuntimeError("WriteLastImageEXR(%s) failed" % path)
    return read_exr(path)[:, :, :3].astype("float64")  # premultiplied RGB over black


def child(args):
    import numpy as np
    scene = json.loads(args.scene)
    s = build_scene(scene, args.size, args.threads)
    mapper, window = s["mapper"], s["window"]
    mapper.SetIntegrator(getattr(mapper, {"PathTracer": "PATH_TRACER", "SingleScatter":
                                          "SINGLE_SCATTER", "RayMarch": "RAY_MARCH"}[
                                              args.integrator]))
    out = {"integrator": args.integrator, "size": args.size, "threads": args.threads}
    tmp = tempfile.mkdtemp(prefix="amrdm-conv-")
    exr = os.path.join(tmp, "image.exr")
    if args.reference:
        images = []
        for seed in (1, 2):
            # Samples by time (--reference-seconds per seed, at least 16 and at most
            # --reference samples): the noise subtraction keeps a short reference unbiased.
            mapper.SetSeed(seed)
            mapper.SetSamplesPerRender(4)
            t0 = time.perf_counter()
            while True:
                window.Render()
                n = mapper.GetNumberOfSamples()
                if n >= args.reference or (n >= 16 and time.perf_counter() - t0 >=
                                           args.reference_seconds):
                    break
            out.setdefault("reference_seconds", []).append(time.perf_counter() - t0)
            out.setdefault("reference_samples", []).append(n)
            images.append(read_image(mapper, exr))
        a, b = images
        np.save(args.reference_out, 0.5 * (a + b))
        out["reference_noise_var"] = float(np.mean((a - b) ** 2) / 4.0)
        out["mean"] = float(np.mean(0.5 * (a + b)))
        print(json.dumps(out))
        return 0
    ref = np.load(args.reference_in)
    noise = args.reference_noise
    t0 = time.perf_counter()
    window.Render()
    out["first_render_s"] = time.perf_counter() - t0
    mapper.SetSeed(7)  # a fresh accumulation: the first Render above included the build
    clock, samples, fixed, curve = 0.0, 0, [], []
    checkpoint = 1
    while True:
        t = time.perf_counter()
        window.Render()
        dt = time.perf_counter() - t
        clock += dt
        samples = mapper.GetNumberOfSamples()
        fixed.append(dt - mapper.GetLastRenderSeconds())
        if samples >= checkpoint or clock >= args.budget:
            img = read_image(mapper, exr)
            mse = float(np.mean((img - ref) ** 2)) - noise
            curve.append({"samples": samples, "seconds": clock,
                          "rmse": math.sqrt(max(mse, 0.0))})
            checkpoint = max(checkpoint * 2, samples + 1)
        if clock >= args.budget or samples >= args.max_samples:
            break
    fixed.sort()
    out.update({"curve": curve, "pass_seconds": clock / max(samples, 1),
                "fixed_render_s": fixed[len(fixed) // 2]})
    print(json.dumps(out))
    return 0


# ---------------------------------------------------------------- parent
def run_child(build, argv, timeout):
    env = dict(os.environ)
    env["PYTHONPATH"] = os.path.join(build, "lib", "python3", "dist-packages") + (
        ":" + env["PYTHONPATH"] if env.get("PYTHONPATH") else "")
    p = subprocess.run([sys.executable, os.path.abspath(__file__), "--child"] + argv, env=env,
                       capture_output=True, text=True, timeout=timeout)
    if p.returncode != 0:
        raise RuntimeError("child failed (%d): %s" % (p.returncode, p.stderr[-2000:]))
    return json.loads(p.stdout.strip().splitlines()[-1])


def time_to(curve, target):
    """Seconds until the RMSE reaches target: interpolated, or extrapolated as t^-1/2."""
    pts = [(c["seconds"], c["rmse"]) for c in curve if c["seconds"] > 0 and c["rmse"] > 0]
    for (t0, e0), (t1, e1) in zip(pts, pts[1:]):
        if e1 <= target < e0 or (e1 <= target and e0 <= target):
            if e0 <= target:
                return t0, False
            f = math.log(e0 / target) / math.log(e0 / e1)
            return math.exp(math.log(t0) + f * math.log(t1 / t0)), False
    if pts and pts[0][1] <= target:
        return pts[0][0], False
    if not pts:
        return None, True
    t, e = pts[-1]
    return t * (e / target) ** 2, True


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("out", nargs="?")
    ap.add_argument("--child", action="store_true", help=argparse.SUPPRESS)
    ap.add_argument("--scene", help=argparse.SUPPRESS)
    ap.add_argument("--integrator", help=argparse.SUPPRESS)
    ap.add_argument("--reference", type=int, default=0, help=argparse.SUPPRESS)
    ap.add_argument("--reference-out", help=argparse.SUPPRESS)
    ap.add_argument("--reference-in", help=argparse.SUPPRESS)
    ap.add_argument("--reference-noise", type=float, default=0.0, help=argparse.SUPPRESS)
    ap.add_argument("--reference-seconds", type=float, help="Render() time per reference seed")
    ap.add_argument("--max-samples", type=int, default=1 << 16, help=argparse.SUPPRESS)
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--size", type=int)
    ap.add_argument("--sets")
    ap.add_argument("--integrators", default="pt,ss,rm")
    ap.add_argument("--budget", type=float, help="seconds of Render() per curve")
    ap.add_argument("--reference-samples", type=int)
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--build", action="append", default=[], help="NAME=BUILD_DIR (repeatable)")
    ap.add_argument("--scaling", action="store_true", help="pass time at 1 and 2 threads")
    ap.add_argument("--images", help="folder for PNGs of the references (to look at)")
    ap.add_argument("--spp", type=int, help="fixed sample count per build instead of --budget")
    args = ap.parse_args(argv)
    if args.child:
        return child(args)
    if not args.out:
        ap.error("OUT.json is required")
    size = args.size or (128 if args.quick else 600)
    budget = args.budget or (2.0 if args.quick else 20.0)
    ref_samples = args.reference_samples or (256 if args.spp else 4096)
    ref_seconds = args.reference_seconds or (2.0 if args.quick else 30.0)
    if args.spp:
        budget, ref_seconds = 1e9, 1e9  # sample counts only: the clock decides nothing
    names = args.sets.split(",") if args.sets else (
        ["enzo", "advection"] if args.quick else list(SETS))
    builds = [b.split("=", 1) for b in args.build] or [["this", os.path.join(ROOT, "build")]]
    result = {"date": time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime()), "size": size,
              "load_start": os.getloadavg()[0],
              "budget_s": budget, "threads": args.threads, "cores": os.cpu_count(),
              "builds": [{"name": n, "dir": d, "commit": commit_of(d)} for n, d in builds],
              "reference_seconds": ref_seconds, "targets": list(TARGETS), "sets": [],
              "spp": args.spp}
    refdir = tempfile.mkdtemp(prefix="amrdm-conv-ref-")
    for name in names:
        scene = find_set(name)
        if scene is None:
            print("convergence: %s not found, skipped" % name, file=sys.stderr)
            continue
        entry = {"name": name, "runs": []}
        for code in args.integrators.split(","):
            integ = INTEGRATORS[code]
            refpath = os.path.join(refdir, "%s-%s.npy" % (name, code))
            base = ["--scene", json.dumps(scene), "--integrator", integ, "--size", str(size),
                    "--threads", str(args.threads)]
            ref = run_child(builds[-1][1], base + [
                "--reference", str(ref_samples), "--reference-seconds", str(ref_seconds),
                "--reference-out", refpath], 7200)
            print("%-9s %-13s reference %s spp in %.1f s, mean %.4f, its noise RMSE %.5f" % (
                name, integ, "+".join(map(str, ref["reference_samples"])),
                sum(ref["reference_seconds"]), ref["mean"],
                math.sqrt(ref["reference_noise_var"])), flush=True)
            if args.images:
                save_png(refpath, os.path.join(args.images, "convergence-%s-%s.png" % (name, code)))
            run = {"integrator": integ, "reference": ref, "builds": []}
            for bname, bdir in builds:
                r = run_child(bdir, base + ["--reference-in", refpath, "--reference-noise",
                                            str(ref["reference_noise_var"]), "--budget",
                                            str(budget)] + (
                                                ["--max-samples", str(args.spp)] if args.spp
                                                else []), 7200)
                r["build"] = bname
                r["time_to"] = {}
                for target in TARGETS:
                    t, extrapolated = time_to(r["curve"], target)
                    r["time_to"][str(target)] = {"seconds": t, "extrapolated": extrapolated}
                if args.scaling and code == "pt":
                    one = run_child(bdir, base[:-2] + ["--threads", "1", "--reference-in", refpath,
                                                       "--budget", str(budget / 2)], 7200)
                    r["pass_seconds_1_thread"] = one["pass_seconds"]
                run["builds"].append(r)
                c = r["curve"][0]
                if args.spp:
                    print("  %-8s RMSE at %s" % (bname, ", ".join(
                        "%d spp %.5f" % (p["samples"], p["rmse"]) for p in r["curve"])),
                        flush=True)
                    continue
                print("  %-8s first Render %.2f s, pass %.3f s, fixed %.4f s, 1 spp RMSE %.4f;"
                      " to 0.008: %s" % (bname, r["first_render_s"], r["pass_seconds"],
                                         r["fixed_render_s"], c["rmse"],
                                         fmt_time(r["time_to"]["0.008"])), flush=True)
            entry["runs"].append(run)
        result["sets"].append(entry)
        json.dump(result, open(args.out, "w"), indent=1)
    result["load_end"] = os.getloadavg()[0]
    json.dump(result, open(args.out, "w"), indent=1)
    return 0 if result["sets"] else 1


def save_png(npy, png):
    """The reference as an 8-bit sRGB PNG (over black, row 0 at the top)."""
    import numpy as np
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    rgb = np.clip(np.load(npy), 0.0, 1.0)
    srgb = np.where(rgb <= 0.0031308, 12.92 * rgb, 1.055 * rgb ** (1 / 2.4) - 0.055)
    os.makedirs(os.path.dirname(os.path.abspath(png)), exist_ok=True)
    plt.imsave(png, srgb[::-1])


def fmt_time(t):
    if t["seconds"] is None:
        return "n/a"
    return "%.1f s%s" % (t["seconds"], " (extrapolated)" if t["extrapolated"] else "")


def commit_of(build):
    try:
        src = open(os.path.join(build, "CMakeCache.txt")).read().split(
            "AMRDualMesh_SOURCE_DIR:STATIC=")[1].split("\n")[0]
        return subprocess.run(["git", "-C", src, "describe", "--always", "--dirty"],
                              capture_output=True, text=True).stdout.strip() or "unknown"
    except (OSError, IndexError):
        return "unknown"


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
