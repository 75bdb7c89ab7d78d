"""ParaView plugin test: a Volume script's property names drive the "Dual-Mesh Path Tracer".

  pvpython TestPluginVolumeNames.py --plugin AMRDualMeshPlugin.so --temp-dir DIR [--pvpython P]

1. The XML (Plugin/Representation/AMRDualMeshRepresentation.xml): ScalarOpacityUnitDistance,
   Shade, Ambient, Diffuse, Specular and SpecularPower are one property each with the name, label
   and default of ParaView's AMR Volume representation (read from ParaView's own proxy
   definition), linked from Volume (unit distance, Shade) or Surface (lighting); no two
   properties of the AMR representation that the panel can show share a label.
2. The pictures: on the AMReX advection set (Ray Marching, one sample per pixel, deterministic),
   setting each of those properties under Volume's name changes our image, and in the same
   direction (mean luminance up or down) as it changes Volume's image.
3. The removed names PathTracerScalarOpacityUnitDistance / PathTracerShade: a value that differs
   from Volume's property changes nothing in the image and is reported once, naming the
   property to set instead. A state saved so (as states of older versions are) loads in a
   fresh pvpython (--load-old, run by this script) with Volume's values, the same image and the
   same two reports.
4. The depth-peeling notice: none without translucent geometry (ParaView's depth peeling on),
   once when a translucent sphere is in the scene.
Run under an X server (ctest runs under `xvfb-run -a`).
"""
import os
import sys
import xml.etree.ElementTree as ET

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "Support"))
from amrdm_testing import checker  # noqa: E402
from pv_testing import (ADVECTION, amrex_source, bare_view, load_plugin, luminance,  # noqa: E402
                        plugin_args, png_rgb, ray_marching, show_dual_mesh)

SOURCE = os.path.dirname(os.path.dirname(HERE))
XML = os.path.join(SOURCE, "Plugin", "Representation", "AMRDualMeshRepresentation.xml")
SIZE = [120, 90]
NAMES = ["ScalarOpacityUnitDistance", "Shade", "Ambient", "Diffuse", "Specular", "SpecularPower"]
failures = []
check = checker(failures, "ok: ", "FAILED: ")


def parse_args():
    def more(p):
        p.add_argument("--pvpython", default="pvpython", help="runs the --load-old phase")
        p.add_argument("--load-old", help="phase 2: load this state and print what it renders")
    return plugin_args(__doc__, more)


def load_old(args):
    """Phase 2 (a fresh process): load the state, render, print the values and the image."""
    simple = load_plugin(args.plugin)  # the state's camera
    simple.LoadState(args.load_old)
    view = simple.GetActiveView()
    d = next(r for r in simple.GetRepresentations().values() if hasattr(r, "Integrator"))
    simple.Render(view)
    png = os.path.join(args.temp_dir, "PluginVolumeNamesOldState.png")
    simple.SaveScreenshot(png, view, ImageResolution=SIZE)
    print("LOADED ScalarOpacityUnitDistance=%r Shade=%r" % (d.ScalarOpacityUnitDistance, d.Shade))
    return 0


def paraview_volume_defaults(sm):
    """name -> (label or None, default_values) of ParaView's AMR Volume representation."""
    pdm = sm.vtkSMProxyManager.GetProxyManager().GetActiveSessionProxyManager() \
        .GetProxyDefinitionManager()
    elem = pdm.GetCollapsedProxyDefinition("internal_representations", "AMRVolumeRepresentation",
                                           None, False)
    out = {}
    for i in range(elem.GetNumberOfNestedElements()):
        e = elem.GetNestedElement(i)
        if e.GetAttribute("name") in NAMES:
            out[e.GetAttribute("name")] = (e.GetAttribute("label"), e.GetAttribute("default_values"))
    return out


