"""Compares a PNG with its baseline through vtkTesting::RegressionTest (the comparison VTK's
and ParaView's own image tests use: per-pixel colour error after a small neighbourhood search,
averaged; threshold 0.05 as in TestPluginRender and TestVolumeMapperPython). A missing baseline
fails with the path to copy the new image to; AMRDM_REGENERATE_BASELINES=1 writes it instead
(then look at the image before committing it)."""
import os
import shutil


def compare_png(png, baseline, temp_dir, threshold=0.05):
    if os.environ.get("AMRDM_REGENERATE_BASELINES") == "1":
        shutil.copyfile(png, baseline)
        print("REGENERATED: %s from %s" % (baseline, png))
        return True
    if not os.path.exists(baseline):
        print("FAILED: no baseline %s (look at %s; copy it there if it is right)" % (baseline, png))
        return False
    from vtkmodules.vtkTestingRendering import vtkTesting
    t = vtkTesting()
    for a in ("-T", temp_dir, "-V", baseline):
        t.AddArgument(a)
    ok = t.RegressionTest(png, threshold) == vtkTesting.PASSED
    print("%s: %s against %s (threshold %g)" % ("PASSED" if ok else "FAILED", png, baseline,
                                                 threshold))
    return ok
