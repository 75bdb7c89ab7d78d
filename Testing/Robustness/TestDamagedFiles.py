"""Damaged AMR files through amrdm-render (issue 33): truncations at many offsets, byte flips in
headers and data, and missing files, over the small sets in Testing/Data (Enzo, two AMReX
plotfiles, and two .vthb written here from the Enzo set: zlib-compressed and uncompressed
appended raw data) and the shared large AMReX set when it is there. Each case runs amrdm-render
(32x32, 1 sample, 2 threads) in a subprocess with a 10 s limit and must end in one of two ways:
- exit 0 with the whole hierarchy: vtkAMRDualMeshFileCheck passed on the damaged copy, and the
  render reports exactly as many leaf cells as on the intact set (a damaged byte the reader never
  reads, or a changed value inside a data array, renders whole);
- exit 1..127 with a message on stderr that names the file (the damaged set's path) and the cause.
  A value a flipped byte made NaN, infinite or beyond float range becomes a hole with a warning
  that counts the holes, and a vtkGhostType byte flipped to "hidden" hides a cell with a warning
  that counts them: the leaf cells must then be the intact count minus those counts; a .vthb
  DataSet whose file attribute is damaged is an empty block, rendered without it after a warning
  that gives the blocks and cells left out.
A hang (10 s), a crash (a signal or exit >= 128), an exit 0 with fewer leaf cells or after a failed
check (a silent partial render), and a failure without a file name each fail the test.

Usage: TestDamagedFiles.py AMRDM_RENDER [CASES] [SEED]; CASES (default 48) are spread over the
sets and damage kinds; ctest runs 48, the `long` label 1200. Prints the counts by outcome."""
import os
import random
import re
import shutil
import subprocess
import sys
import tempfile
import time

from amrdualmesh import vtkAMRDualMeshFileCheck

APP = sys.argv[1]
CASES = int(sys.argv[2]) if len(sys.argv) > 2 else 48
SEED = int(sys.argv[3]) if len(sys.argv) > 3 else 33
DATA = os.environ.get("AMRDM_TEST_DATA", os.path.join(os.path.dirname(__file__), "..", "Data"))
SHARED = os.environ.get("AMRDM_SHARED_DATA", "")
LIMIT_S = 10.0
RENDER = ["--size", "32", "32", "--spp", "1", "--threads", "2"]
# The reader's watchdog must fire inside the 10 s limit (its default scales with the data).
ENV = dict(os.environ, AMRDM_READ_TIMEOUT="5")


def write_vthb(folder, compressed):
    """The Enzo set as a .vthb (appended raw data), as vtkXMLUniformGridAMRWriter writes it."""
    sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "Support"))
    from amrdm_testing import write_enzo_vthb
    path = os.path.join(folder, "enzo.vthb")
    if not write_enzo_vthb(path, compressed):
        raise SystemExit("could not write " + path)
    return path


def render(path):
    t0 = time.time()
    try:
        p = subprocess.run([APP, path] + RENDER, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                           universal_newlines=True, errors="replace", timeout=LIMIT_S, env=ENV)
    except subprocess.TimeoutExpired:
        return None, "", "", time.time() - t0
    return p.returncode, p.stdout, p.stderr, time.time() - t0


def leaf_cells(stdout):
    m = re.search(r"(\d+) leaf cells", stdout)
    return int(m.group(1)) if m else None


