"""Memory per rank and time per frame of data-parallel rendering (not a test: a measurement).

  xvfb-run -a -s "-noreset -screen 0 1280x1024x24" python3 MPIScaling.py --plugin SO \\
      [--data DIR] [--ranks 1 2 4] [--frames 3] [--size 400 300] [--mode Proxy]

Runs MPIRender.py (Ray Marching, 1 sample per frame, one thread per rank) with `mpiexec -np N
pvbatch --symmetric` for each N, and prints per rank: cell data received, dual-mesh bytes, peak
resident memory (VmHWM: ParaView itself, the reader's blocks, the region's blocks and the mesh),
the first render (the dual-mesh build included) and the mean of the timed frames.
"""
import argparse
import os
import re
import subprocess

HERE = os.path.dirname(os.path.abspath(__file__))


def main():
    p = argparse.ArgumentParser(description=__doc__)
    p.add_argument("--plugin", required=True)
    p.add_argument("--data", default=os.path.join(
        os.path.dirname(os.path.dirname(os.path.dirname(HERE))), "shared", "amr-data",
        "amrex-singlevortex3d-128", "plt00040"))
    p.add_argument("--ranks", type=int, nargs="+", default=[1, 2, 4])
    p.add_argument("--frames", type=int, default=3)
    p.add_argument("--size", type=int, nargs=2, default=[400, 300])
    p.add_argument("--out", default="/tmp")
    p.add_argument("--mode", default="Partitioned", help="DistributionMode")
    args = p.parse_args()
    for n in args.ranks:
        cmd = ["mpiexec", "--oversubscribe", "-np", str(n)]
        if os.geteuid() == 0:
            cmd.insert(1, "--allow-run-as-root")
        cmd += ["pvbatch", "--symmetric", os.path.join(HERE, "MPIRender.py"), "--plugin",
                args.plugin, "--data", args.data, "--samples", "1", "--unit", "0.02",
                "--size", str(args.size[0]), str(args.size[1]), "--frames", str(args.frames),
                "--mode", args.mode,
                "--camera", "1.9", "-1.3", "1.6", "0.5", "0.5", "0.5", "0", "0", "1",
                "--out", os.path.join(args.out, "MPIScaling-np%d.png" % n)]
        out = subprocess.run(cmd, capture_output=True, text=True).stdout
        reports = sorted(re.findall(r"rank \d+/\d+: .*?vmhwm_kib=\d+", out))
        print("-np %d" % n)
        for r in reports:
            f = dict(re.findall(r"(\w+)=([^ ]+)", r))
            print("  %s received %.1f MB, mesh %.1f MB, peak RSS %.0f MB, first render %s, "
                  "frame %s" % (r.split(":")[0], int(f["bytes"]) / 1e6,
                                int(f["mesh_bytes"]) / 1e6, int(f["vmhwm_kib"]) / 1024.0,
                                f["render"], f["frame"]))


if __name__ == "__main__":
    main()
