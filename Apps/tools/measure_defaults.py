#!/usr/bin/python3
"""Measures amrdm-render's defaults on the shared sets (README "Defaults, measured"):
1. exposure: the mean linear brightness of the ray-marched (emission-absorption) image over that
   of the path-traced image of the same scene at exposure 0, per set and colour map; the default
   --exposure of pt is the median of log2 of these ratios;
2. ray marching: time per frame and RMSE against a converged reference (4 samples per cell of
   every level, half the default step in the finest cells, 32 spp) for the uniform default step (--samples-per-cell 0) and the
   level-adaptive step (--samples-per-cell 1: 1 sample per finest cell), with and without --shade.
Times are medians of --repeat runs of amrdm-render's own "median ms per frame".
Usage: measure_defaults.py AMRDM_RENDER DATA_DIR [--repeat N] [--size N] [--sets a,b]"""
import argparse
import math
import os
import re
import statistics
import subprocess
import tempfile

from vtkmodules.vtkIOImage import vtkPNGReader
from vtkmodules.util.numpy_support import vtk_to_numpy

SETS = {
    "enzo": "enzo-moving7_DD0010/moving7_0010.hierarchy",
    "flame": "amrex-pelelmex-flame3d_plt",
    "advection": "amrex-advection-amrcore3d/plt00040",
    "vortex": "amrex-singlevortex3d-128/plt00040",
}


def linear_image(path):
    r = vtkPNGReader()
    r.SetFileName(path)
    r.Update()
    v = vtk_to_numpy(r.GetOutput().GetPointData().GetScalars()).astype(float) / 255.0
    return ((v + 0.055) / 1.055) ** 2.4 * (v > 0.04045) + v / 12.92 * (v <= 0.04045)


def render(app, data, out, *args):
    p = subprocess.run([app, data, "-o", out, "--threads", "2"] + list(args), stdout=subprocess.PIPE,
                       stderr=subprocess.PIPE, universal_newlines=True, check=True)
    ms = float(re.search(r"median ([0-9.]+) ms per frame", p.stdout).group(1))
    return ms, linear_image(out)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("app")
    ap.add_argument("data")
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--size", type=int, default=256)
    ap.add_argument("--sets", default=",".join(SETS))
    ap.add_argument("--only", choices=("exposure", "raymarch"), help="one of the two measurements")
    a = ap.parse_args()
    size = ["--size", str(a.size), str(a.size)]
    tmp = tempfile.mkdtemp(prefix="amrdm-measure-")
    if a.only != "raymarch":
        exposure(a, size, tmp)
    if a.only != "exposure":
        raymarch(a, size, tmp)


def exposure(a, size, tmp):
    stops = []
    print("## Exposure (linear mean brightness, exposure 0, %d^2)\n" % a.size)
    print("| set | colour map | rm / pt | stops |\n|---|---|---|---|")
    for name in a.sets.split(","):
        data = os.path.join(a.data, SETS[name])
        for tf in ("cool-warm", "white"):
            _, pt = render(a.app, data, os.path.join(tmp, "pt.png"), *size, "--tf", tf, "--spp", "16",
                           "--exposure", "0")
            _, rm = render(a.app, data, os.path.join(tmp, "rm.png"), *size, "--tf", tf, "--spp", "4",
                           "--integrator", "rm", "--exposure", "0")
            ratio = rm.mean() / max(pt.mean(), 1e-12)
            stops.append(math.log2(ratio))
            print("| %s | %s | %.2f | %+.2f |" % (name, tf, ratio, stops[-1]))
    print("\nmedian: %+.2f stops\n" % statistics.median(stops))


def raymarch(a, size, tmp):
    print("## Ray marching (%d^2, 4 spp; RMSE of linear RGB against a 32-spp reference at 4 samples "
          "per cell)\n" % a.size)
    print("| set | shade | uniform step: ms/frame, RMSE | 1 sample/cell: ms/frame, RMSE | speed-up |")
    print("|---|---|---|---|---|")
    for name in a.sets.split(","):
        data = os.path.join(a.data, SETS[name])
        for shade in ([], ["--shade"]):
            # reference: 4 samples per cell of every level (half the default step in
            # the finest cells, finer elsewhere), 64 spp
            _, ref = render(a.app, data, os.path.join(tmp, "ref.png"), *size, "--integrator", "rm",
                            "--spp", "32", "--samples-per-cell", "4", "--step", "1e-9", *shade)
            rows = []
            for spc in ("0", "1"):
                times, rmse = [], 0.0
                for r in range(a.repeat):
                    ms, img = render(a.app, data, os.path.join(tmp, "rm%s.png" % spc), *size,
                                     "--integrator", "rm", "--spp", "4", "--samples-per-cell", spc,
                                     "--seed", str(r), *shade)
                    times.append(ms)
                    rmse = math.sqrt(((img - ref) ** 2).mean())
                rows.append((statistics.median(times), rmse))
            print("| %s | %s | %.0f, %.4f | %.0f, %.4f | %.1fx |" % (
                name, "yes" if shade else "no", rows[0][0], rows[0][1], rows[1][0], rows[1][1],
                rows[0][0] / rows[1][0]))


if __name__ == "__main__":
    main()
