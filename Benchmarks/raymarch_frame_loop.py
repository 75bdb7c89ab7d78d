"""Ray-marching frames through the mapper alone, in a VTK window, for profiling (perf record -g).

    PYTHONPATH=build/lib/python3/dist-packages xvfb-run -a /usr/bin/python3 \
        Benchmarks/raymarch_frame_loop.py SCENES.json SET FRAMES [STEP]

SCENES.json: amrdm-bench's scenes.json (camera, colour / opacity table, unit distance; linear
sets only: a log set needs ParaView's Calculator). The mapper at Ray Marching, 1 sample a
render, StepSize STEP (default 0: the automatic step), 2 threads; one untimed Render (the
build), then FRAMES renders with the camera nudged by 1e-4 degree between them. Prints the
median wall time of a frame and the mapper's GetLastRenderSeconds (the renderer's part):
their difference is the per-frame cost outside the kernels.
"""
import sys, time, json, statistics
from vtkmodules.vtkCommonDataModel import vtkPiecewiseFunction
from vtkmodules.vtkIOAMR import vtkAMREnzoReader, vtkAMReXGridReader
from vtkmodules.vtkRenderingCore import (vtkColorTransferFunction, vtkRenderer, vtkRenderWindow, vtkVolume, vtkVolumeProperty)
import vtkmodules.vtkRenderingOpenGL2  # noqa
from amrdualmesh import vtkAMRDualMeshVolumeMapper
if len(sys.argv) < 4:
    sys.exit(__doc__)
scenes, name, n = sys.argv[1], sys.argv[2], int(sys.argv[3])
step = float(sys.argv[4]) if len(sys.argv) > 4 else 0.0
sc = [s for s in json.load(open(scenes)) if s["name"] == name][0]
r = vtkAMREnzoReader() if sc["reader"] == "enzo" else vtkAMReXGridReader()
r.SetFileName(sc["path"]); r.UpdateInformation(); r.SetMaxLevel(99); r.GetCellDataArraySelection().EnableAllArrays(); r.Update()
amr = r.GetOutput()
if sc["log_scale"]:
    raise SystemExit("log sets: use pvpython")
tf = sc["tf"]; lo, hi, table = tf["lo"], tf["hi"], tf["table"]
col, op, prop = vtkColorTransferFunction(), vtkPiecewiseFunction(), vtkVolumeProperty()
for i, e in enumerate(table):
    v = lo + (hi - lo) * i / (len(table) - 1); col.AddRGBPoint(v, e[0], e[1], e[2]); op.AddPoint(v, e[3])
prop.SetColor(col); prop.SetScalarOpacity(op); prop.SetScalarOpacityUnitDistance(tf["unit_distance"])
m, vol, ren, w = vtkAMRDualMeshVolumeMapper(), vtkVolume(), vtkRenderer(), vtkRenderWindow()
m.SetInputData(amr); m.SelectScalarArray(sc["array"]); m.SetIntegrator(m.RAY_MARCH); m.SetNumberOfThreads(2)
m.SetSamplesPerRender(1); m.SetMaximumSamples(1); m.SetStepSize(step)
vol.SetMapper(m); vol.SetProperty(prop); ren.AddVolume(vol); w.SetSize(sc["width"], sc["height"]); w.SetOffScreenRendering(True); w.AddRenderer(ren)
cam = ren.GetActiveCamera(); c = sc["camera"]
cam.SetPosition(c["position"]); cam.SetFocalPoint(c["focal_point"]); cam.SetViewUp(c["view_up"]); cam.SetViewAngle(c["view_angle"]); ren.ResetCameraClippingRange()
t0 = time.perf_counter(); w.Render(); print("first %.2f s" % (time.perf_counter() - t0), flush=True)
ts, rs = [], []
for k in range(n):
    cam.Azimuth(1e-4 if k % 2 == 0 else -1e-4)
    t = time.perf_counter(); w.Render(); ts.append(time.perf_counter() - t); rs.append(m.GetLastRenderSeconds())
print("%s median frame %.1f ms, render %.1f ms" % (name, 1e3 * statistics.median(ts), 1e3 * statistics.median(rs)), flush=True)
