#!/usr/bin/env python3
"""Writes every layer's parameter declarations from the one parameter table.

Kernels/core/ParameterTable.h declares each user-visible parameter once (one row per line between
"PARAMETER ROWS BEGIN" and "PARAMETER ROWS END"). This script reads the rows and writes, between
"BEGIN GENERATED <block>" and "END GENERATED <block>" markers in committed files:

  Kernels/core/ParameterTable.h            table-index (kParameters)
  Kernels/render/RenderParams.h            render-params (the fields of the rows whose kernel
                                            field is "[Type ]RenderParams::<member>"; the type
                                            defaults to int / float / glm::vec3 by the row's type)
  Mapper/vtkAMRDualMeshVolumeMapper.h       mapper-api (Set/Get macros), mapper-fields
  Mapper/vtkAMRDualMeshVolumeMapper.cxx     mapper-print (PrintSelf lines)
  Plugin/Representation/vtkAMRDualMeshRepresentation.h               representation-setters
  Plugin/Representation/vtkAMRDualMeshRepresentationProperties.cxx   representation-forwarders
  Plugin/Representation/AMRDualMeshRepresentation.xml   xml-properties, xml-exposed-basic,
                                                        xml-exposed-advanced
  Mapper/vtkAMRDualMesh.h/.cxx, vtkAMRDualMeshProbeFilter.h/.cxx,
  vtkAMRDualMeshToUnstructuredGrid.h/.cxx   field-api, field-fields, field-print (the rows with
                                            InDualMesh, InProbeFilter, InExport)
  Apps/RenderCommandLine.cxx                cli-options (amrdm-render's option rows)
  Mapper/AMRDualMeshFrameBuilder.cxx        frame-params (the Render rows' copy into RenderParams)
  Kernels/io/SceneFile.h / SceneFile.cpp    scene-build-fields, scene-parameters (the rows a scene
                                            file stores, by name, with their ranges)

The Integrator row's maximum is `kIntegratorCount - 1` and its ParaView entries extend to every
row of Kernels/render/IntegratorList.h (a new integrator is listed under its long name in title
case unless the row's enumeration texts name it), so adding an integrator needs no table edit.

and checks that each View row's kernel field is set by the mapper's hand-written policy code.

usage: generate_parameters.py [--check | --write] [SOURCE_DIR]
  --check  (default) exit 1 with a unified diff when a generated block is stale
  --write  rewrite the stale blocks in place
Python 3 standard library only.
"""
import difflib
import os
import re
import sys

TOOL = "Tools/generate_parameters.py"
TABLE = "Kernels/core/ParameterTable.h"
ROW_RE = re.compile(
    r'constexpr ParameterSpec (\w+)\{ "(\w+)", ParameterType::(\w+), ([^,]+), ([^,]+), ([^,]+), '
    r'([^,]+), ParameterClass::(\w+), "([^"]*)", "([^"]*)", "([^"]*)", "([^"]*)", "([^"]+)", '
    r'"([^"]*)" \};$')
OLD_ROW_RE = re.compile(r'constexpr ParameterSpec (\w+)\{ "(\w+)", ParameterType::(\w+), '
                        r'([^,]+), ([^,]+), ([^,]+), ([^,]+), "([^"]*)", "([^"]+)" \};$')
CONSTS = {"DBL_MAX": sys.float_info.max, "INT_MIN": -2**31, "INT_MAX": 2**31 - 1}
INTEGRATORS = "Kernels/render/IntegratorList.h"
# The Integrator row's maximum: the last row of render/IntegratorList.h (read_rows sets it).
INTEGRATOR_MAX = "kIntegratorCount - 1"
DERIVED = {}
LAYER_BITS = {"InMapper": 1, "InPlugin": 2, "InCli": 4, "Advanced": 8, "SetByHand": 16,
              "CliByHand": 32, "NotInSceneFile": 64, "InDualMesh": 128, "InProbeFilter": 256,
              "InExport": 512, "kAllLayers": 7}
