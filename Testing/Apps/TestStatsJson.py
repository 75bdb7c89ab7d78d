"""amrdm-render --stats is valid JSON (nlohmann-json) for a file name that needs escaping.

The name has quotes, a newline, a tab, 0x01, UTF-8 and a byte that is not UTF-8 (Latin-1
e-acute); no backslash, which the Enzo reader turns into a slash (TestJsonEscaping has one). The
hand-written writer this replaced passed the Latin-1 byte through, so the output was not UTF-8
and no JSON reader took it. Here it must parse, be ASCII, give the name back (the
invalid byte as U+FFFD) and carry the dual-mesh report.

usage: TestStatsJson.py AMRDM_RENDER DATA_DIR
"""
import json
import os
import subprocess
import sys
import tempfile

render_exe, data_dir = sys.argv[1], sys.argv[2]
with tempfile.TemporaryDirectory() as tmp:
    weird = os.path.join(tmp.encode(), b'a "q" b\nnew\tline \x01 caf\xc3\xa9 latin1-\xe9')
    os.symlink(os.path.abspath(os.path.join(data_dir, "enzo-moving7_DD0010")), weird)
    path = os.path.join(weird, b"moving7_0010.hierarchy")
    r = subprocess.run([render_exe.encode(), path, b"--stats"], capture_output=True)
    if r.returncode != 0:
        print("FAIL: amrdm-render --stats exited %d: %s" % (r.returncode, r.stderr[-500:]))
        sys.exit(1)
    out = r.stdout
    failures = []
    if any(c >= 0x80 for c in out):
        failures.append("the output is not ASCII")
    try:
        stats = json.loads(out.decode("utf-8"))
    except (UnicodeDecodeError, ValueError) as e:
        print("FAIL: not JSON (%s): %r" % (e, out[:300]))
        sys.exit(1)
    want = path.decode("utf-8", errors="replace")
    if stats.get("file") != want:
        failures.append("file is %r, expected %r" % (stats.get("file"), want))
    if not isinstance(stats.get("counts"), dict) or not isinstance(stats.get("memory"), dict):
        failures.append("the dual-mesh report (counts, memory) is missing: %s" % sorted(stats))
    for f in failures:
        print("FAIL:", f)
    print("passed" if not failures else "FAILED")
    sys.exit(1 if failures else 0)
