"""Demo: the dual mesh of the embedded Enzo data set (counts, memory, a probe)."""
import json
import sys

from vtkmodules.vtkIOAMR import vtkAMREnzoReader
from amrdualmesh import vtkAMRDualMesh

path = sys.argv[1]
reader = vtkAMREnzoReader()
reader.SetFileName(path)
reader.UpdateInformation()
reader.SetMaxLevel(99)
reader.GetCellDataArraySelection().EnableAllArrays()
reader.Update()

mesh = vtkAMRDualMesh()
mesh.SetInputData(reader.GetOutput())
mesh.SetArrayName("Density")
if not mesh.Update():
    sys.exit("demo: building the dual mesh failed")
print(json.dumps(json.loads(mesh.GetReportJSON()), indent=2))
print("Density at the domain centre:", mesh.Sample(0.5, 0.5, 0.5))