# The field classes that take a row's Set/Get, field and PrintSelf line from the table, by their
# layer bit: (header, source).
FIELD_CLASSES = {
    "InDualMesh": ("Mapper/vtkAMRDualMesh.h", "Mapper/vtkAMRDualMesh.cxx"),
    "InProbeFilter": ("Mapper/vtkAMRDualMeshProbeFilter.h", "Mapper/vtkAMRDualMeshProbeFilter.cxx"),
    "InExport": ("Mapper/vtkAMRDualMeshToUnstructuredGrid.h",
                 "Mapper/vtkAMRDualMeshToUnstructuredGrid.cxx"),
}


class TableError(Exception):
    pass


def _value(text):
    text = text.strip()
    if text in DERIVED:
        return float(DERIVED[text])
    return float(CONSTS[text]) if text in CONSTS else float(text)


def read_integrators(source_dir):
    """The integrators' long names ("path-tracer", ...) in IntegratorType order, from the rows
    X(Type, "short", "long", ...) of AMRDM_INTEGRATORS."""
    text = open(os.path.join(source_dir, INTEGRATORS)).read()
    try:
        body = text.split("#define AMRDM_INTEGRATORS(X)")[1].split("// clang-format on")[0]
    except IndexError:
        raise TableError(INTEGRATORS + ": no '#define AMRDM_INTEGRATORS(X)' list")
    names = re.findall(r'^\s*X\(\w+, "[^"]*", "([^"]*)"', body, re.M)
    if not names:
        raise TableError(INTEGRATORS + ": no rows X(Type, \"short\", \"long\", ...)")
    return names


def _integrator_choices(row, names):
    """The Integrator row's ParaView entries: its own texts for the first rows of the list, then
    each later integrator's long name in title case ("depth-view" -> "Depth View"), so a new
    integrator reaches ParaView without a table edit (append a text to the row to name it)."""
    if len(row["choices"]) > len(names):
        raise TableError("%s row %s has %d enumeration texts for the %d integrators of %s; "
                         "expected at most one per integrator" % (TABLE, row["ident"],
                                                                   len(row["choices"]),
                                                                   len(names), INTEGRATORS))
    return row["choices"] + [" ".join(w.capitalize() for w in n.split("-"))
                             for n in names[len(row["choices"]):]]


# The kernel type of a RenderParams field, by the row's type, unless the kernel field names it
# ("glm::ivec3 RenderParams::majorantResolution").
KERNEL_TYPES = {"Int": "int", "Double": "float", "Double3": "glm::vec3"}


def _kernel_type(field, ptype):
    """(kernel type, "Struct::member") of a kernel field written "[Type ]Struct::member"."""
    m = re.match(r"(?:([\w:]+) )?(\w+::[\w.]+)$", field)
    if not field or not m:
        return "", field
    return m.group(1) or KERNEL_TYPES.get(ptype, ""), m.group(2)


def _layers(text):
    bits = 0
    for part in text.split("|"):
        part = part.strip()
        if part not in LAYER_BITS:
            raise TableError("unknown layer bit '%s'; expected one of %s"
                             % (part, ", ".join(LAYER_BITS)))
        bits |= LAYER_BITS[part]
    return bits


