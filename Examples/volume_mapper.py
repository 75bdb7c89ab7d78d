"""Path-trace the embedded Enzo AMR set with vtkAMRDualMeshVolumeMapper and save a PNG.
Run: PYTHONPATH=build/lib/python3/dist-packages /usr/bin/python3 Examples/volume_mapper.py [out.png]"""
import os, sys
from vtkmodules.vtkCommonDataModel import vtkPiecewiseFunction
from vtkmodules.vtkIOAMR import vtkAMREnzoReader
from vtkmodules.vtkIOImage import vtkPNGReader, vtkPNGWriter
from vtkmodules.vtkRenderingCore import (vtkColorTransferFunction, vtkRenderer, vtkRenderWindow,
                                         vtkVolume, vtkVolumeProperty, vtkWindowToImageFilter)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (registers the OpenGL render window)
from amrdualmesh import vtkAMRDualMeshVolumeMapper

reader = vtkAMREnzoReader()
reader.SetFileName(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "Testing", "Data",
                                "enzo-moving7_DD0010", "moving7_0010.hierarchy"))
reader.UpdateInformation(); reader.SetMaxLevel(99)  # readers load level 0 and no arrays by default
reader.GetCellDataArraySelection().EnableAllArrays()

color, opacity, prop = vtkColorTransferFunction(), vtkPiecewiseFunction(), vtkVolumeProperty()
color.AddRGBPoint(2e-27, 0.3, 0.5, 0.95); color.AddRGBPoint(1.5e-26, 1.0, 0.5, 0.15)  # g/cm^3
opacity.AddPoint(1e-27, 0.0); opacity.AddPoint(4e-26, 0.9)
prop.SetColor(color); prop.SetScalarOpacity(opacity); prop.SetScalarOpacityUnitDistance(0.02)

mapper, volume = vtkAMRDualMeshVolumeMapper(), vtkVolume()
ren, window = vtkRenderer(), vtkRenderWindow()
mapper.SetInputConnection(reader.GetOutputPort()); mapper.SelectScalarArray("Density")
mapper.SetEnvironmentRadiance(1.0, 1.0, 1.0)  # white environment light for scattered paths
volume.SetMapper(mapper); volume.SetProperty(prop); ren.AddVolume(volume)
window.SetSize(400, 400); window.SetOffScreenRendering(True); window.AddRenderer(ren)
ren.ResetCamera(); ren.GetActiveCamera().Zoom(1.3)
mapper.RenderUntil(window, 64)  # progressive path tracing: 64 samples per pixel

grab, writer = vtkWindowToImageFilter(), vtkPNGWriter()
grab.SetInput(window); writer.SetInputConnection(grab.GetOutputPort())
writer.SetFileName(sys.argv[1] if len(sys.argv) > 1 else "enzo-mapper.png"); writer.Write()

png = vtkPNGReader(); png.SetFileName(writer.GetFileName()); png.Update()  # fail when blank
sys.exit(0 if png.GetOutput().GetScalarRange()[1] > 32 else "blank image: " + writer.GetFileName())
