"""Runs inside the ParaView GUI (`paraview --script=PluginGUIScript.py --exit`, see
RunPluginGUITest.py): loads the plugin, shows the AMReX test set with the "Dual-Mesh Path Tracer"
representation in the GUI's render view and saves a screenshot of it. Inputs come from the
environment: AMRDM_PLUGIN (the .so), AMRDM_DATA (Testing/Data), AMRDM_GUI_SCREENSHOT (PNG)."""
import os
from paraview import simple

simple.LoadPlugin(os.environ["AMRDM_PLUGIN"], remote=False, ns=globals())
reader = simple.AMReXBoxLibGridReader(FileNames=[os.path.join(
    os.environ["AMRDM_DATA"], "amrex-advection-amrcore3d", "plt00040")])
reader.UpdatePipelineInformation()
reader.Level = 100
reader.CellArrayStatus = ["phi"]
view = simple.GetActiveViewOrCreate("RenderView")
display = simple.Show(reader, view)
display.SetRepresentationType("Dual-Mesh Path Tracer")
simple.ColorBy(display, ("CELLS", "phi"))
display.RescaleTransferFunctionToDataRange(True, False)
display.SetScalarBarVisibility(view, True)
display.SamplesPerRender = 16
display.MaximumSamples = 16
view.CameraPosition = [0.65, -0.5, 1.1]
view.CameraFocalPoint = [0.65, 0.6, 0.125]
view.CameraViewUp = [0.0, 0.0, 1.0]
simple.Render(view)
simple.SaveScreenshot(os.environ["AMRDM_GUI_SCREENSHOT"], view, ImageResolution=[640, 480])
print("AMRDM_GUI_OK representations:", ", ".join(display.Representation.Available))
