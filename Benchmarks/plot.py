"""Plots of a benchmark run: python3 Benchmarks/plot.py RUN_DIR OUT_DIR

RUN_DIR holds results.json (amrdm-bench) and paraview-SET.json (paraview_volume.py). Writes into
OUT_DIR, per set:
  error-time-SET.png   error against time, one curve per knob (path tracer, left) and the
                       emission-absorption comparison with ParaView (right)
  images-SET.png       small previews: references, alternative samplers, ParaView
and memory-gridlets.png (bytes per leaf cell by category for gridlet sizes 2..16, all sets).
Uses Debian's /usr/bin/python3 with matplotlib (Agg backend, no display).
"""
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

PT_KNOBS = ["sampler", "element test", "gridlet size", "bvh leaf size", "majorant grid", "max bounces"]
COLORS = {"spp": "black", "sampler": "tab:red", "element test": "tab:blue", "gridlet size": "tab:green", "bvh leaf size": "tab:olive",
          "majorant grid": "tab:purple", "max bounces": "tab:orange"}


def load(run):
    res = json.load(open(os.path.join(run, "results.json")))
    pv = {}
    for s in res["sets"]:
        p = os.path.join(run, "paraview-%s.json" % s["name"])
        if os.path.exists(p):
            pv[s["name"]] = json.load(open(p))
    return res, pv


def short(label):
    return (label.replace("ParaView default cap, donor", "PV cap").replace("uniform ", "")
            .replace(", from dual", " dual").replace(", donor", " donor")
            .replace("nearest finest cell", "nearest").replace("bilinear, ", "").replace(" Newton it.", " it")
            .replace("dual mesh (exact)", "dual").replace("planar faces", "planar"))


def plot_rm_curves(ax, curves, knob, style, colormap, label):
    """One error-against-time curve per setting of a ray-marching knob, settings in numeric order."""
    settings = sorted({c["setting"] for c in curves if c["knob"] == knob}, key=lambda s: float(s.split()[0]))
    cmap = plt.get_cmap(colormap)
    for i, s in enumerate(settings):
        cs = [c for c in curves if c["knob"] == knob and c["setting"] == s]
        ax.plot([c["seconds"] for c in cs], [c["rmse"] for c in cs], style, ms=3,
                color=cmap(i / max(1, len(settings) - 1)), label=label + s)


def plot_error_time(res, pv, name, out):
    rows = [r for r in res["rows"] if r["set"] == name]
    curves = [c for c in res["curves"] if c["set"] == name]
    fig, (a, b) = plt.subplots(1, 2, figsize=(13, 5.2))
    # Path tracer: spp curve plus every knob's settings (time for the measured image).
    spp = [c for c in curves if c["knob"] == "spp"]
    if spp:
        a.plot([c["seconds"] for c in spp], [c["rmse"] for c in spp], "-o", color="black", ms=3,
               label="spp 1..%d (dual mesh, defaults)" % spp[-1]["spp"])
    for knob in PT_KNOBS:
        rs = [r for r in rows if r["knob"] == knob and r["integrator"] == "pt" and r["rmse"] is not None]
        if not rs:
            continue
        xs = [r["ms_per_frame"] * r["frames"] / 1e3 for r in rs]
        ys = [r["rmse"] for r in rs]
        a.plot(xs, ys, "-s" if knob != "sampler" else "s", color=COLORS[knob], ms=5, alpha=0.8,
               label="%s (%d spp)" % (knob, rs[0]["frames"]))
        for x, y, r in zip(xs, ys, rs):
            a.annotate(short(r["setting"]), (x, y), fontsize=6, color=COLORS[knob], xytext=(3, 2),
                       textcoords="offset points")
    a.set_xscale("log")
    a.set_yscale("log")
    a.set_xlabel("render time of the image, s (%dx%d, 2 threads)" % (res["width"], res["height"]))
    a.set_ylabel("RMSE vs converged path-traced reference (linear RGB)")
    a.set_title("%s: path tracer, error against time per knob" % name)
    a.grid(True, which="both", alpha=0.3)
    a.legend(fontsize=7)
    # Emission-absorption: our step-size curves, our samplers, ParaView.
    plot_rm_curves(b, curves, "rm step", "-o", "viridis", "ours, step ")
    rs = [r for r in rows if r["knob"] == "rm sampler"]
    for r in rs:
        x = r["ms_per_frame"] * r["frames"] / 1e3
        b.plot([x], [r["rmse"]], "s", color="tab:red", ms=5)
        b.annotate(short(r["setting"]), (x, r["rmse"]), fontsize=6, color="tab:red", xytext=(3, 2),
                   textcoords="offset points")
    if rs:
        b.plot([], [], "s", color="tab:red", label="ours, other samplers (%d spp)" % rs[0]["frames"])
    plot_rm_curves(b, curves, "rm adaptive", "--^", "autumn", "ours, adaptive step, ")
    for v in pv.get(name, {}).get("variants", []):
        mark = "*" if v["variant"] == "default" else "P"
        b.plot([v["ms_per_frame"] / 1e3], [v["rmse"]], mark, color="tab:cyan", ms=12, mec="k",
               label="ParaView %s (%s), 1 frame" % (v["variant"], "x".join(map(str, v["resample_dims"]))))
    b.set_xscale("log")
    b.set_yscale("log")
    b.set_xlabel("render time of the image, s")
    b.set_ylabel("RMSE vs converged ray-marched reference (linear RGB)")
    b.set_title("%s: emission-absorption, ours vs ParaView" % name)
    b.grid(True, which="both", alpha=0.3)
    b.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "error-time-%s.png" % name), dpi=90)
    plt.close(fig)


