"""pvbatch script of the MPI tests (TestPluginMPI.py runs it): one image of an AMR set drawn by
the "Dual-Mesh Path Tracer" on every rank of `mpiexec -np N pvbatch --symmetric`.

  mpiexec -np N pvbatch --symmetric MPIRender.py --plugin P --data FILE --out PNG [options]

Every rank runs this script (symmetric mode). Gotchas of symmetric mode, all handled here:
property defaults computed from the data's domains are not applied (the unit distance is set
explicitly) and each rank would rescale the colour map to its local range (the range is set
explicitly, never rescaled). Prints one report per rank ("rank R/N: ordered=O samples=S region=(...)
... frame=SECONDS vmhwm_kib=PEAK_RSS"); rank 0 writes the PNG(s).
"""
import argparse
import os
import sys


def parse_args():
    p = argparse.ArgumentParser()
    p.add_argument("--plugin", required=True)
    p.add_argument("--data", required=True, help="plotfile directory, .vthb or Enzo .hierarchy")
    p.add_argument("--array", default="phi")
    p.add_argument("--range", type=float, nargs=2, default=[1.0, 2.0])
    p.add_argument("--opacity", type=float, nargs="+",
                   default=[1.0, 0.0, 0.5, 0.0, 1.3, 0.05, 0.5, 0.0, 2.0, 1.0, 0.5, 0.0])
    p.add_argument("--unit", type=float, default=0.05, help="ScalarOpacityUnitDistance")
    p.add_argument("--integrator", default="Ray Marching")
    p.add_argument("--mode", default="Partitioned", help="DistributionMode")
    p.add_argument("--samples", type=int, default=8)
    p.add_argument("--step", type=float, default=0.0, help="StepSize (0: automatic)")
    p.add_argument("--seed", type=int, default=7)
    p.add_argument("--size", type=int, nargs=2, default=[200, 150])
    p.add_argument("--camera", type=float, nargs=9,
                   default=[0.65, -0.5, 1.1, 0.65, 0.6, 0.125, 0.0, 0.0, 1.0],
                   help="position, focal point, view up")
    p.add_argument("--out", required=True)
    p.add_argument("--connect", default="", help="HOST:PORT of a pvserver (run by pvpython)")
    p.add_argument("--seeds", type=int, nargs="*", default=[],
                   help="also render these seeds, one PNG each (OUT with -seedS before .png)")
    p.add_argument("--frames", type=int, default=0,
                   help="then time this many more frames (a new seed each: a full frame)")
    return p.parse_args()


def rss_kib():
    with open("/proc/self/status") as f:
        for line in f:
            if line.startswith("VmHWM:"):
                return int(line.split()[1])
    return 0


def main():
    args = parse_args()
    from paraview import simple
    from paraview.modules.vtkRemotingCore import vtkProcessModule
    pm = vtkProcessModule.GetProcessModule()
    rank, ranks = pm.GetPartitionId(), pm.GetNumberOfLocalPartitions()
    simple._DisableFirstRenderCameraReset()
    if args.connect:
        host, port = args.connect.rsplit(":", 1)
        simple.Connect(host, int(port))
    simple.LoadPlugin(args.plugin, remote=False, ns=globals())
    if args.connect:
        simple.LoadPlugin(args.plugin, remote=True, ns=globals())
    if args.data.endswith(".vthb"):
        reader = simple.XMLUniformGridAMRReader(FileName=[args.data])
        reader.DefaultNumberOfLevels = 0  # all levels
    elif args.data.endswith(".hierarchy"):
        reader = simple.EnzoReader(FileNames=[args.data])
    else:
        reader = simple.AMReXBoxLibGridReader(FileNames=[args.data])
    reader.UpdatePipelineInformation()
    if hasattr(reader, "Level"):
        reader.Level = 100
    reader.CellArrayStatus = [args.array]
    view = simple.CreateView("RenderView")
    view.ViewSize = args.size
    view.OrientationAxesVisibility = 0
    view.UseColorPaletteForBackground = 0
    view.Background = [0.0, 0.0, 0.0]
    d = simple.Show(reader, view)
    d.SetRepresentationType("Dual-Mesh Path Tracer")
    simple.ColorBy(d, ("CELLS", args.array))
    lut = simple.GetColorTransferFunction(args.array)
    lut.ApplyPreset("Cool to Warm", True)
    lut.AutomaticRescaleRangeMode = "Never"
    lut.RescaleTransferFunction(*args.range)
    pwf = simple.GetOpacityTransferFunction(args.array)
    pwf.Points = args.opacity
    pwf.AllowDuplicateScalars = 1
    d.Integrator = args.integrator
    d.DistributionMode = args.mode
    d.ScalarOpacityUnitDistance = args.unit
    d.NumberOfThreads = 1
    d.Seed = args.seed
    d.StepSize = args.step
    d.SamplesPerRender = args.samples
    d.MaximumSamples = args.samples
    d.RefineWhileIdle = 0
    view.CameraPosition = args.camera[0:3]
    view.CameraFocalPoint = args.camera[3:6]
    view.CameraViewUp = args.camera[6:9]
    view.CameraViewAngle = 30
    import time
    start = time.time()
    simple.Render(view)
    seconds = time.time() - start
    simple.SaveScreenshot(args.out, view, ImageResolution=args.size)
    frame = 0.0
    for i in range(args.frames):
        d.Seed = 1000 + i
        start = time.time()
        simple.Render(view)
        frame += (time.time() - start) / args.frames
    for s in args.seeds:
        d.Seed = s
        simple.Render(view)
        simple.SaveScreenshot(args.out.replace(".png", "-seed%d.png" % s), view,
                              ImageResolution=args.size)
    ordered = view.GetClientSideObject().GetUseOrderedCompositing()
    d.UpdatePropertyInformation()
    info = lambda name: d.SMProxy.GetProperty(name)
    region = [info("RegionBounds").GetElement(i) for i in range(6)]
    print("rank %d/%d: ordered=%d samples=%d region=(%s) redistribution=%.2fs bytes=%d "
          "mesh_bytes=%d render=%.2fs frame=%.3fs vmhwm_kib=%d" % (
              rank, ranks, int(ordered), info("AccumulatedSamples").GetElement(0),
              ", ".join("%.6g" % v for v in region),
              info("RedistributionSeconds").GetElement(0),
              int(info("RedistributedBytes").GetElement(0)),
              int(info("DualMeshBytes").GetElement(0)), seconds, frame, rss_kib()), flush=True)
    simple.Delete(d)
    simple.Delete(view)
    if args.connect:
        simple.Disconnect()
    return 0


if __name__ == "__main__":
    main()  # no sys.exit: pvbatch finalizes MPI when the script returns
