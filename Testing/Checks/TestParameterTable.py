"""Every layer against the one parameter table (Kernels/core/ParameterTable.h).

Fails when a layer misses a parameter, names it differently, or has another default or range:
- the mapper (vtkAMRDualMeshVolumeMapper through Python): Get<Name>() is the default,
  Set<Name>() clamps to the range, PrintSelf prints "<Name>: ", and every Set/Get pair the class
  adds to vtkVolumeMapper is in the table (a new mapper parameter must be added to the table);
- the ParaView XML (AMRDualMeshRepresentation.xml): a property <Name> with command Set<Name>,
  the default_values, the range domain (or enumeration values) and a Documentation element,
  and every forwarded mapper-like property of the representation is in the table;
- amrdm-render: --help lists the option of every row with one, with the table's documentation;
  for rows whose option is generated (not CliByHand) the help shows the table's default, and a
  value outside the range is refused with a message naming the option; the removed aliases
  (--ambient, --g) are refused naming the one name.
The rows are read by Tools/generate_parameters.py (ctest ParametersGenerated checks that the
generated blocks are current; this test checks what the build made of them).

usage: TestParameterTable.py SOURCE_DIR AMRDM_RENDER
"""
import re
import subprocess
import sys
import xml.etree.ElementTree as ET

source_dir, render_exe = sys.argv[1], sys.argv[2]
failures = []


def fail(msg):
    failures.append(msg)
    print("FAIL:", msg)


# --- The table (parsed by the generator that writes the layers from it) --------------------
sys.path.insert(0, source_dir + "/Tools")
import generate_parameters  # noqa: E402

try:
    table = generate_parameters.read_rows(source_dir)
except generate_parameters.TableError as e:
    print("FAIL:", e)
    sys.exit(1)
for p in table:
    p["cli_checked"] = p["in_cli"] and not p["cli_by_hand"]
if len(table) < 15:
    fail("only %d table rows parsed" % len(table))
by_name = {p["name"]: p for p in table}

# --- The mapper -----------------------------------------------------------------------------
from vtkmodules.vtkRenderingVolume import vtkVolumeMapper  # noqa: E402
import amrdualmesh  # noqa: E402

Mapper = amrdualmesh.vtkAMRDualMeshVolumeMapper
mapper = Mapper()
printed = str(mapper)


def close(a, b):
    return a == b or abs(a - b) <= 1e-12 * max(abs(a), abs(b))


for p in table:
    name = p["name"]
    if not p["mapper"]:
        continue  # a field class's row (InDualMesh, InProbeFilter, InExport) only
    getter, setter = getattr(mapper, "Get" + name, None), getattr(mapper, "Set" + name, None)
    if getter is None or setter is None:
        fail("mapper has no Set%s/Get%s" % (name, name))
        continue
    got = getter()
    want = [p["default"]] * 3 if p["type"] == "Double3" else p["default"]
    if (list(got) if p["type"] == "Double3" else got) != want:
        fail("mapper default of %s is %s, the table says %s" % (name, got, want))
    if not re.search(r"^\s*%s: " % name, printed, re.M):
        fail("mapper PrintSelf does not print %s" % name)
    if p["type"] == "Double3":
        # Each component is clamped to the table's range (-1 -> the minimum).
        setter(p["min"] - 1.0, p["default"], p["default"])
        if not close(getter()[0], p["min"]):
            fail("mapper Set%s(%s, ...) gives %s, the table's range starts at %s"
                 % (name, p["min"] - 1.0, list(getter()), p["min"]))
        setter(p["default"], p["default"], p["default"])
    if p["type"] in ("Int", "Enum", "Double"):
        integral = p["type"] != "Double"
        for bound, beyond in ((p["min"], -1), (p["max"], 1)):
            if abs(bound) >= 2**31 - 1 or abs(bound) > 1e300:
                continue  # no clamp to probe beyond the type's own limit
            probe = bound + beyond * (1 if integral else max(1.0, abs(bound)))
            setter(int(probe) if integral else probe)
            if not close(getter(), bound):
                fail("mapper Set%s(%s) gives %s, the table's range ends at %s"
                     % (name, probe, getter(), bound))
            setter(int(bound) if integral else bound)
            if not close(getter(), bound):
                fail("mapper Set%s(%s) does not keep the table's bound" % (name, bound))

base = set(dir(vtkVolumeMapper))
for attr in sorted(set(dir(Mapper)) - base):
    if not attr.startswith("Set"):
        continue
    name = attr[3:]
    if hasattr(Mapper, "Get" + name) and name not in by_name:
        fail("mapper parameter %s (Set%s/Get%s) is not in the parameter table" % (name, name, name))

