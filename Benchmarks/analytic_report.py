"""docs/BENCHMARKS-ANALYTIC.md and its error-against-time plots, generated from the last
analytic_compare.py run (no number in the document is typed by hand).

    /usr/bin/python3 Benchmarks/analytic_report.py ANALYTIC.json DOCS_DIR [EQUAL-CLOCK.json]
        [--readme README.md]    (also rewrite the README's headline table between its markers)
"""
import json
import os
import shutil
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

MARKERS = {"ours": "o-", "vtk-amr": "s--", "resample": "^:", "ug-raycast": "v-.",
           "ug-pt": "D-.", "ug-zsweep": "P-.", "yt": "*-"}
PEERS = (("vtk-amr", lambda r: r["setting"].startswith("default"),
          "vtkAMRVolumeMapper default (128^3)"),
         ("yt", lambda r: r["setting"].endswith("(default)"),
          "yt default (10 samples/cell, no ghost zones)"),
         ("yt", lambda r: r["setting"] == "10 samples/cell, ghost zones",
          "yt with ghost zones (10 samples/cell)"))


def frontier(rows):
    """Pareto curve (time, rmse) of one renderer's settings, fastest first."""
    pts = sorted((r["frame_s"], r["rmse"]) for r in rows)
    out, best = [], float("inf")
    for t, e in pts:
        if e < best:
            out.append((t, e))
            best = e
    return out


def time_to_error(rows, target):
    ok = [r["frame_s"] for r in rows if r["rmse"] <= target]
    return min(ok) if ok else None


def error_at_time(rows, budget):
    ok = [r["rmse"] for r in rows if r["frame_s"] <= budget]
    return min(ok) if ok else None


def memory_at_error(rows, target):
    ok = [r["bytes_per_leaf"] for r in rows if r["rmse"] <= target and "bytes_per_leaf" in r]
    return min(ok) if ok else None


def fmt(x, unit="", digits="%.3g"):
    return "not reached" if x is None else (digits % x) + unit