class DataSet:
    def __init__(self, name, source, entry, weight):
        """source: the intact folder; entry: the path amrdm-render opens, relative to it."""
        self.name, self.source, self.entry, self.weight = name, source, entry, weight
        self.files = sorted(os.path.relpath(os.path.join(d, f), source)
                            for d, _, fs in os.walk(source) for f in fs)

    def prepare(self, work):
        self.copy = os.path.join(work, self.name)
        shutil.copytree(self.source, self.copy, copy_function=shutil.copyfile)
        for d, _, fs in os.walk(self.copy):  # the shared sets are read-only
            os.chmod(d, 0o755)
            for f in fs:
                os.chmod(os.path.join(d, f), 0o644)
        self.path = os.path.join(self.copy, self.entry) if self.entry else self.copy
        rc, out, err, _ = render(self.path)
        self.cells = leaf_cells(out)
        if rc != 0 or not self.cells:
            raise SystemExit("FAIL: the intact %s does not render (exit %s): %s" % (
                self.name, rc, err.strip()[-300:]))
        print("intact %s: %d leaf cells, %d files" % (self.name, self.cells, len(self.files)))

    def restore(self, rel):
        shutil.copyfile(os.path.join(self.source, rel), os.path.join(self.copy, rel))


def is_text(path):
    with open(path, "rb") as f:
        return b"\0" not in f.read(4096)