# --- The ParaView XML --------------------------------------------------------------------
xml_path = source_dir + "/Plugin/Representation/AMRDualMeshRepresentation.xml"
root = ET.parse(xml_path).getroot()
proxy = root.find(".//RepresentationProxy[@name='AMRDualMeshRepresentation']")
props = {e.get("name"): e for e in proxy if e.get("name")}
exposed = {e.get("name") for e in root.iter("Property") if e.get("name")}
for p in table:
    name = p["name"]
    if not p["plugin"]:
        if name in props:
            fail("XML has %s but the table says it is not in the plugin" % name)
        continue
    e = props.get(name)
    if e is None:
        fail("XML has no property %s" % name)
        continue
    if e.get("label") != p["label"]:
        fail("XML label of %s is %s, the table says %s" % (name, e.get("label"), p["label"]))
    if e.get("command") != "Set" + name:
        fail("XML property %s calls %s, expected Set%s" % (name, e.get("command"), name))
    if name not in exposed:
        fail("XML does not expose %s in the representation's property group" % name)
    defaults = [float(x) for x in e.get("default_values", "").split()]
    want = [p["default"]] * (3 if p["type"] == "Double3" else 1)
    if defaults != want:
        fail("XML default of %s is %s, the table says %s" % (name, defaults, want))
    doc = e.find("Documentation")
    if doc is None or not (doc.text or "").strip():
        fail("XML property %s has no documentation" % name)
    if p["type"] == "Enum":
        dom = e.find("EnumerationDomain")
        values = sorted(int(x.get("value")) for x in dom) if dom is not None else []
        if values != list(range(int(p["min"]), int(p["max"]) + 1)):
            fail("XML %s enumerates %s, the table's range is %s..%s"
                 % (name, values, p["min"], p["max"]))
        continue
    dom = e.find("IntRangeDomain") if p["type"] == "Int" else e.find("DoubleRangeDomain")
    if dom is None:
        fail("XML property %s has no range domain" % name)
        continue
    for key, bound in (("min", p["min"]), ("max", p["max"])):
        text = dom.get(key)
        unbounded = abs(bound) > 1e300 or abs(bound) >= 2**31 - 1
        if text is None:
            if not unbounded:
                fail("XML %s has no %s, the table says %s" % (name, key, bound))
            continue
        vals = [float(x) for x in text.split()]
        if any(not close(v, bound) for v in vals):
            fail("XML %s %s is %s, the table says %s" % (name, key, text, bound))
mapperish = {"Set" + n for n in by_name}
for name, e in props.items():
    cmd = e.get("command", "")
    if e.tag in ("IntVectorProperty", "DoubleVectorProperty") and cmd == "Set" + name \
            and hasattr(Mapper, cmd) and cmd not in mapperish and not hasattr(vtkVolumeMapper, cmd):
        fail("XML property %s is a mapper parameter missing from the table" % name)

# --- amrdm-render ---------------------------------------------------------------------------
help_text = subprocess.run([render_exe, "--help"], capture_output=True, text=True).stdout
lines = {}
current = None
for line in help_text.splitlines():
    m = re.match(r"  (-\S+)", line)
    if m:
        current = m.group(1)
        lines[current] = line
    elif current:
        lines[current] += " " + line.strip()


def short(v):
    return ("%g" % v)


for p in table:
    if not p["cli"]:
        continue
    if p["cli"] not in lines:
        fail("amrdm-render --help has no %s (parameter %s)" % (p["cli"], p["name"]))
        continue
    text = lines[p["cli"]]
    if p["doc"] not in text:
        fail("amrdm-render %s help lacks the table's documentation" % p["cli"])
    if not p["cli_checked"]:
        continue
    d = short(p["default"])
    want_default = "(default %s)" % (" ".join([d] * 3) if p["type"] == "Double3" else d)
    if want_default not in text:
        fail("amrdm-render %s help '%s' lacks '%s'" % (p["cli"], text, want_default))
    if p["type"] == "Double3" or p["max"] > 1e300:
        continue
    beyond = p["max"] + (1 if p["type"] != "Double" else 0.5)
    arg = str(int(beyond)) if p["type"] != "Double" else repr(beyond)
    r = subprocess.run([render_exe, p["cli"], arg, "--list-arrays"], capture_output=True, text=True)
    if r.returncode == 0 or p["cli"] not in r.stderr + r.stdout:
        fail("amrdm-render %s %s (beyond the table's %s) was not refused naming the option: %s"
             % (p["cli"], arg, p["max"], (r.stderr + r.stdout).strip()[:200]))

# Removed aliases: refused with a message naming the one name.
for old, new in (("--ambient", by_name["EnvironmentRadiance"]["cli"]),
                 ("--g", by_name["ScatteringAnisotropy"]["cli"])):
    r = subprocess.run([render_exe, old, "1", "1", "1", "--list-arrays"], capture_output=True,
                       text=True)
    if r.returncode == 0 or new not in r.stderr + r.stdout:
        fail("amrdm-render %s was not refused naming %s: %s"
             % (old, new, (r.stderr + r.stdout).strip()[:200]))

print("%d parameters checked; %d failures" % (len(table), len(failures)))
sys.exit(1 if failures else 0)