def check_xml(sm, proxy):
    root = ET.parse(XML).getroot()
    ours = root.find(".//RepresentationProxy[@name='AMRDualMeshRepresentation']")
    props = {e.get("name"): e for e in ours if e.get("name")}
    volume = paraview_volume_defaults(sm)
    for name in NAMES:
        e = props.get(name)
        check(e is not None, "our XML has %s" % name)
        if e is None or name not in volume:
            check(name in volume, "ParaView's AMR Volume has %s" % name)
            continue
        label, default = volume[name]
        check(e.get("label") == label, "%s has Volume's label (%s, ours %s)"
              % (name, label, e.get("label")))
        check([float(x) for x in e.get("default_values").split()] ==
              [float(x) for x in default.split()],
              "%s has Volume's default %s (ours %s)" % (name, default, e.get("default_values")))
    shares = {s.get("subproxy"): {x.get("name") for x in s.findall("Exception")}
              for s in root.iter("ShareProperties")}
    for name in ("ScalarOpacityUnitDistance", "Shade"):
        check(name not in shares.get("VolumeRepresentation", {name}),
              "%s is linked from the Volume representation" % name)
    for name in ("Ambient", "Diffuse", "Specular", "SpecularPower"):
        check(name not in shares.get("SurfaceRepresentation", {name}),
              "%s is linked from the Surface representation (as Volume's)" % name)
    exposed = [e for e in root.iter("Property") if e.get("exposed_name")]
    check(not any(e.get("exposed_name") in NAMES for e in exposed),
          "no property of ours is exposed under one of Volume's names")

    # Labels the panel can show (not panel_visibility never), across the whole AMR representation.
    labels = {}
    it = proxy.NewPropertyIterator()
    it.Begin()
    while not it.IsAtEnd():
        prop = it.GetProperty()
        if prop.GetPanelVisibility() != "never" and not prop.GetInformationOnly():
            labels.setdefault(prop.GetXMLLabel(), set()).add(it.GetKey())
        it.Next()
    # ParaView's own representations may share a label among themselves (5.11: "Scale Array" of
    # 3D Glyphs and OSPRay); a label of ours, or of a property ours uses, must be unique.
    ours_names = set(NAMES) | {e.get("exposed_name") or e.get("name") for e in
                               root.find(".//Extension").iter("Property") if e.get("name")}
    dup = {k: sorted(v) for k, v in labels.items() if len(v) > 1}
    print("labels shared by ParaView's own properties:", dup)
    ours_dup = {k: v for k, v in dup.items() if ours_names & set(v)}
    check(not ours_dup, "no property of ours shares its label in the panel %s" % (ours_dup or ""))

    def values(xml_element):
        out = {xml_element.GetAttribute("value")}
        for i in range(xml_element.GetNumberOfNestedElements()):
            out |= values(xml_element.GetNestedElement(i))
        return out

    for name in ("ScalarOpacityUnitDistance", "Shade"):
        target = proxy.GetProperty(name).GetAddressAsString("vtkSMProperty")
        group = None
        for i in range(proxy.GetNumberOfPropertyGroups()):
            g = proxy.GetPropertyGroup(i)
            if any(g.GetProperty(k).GetAddressAsString("vtkSMProperty") == target
                   for k in range(g.GetNumberOfProperties())):
                group = g  # the last group of a property is the one the panel uses
        shown = values(group.GetHints()) if group and group.GetHints() else set()
        check({"Volume", "Dual-Mesh Path Tracer"} <= shown,
              "the panel shows %s for Volume and for ours (its last group %s: %s)"
              % (name, group.GetXMLLabel() if group else None, sorted(v for v in shown if v)))


def stats(png):
    a = png_rgb(png, unit=1.0).reshape(-1, 3)
    return a, float(luminance(a).mean())


def main():
    args = parse_args()
    if args.load_old:
        return load_old(args)
    path = ADVECTION
    if not os.path.isdir(path):
        print("SKIP: the AMReX advection set is missing")
        return 125
    from paraview import servermanager as sm
    from vtkmodules.vtkCommonCore import vtkOutputWindow, vtkStringOutputWindow
    simple = load_plugin(args.plugin)
    # Every message of this process (pvpython's prints included) goes to `window` from here
    # on, and is echoed at the end.
    window = vtkStringOutputWindow()
    previous = vtkOutputWindow.GetInstance()
    vtkOutputWindow.SetInstance(window)
    try:
        run(args, simple, sm, path, window)
    except Exception:
        import traceback
        failures.append(traceback.format_exc())
    finally:
        vtkOutputWindow.SetInstance(previous)
        print(window.GetOutput())
        for f in failures:
            if "Traceback" in f:
                print(f)
    print("PASSED" if not failures else "FAILED: %d checks" % len(failures))
    return 0 if not failures else 1


