"""ParaView plugin test: ParaView's Volume blend properties drive the "Dual-Mesh Path Tracer".

  pvpython TestPluginBlendModes.py --plugin AMRDualMeshPlugin.so --temp-dir DIR

On the AMReX advection set (phi in [1, 2]), seen down -z, Ray Marching, one
sample per pixel, a grey colour map, black background:
1. The properties: BlendMode, IsosurfaceValues and SliceFunction have the names, labels, values
   and defaults of ParaView's UniformGridVolumeRepresentation (read from ParaView's own proxy
   definition), and SliceFunction is a Plane.
2. The pictures, set by ParaView's names (BlendMode = 'Isosurface', IsosurfaceValues = [...],
   BlendMode = 'Slice' with SliceFunction.Origin / Normal, 'Maximum Intensity', 'Minimum
   Intensity', 'Average Intensity', 'Additive'): each differs from the Composite image as it
   should (isosurface: a smaller footprint than Composite's; slice through the middle: the
   data's whole footprint, edge-on: almost nothing; MIP: not Composite's image; MinIP, Average,
   Additive: not Composite's nor any earlier mode's image), and its covered pixels agree with
   ParaView's own Volume representation, same blend mode and values (the four intensity modes by
   vtkVolumeMapper's values 1-4, which 5.11's Volume does not list), on the AMR resampled to a
   128^3 image (ResampleToImage): intersection over union >= 0.9 (MIP: also the mean grey within
   0.1; MinIP, Average, Additive: within 0.015; measured 2026-12-03: IoU 0.995, 0.983, 0.965,
   mean grey 0.017 / 0.017, 0.074 / 0.073, 0.064 / 0.069).
3. A state round trip: SaveState, then LoadState in a fresh pvpython (--load) keeps BlendMode, IsosurfaceValues and
   the plane, and renders the same image.
The images are left in DIR (PluginBlend*.png). Run under an X server (`xvfb-run -a`).
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "Support"))
from amrdm_testing import checker  # noqa: E402
from pv_testing import (ADVECTION, amrex_source, bare_view, load_plugin, luminance, plugin_args,  # noqa: E402
                        png_rgb, ray_marching)

SIZE = [256, 256]
LIT = 0.5 / 255  # a covered pixel: not the black background
IOU = 0.9
failures = []
# BlendMode entries ParaView 5.11's Volume does not list, by vtkVolumeMapper's values.
VTK_ONLY = {"Maximum Intensity": 1, "Minimum Intensity": 2, "Average Intensity": 3, "Additive": 4}


check = checker(failures, "ok: ", "FAILED: ")


def grey(png):
    """The image's luminance (0..1) as a flat numpy array."""
    return luminance(png_rgb(png)).ravel()


def iou(a, b):
    union = (a | b).sum()
    return float((a & b).sum()) / union if union else 1.0


def check_definitions(sm, d, volume):
    """Our properties against ParaView's UniformGridVolumeRepresentation definition."""
    pdm = sm.vtkSMProxyManager.GetProxyManager().GetActiveSessionProxyManager() \
        .GetProxyDefinitionManager()
    theirs = pdm.GetCollapsedProxyDefinition("representations", "UniformGridVolumeRepresentation",
                                             None, False)
    ours = d.SMProxy
    for i in range(theirs.GetNumberOfNestedElements()):
        e = theirs.GetNestedElement(i)
        name = e.GetAttribute("name")
        if name not in ("BlendMode", "IsosurfaceValues", "SliceFunction"):
            continue
        p = ours.GetProperty(name)
        check(p is not None, "ours has %s" % name)
        if p is None:
            continue
        label = volume.GetProperty(name).GetXMLLabel()
        check(p.GetXMLLabel() == label, "%s has Volume's label %s (ours %s)"
              % (name, label, p.GetXMLLabel()))
        check(p.GetCommand() == e.GetAttribute("command"), "%s calls Volume's %s (ours %s)"
              % (name, e.GetAttribute("command"), p.GetCommand()))
        if e.GetAttribute("default_values"):
            check(str(p.GetDefaultValue(0)) == e.GetAttribute("default_values"),
                  "%s has Volume's default %s (ours %s)"
                  % (name, e.GetAttribute("default_values"), p.GetDefaultValue(0)))
        check(p.GetPanelVisibility() == volume.GetProperty(name).GetPanelVisibility(),
              "%s has Volume's panel visibility (%s)" % (name, p.GetPanelVisibility()))
        enum = e.FindNestedElementByName("EnumerationDomain")
        if enum is not None:
            domain = p.FindDomain("vtkSMEnumerationDomain")
            entries = {domain.GetEntryText(k): domain.GetEntryValue(k)
                       for k in range(domain.GetNumberOfEntries())}
            for k in range(enum.GetNumberOfNestedElements()):
                x = enum.GetNestedElement(k)
                check(entries.get(x.GetAttribute("text")) == int(x.GetAttribute("value")),
                      "BlendMode %s = %s as Volume's" % (x.GetAttribute("text"),
                                                          x.GetAttribute("value")))
    check(d.SliceFunction is not None and d.SliceFunction.GetXMLName() == "Plane",
          "SliceFunction is a Plane (%s)" % (d.SliceFunction and d.SliceFunction.GetXMLName()))


