#!/usr/bin/env bash
# The default amrdm-render picture of each shared set (no options but -o), and the 2x2 overview
# amrdm-render-sets.png that the README shows. Usage:
#   bash docs/images/make-default-pictures.sh build/bin/amrdm-render ../shared/amr-data
set -euo pipefail
app="$1"
data="$2"
out="$(cd "$(dirname "$0")" && pwd)"
declare -A sets=(
  [enzo]="enzo-moving7_DD0010/moving7_0010.hierarchy"
  [flame]="amrex-pelelmex-flame3d_plt"
  [advection]="amrex-advection-amrcore3d/plt00040"
  [vortex]="amrex-singlevortex3d-128/plt00040"
)
for name in enzo flame advection vortex; do
  echo "== $name: amrdm-render $data/${sets[$name]} -o $out/default-$name.png"
  "$app" "$data/${sets[$name]}" -o "$out/default-$name.png" 2>&1 | grep -v "frame [0-9]"
  rm -f "$out/default-$name.exr"
done
/usr/bin/python3 - "$out" <<'PY'
import sys
from vtkmodules.vtkIOImage import vtkPNGReader, vtkPNGWriter
from vtkmodules.vtkFiltersCore import vtkImageAppend
folder = sys.argv[1]
def load(name):
    r = vtkPNGReader()
    r.SetFileName("%s/default-%s.png" % (folder, name))
    r.Update()
    return r.GetOutput()
rows = []
for pair in (("advection", "vortex"), ("enzo", "flame")):  # VTK images run bottom-up
    row = vtkImageAppend()
    row.SetAppendAxis(0)
    for name in pair:
        row.AddInputData(load(name))
    row.Update()
    rows.append(row.GetOutput())
grid = vtkImageAppend()
grid.SetAppendAxis(1)
for r in rows:
    grid.AddInputData(r)
w = vtkPNGWriter()
w.SetFileName("%s/amrdm-render-sets.png" % folder)
w.SetInputConnection(grid.GetOutputPort())
w.Write()
print("wrote %s/amrdm-render-sets.png (top: Enzo, flame; bottom: advection, vortex)" % folder)
PY