def read_rows(source_dir):
    """The table's rows as dicts, in order; TableError names a malformed row."""
    header = open(os.path.join(source_dir, TABLE)).read()
    try:
        text = header.split("// PARAMETER ROWS BEGIN")[1].split("// PARAMETER ROWS END")[0]
    except IndexError:
        raise TableError(TABLE + ": no PARAMETER ROWS BEGIN/END markers")
    integrators = read_integrators(source_dir)
    DERIVED[INTEGRATOR_MAX] = len(integrators) - 1
    rows = []
    for line in text.strip().splitlines():
        m = ROW_RE.match(line.strip())
        if not m and OLD_ROW_RE.match(line.strip()):
            raise TableError(TABLE + ": row in the old 8-field form (name, type, default, min, "
                             "max, layers, option, doc); the generator needs 13 fields: after the "
                             "layers add ParameterClass::Build|Render|View, after the option the "
                             "kernel field (\"RenderParams::member\" or \"\"), the ParaView label "
                             "and the enumeration texts (\"A|B\" or \"\"), after the doc the "
                             "ParaView guide (\"\" = doc); then delete the hand-written Set/Get, "
                             "PrintSelf, forwarder, XML and option lines of that parameter: "
                             + line.strip()[:100])
        if not m:
            raise TableError(TABLE + ": row not in the expected form (one line, the fields of "
                             "ParameterSpec in order, strings without double quotes): "
                             + line.strip()[:120])
        (ident, name, ptype, d, lo, hi, layers, kind, cli, field, label, choices, doc,
         guide) = m.groups()
        ktype, field = _kernel_type(field, ptype)
        bits = _layers(layers)
        row = dict(ident=ident, name=name, type=ptype, default=_value(d), min=_value(lo),
                   max=_value(hi), min_text=lo.strip(), max_text=hi.strip(), kind=kind,
                   cli=cli, field=field, ktype=ktype, label=label or name, doc=doc, guide=guide or doc,
                   choices=choices.split("|") if choices else [],
                   mapper=bool(bits & 1), plugin=bool(bits & 2), in_cli=bool(bits & 4),
                   advanced=bool(bits & 8), set_by_hand=bool(bits & 16),
                   cli_by_hand=bool(bits & 32), in_scene=not bits & 64,
                   classes={c for c in FIELD_CLASSES if bits & LAYER_BITS[c]})
        if row["max_text"] == INTEGRATOR_MAX:
            row["choices"] = _integrator_choices(row, integrators)
        _validate(row)
        rows.append(row)
    return rows


def _validate(r):
    where = "%s row %s" % (TABLE, r["ident"])
    if r["ident"] != r["name"]:
        raise TableError("%s has the name %s; expected the same" % (where, r["name"]))
    if r["type"] not in ("Int", "Enum", "Double", "Double3"):
        raise TableError("%s has type %s; expected Int, Enum, Double or Double3"
                         % (where, r["type"]))
    if r["kind"] not in ("Build", "Render", "View"):
        raise TableError("%s has class %s; expected Build, Render or View" % (where, r["kind"]))
    if not r["min"] <= r["default"] <= r["max"]:
        raise TableError("%s: default %g outside %g..%g" % (where, r["default"], r["min"],
                                                             r["max"]))
    if r["type"] == "Enum" and len(r["choices"]) != int(r["max"] - r["min"]) + 1 and r["plugin"]:
        raise TableError("%s: %d choices for the values %g..%g" % (where, len(r["choices"]),
                                                                    r["min"], r["max"]))
    if bool(r["cli"]) != r["in_cli"]:
        raise TableError("%s: an option name needs InCli and InCli an option name" % where)
    if r["in_cli"] and not r["cli_by_hand"] and not r["field"]:
        raise TableError("%s: a generated amrdm-render option needs the kernel field" % where)
    if r["field"] and not re.match(r"(RenderParams|DualMeshBuildOptions)::[\w.]+$", r["field"]):
        raise TableError("%s: kernel field '%s'; expected RenderParams::<member> or "
                         "DualMeshBuildOptions::<member>" % (where, r["field"]))
    if r["field"].startswith("RenderParams::") and "." not in r["field"] and not r["ktype"]:
        raise TableError("%s: the RenderParams field of an %s row needs its kernel type: "
                         "\"Type RenderParams::%s\"" % (where, r["type"], member(r)))
    if "." in r["field"] and r["field"] != r["field"].split()[-1]:
        raise TableError("%s: a nested kernel field is declared by its struct; expected no "
                         "type" % where)
    if r["kind"] == "Build" and (r["type"] != "Int" or (
            r["field"] and not r["field"].startswith("DualMeshBuildOptions::"))):
        raise TableError("%s: a Build row is an Int (in DualMeshBuildOptions when it has a "
                         "kernel field)" % where)
    if not r["mapper"] and not r["classes"]:
        raise TableError("%s: a row is a parameter of the mapper (InMapper) or of a field class "
                         "(%s)" % (where, ", ".join(FIELD_CLASSES)))
    if not r["mapper"] and (r["plugin"] or r["in_cli"]):
        raise TableError("%s: InPlugin and InCli forward the mapper's parameter; expected "
                         "InMapper with them" % where)