def main():
    def more(p):
        p.add_argument("--pvpython", default="pvpython", help="runs the --load phase")
        p.add_argument("--load", help="phase 2: load this state and print its blend properties")
    args = plugin_args(__doc__, more)
    if args.load:
        return load(args)
    path = ADVECTION
    if not os.path.isdir(path):
        print("SKIP: the AMReX advection set is missing (%s)" % path)
        return 125
    from paraview import servermanager as sm
    simple = load_plugin(args.plugin)
    try:
        run(args, simple, sm, path)
        # Representations, then views: pvpython's exit otherwise ends in a GLX error (rc 1).
        for rep in list(simple.GetRepresentations().values()):
            simple.Delete(rep)
        for view in simple.GetViews():
            simple.Delete(view)
    except Exception:
        import traceback
        failures.append(traceback.format_exc())
        print(failures[-1])
    print("PASSED" if not failures else "FAILED: %d checks" % len(failures))
    return 0 if not failures else 1


def setup_view(simple):
    return bare_view(simple, SIZE)


def colour(simple, d):
    simple.ColorBy(d, ("POINTS" if d.ColorArrayName[0] == "POINTS" else "CELLS", "phi"))
    lut = simple.GetColorTransferFunction("phi")
    lut.RGBPoints = [1.0, 0.2, 0.2, 0.2, 2.0, 1.0, 1.0, 1.0]
    lut.AutomaticRescaleRangeMode = "Never"
    simple.GetOpacityTransferFunction("phi").Points = [1.0, 0.05, 0.5, 0.0, 2.0, 0.5, 0.5, 0.0]


def aim(view, bounds):
    c = [(bounds[2 * k] + bounds[2 * k + 1]) / 2 for k in range(3)]
    # Perspective: with a parallel camera neither ours nor ParaView's Volume draws isosurfaces
    # here (seen 2026-12-03; Slice and MIP do), which this test does not cover.
    view.CameraParallelProjection = 0
    view.CameraViewAngle = 30.0
    view.CameraFocalPoint = c
    view.CameraPosition = [c[0], c[1], bounds[5] + 2.1 * max(bounds[1] - bounds[0], 1e-30)]
    view.CameraViewUp = [0, 1, 0]