def protocol(res, equal):
    return [
        "## Protocol", "",
        "- **Scenes** (`Benchmarks/analytic_scenes.py`): analytic fields sampled at cell centres on "
        "an AMReX-like hierarchy (domain [0,1]^3, 32^3 base, refinement ratio 2, boxes of 16^3 "
        "cells, a box refined where the field changes by more than 0.05 over a cell, proper "
        "nesting), written as `.vthb` with `vtkXMLUniformGridAMRWriter` and read back with "
        "`vtkXMLUniformGridAMRReader`; every VTK renderer reads the file, none sees the field. yt "
        "cannot read `.vthb`: it gets the same boxes and cell values through `yt.load_amr_grids` "
        "(`Benchmarks/yt_volume.py`).",
        "- **Truth** (`Benchmarks/analytic_truth.py`): the emission-absorption integral of the "
        "*analytic* field over the whole domain box, by midpoint quadrature (1024 segments a "
        "chord, 2 x 2 samples a pixel), with VTK's transfer-function conventions (linear RGBA "
        "table, sigma = -ln(1 - alpha) / unit distance, black background). It owes nothing to our "
        "code. `TestAnalyticTruth` checks it against the closed-form transmittance of a constant "
        "field (to 1e-15) and its h^2 convergence on a smooth one; its own error estimate per "
        "scene is given below.",
        "- **Equal treatment**: one Python script (`Benchmarks/analytic_compare.py`), one camera, "
        "one transfer function and unit distance for all; every VTK renderer (ours, vtk-amr, "
        "resample, ug-*) draws in the same render window. Time: `time.perf_counter()` around "
        "`vtkRenderWindow::Render()` (yt: around `Scene.render()`); *first* = the first render "
        "after a setting changes (mesh build, resample, upload; yt: its kd-tree of bricks), "
        "*frame* = median of %d renders after it, each with the camera nudged 1e-4 degree so every "
        "render draws from scratch. Error: the 8-bit image (VTK: the captured framebuffer, which "
        "holds the linear composite, what a user sees; yt: its float image quantised the same "
        "way) against the truth quantised the same way, RMSE / 99th percentile / max in 8-bit "
        "units; the quantisation floor is given. Where a renderer also gives a float image (ours "
        "through `WriteLastImageEXR`, yt) the float RMSE against the float truth is given too, "
        "in the same units (x 255)." % res.get("frames", 5),
        "- **Kernel time** (ours only, `LastRenderSeconds`: sampling and compositing, without "
        "the window's own work) is a separate column and never enters the comparisons.",
        "- **Memory per leaf cell**: ours = the dual mesh's `GetTotalBytes` (gridlets, elements, "
        "BVH); vtk-amr and resample = the float voxels they request; ug-* = "
        "`GetActualMemorySize` of the `vtkUnstructuredGrid` the mapper draws; yt = the bytes of "
        "its bricks (vertex-centred float64 + masks). Each divided by the scene's leaf cells.",
        "- **Curves, not points**: each renderer is run at every setting listed; the crossing "
        "numbers compare the curves (frame time to reach an error; error within a time; memory "
        "of the cheapest setting reaching an error).",
        "- **Defaults**: our settings here are explicit step sizes and samples a pixel, not tuned on these scenes; the "
        "shipped defaults were chosen on the real sets of `docs/BENCHMARKS.md`, not on these.",
        "- Peer `vtk-amr` is `vtkAMRVolumeMapper` driven from VTK directly (it resamples the "
        "visible part of the hierarchy into the requested number of voxels); `resample` is "
        "`vtkResampleToImage` at N^3 + `vtkSmartVolumeMapper`. ParaView's own \"Volume\" "
        "representation (its own resample, default 64 x 128 x 64) is measured in pvpython, in the "
        "equal-clock table of each scene; its errors differ from `vtk-amr`'s.",
        "- Peers `ug-*`: the dual mesh as a plain `vtkUnstructuredGrid` "
        "(`vtkAMRDualMeshToUnstructuredGrid`: one point per leaf-cell centre, gridlet cells as "
        "hexahedra, stitching elements as tets / pyramids / wedges / hexes), the \"plain dual "
        "unstructured mesh\" route. VTK's `vtkUnstructuredGridVolumeRayCastMapper` (Bunyk) and "
        "`vtkProjectedTetrahedraMapper` accept tetrahedra only, so they draw it after "
        "`vtkDataSetTriangleFilter` (tetrahedralised, memory counted for the tets); "
        "`vtkUnstructuredGridVolumeZSweepMapper` takes the mixed cells but needs about a minute a "
        "frame on the 90 k-cell scene here, so it runs only on the smallest scene. Bunyk warns "
        "\"Degenerate topology - cell face used more than twice\" on the tetrahedralised mesh "
        "and leaves dark specks on the blob (where the faces of neighbouring split cells do not "
        "match, we suppose; not checked). These mappers read the scalar-opacity value as an "
        "attenuation coefficient per unit distance (`vtkUnstructuredGridHomogeneousRayIntegrator`: "
        "tau = opacity / unit distance), where the image-data mappers and ours read it as the "
        "opacity of one unit distance (sigma = -ln(1 - alpha) / unit distance); given the same "
        "`vtkVolumeProperty` they drew the constant scene visibly more transparent (mean 8-bit "
        "error inside the cube -13 to -14 for ray casting, -11 for ZSweep, -6 for projected "
        "tetrahedra, measured 2026-12-02). So they get the same sigma(v): the opacity table "
        "resampled at 256 values as -ln(1 - alpha(v)) / K with the unit distance divided by K "
        "(K = the largest -ln(1 - alpha), keeping every value in [0, 1]; "
        "`analytic_compare.attenuation_property`). With it the mean error inside the cube was "
        "+1.2 to +1.7 (ray casting), +2.6 (ZSweep) and +4.1 (projected tetrahedra, whose 8-bit "
        "opacities and thickness table leave a bias). The exported mesh covers the whole domain "
        "box, like ours (the clamped boundary layer).",
        "- Peer `yt` (4.1, Debian `python3-yt`), its transfer function as close to ours as yt "
        "allows, **and it cannot match it exactly**: a `ColorTransferFunction` with "
        "`grey_opacity=True`, colour tables = our linear table (exact), alpha table = sigma times "
        "the centre ray's length (yt's step is a fraction of the ray vector, not a length). "
        "Residual mismatch: yt composites to first order (1 - sigma dt instead of "
        "exp(-sigma dt)); its perspective rays are not unit vectors, so a pixel at angle theta "
        "off the view axis gets its optical depth scaled by 1 / cos(theta) (up to about 5 %% in "
        "the corners of this 30-degree view); its pixel centres span its width end to end, so "
        "the width is shrunk by (n - 1) / n (vertical centres then differ by under a quarter "
        "pixel); one ray a pixel. yt interpolates vertex data it averages from the cells (not "
        "the dual mesh). yt's ghost zones need a periodic domain in 4.1, so the ghost-zone runs "
        "force periodicity (this changes only the outer vertex layer). yt runs on one thread: "
        "with 2 OpenMP threads on this loaded 2-core machine a frame took 2.7 s instead of 0.3 s.",
        "- **Equal clock** (`Benchmarks/paraview_equal_clock.py`, pvpython): the same scenes read "
        "by ParaView's `XMLUniformGridAMRReader`, shown in one render view as \"Volume\" "
        "(default `NumberOfSamples` 64 128 64, and the finest level's resolution) and as our "
        "\"Dual-Mesh Path Tracer\" representation (Ray Marching, the settings of `ours` above), "
        "each timed by the same loop around `paraview.simple.Render(view)` (first render, then the "
        "median of %d) and scored from `SaveScreenshot` against the same truth. %s"
        % (equal.get("frames", 5) if equal else 5,
           "Run of %s." % equal["date"] if equal else "**Not in this run** (no equal-clock JSON)."),
        "- yt on the real AMReX and Enzo sets is scored in `docs/BENCHMARKS.md` "
        "(`Benchmarks/yt_real.py`: VTK's readers -> `yt.load_amr_grids`, since the moving7 Enzo "
        "set is HDF4, which yt cannot read), against our converged reference as ParaView is "
        "there; it appears after a full `bash Benchmarks/run.sh`.", ""]