def plot_memory(res, out):
    cats = [("gridlet_scalars", "gridlet scalars"), ("gridlet_headers", "gridlet headers"),
            ("element_vertices", "element vertices"), ("element_indices", "element indices"), ("bvh", "BVH")]
    sets = [s for s in res["sets"] if s.get("gridlets")]
    if not sets:
        return
    fig, axes = plt.subplots(1, len(sets), figsize=(3.4 * len(sets), 4.2), squeeze=False)
    for ax, s in zip(axes[0], sets):
        leaf = s["dual_mesh"]["counts"]["leafCells"]
        gs = s["gridlets"]
        x = np.arange(len(gs))
        bottom = np.zeros(len(gs))
        for key, label in cats:
            v = np.array([g[key] / leaf for g in gs])
            ax.bar(x, v, bottom=bottom, label=label)
            bottom += v
        for i, g in enumerate(gs):
            ax.text(i, bottom[i], "%.1f" % g["bytes_per_leaf_cell"], ha="center", va="bottom", fontsize=8)
        ax.axhline(4.0, color="k", ls="--", lw=1, label="floor: 4 B (one float per leaf)")
        ax.axhline(5.8, color="gray", ls=":", lw=1, label="paper: full gridlet 5.8 B/dual cell")
        ax.set_xticks(x)
        ax.set_xticklabels([str(g["gridlet_size"]) for g in gs])
        ax.set_xlabel("gridlet size G")
        ax.set_title(s["name"], fontsize=10)
        ax.set_ylim(0, max(bottom) * 1.15)
    axes[0][0].set_ylabel("bytes per leaf cell")
    axes[0][-1].legend(fontsize=7)
    fig.suptitle("Dual-mesh memory by gridlet size (the supplement's Fig. 7); plain dual unstructured mesh "
                 "≈ 48 B/cell (paper)", fontsize=10)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "memory-gridlets.png"), dpi=90)
    plt.close(fig)


def srgb(linear):
    linear = np.clip(linear, 0.0, 1.0)
    return np.where(linear <= 0.0031308, 12.92 * linear, 1.055 * np.power(linear, 1 / 2.4) - 0.055)


def plot_images(run, pv, name, out):
    panels = [("ref-pt-%s.png" % name, "path-traced reference", False),
              ("pt-%s-dual.png" % name, "PT dual mesh, few spp", False),
              ("pt-%s-nearest.png" % name, "PT nearest cell", False),
              ("pt-%s-pvcap.png" % name, "PT ParaView-cap resample", False),
              ("ref-rm-%s.png" % name, "ray-marched reference", False),
              ("rm-%s-pvcap.png" % name, "RM ParaView-cap resample", False)]
    for v in pv.get(name, {}).get("variants", []):
        panels.append((os.path.basename(v["image"]), "ParaView %s %s" % (v["variant"], "x".join(
            map(str, v["resample_dims"]))), True))
    panels = [p for p in panels if os.path.exists(os.path.join(run, p[0]))]
    fig, axes = plt.subplots(1, len(panels), figsize=(2.0 * len(panels), 2.3))
    for ax, (f, title, linear) in zip(np.atleast_1d(axes), panels):
        img = plt.imread(os.path.join(run, f))[:, :, :3]
        ax.imshow(srgb(img) if linear else img)  # ParaView's PNG is linear, ours sRGB-encoded
        ax.set_title(title, fontsize=6)
        ax.axis("off")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "images-%s.png" % name), dpi=90)
    plt.close(fig)


def main():
    run, out = sys.argv[1], sys.argv[2]
    os.makedirs(out, exist_ok=True)
    res, pv = load(run)
    for s in res["sets"]:
        plot_error_time(res, pv, s["name"], out)
        plot_images(run, pv, s["name"], out)
    plot_memory(res, out)
    print("plots written to", out)


if __name__ == "__main__":
    main()