# --- Number formatting --------------------------------------------------------------------
def c_number(r, v, text):
    """A C++ literal of the row's type for v (text is the table's spelling)."""
    vtk_names = {"DBL_MAX": "VTK_DOUBLE_MAX", "INT_MIN": "VTK_INT_MIN", "INT_MAX": "VTK_INT_MAX"}
    if text in vtk_names:
        return vtk_names[text]
    return str(int(v)) if r["type"] in ("Int", "Enum") else repr(float(v))


def short(v):
    return str(int(v)) if v == int(v) and abs(v) < 2**53 else "%g" % v


def range_text(r):
    lo = short(r["min"]) if r["min_text"] not in CONSTS else None
    hi = short(r["max"]) if r["max_text"] not in CONSTS else None
    if lo and hi:
        return "%s..%s" % (lo, hi)
    if lo:
        return ">= %s" % lo
    return "<= %s" % hi if hi else "any"


def default_text(r):
    d = short(r["default"])
    return "(%s, %s, %s)" % (d, d, d) if r["type"] == "Double3" else d


def ctype(r):
    return "int" if r["type"] in ("Int", "Enum") else "double"


def unbounded(r):
    return r["min_text"] in CONSTS and r["max_text"] in CONSTS


# --- The blocks ---------------------------------------------------------------------------
def mapper_api(rows):
    out = []
    for r in rows:
        doc = r["doc"][0].upper() + r["doc"][1:]
        out += wrap("%s; %s, default %s." % (doc, range_text(r), default_text(r)),
                                "/// ", 98)
        t, n = ctype(r), r["name"]
        if r["type"] == "Double3":
            lo, hi = c_number(r, r["min"], r["min_text"]), c_number(r, r["max"], r["max_text"])
            clamp = "(%%s < %s ? %s : (%%s > %s ? %s : %%s))" % (lo, lo, hi, hi)
            out += ["virtual void Set%s(double r, double g, double b)" % n, "{",
                    "  const double v[3] = {"] + \
                ["    %s," % (clamp % (c, c, c)) for c in "rgb"] + \
                   ["  };",
                    "  if (v[0] != this->%s[0] || v[1] != this->%s[1] ||" % (n, n),
                    "    v[2] != this->%s[2])" % n,
                    "  {", "    std::copy(v, v + 3, this->%s);" % n,
                    "    this->Modified();", "  }", "}",
                    "void Set%s(const double rgb[3])" % n,
                    "{", "  this->Set%s(rgb[0], rgb[1], rgb[2]);" % n, "}",
                    "vtkGetVector3Macro(%s, double);" % n]
        else:
            if r["set_by_hand"]:
                out.append("virtual void Set%s(%s value); // by hand (see below)" % (n, t))
            elif unbounded(r):
                out.append("vtkSetMacro(%s, %s);" % (n, t))
            else:
                out.append("vtkSetClampMacro(%s, %s, %s, %s);"
                           % (n, t, c_number(r, r["min"], r["min_text"]),
                              c_number(r, r["max"], r["max_text"])))
            out.append("vtkGetMacro(%s, %s);" % (n, t))
            if r["type"] == "Int" and r["min"] == 0 and r["max"] == 1:
                out.append("vtkBooleanMacro(%s, %s);" % (n, t))
    return ["  " + line for line in out]


def mapper_fields(rows):
    out = []
    for r in rows:
        if r["type"] == "Double3":
            d = repr(float(r["default"]))
            out.append("  double %s[3] = { %s, %s, %s };" % (r["name"], d, d, d))
        else:
            out.append("  %s %s = %s;" % (ctype(r), r["name"],
                                          c_number(r, r["default"], "")))
    return out


def mapper_print(rows):
    out = []
    for r in rows:
        n = r["name"]
        if r["type"] == "Double3":
            out.append('  os << indent << "%s: (" << this->%s[0] << ", " << this->%s[1] << ", "'
                       % (n, n, n))
            out.append('     << this->%s[2] << ")\\n";' % n)
        else:
            out.append('  os << indent << "%s: " << this->%s << "\\n";' % (n, n))
    return out


