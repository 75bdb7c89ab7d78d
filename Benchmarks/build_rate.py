"""The dual-mesh build alone on the real sets, two commits side by side in one run: build time,
the build's CPU seconds, M leaf cells per second, the peak resident memory above the input
(every temporary of intake and build included) as a multiple of the final mesh, and a hash of the
built arrays (gridlets, scalars, vertices, element indices, BVH) that must match between them.

Each build runs in a fresh process (amrdm-buildbench, one repeat), the two commits alternating,
`--runs` times per set; the table gives medians. The baseline is the same amrdm-buildbench
binary run against the baseline commit's libAMRDualMeshMapper.so (copy that build's `lib/`
folder; the bench only calls vtkAMRDualMesh's public API, whose layout both share).

    /usr/bin/python3 Benchmarks/build_rate.py --bench build/bin/amrdm-buildbench \\
        --baseline-lib /tmp/main-lib [--data DIR] [--runs 3] [--threads 2] [--sets a,b]
        [--series 16e6,40e6 --series-dir /tmp]
`--series` adds points of the scale series (Benchmarks/scale_series.py's AMReX-like hierarchies,
array "f"), written once as .vthb files into --series-dir and read back by both builds.
Not a test: it measures and prints a Markdown table; it exits 1 when a hash differs.
"""
import argparse
import json
import os
import statistics
import subprocess
import sys

SETS = {
    "enzo": ("enzo-moving7_DD0010/moving7_0010.hierarchy", "Density"),
    "flame": ("amrex-pelelmex-flame3d_plt", "temp"),
    "advection": ("amrex-advection-amrcore3d/plt00040", "phi"),
    "vortex": ("amrex-singlevortex3d-128/plt00040", "phi"),
}


def run(bench, lib, path, array, threads):
    env = dict(os.environ)
    if lib:
        env["LD_LIBRARY_PATH"] = lib + (":" + env["LD_LIBRARY_PATH"] if env.get("LD_LIBRARY_PATH") else "")
    out = subprocess.run([bench, path, array, "--threads", str(threads)], env=env, check=True,
                         capture_output=True, text=True).stdout
    return json.loads(out.strip().splitlines()[-1])


def series_file(target, directory):
    """The scale series' hierarchy of about `target` leaf cells as a .vthb file (made once)."""
    path = os.path.join(directory, "scale-series-%de6.vthb" % round(target / 1e6))
    if not os.path.exists(path):
        sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
        import scale_series
        from vtkmodules.vtkIOXML import vtkXMLUniformGridAMRWriter
        n0, levels = scale_series.plan(target)
        amr, keep = scale_series.make_amr(n0, levels)
        writer = vtkXMLUniformGridAMRWriter()
        writer.SetFileName(path)
        writer.SetInputData(amr)
        writer.Write()
        del keep
    return path


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--bench", required=True)
    ap.add_argument("--baseline-lib", required=True)
    ap.add_argument("--data", default="/work/shared/amr-data")
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--sets", default=",".join(SETS))
    ap.add_argument("--series", default="", help="scale-series points, leaf cells, e.g. 16e6")
    ap.add_argument("--series-dir", default="/tmp")
    args = ap.parse_args()
    cases = [(n, os.path.join(args.data, SETS[n][0]), SETS[n][1]) for n in args.sets.split(",") if n]
    for t in [float(x) for x in args.series.split(",") if x]:
        cases.append(("series %.0fM" % (t / 1e6), series_file(t, args.series_dir), "f"))
    rows = []
    same = True
    for name, path, array in cases:
        res = {"before": [], "after": []}
        for _ in range(args.runs):
            res["before"].append(run(args.bench, args.baseline_lib, path, array, args.threads))
            res["after"].append(run(args.bench, None, path, array, args.threads))
        hashes = {r["hash"] for r in res["before"] + res["after"]}
        same = same and len(hashes) == 1
        med = {k: {f: statistics.median(r[f] for r in v)
                   for f in ("build_s", "cpu_s", "mleaf_per_s", "mleaf_per_cpu_s", "peak_x_mesh")}
               for k, v in res.items()}
        rows.append((name, res["after"][0]["leaf_cells"], res["after"][0]["mesh_bytes"], med,
                     "same" if len(hashes) == 1 else "DIFFERENT"))
        print("%s done" % name, file=sys.stderr, flush=True)
    print("| set | leaf cells | mesh MB | build s | build CPU s | M leaf cells/s | M leaf cells/CPU s"
          " | peak above input / mesh | built arrays |")
    print("|---|---|---|---|---|---|---|---|---|")
    for name, leaf, mesh, med, h in rows:
        b, a = med["before"], med["after"]
        print("| %s | {:,} | %.1f | %.3f -> %.3f | %.3f -> %.3f | %.2f -> %.2f | %.2f -> %.2f | %.2fx -> %.2fx | %s |"
              .format(int(leaf)) % (name, mesh / 1e6, b["build_s"], a["build_s"], b["cpu_s"], a["cpu_s"],
                                    b["mleaf_per_s"], a["mleaf_per_s"], b["mleaf_per_cpu_s"],
                                    a["mleaf_per_cpu_s"], b["peak_x_mesh"], a["peak_x_mesh"], h))
    return 0 if same else 1


if __name__ == "__main__":
    sys.exit(main())
