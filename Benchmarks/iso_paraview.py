"""ParaView's Contour of an AMR .vthb resampled to its finest level, for the isosurface accuracy
benchmark (Benchmarks/iso_accuracy.py scores the triangles along the same rays as ours).

    pvpython Benchmarks/iso_paraview.py FILE.vthb ARRAY ISO[,ISO...] OUT_DIR

Two ParaView pipelines, both at the finest level's spacing h over the domain [lo, hi]:
  centres   ResampleToImage of the cell data with SamplingBounds at the finest cell centres
            (lo + h/2 .. hi - h/2, (hi - lo) / h samples a side): every sample is the value of
            the leaf cell holding it (a finest cell's own value where the finest level exists);
            Contour (marching cubes, linear along the edges) of that image.
  pointdata CellDatatoPointData (per block), then ResampleToImage over the input bounds at
            (hi - lo) / h + 1 samples a side (spacing h), then Contour: ParaView's usual idiom.
Each contour is written as OUT_DIR/<pipeline>-<k>.vtp (k: index of the iso value) and a summary
OUT_DIR/paraview.json (sampling, triangle counts, seconds).
"""
import json
import os
import sys
import time

from paraview import simple, servermanager
from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter, vtkXMLUniformGridAMRReader


def main():
    if len(sys.argv) != 5:
        sys.exit("usage: iso_paraview.py FILE.vthb ARRAY ISO[,ISO...] OUT_DIR")
    path, array, iso_text, out_dir = sys.argv[1:]
    try:
        isos = [float(v) for v in iso_text.split(",")]
    except ValueError:
        sys.exit("iso_paraview.py: ISO '%s': expected numbers separated by commas" % iso_text)
    if not os.path.isfile(path):
        sys.exit("iso_paraview.py: %s: no such file" % path)
    os.makedirs(out_dir, exist_ok=True)
    reader = simple.XMLUniformGridAMRReader(FileName=[path])
    reader.DefaultNumberOfLevels = 0  # every level (ParaView's default reads one)
    reader.CellArrayStatus = [array]
    reader.UpdatePipeline()
    meta = vtkXMLUniformGridAMRReader()  # the hierarchy's levels, spacing and bounds
    meta.SetFileName(path)
    meta.SetMaximumLevelsToReadByDefault(0)
    meta.Update()
    amr = meta.GetOutput()
    levels = amr.GetNumberOfLevels()
    if levels == 0:
        sys.exit("iso_paraview.py: %s: ParaView read no AMR levels" % path)
    h = [0.0, 0.0, 0.0]
    amr.GetAMRInfo().GetSpacing(levels - 1, h)
    b = [0.0] * 6
    amr.GetBounds(b)
    n = [int(round((b[2 * a + 1] - b[2 * a]) / h[a])) for a in range(3)]
    centres = [b[0] + h[0] / 2, b[1] - h[0] / 2, b[2] + h[1] / 2, b[3] - h[1] / 2,
               b[4] + h[2] / 2, b[5] - h[2] / 2]
    pipelines = {
        "centres": (simple.ResampleToImage(Input=reader, UseInputBounds=0, SamplingBounds=centres,
                                           SamplingDimensions=n), n),
        "pointdata": (simple.ResampleToImage(Input=simple.CellDatatoPointData(Input=reader),
                                             UseInputBounds=1,
                                             SamplingDimensions=[m + 1 for m in n]),
                      [m + 1 for m in n]),
    }
    summary = {"file": path, "levels": levels, "finest_spacing": h, "bounds": list(b),
               "pipelines": {}}
    for name, (resample, dims) in pipelines.items():
        t0 = time.time()
        resample.UpdatePipeline()
        t_resample = time.time() - t0
        rows = []
        for k, iso in enumerate(isos):
            t0 = time.time()
            contour = simple.Contour(Input=resample, ContourBy=["POINTS", array],
                                     Isosurfaces=[iso], ComputeNormals=0, ComputeScalars=0)
            contour.UpdatePipeline()
            poly = servermanager.Fetch(contour)
            seconds = time.time() - t0
            out = os.path.join(out_dir, "%s-%d.vtp" % (name, k))
            w = vtkXMLPolyDataWriter()
            w.SetFileName(out)
            w.SetInputData(poly)
            if not w.Write():
                sys.exit("iso_paraview.py: cannot write %s" % out)
            rows.append({"iso": iso, "triangles": poly.GetNumberOfCells(),
                         "points": poly.GetNumberOfPoints(), "contour_s": seconds, "file": out})
            simple.Delete(contour)
        summary["pipelines"][name] = {"dims": dims, "resample_s": t_resample, "contours": rows}
        print("paraview %s: %s samples, resample %.1f s, %s triangles" % (
            name, "x".join(str(d) for d in dims), t_resample,
            ", ".join(str(r["triangles"]) for r in rows)))
    with open(os.path.join(out_dir, "paraview.json"), "w") as f:
        json.dump(summary, f, indent=1)


if __name__ == "__main__":
    main()