def representation_setters(rows):
    out = []
    for r in rows:
        if not r["plugin"]:
            continue
        if r["type"] == "Double3":
            out.append("  void Set%s(double r, double g, double b);" % r["name"])
        else:
            out.append("  void Set%s(%s val);" % (r["name"], ctype(r)))
    return out


def representation_forwarders(rows):
    out = []
    for r in rows:
        if not r["plugin"]:
            continue
        if r["type"] == "Double3":
            out.append("AMRDM_FORWARD3(Mapper, %s)" % r["name"])
        else:
            out.append("AMRDM_FORWARD(Mapper, %s, %s)" % (r["name"], ctype(r)))
    return out


def xml_escape(s):
    return s.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;")


def wrap(text, indent, width=100):
    words, lines, line = text.split(), [], ""
    for w in words:
        if line and len(indent) + len(line) + 1 + len(w) > width:
            lines.append(line)
            line = w
        else:
            line = (line + " " + w) if line else w
    lines.append(line)
    return [indent + text_line for text_line in lines]


def xml_number(r, v):
    return str(int(v)) if r["type"] in ("Int", "Enum") else short(v)


def xml_properties(rows):
    ind = " " * 6
    out = []
    for r in rows:
        if not r["plugin"]:
            continue
        n = r["name"]
        tag = "DoubleVectorProperty" if r["type"] in ("Double", "Double3") else \
            "IntVectorProperty"
        count = 3 if r["type"] == "Double3" else 1
        d = " ".join([xml_number(r, r["default"])] * count)
        attrs = ['command="Set%s"' % n, 'default_values="%s"' % d, 'name="%s"' % n,
                 'label="%s"' % xml_escape(r["label"]), 'number_of_elements="%d"' % count]
        if r["advanced"]:
            attrs.append('panel_visibility="advanced"')
        pad = ind + " " * (len(tag) + 2)
        out.append("%s<%s %s" % (ind, tag, " ".join(attrs[:3])))
        out.append(pad + " ".join(attrs[3:]) + ">")
        if r["type"] == "Enum":
            out.append(ind + '  <EnumerationDomain name="enum">')
            for i, text in enumerate(r["choices"]):
                out.append(ind + '    <Entry text="%s" value="%d" />'
                           % (xml_escape(text), int(r["min"]) + i))
            out.append(ind + "  </EnumerationDomain>")
        else:
            dom = "IntRangeDomain" if r["type"] == "Int" else "DoubleRangeDomain"
            bounds = ""
            if r["min_text"] not in CONSTS:
                bounds += ' min="%s"' % " ".join([xml_number(r, r["min"])] * count)
            if r["max_text"] not in CONSTS:
                bounds += ' max="%s"' % " ".join([xml_number(r, r["max"])] * count)
            out.append(ind + '  <%s%s name="range" />' % (dom, bounds))
        out += wrap("<Documentation>" + xml_escape(r["guide"]) + "</Documentation>", ind + "  ",
                    100)
        out.append("%s</%s>" % (ind, tag))
    return out


def xml_exposed(rows, advanced):
    return [' ' * 12 + '<Property name="%s" />' % r["name"] for r in rows
            if r["plugin"] and r["advanced"] == advanced]


def cli_field(r):
    struct, member = r["field"].split("::")
    return ("o.params." if struct == "RenderParams" else "o.") + member


def cli_options(rows):
    out = []
    for r in rows:
        if not r["in_cli"] or r["cli_by_hand"]:
            continue
        n = r["name"]
        if r["type"] == "Enum":
            raise TableError("%s: an Enum option parses names; mark it CliByHand" % n)
        metavars = {"Int": '"N"', "Double": '"X"', "Double3": '"R", "G", "B"'}[r["type"]]
        out.append("    tableOption(param::%s, { %s }, into(param::%s, %s)),"
                   % (n, metavars, n, cli_field(r)))
    return out


def build_rows(rows):
    """The Build rows of DualMeshBuildOptions (the others are the field classes' own)."""
    return [r for r in rows if r["kind"] == "Build" and r["field"]]


def mapper_rows(rows):
    return [r for r in rows if r["mapper"]]