def run(args, simple, sm, path, window):
    reader = amrex_source(simple, path, "phi")

    view = bare_view(simple, SIZE)
    d, lut = show_dual_mesh(simple, reader, view, "phi")
    lut.RescaleTransferFunction(1.0, 2.0)
    simple.GetOpacityTransferFunction("phi").Points = [1.0, 0.0, 0.5, 0.0, 2.0, 1.0, 0.5, 0.0]
    ray_marching(d, 1)  # one sample per pixel is the converged image
    view.CameraPosition = [1.6, -0.7, 1.0]
    view.CameraFocalPoint = [0.5, 0.5, 0.125]
    view.CameraViewUp = [0, 0, 1]
    check_xml(sm, d.SMProxy)

    counter = [0]

    def shot(representation):
        d.SetRepresentationType(representation)
        simple.Render(view)
        counter[0] += 1
        png = os.path.join(args.temp_dir, "PluginVolumeNames%02d.png" % counter[0])
        simple.SaveScreenshot(png, view, ImageResolution=SIZE)
        return stats(png)

    unit = d.ScalarOpacityUnitDistance
    # (property, value) applied in turn; each is compared with the image before it.
    # SpecularPower first sets a broad highlight (no effect while Specular is 0), so that
    # Specular and a second SpecularPower show on this small image.
    steps = [("ScalarOpacityUnitDistance", unit / 4.0), ("Shade", 1), ("Ambient", 0.6),
             ("Diffuse", 0.3), ("SpecularPower", 5.0), ("Specular", 0.8),
             ("SpecularPower", 30.0)]
    before = {rep: shot(rep) for rep in ("Dual-Mesh Path Tracer", "Volume")}
    for name, val in steps:
        setattr(d, name, val)
        after = {rep: shot(rep) for rep in ("Dual-Mesh Path Tracer", "Volume")}
        (o0, ol0), (o1, ol1) = before["Dual-Mesh Path Tracer"], after["Dual-Mesh Path Tracer"]
        (v0, vl0), (v1, vl1) = before["Volume"], after["Volume"]
        ours_diff = float(abs(o1 - o0).mean())
        print("%s = %s: ours mean luminance %.2f -> %.2f (mean |diff| %.2f), Volume %.2f -> %.2f"
              % (name, val, ol0, ol1, ours_diff, vl0, vl1))
        volume_diff = float(abs(v1 - v0).mean())
        before = after
        if name == "SpecularPower" and d.Specular == 0:
            check(ours_diff == 0 and volume_diff == 0,
                  "SpecularPower changes nothing while Specular is 0, in both")
            continue
        check(ours_diff > 0.5, "d.%s = %s changes our picture" % (name, val))
        if name == "Ambient" and volume_diff == 0:
            # Known difference (Plugin/README.md): VTK's GPU volume shading scales the ambient
            # term by the lights' ambient colour, black in ParaView's light kit.
            print("NOTE: Ambient does not change Volume's picture with ParaView's light kit")
            continue
        check(volume_diff > 0.1, "d.%s changes Volume's picture" % name)
        if abs(vl1 - vl0) > 0.25:
            check((ol1 - ol0) * (vl1 - vl0) > 0,
                  "d.%s changes our picture in the direction it changes Volume's" % name)

    # The removed names: not used, said once with the property to set instead.
    notice = "translucent geometry in the scene"
    check(view.GetRenderer().GetUseDepthPeeling() == 1 and notice not in window.GetOutput(),
          "no depth-peeling notice without translucent geometry (depth peeling is on: %s)"
          % view.GetRenderer().GetUseDepthPeeling())
    ref = shot("Dual-Mesh Path Tracer")[0]
    d.PathTracerScalarOpacityUnitDistance = unit * 3.0
    d.PathTracerShade = 0
    img = shot("Dual-Mesh Path Tracer")[0]
    shot("Dual-Mesh Path Tracer")
    text = window.GetOutput()
    print(text.strip())
    check(abs(img - ref).max() == 0, "the removed names change nothing in the image")
    check(text.count("PathTracerScalarOpacityUnitDistance was removed") == 1 and
          "ScalarOpacityUnitDistance =" in text, "the removed unit distance is reported once")
    check(text.count("PathTracerShade was removed") == 1 and "Shade =" in text,
          "the removed Shade is reported once")

    # A state with the removed names set (as an older version's state has them), in a fresh
    # process: it loads, renders with Volume's values (the same image) and reports both.
    import subprocess
    state = os.path.join(args.temp_dir, "PluginVolumeNamesOld.pvsm")
    simple.SaveState(state)
    r = subprocess.run([args.pvpython, os.path.abspath(__file__), "--plugin", args.plugin,
                        "--temp-dir", args.temp_dir, "--load-old", state],
                       capture_output=True, text=True, timeout=240)
    out = r.stdout + r.stderr
    print(out.strip())
    want = "LOADED ScalarOpacityUnitDistance=%r Shade=%r" % (d.ScalarOpacityUnitDistance, d.Shade)
    check(r.returncode == 0 and want in out, "the old state loads with Volume's values (%s)" % want)
    check("PathTracerScalarOpacityUnitDistance was removed" in out and
          "PathTracerShade was removed" in out and "ERR|" not in out,
          "loading it reports both removed names, and no error")
    if r.returncode == 0:
        old = stats(os.path.join(args.temp_dir, "PluginVolumeNamesOldState.png"))[0]
        check(abs(old - img).max() == 0, "the old state renders the same image")
    # Translucent geometry: the notice, once.
    sphere = simple.Sphere(Center=[0.5, 0.5, 0.125], Radius=0.2)
    sd = simple.Show(sphere, view)
    sd.Opacity = 0.4
    shot("Dual-Mesh Path Tracer")
    shot("Dual-Mesh Path Tracer")
    check(window.GetOutput().count(notice) == 1,
          "the depth-peeling notice once with translucent geometry in the scene")
    simple.Delete(sd)
    simple.Delete(d)
    simple.Delete(view)


if __name__ == "__main__":
    sys.exit(main())