def crossings(by):
    """Lines: our time to reach each peer default's error, our error at its time."""
    ours, out = by.get("ours", []), []
    for peer, pick, label in PEERS:
        ref = [r for r in by.get(peer, []) if pick(r)]
        if not ours or not ref:
            continue
        e, t = ref[0]["rmse"], ref[0]["frame_s"]
        fastest = min(ours, key=lambda r: r["frame_s"])
        at_t = error_at_time(ours, t)
        out.append("- Against %s (RMSE %.2f at %.3f s): our time to reach its error %s; our error "
                   "at its time %s." % (
                       label, e, t, fmt(time_to_error(ours, e), " s"),
                       "%.2f" % at_t if at_t is not None else
                       "- none of our settings is that fast (our fastest: %.3f s at RMSE %.2f)"
                       % (fastest["frame_s"], fastest["rmse"])))
    return out


def memory_table(by):
    """Memory per leaf cell of each renderer's cheapest setting reaching each peer's error."""
    targets = []
    for peer, pick, label in PEERS[:2]:
        ref = [r for r in by.get(peer, []) if pick(r)]
        if ref:
            targets.append((label.split(" (")[0], ref[0]["rmse"]))
    if not targets:
        return []
    L = ["Memory per leaf cell at equal error (bytes; the cheapest setting of each renderer whose "
         "RMSE is at most the target):", "",
         "| renderer | " + " | ".join("at %s's RMSE %.2f" % t for t in targets) + " |",
         "|---|" + "---|" * len(targets)]
    for name, rs in by.items():
        L.append("| %s | %s |" % (name, " | ".join(fmt(memory_at_error(rs, e), "", "%.0f")
                                                 for _, e in targets)))
    return L + [""]


def equal_clock_section(scene):
    """The pvpython table of one scene and our crossings against ParaView's default there."""
    if not scene:
        return []
    L = ["Equal clock, pvpython `Render(view)` (ours as a ParaView representation next to "
         "\"Volume\", one script, one loop):", "",
         "| representation | setting | RMSE | p99 | max | first render s | frame s (median) |",
         "|---|---|---|---|---|---|---|"]
    for r in scene["rows"]:
        L.append("| %s | %s | %.2f | %.1f | %.0f | %.3f | %.3f |" % (
            r["renderer"], r["setting"], r["rmse"], r["p99"], r["max"], r["first_s"], r["frame_s"]))
    ours = [r for r in scene["rows"] if r["renderer"] == "ours-pv"]
    ref = [r for r in scene["rows"] if r["renderer"] == "pv-volume" and r["setting"].startswith("default")]
    if ours and ref:
        e, t = ref[0]["rmse"], ref[0]["frame_s"]
        at_t = error_at_time(ours, t)
        L += ["", "- Same clock, against ParaView \"Volume\" default (RMSE %.2f at %.3f s): our time "
              "to reach its error %s; our error at its time %s." % (
                  e, t, fmt(time_to_error(ours, e), " s"),
                  "%.2f" % at_t if at_t is not None else "- none of our settings is that fast")]
    return L + [""]


def crossing(ours, ref):
    """(our frame time to reach ref's RMSE or None, our RMSE within ref's frame time or None)."""
    return time_to_error(ours, ref["rmse"]), error_at_time(ours, ref["frame_s"])