def member(r):
    return r["field"].split("::")[1]


def scene_build_fields(rows):
    return ["  int %s = int(param::%s.defaultValue);" % (member(r), r["name"])
            for r in build_rows(rows)]


def scene_rows(rows):
    """The rows a scene file stores: every Build row and every row with a RenderParams field,
    except those marked NotInSceneFile."""
    return [r for r in rows if r["field"] and r["in_scene"]]


def scene_parameters(rows):
    out = []
    for r in scene_rows(rows):
        struct, m = r["field"].split("::")
        where = "s.params." if struct == "RenderParams" else "s."
        out.append("  visit(param::%s, %s%s);" % (r["name"], where, m))
    return out


def frame_rows(rows):
    """The rows the mapper's frame builder copies into RenderParams: the Render rows (View rows
    with a kernel field are set by the mapper's policy code: effective threads, the sample
    budget)."""
    return [r for r in rows if r["kind"] == "Render" and r["field"].startswith("RenderParams::")]


def frame_params(rows):
    return ["  amrdm_vtk::FromMapper(params.%s, mapper->Get%s());" % (member(r), r["name"])
            for r in frame_rows(rows)]


def class_rows(rows, bit):
    """The rows of the field class with layer bit `bit` (FIELD_CLASSES)."""
    return [r for r in rows if bit in r["classes"]]


def render_params(rows):
    """RenderParams' fields of the rows with a kernel field "RenderParams::<member>" (a nested
    one, "RenderParams::elementTest.test", is declared by its struct): the kernel type, the
    table's default, the row's documentation."""
    out = []
    for r in rows:
        if not r["field"].startswith("RenderParams::") or "." in r["field"]:
            continue
        t, n, d = r["ktype"], member(r), "param::%s.defaultValue" % r["name"]
        init = {"int": "int(%s)" % d, "float": "float(%s)" % d, "bool": "%s != 0.0" % d,
                "glm::vec3": "glm::vec3{ float(%s) }" % d,
                "glm::ivec3": "glm::ivec3{ int(%s) }" % d}.get(t, "%s(int(%s))" % (t, d))
        text = "%s: %s; %s, default %s." % (r["name"], r["doc"], range_text(r),
                                            default_text(r))
        out += wrap(text, "  /// ", 98)
        out.append("  %s %s = %s;" % (t, n, init))
    return out


def table_index(rows):
    return ["  &param::%s," % r["name"] for r in rows]


def _field_blocks():
    blocks = []
    for bit, (header, source) in FIELD_CLASSES.items():
        blocks += [(header, "field-api", lambda rows, b=bit: mapper_api(class_rows(rows, b))),
                   (header, "field-fields", lambda rows, b=bit: mapper_fields(class_rows(rows, b))),
                   (source, "field-print", lambda rows, b=bit: mapper_print(class_rows(rows, b)))]
    return blocks


BLOCKS = [
    (TABLE, "table-index", table_index),
    ("Kernels/render/RenderParams.h", "render-params", render_params),
    ("Mapper/vtkAMRDualMeshVolumeMapper.h", "mapper-api", lambda rows: mapper_api(mapper_rows(rows))),
    ("Mapper/vtkAMRDualMeshVolumeMapper.h", "mapper-fields",
     lambda rows: mapper_fields(mapper_rows(rows))),
    ("Mapper/vtkAMRDualMeshVolumeMapper.cxx", "mapper-print",
     lambda rows: mapper_print(mapper_rows(rows))),
    ("Plugin/Representation/vtkAMRDualMeshRepresentation.h", "representation-setters",
     representation_setters),
    ("Plugin/Representation/vtkAMRDualMeshRepresentationProperties.cxx",
     "representation-forwarders", representation_forwarders),
    ("Plugin/Representation/AMRDualMeshRepresentation.xml", "xml-properties", xml_properties),
    ("Plugin/Representation/AMRDualMeshRepresentation.xml", "xml-exposed-basic",
     lambda rows: xml_exposed(rows, False)),
    ("Plugin/Representation/AMRDualMeshRepresentation.xml", "xml-exposed-advanced",
     lambda rows: xml_exposed(rows, True)),
    ("Apps/RenderCommandLine.cxx", "cli-options", cli_options),
    ("Kernels/io/SceneFile.h", "scene-build-fields", scene_build_fields),
    ("Kernels/io/SceneFile.cpp", "scene-parameters", scene_parameters),
    ("Mapper/AMRDualMeshFrameBuilder.cxx", "frame-params", frame_params),
] + _field_blocks()