def damage(rng, data, rel):
    """Damages one file of the working copy; returns a description of the damage."""
    target = os.path.join(data.copy, rel)
    size = os.path.getsize(target)
    kind = rng.choice(["truncate", "truncate", "flip-header", "flip-data", "missing"])
    if kind == "missing":
        os.remove(target)
        return "missing " + rel
    with open(target, "rb") as f:
        content = bytearray(f.read())
    if kind == "truncate":
        at = rng.choice([0, 1, size // 2, size - 1, rng.randrange(max(size, 1))])
        at = min(max(at, 0), max(size - 1, 0))
        with open(target, "wb") as f:
            f.write(content[:at])
        return "%s cut at %d of %d bytes" % (rel, at, size)
    # Flips: in the header region (text files anywhere, binary files their first 4 KiB), or
    # anywhere in the data.
    span = size if (kind == "flip-data" or is_text(target)) else min(size, 4096)
    where = sorted(rng.randrange(span) for _ in range(rng.randint(1, 3))) if span else []
    for at in where:
        content[at] ^= rng.choice([0x01, 0x10, 0x20, 0x5A, 0xFF])
    with open(target, "wb") as f:
        f.write(content)
    return "%s: bytes %s flipped (%s)" % (rel, where, kind)


def main():
    rng = random.Random(SEED)
    work = tempfile.mkdtemp(prefix="amrdm-damaged-")
    sets = []
    vthb_dirs = []
    for compressed in (True, False):
        folder = os.path.join(work, "vthb-src-" + ("zlib" if compressed else "raw"))
        os.makedirs(folder)
        write_vthb(folder, compressed)
        vthb_dirs.append(folder)
    sets.append(DataSet("enzo", os.path.join(DATA, "enzo-moving7_DD0010"),
                        "moving7_0010.hierarchy", 4))
    sets.append(DataSet("flame", os.path.join(DATA, "amrex-pelelmex-flame3d_plt"), "", 2))
    sets.append(DataSet("advection", os.path.join(DATA, "amrex-advection-amrcore3d", "plt00040"),
                        "", 2))
    sets.append(DataSet("vthb-zlib", vthb_dirs[0], "enzo.vthb", 2))
    sets.append(DataSet("vthb-raw", vthb_dirs[1], "enzo.vthb", 2))
    vortex = os.path.join(SHARED, "amrex-singlevortex3d-128", "plt00040") if SHARED else ""
    if vortex and os.path.isdir(vortex):
        sets.append(DataSet("singlevortex", vortex, "", 1))
    else:
        print("skipped: the shared set amrex-singlevortex3d-128 (not found at %r)" % vortex)
    for s in sets:
        s.prepare(os.path.join(work, "work"))

    # The reader's watchdog: with AMRDM_READ_TIMEOUT=0.001 even an intact read is cut short.
    advection = sets[2].path
    p = subprocess.run([APP, advection] + RENDER, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                       universal_newlines=True, timeout=LIMIT_S,
                       env=dict(os.environ, AMRDM_READ_TIMEOUT="0.001"))
    watchdog = "'%s': VTK's reader did not finish within 0.001 s" % advection
    if p.returncode != 1 or watchdog not in p.stderr:
        print("FAIL: the watchdog (exit %d): %s" % (p.returncode, p.stderr.strip()[-300:]))
        return 1
    print("ok: the watchdog ends a read that takes longer than AMRDM_READ_TIMEOUT (exit 1, file named)")

    counts = {}
    failures = []
    slowest, slowest_case = 0.0, ""
    t_start = time.time()
    weighted = [s for s in sets for _ in range(s.weight)]
    for case in range(CASES):
        data = weighted[case % len(weighted)]
        rel = rng.choice(data.files)
        what = data.name + ": " + damage(rng, data, rel)
        rc, out, err, seconds = render(data.path)
        if seconds > slowest:
            slowest, slowest_case = seconds, what
        check = vtkAMRDualMeshFileCheck.Check(data.path)
        if isinstance(check, bytes):  # a flipped byte in a name: not UTF-8
            check = check.decode("utf-8", "replace")
        data.restore(rel)
        lines = [l for l in err.splitlines() if l.startswith("amrdm-render: ")]
        last = lines[-1] if lines else ""
        if rc is None:
            outcome, ok = "hang", False
        elif rc < 0 or rc >= 128:
            outcome, ok = "crash (%s)" % rc, False
        elif rc == 0:
            # A value a flip made non-finite (or beyond float) is a hole, with a warning that
            # counts them: the hierarchy is whole and the render says what it left out.
            holes = re.search(r"has (\d+) NaN or infinite leaf values", err)
            holes = int(holes.group(1)) if holes else 0
            # Cells a flipped vtkGhostType byte flags hidden: warned with their count too.
            hidden = re.search(r"(\d+) cells are flagged hidden or duplicate", err)
            holes += int(hidden.group(1)) if hidden else 0
            complete = leaf_cells(out) == data.cells - holes
            # A .vthb DataSet without a file is an empty block: rendered without it, with a
            # warning that says how many blocks and cells are left out.
            empty = re.search(r"(\d+) of \d+ blocks \((\d+) of \d+ cells\) have no file", err)
            ok = check == "" and (complete or (empty is not None and leaf_cells(out) is not None
                                               and leaf_cells(out) < data.cells))
            outcome = ("whole render" + (", cells as holes (warned)" if holes else "")
                       if ok and complete
                       else "partial render with a warning saying how much" if ok
                       else "exit 0 on a file the check refuses" if complete
                       else "silent partial render")
        elif data.copy not in last:
            outcome, ok = "failure without the file's name", False
        elif "crashed" in last or "did not finish" in last:
            outcome, ok = "error from the reader guard", True
        elif check and last.endswith(check):
            outcome, ok = "error from the file check", True
        else:
            outcome, ok = "error after reading", True
        counts[outcome] = counts.get(outcome, 0) + 1
        if not ok:
            failures.append("%s -> %s: %s" % (what, outcome, (last or err.strip()[-200:])))
        if not ok or CASES <= 60 or outcome == "error from the reader guard":
            print("%-4s %s -> %s (%.1f s) %s" % ("ok" if ok else "FAIL", what, outcome, seconds,
                                                  last[len("amrdm-render: "):][:160]))
    shutil.rmtree(work, ignore_errors=True)
    print("%d cases in %.0f s (slowest %.1f s: %s):" % (CASES, time.time() - t_start, slowest,
                                                        slowest_case))
    for outcome in sorted(counts):
        print("  %5d  %s" % (counts[outcome], outcome))
    if failures:
        print("FAIL: %d of %d cases" % (len(failures), CASES))
        for f in failures[:40]:
            print("  " + f)
        return 1
    print("ok: 0 hangs, 0 crashes, 0 silent partial renders, every failure names the file")
    return 0


if __name__ == "__main__":
    sys.exit(main())