def headline(res, equal):
    """The headline table (this document's top and the README's): per scene, ParaView's "Volume"
    default and yt's default against our curve, each pair timed by one clock in one run."""
    equal_by = {s["name"]: s for s in (equal or {}).get("scenes", [])}
    L = ["| scene | leaf cells | ParaView \"Volume\" default: RMSE, s/frame | ours, same pvpython "
         "loop: s to reach that RMSE; RMSE within that time | yt 4.1 default: RMSE, s/frame | ours, "
         "same VTK script: s to reach that RMSE; RMSE within that time | ours: B / leaf cell |",
         "|---|---|---|---|---|---|---|"]
    for s in res["scenes"]:
        rows = s["rows"]
        ours = [r for r in rows if r["renderer"] == "ours"]
        yt = [r for r in rows if r["renderer"] == "yt" and r["setting"].endswith("(default)")]
        eq = equal_by.get(s["name"], {}).get("rows", [])
        pv = [r for r in eq if r["renderer"] == "pv-volume" and r["setting"].startswith("default")]
        ours_pv = [r for r in eq if r["renderer"] == "ours-pv"]

        def cells(peer, mine):
            if not peer or not mine:
                return "not run", "not run"
            t, e = crossing(mine, peer[0])
            return ("%.2f, %.3f s" % (peer[0]["rmse"], peer[0]["frame_s"]),
                    "%s; %s" % (fmt(t, " s"), "%.2f" % e if e is not None else
                                "none as fast (fastest %.3f s)" % min(r["frame_s"] for r in mine)))
        pv_cell, pv_ours = cells(pv, ours_pv)
        yt_cell, yt_ours = cells(yt, ours)
        mem = min((r["bytes_per_leaf"] for r in ours if "bytes_per_leaf" in r), default=None)
        L.append("| %s | %d | %s | %s | %s | %s | %s |" % (
            s["name"], s["leaf_cells"], pv_cell, pv_ours, yt_cell, yt_ours, fmt(mem, "", "%.1f")))
    return L


def write_headline(readme, res, equal):
    """Replaces the text between the headline markers of `readme` (the README, BENCHMARKS.md)
    with this run's table."""
    begin, end = "<!-- analytic-headline:begin -->", "<!-- analytic-headline:end -->"
    text = open(readme).read()
    if begin not in text or end not in text:
        sys.exit("analytic_report.py: %s has no %s ... %s markers" % (readme, begin, end))
    commit_file = os.path.join(os.path.dirname(os.path.abspath(sys.argv[1])), "commit")
    commit = open(commit_file).read().strip() if os.path.exists(commit_file) else "unknown"
    block = [begin, "Generated by `Benchmarks/analytic_report.py` from the run of %s at commit %s "
             "(%d x %d, 8-bit RMSE against the analytic truth; %s):" % (
                 res["date"], commit, res["width"], res["height"],
                 "QUICK MODE" if res["quick"] else "full mode"), ""] + headline(res, equal) + ["", end]
    head, rest = text.split(begin, 1)
    open(readme, "w").write(head + "\n".join(block) + rest.split(end, 1)[1])


def plot(s, by, res, docs):
    fig, ax = plt.subplots(figsize=(5.5, 3.6))
    for name, rs in by.items():
        rs = sorted(rs, key=lambda r: r["frame_s"])
        ax.plot([r["frame_s"] for r in rs], [r["rmse"] for r in rs], MARKERS.get(name, "x-"),
                label=name, ms=4)
    ax.axhline(s["quantisation_floor"]["rmse"], color="grey", lw=0.8, label="8-bit floor")
    ax.set_xlabel("frame time, s (median of %d)" % res.get("frames", 5))
    ax.set_ylabel("RMSE vs analytic truth (8-bit)")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_title("%s (%s)" % (s["name"], res["date"]), fontsize=9)
    ax.legend(fontsize=6, ncol=2)
    fig.tight_layout()
    fig.savefig(os.path.join(docs, "benchmarks", "analytic-%s.png" % s["name"]), dpi=100)
    plt.close(fig)


