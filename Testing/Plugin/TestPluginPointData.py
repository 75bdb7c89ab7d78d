"""ParaView plugin test (issue 35): the "Dual-Mesh Path Tracer" representation coloured by a point
(vertex-centred) array, ColorBy(d, ('POINTS', 'phi')), renders it as it is, like its cell-centred
twin. The AMReX advection set through vtkCellDataToPointData is written as a .vthb (point 'phi'
only) and read back with ParaView's XMLUniformGridAMRReader; the plotfile's cell 'phi' is the
twin. Ray Marching, 2 samples, the same camera and maps: the pixels brighter than 0.05 cover the
same area (IoU >= 0.9); both screenshots go to the temp folder.

  pvpython TestPluginPointData.py --plugin AMRDualMeshPlugin.so --temp-dir DIR
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "Support"))
from amrdm_testing import amrex_reader  # noqa: E402
from pv_testing import (ADVECTION, bare_view, load_plugin, plugin_args, png_rgb,  # noqa: E402
                        ray_marching, shoot, show_dual_mesh)


def main():
    args = plugin_args(__doc__)
    from vtkmodules.vtkFiltersCore import vtkCellDataToPointData
    from vtkmodules.vtkIOXML import vtkXMLUniformGridAMRWriter
    import numpy as np

    simple = load_plugin(args.plugin)
    plotfile = ADVECTION
    reader = amrex_reader(plotfile)
    to_points = vtkCellDataToPointData()
    to_points.SetInputConnection(reader.GetOutputPort())
    vthb = os.path.join(args.temp_dir, "PluginPointData.vthb")
    writer = vtkXMLUniformGridAMRWriter()
    writer.SetInputConnection(to_points.GetOutputPort())
    writer.SetFileName(vthb)
    writer.Write()

    coverage = {}
    for label, association, make in (
            ("points", "POINTS", lambda: simple.XMLUniformGridAMRReader(FileName=[vthb])),
            ("cells", "CELLS", lambda: simple.AMReXBoxLibGridReader(FileNames=[plotfile]))):
        src = make()
        src.UpdatePipelineInformation()
        if label == "cells":
            src.Level = 100
            src.CellArrayStatus = ["phi"]
        else:
            src.DefaultNumberOfLevels = 100  # all levels (level 0 only by default)
        src.UpdatePipeline()
        view = bare_view(simple, [240, 180])
        display, lut = show_dual_mesh(simple, src, view, "phi", association)
        lut.ApplyPreset("Cool to Warm", True)
        lut.RescaleTransferFunction(1.0, 2.0)
        pwf = simple.GetOpacityTransferFunction("phi")
        pwf.Points = [1.0, 0.0, 0.5, 0.0, 1.3, 0.3, 0.5, 0.0, 2.0, 0.9, 0.5, 0.0]
        ray_marching(display, 2)
        png = shoot(simple, view, ([1.2, -0.6, 1.0], [0.5, 0.5, 0.12], [0.0, 0.0, 1.0]),
                    os.path.join(args.temp_dir, "PluginPointData-%s.png" % label), [240, 180])
        coverage[label] = png_rgb(png).reshape(-1, 3).sum(axis=1) > 0.05
        simple.Delete(display)
        simple.Delete(view)
    inter = np.logical_and(coverage["points"], coverage["cells"]).sum()
    union = max(1, np.logical_or(coverage["points"], coverage["cells"]).sum())
    iou = inter / union
    print("coverage: points %.3f, cells %.3f of the image; IoU %.3f (>= 0.9); screenshots in %s"
          % (coverage["points"].mean(), coverage["cells"].mean(), iou, args.temp_dir))
    ok = coverage["cells"].mean() > 0.02 and iou >= 0.9
    print("PASS" if ok else "FAIL")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
