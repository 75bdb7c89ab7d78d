"""Frame time of two builds side by side in one run: `amrdm-render --fps-frames` of a baseline
commit's build and of this one, alternating process by process, on the real sets, per integrator.

    /usr/bin/python3 Benchmarks/frame_time_ab.py --base BASE/bin/amrdm-render \\
        --this build/bin/amrdm-render [--data DIR] [--shared DIR] [--runs 5] [--threads 2]
        [--size 256] [--integrators rm,pt] [--sets enzo,flame] [--scenes SCENES.json]

Each run renders 12 frames at one sample a pixel and reads the mean of frames 11..12 (the
command line's own protocol: the first ten warm caches and clocks); the table gives the median of
`--runs` runs per build and the ratio this / base (below 1: this build is faster). Two scenes
per set: the command line's defaults (its transfer function fades the bulk of the values), and
with `--scenes` the benchmark scene of amrdm-bench's scenes.json (a linear opacity ramp over the
whole range, the scenes ParaView users see by default and the pvpython comparisons draw; linear
sets only). Not a test: it prints a Markdown table.
"""
import argparse
import json
import os
import re
import statistics
import subprocess
import sys

SETS = {
    "enzo": "enzo-moving7_DD0010/moving7_0010.hierarchy",
    "flame": "amrex-pelelmex-flame3d_plt",
    "advection": "amrex-advection-amrcore3d/plt00040",
    "vortex": "amrex-singlevortex3d-128/plt00040",
}
FPS = re.compile(r"mean of frames \d+\.\.\d+: ([0-9.]+) ms per frame")


def scene_args(scene, tf_path):
    """amrdm-render options that draw amrdm-bench's scene: its camera, table and unit distance."""
    tf = scene["tf"]
    lo, hi, table = tf["lo"], tf["hi"], tf["table"]
    with open(tf_path, "w") as f:
        for i, e in enumerate(table):
            f.write("%.9g %g %g %g %g\n" % (lo + (hi - lo) * i / (len(table) - 1), *e))
    c = scene["camera"]
    return (["--tf", tf_path, "--range", repr(lo), repr(hi), "--unit-distance",
             repr(tf["unit_distance"]), "--view-angle", repr(c["view_angle"])] +
            ["--eye"] + [repr(x) for x in c["position"]] +
            ["--focal"] + [repr(x) for x in c["focal_point"]] +
            ["--up"] + [repr(x) for x in c["view_up"]])


def frame_ms(binary, path, integrator, args, extra):
    cmd = [binary, path, "--integrator", integrator, "--size", str(args.size), str(args.size),
           "--fps-frames", "12", "--threads", str(args.threads)] + extra
    out = subprocess.run(cmd, capture_output=True, text=True)
    m = FPS.search(out.stdout)
    if not m:
        sys.exit("no frame time from: %s\n%s" % (" ".join(cmd), out.stderr[-2000:]))
    return float(m.group(1))


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--base", required=True, help="the baseline build's amrdm-render")
    p.add_argument("--this", required=True, help="this build's amrdm-render")
    p.add_argument("--data", default=os.path.join(here, "..", "Testing", "Data"))
    p.add_argument("--shared", default=os.path.join(here, "..", "..", "shared", "amr-data"))
    p.add_argument("--runs", type=int, default=5)
    p.add_argument("--threads", type=int, default=2)
    p.add_argument("--size", type=int, default=256)
    p.add_argument("--integrators", default="rm,pt")
    p.add_argument("--sets", default=",".join(SETS))
    p.add_argument("--scenes", default=None, help="amrdm-bench's scenes.json (benchmark scenes)")
    args = p.parse_args()
    scenes = {s["name"]: s for s in json.load(open(args.scenes))} if args.scenes else {}
    rows = []
    for name in args.sets.split(","):
        path = os.path.join(args.data, SETS[name])
        if not os.path.exists(path):
            path = os.path.join(args.shared, SETS[name])
        if not os.path.exists(path):
            print("skipped %s: %s not found" % (name, SETS[name]), file=sys.stderr)
            continue
        variants = [("defaults", [])]
        if name in scenes and not scenes[name]["log_scale"]:
            variants.append(("bench scene", scene_args(scenes[name], "/tmp/frame_time_ab_tf.txt")))
        for label, extra in variants:
            for integrator in args.integrators.split(","):
                times = {"base": [], "this": []}
                for _ in range(args.runs):
                    for key, binary in (("base", args.base), ("this", args.this)):
                        times[key].append(frame_ms(binary, path, integrator, args, extra))
                b, t = statistics.median(times["base"]), statistics.median(times["this"])
                rows.append((name, label, integrator, b, t, t / b))
                print("%s %s %s: base %.1f ms, this %.1f ms (%.2f)" % (name, label, integrator,
                                                                       b, t, t / b),
                      file=sys.stderr, flush=True)
    print("| set | scene | integrator | base ms/frame | this ms/frame | this / base |")
    print("|---|---|---|---:|---:|---:|")
    for name, label, integrator, b, t, r in rows:
        print("| %s | %s | %s | %.1f | %.1f | %.2f |" % (name, label, integrator, b, t, r))


if __name__ == "__main__":
    main()
