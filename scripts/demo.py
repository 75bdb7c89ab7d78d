"""Demo from Python: the dual mesh of the embedded Enzo data set, sampled at the domain centre."""
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
print("Python: %d leaf cells, %.2f bytes per leaf cell" % (mesh.GetNumberOfLeafCells(), mesh.GetBytesPerLeafCell()))
print("Density at the domain centre:", mesh.Sample(0.5, 0.5, 0.5))
