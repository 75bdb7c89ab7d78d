"""Runs a README example that writes a PNG (its first argument) and compares that PNG with its
baseline (baseline_image.py): the example must not only run but draw the right picture.

  python3 RunExample.py EXAMPLE.py OUTPUT.png BASELINE.png TEMP_DIR
"""
import os
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "Support"))
from baseline_image import compare_png  # noqa: E402


def main():
    example, png, baseline, temp_dir = sys.argv[1:5]
    os.makedirs(temp_dir, exist_ok=True)
    if os.path.exists(png):
        os.remove(png)
    run = subprocess.run([sys.executable, example, png])
    if run.returncode != 0:
        print("FAILED: %s exited with %d" % (example, run.returncode))
        return 1
    if not os.path.exists(png):
        print("FAILED: %s wrote no %s" % (example, png))
        return 1
    return 0 if compare_png(png, baseline, temp_dir) else 1


if __name__ == "__main__":
    sys.exit(main())
