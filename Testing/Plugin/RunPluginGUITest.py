"""GUI smoke test: `paraview --script=PluginGUIScript.py --exit` loads the plugin and renders
with it; fails when ParaView's output holds an error, a Python traceback or no success line,
when it does not finish in time, or when its screenshot does not match BASELINE_PNG
(Testing/Support/baseline_image.py). Run under an X server (ctest runs under `xvfb-run -a`).

  python3 RunPluginGUITest.py PARAVIEW PLUGIN DATA_DIR SCREENSHOT_PNG BASELINE_PNG
"""
import os
import subprocess
import sys

paraview, plugin, data, screenshot, baseline = sys.argv[1:6]
here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(here, "..", "Support"))
from baseline_image import compare_png  # noqa: E402

env = dict(os.environ, AMRDM_PLUGIN=plugin, AMRDM_DATA=data, AMRDM_GUI_SCREENSHOT=screenshot)
os.makedirs(os.path.dirname(os.path.abspath(screenshot)), exist_ok=True)
if os.path.exists(screenshot):
    os.remove(screenshot)
# --dr: no user settings; the script runs once the main window is up, --exit quits after it.
cmd = [paraview, "--dr", "--script=" + os.path.join(here, "PluginGUIScript.py"), "--exit"]
try:
    run = subprocess.run(cmd, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                         text=True, timeout=240)
except subprocess.TimeoutExpired as e:
    print((e.stdout or b"").decode(errors="replace") if isinstance(e.stdout, bytes) else e.stdout)
    print("FAILED: paraview did not exit within 240 s")
    sys.exit(1)
out = run.stdout
print(out)
problems = [line for line in out.splitlines()
            if "ERR|" in line or "Traceback" in line or "Error" in line.split("|")[-1][:40]]
if problems:
    print("FAILED: errors in the output:\n  " + "\n  ".join(problems))
    sys.exit(1)
if run.returncode != 0:
    print("FAILED: paraview exited with %d" % run.returncode)
    sys.exit(1)
if "AMRDM_GUI_OK" not in out or "Dual-Mesh Path Tracer" not in out:
    print("FAILED: the script did not finish (no AMRDM_GUI_OK line with the representation)")
    sys.exit(1)
if not os.path.exists(screenshot):
    print("FAILED: no screenshot at " + screenshot)
    sys.exit(1)
if not compare_png(screenshot, baseline, os.path.dirname(os.path.abspath(screenshot))):
    sys.exit(1)
print("PASSED: the GUI loaded the plugin and rendered the baseline's picture: " + screenshot)