def main():
    readme = None
    if "--readme" in sys.argv:
        i = sys.argv.index("--readme")
        readme = sys.argv[i + 1]
        del sys.argv[i:i + 2]
    res = json.load(open(sys.argv[1]))
    docs = sys.argv[2]
    equal = None
    if len(sys.argv) > 3 and os.path.exists(sys.argv[3]):
        equal = json.load(open(sys.argv[3]))
    equal_by = {s["name"]: s for s in (equal or {}).get("scenes", [])}
    os.makedirs(os.path.join(docs, "benchmarks"), exist_ok=True)
    load = ""
    if "load_start" in res:
        load = " Load average (1, 5, 15 min) at the start %s, at the end %s." % (
            ", ".join("%.1f" % x for x in res["load_start"]),
            ", ".join("%.1f" % x for x in res.get("load_end", res["load_start"])))
    commit_file = os.path.join(os.path.dirname(os.path.abspath(sys.argv[1])), "commit")
    commit = open(commit_file).read().strip() if os.path.exists(commit_file) else "unknown"
    L = ["# Benchmarks against an analytic truth", "",
         "Generated by `Benchmarks/analytic_report.py` from the run of %s at commit %s (%d x %d "
         "pixels, %d CPU cores%s).%s%s Rerun `bash Benchmarks/run.sh` to regenerate every number."
         % (res["date"], commit, res["width"], res["height"], res["cpu_count"],
            ", QUICK MODE" if res["quick"] else "",
            " **The machine was busy (load average above the core count + 1): timings are noisy.**"
            if max(res.get("load_start", [0])[0], res.get("load_end", [0])[0]) > res["cpu_count"] + 1
            else "", load), "",
         "## Headline", "", "Our time to reach the error of ParaView's \"Volume\" default and of "
         "yt's default, and our error within their time (the curves of every setting below; "
         "\"not reached\": no setting of ours got there).", ""] + headline(res, equal) + [""] + \
        protocol(res, equal)
    for s in res["scenes"]:
        by = {}
        for r in s["rows"]:
            by.setdefault(r["renderer"], []).append(r)
        L += ["## Scene `%s`" % s["name"], "",
              "%s; %d levels, %d leaf cells. Truth error estimate %.2g (linear), quantisation "
              "floor RMSE %.2f (8-bit)." % (s["doc"], s["levels"], s["leaf_cells"],
                                          s["truth_error_estimate"], s["quantisation_floor"]["rmse"]),
              ""]
        ug = s.get("unstructured_grid")
        if ug:
            L += ["Dual mesh as `vtkUnstructuredGrid`: %d points, %d cells, %d tets after "
                  "`vtkDataSetTriangleFilter`; export %.2f s, tetrahedralisation %.2f s (not in "
                  "the render times)." % (ug["points"], ug["cells"], ug["tets"], ug["export_s"],
                                          ug["tetrahedralise_s"]), ""]
        if s.get("yt_skipped"):
            L += ["yt skipped: %s." % s["yt_skipped"], ""]
        strip = os.path.join(os.path.dirname(os.path.abspath(sys.argv[1])), "analytic-%s.png" % s["name"])
        images = []
        if os.path.exists(strip):  # every renderer's image, as captured (analytic_compare.py)
            shutil.copyfile(strip, os.path.join(docs, "benchmarks", "analytic-images-%s.png" % s["name"]))
            images = ["![every renderer's image](benchmarks/analytic-images-%s.png)" % s["name"], ""]
        L += ["![error against time](benchmarks/analytic-%s.png)" % s["name"], ""] + images + [
              "| renderer | setting | RMSE | p99 | max | float RMSE | first render s | frame s "
              "(median) | memory B / leaf cell |", "|---|---|---|---|---|---|---|---|---|"]
        for r in s["rows"]:
            L.append("| %s | %s | %.2f | %.1f | %.0f | %s | %.3f | %.3f | %s |" % (
                r["renderer"], r["setting"], r["rmse"], r["p99"], r["max"],
                "%.2f" % r["float_rmse"] if "float_rmse" in r else "-", r["first_s"],
                r["frame_s"], "%.0f" % r["bytes_per_leaf"] if "bytes_per_leaf" in r else "-"))
        L.append("")
        L += crossings(by) + [""] + memory_table(by) + equal_clock_section(equal_by.get(s["name"]))
        kern = [r for r in s["rows"] if "kernel_s" in r]
        if kern:
            L += ["Kernel-level times of ours (`LastRenderSeconds`, median of the same frames; "
                  "not comparable with the frame times above):", "",
                  "| setting | kernel s | frame s |", "|---|---|---|"]
            L += ["| %s | %.3f | %.3f |" % (r["setting"], r["kernel_s"], r["frame_s"]) for r in kern]
            L.append("")
        plot(s, by, res, docs)
    with open(os.path.join(docs, "BENCHMARKS-ANALYTIC.md"), "w") as f:
        f.write("\n".join(L) + "\n")
    summary = os.path.join(docs, "BENCHMARKS.md")  # report.py leaves the markers there
    if os.path.exists(summary) and "<!-- analytic-headline:begin -->" in open(summary).read():
        write_headline(summary, res, equal)
    if readme:
        write_headline(readme, res, equal)


if __name__ == "__main__":
    main()