def run(args, simple, sm, path):
    reader = amrex_source(simple, path, "phi")
    reader.UpdatePipeline()
    bounds = reader.GetDataInformation().GetBounds()
    centre = [(bounds[2 * k] + bounds[2 * k + 1]) / 2 for k in range(3)]
    iso = [1.5]

    view = setup_view(simple)
    d = simple.Show(reader, view)
    d.SetRepresentationType("Dual-Mesh Path Tracer")
    colour(simple, d)
    ray_marching(d, 1)  # the blend modes' integrator; one sample is converged
    aim(view, bounds)
    check(d.BlendMode == "Composite", "BlendMode defaults to Composite (%s)" % d.BlendMode)

    # ParaView's own Volume on the AMR resampled to 128^3 (cell data -> point data first).
    resample = simple.ResampleToImage(Input=simple.CellDatatoPointData(Input=reader),
                                      SamplingDimensions=[128, 128, 128])
    pv = simple.Show(resample, view)
    pv.SetRepresentationType("Volume")
    simple.ColorBy(pv, ("POINTS", "phi"))
    pv.Visibility = 0
    check_definitions(sm, d, pv.SMProxy)

    def shot(name, paraview=False):
        d.Visibility, pv.Visibility = (0, 1) if paraview else (1, 0)
        simple.Render(view)
        png = os.path.join(args.temp_dir, "PluginBlend%s.png" % name)
        simple.SaveScreenshot(png, view, ImageResolution=SIZE)
        return grey(png)

    def both(name, mode, **props):
        d.BlendMode = mode
        if mode in VTK_ONLY:  # not in ParaView 5.11's list: vtkVolumeMapper's value
            pv.SMProxy.GetProperty("BlendMode").SetElement(0, VTK_ONLY[mode])
            pv.SMProxy.UpdateVTKObjects()
        else:
            pv.BlendMode = mode
        for k, val in props.items():
            setattr(d, k, val)
            setattr(pv, k, val)
        return shot(name), shot(name + "ParaView", True)

    composite = shot("Composite")
    footprint = composite > LIT
    check(footprint.mean() > 0.2, "the Composite image covers the data (%.2f of the pixels)"
          % footprint.mean())

    ours, theirs = both("Isosurface", "Isosurface", IsosurfaceValues=iso)
    a, b = ours > LIT, theirs > LIT
    print("isosurface %s: coverage %.3f (Composite %.3f, ParaView %.3f), IoU %.3f"
          % (iso, a.mean(), footprint.mean(), b.mean(), iou(a, b)))
    check(0.005 < a.mean() < footprint.mean() / 2,
          "the isosurface covers less than the Composite footprint")
    check(iou(a, b) >= IOU, "isosurface coverage agrees with ParaView's Volume (IoU %.3f)"
          % iou(a, b))
    d.IsosurfaceValues = [1.2]
    wider = shot("Isosurface12") > LIT
    check(wider.mean() > a.mean(), "a lower isosurface value (1.2) covers more (%.3f > %.3f)"
          % (wider.mean(), a.mean()))
    d.IsosurfaceValues = iso

    for tag, normal in (("Middle", [0.0, 0.1, 1.0]), ("EdgeOn", [1.0, 0.0, 0.0])):
        for rep in (d, pv):
            rep.SliceFunction.Origin = centre
            rep.SliceFunction.Normal = normal
        ours, theirs = both("Slice" + tag, "Slice")
        a, b = ours > LIT, theirs > LIT
        print("slice normal %s: coverage %.3f (ParaView %.3f), IoU %.3f"
              % (normal, a.mean(), b.mean(), iou(a, b)))
        if tag == "Middle":
            check(a.mean() > 0.8 * footprint.mean() and (a & ~footprint).mean() < 0.01,
                  "the slice through the middle covers the data's footprint (%.3f of %.3f)"
                  % (a.mean(), footprint.mean()))
            check(abs(ours - composite).mean() > LIT, "the slice differs from Composite")
            check(iou(a, b) >= IOU, "slice coverage agrees with ParaView's Volume (IoU %.3f)"
                  % iou(a, b))
        else:
            check(a.mean() < 0.05, "an edge-on slice covers almost nothing (%.3f)" % a.mean())
    for rep in (d, pv):
        rep.SliceFunction.Normal = [0.0, 0.1, 1.0]

    ours, theirs = both("MIP", "Maximum Intensity")
    a, b = ours > LIT, theirs > LIT
    print("MIP: coverage %.3f, mean grey %.3f (ParaView %.3f, Composite %.3f), IoU %.3f"
          % (a.mean(), ours[a].mean(), theirs[a].mean(), composite[a].mean(), iou(a, b)))
    check(abs(ours - composite).mean() > LIT, "MIP differs from Composite")
    check(iou(a, b) >= IOU and abs(ours[a].mean() - theirs[a].mean()) < 0.1,
          "MIP agrees with ParaView's Volume (IoU %.3f)" % iou(a, b))

    # Minimum / Average Intensity and Additive by our BlendMode names; ParaView's Volume through
    # vtkVolumeMapper's values (VTK_ONLY). Each is its own picture: it differs from Composite and
    # from every mode before it, and covers what ParaView's Volume covers.
    seen = {"Composite": composite, "MIP": ours}
    for name, mode in (("MinIP", "Minimum Intensity"), ("Average", "Average Intensity"),
                       ("Additive", "Additive")):
        ours, theirs = both(name, mode)
        a, b = ours > LIT, theirs > LIT
        print("%s: coverage %.3f, mean grey %.3f (ParaView %.3f), IoU %.3f" % (
            name, a.mean(), ours[a].mean() if a.any() else 0.0,
            theirs[b].mean() if b.any() else 0.0, iou(a, b)))
        check(a.mean() > 0.005, "%s draws something (%.3f of the pixels)" % (name, a.mean()))
        for other, img in seen.items():
            check(abs(ours - img).mean() > LIT, "%s differs from %s (mean %.4f)"
                  % (name, other, abs(ours - img).mean()))
        grey_diff = abs(ours[a].mean() - theirs[a].mean()) if a.any() else 1.0
        check(iou(a, b) >= IOU and grey_diff < 0.015, "%s agrees with ParaView's Volume (IoU "
              "%.3f, mean grey difference %.4f)" % (name, iou(a, b), grey_diff))
        seen[name] = ours

    # State round trip: Slice with its plane, the isosurface values kept.
    d.BlendMode = "Slice"
    d.IsosurfaceValues = [1.3, 1.7]
    before = shot("StateBefore")
    state = os.path.join(args.temp_dir, "PluginBlendModes.pvsm")
    simple.SaveState(state)
    import subprocess
    out = subprocess.run([args.pvpython, __file__, "--plugin", args.plugin, "--temp-dir",
                          args.temp_dir, "--load", state], capture_output=True, text=True,
                         timeout=300)
    loaded = [x for x in out.stdout.splitlines() if x.startswith("LOADED ")]
    check(out.returncode == 0 and len(loaded) == 1,
          "a fresh pvpython loads the state (rc %d%s)" % (out.returncode, "" if loaded else
                                                          ": " + out.stdout + out.stderr))
    if not loaded:
        return
    e = eval(loaded[0][len("LOADED "):])
    check(e["BlendMode"] == "Slice", "BlendMode survives the state (%s)" % e["BlendMode"])
    check(e["IsosurfaceValues"] == [1.3, 1.7], "IsosurfaceValues survive the state (%s)"
          % e["IsosurfaceValues"])
    check(e["Origin"] == list(centre) and e["Normal"] == [0.0, 0.1, 1.0],
          "the slice plane survives the state (%s, %s)" % (e["Origin"], e["Normal"]))
    after = grey(os.path.join(args.temp_dir, "PluginBlendStateAfter.png"))
    diff = float(abs(after - before).max()) if after.shape == before.shape else 1.0
    check(diff < 0.02, "the loaded state renders the same image (max difference %.3f)" % diff)


def load(args):
    """Phase 2 (a fresh process): load the state, render, print the values."""
    simple = load_plugin(args.plugin)  # the state's camera
    simple.LoadState(args.load)
    e = [r for r in simple.GetRepresentations().values() if hasattr(r, "Integrator")][0]
    view = [v for v in simple.GetViews() if e in v.Representations][0]
    simple.Render(view)
    simple.SaveScreenshot(os.path.join(args.temp_dir, "PluginBlendStateAfter.png"), view,
                          ImageResolution=SIZE)
    print("LOADED " + repr({"BlendMode": e.BlendMode, "IsosurfaceValues": list(e.IsosurfaceValues),
                            "Origin": list(e.SliceFunction.Origin),
                            "Normal": list(e.SliceFunction.Normal)}))
    return 0

if __name__ == "__main__":
    sys.exit(main())