def marker_re(kind, name):
    return re.compile(r"^[ \t]*(?://|<!--) %s GENERATED %s\b.*$" % (kind, re.escape(name)),
                      re.M)


def replace_block(text, name, lines, path):
    """text with the lines between the block's markers replaced; TableError without markers.
    C++ blocks are kept out of clang-format (FormatCheck) so that the generator alone writes
    them."""
    begin, end = marker_re("BEGIN", name).search(text), marker_re("END", name).search(text)
    if not begin or not end or end.start() < begin.end():
        raise TableError("%s: no '%s' block; expected a line '// BEGIN GENERATED %s (%s)' "
                         "(or '<!-- ... -->' in XML) and later '// END GENERATED %s'"
                         % (path, name, name, TOOL, name))
    marker = text[begin.start():begin.end()]
    if marker.lstrip().startswith("//") and lines:
        indent = marker[:len(marker) - len(marker.lstrip())]
        lines = [indent + "// clang-format off"] + lines + [indent + "// clang-format on"]
    body = "\n".join(lines)
    return text[:begin.end()] + "\n" + body + ("\n" if body else "") + text[end.start():]


# --- Checks of the hand-written code that carries the rows --------------------------------
def carried(rows, source_dir):
    """Messages for View rows whose RenderParams field no hand-written mapper code sets (Render
    rows are copied by the generated frame-params block)."""
    problems = []
    mapper = "".join(open(os.path.join(source_dir, "Mapper", f)).read()
                     for f in sorted(os.listdir(os.path.join(source_dir, "Mapper")))
                     if f.endswith(".cxx"))
    for r in rows:
        if r["kind"] != "View" or not r["field"].startswith("RenderParams::"):
            continue
        if not re.search(r"\bparams\.%s\s*=" % re.escape(member(r)), mapper):
            problems.append("%s: no Mapper/*.cxx sets params.%s (a View row's kernel field is "
                            "set by the mapper's policy code)" % (r["name"], member(r)))
    return problems


def main(argv):
    mode, args = "--check", []
    for a in argv[1:]:
        if a in ("--check", "--write"):
            mode = a
        elif a in ("-h", "--help"):
            print(__doc__)
            return 0
        else:
            args.append(a)
    source_dir = args[0] if args else os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    try:
        rows = read_rows(source_dir)
        contents, originals = {}, {}
        for path, name, make in BLOCKS:
            full = os.path.join(source_dir, path)
            if path not in contents:
                contents[path] = originals[path] = open(full).read()
            contents[path] = replace_block(contents[path], name, make(rows), path)
    except (TableError, OSError) as e:
        print("generate_parameters: %s" % e, file=sys.stderr)
        return 2
    stale = [p for p in contents if contents[p] != originals[p]]
    problems = carried(rows, source_dir)
    for p in problems:
        print("generate_parameters: not carried: " + p, file=sys.stderr)
    if mode == "--write":
        for p in stale:
            with open(os.path.join(source_dir, p), "w") as f:
                f.write(contents[p])
            print("wrote " + p)
        print("%d rows; %d files rewritten, %d current" % (len(rows), len(stale),
                                                           len(contents) - len(stale)))
        return 1 if problems else 0
    for p in stale:
        sys.stdout.writelines(difflib.unified_diff(
            originals[p].splitlines(True), contents[p].splitlines(True),
            "a/" + p + " (committed)", "b/" + p + " (generated from the table)"))
    if stale:
        print("\n%d file(s) have stale generated blocks: %s\nrun: python3 %s --write"
              % (len(stale), ", ".join(stale), TOOL))
    else:
        print("%d rows; every generated block in %d files is current" % (len(rows),
                                                                         len(contents)))
    return 1 if stale or problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
