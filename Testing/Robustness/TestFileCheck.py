"""vtkAMRDualMeshFileCheck on hand-made damaged files (issue 33): each damage gives a one-line
error naming the damaged file and the cause, in well under a second (huge counts are refused
before anything is allocated); the intact sets pass with the blocks per level and cells their
READMEs give; CheckOutput refuses a reader's output with fewer blocks or a missing array;
GetReadTimeoutSeconds scales with the data and honours AMRDM_READ_TIMEOUT."""
import os
import re
import shutil
import sys
import tempfile
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "Support"))
from amrdm_testing import (TEST_DATA, all_levels, checker, read_enzo,  # noqa: E402
                           write_enzo_vthb)
from amrdualmesh import vtkAMRDualMeshFileCheck  # noqa: E402
from vtkmodules.vtkIOAMR import vtkAMREnzoReader  # noqa: E402
from vtkmodules.vtkIOXML import vtkXMLUniformGridAMRReader  # noqa: E402

failures = []
WORK = tempfile.mkdtemp(prefix="amrdm-filecheck-")
ENZO = os.path.join(TEST_DATA, "enzo-moving7_DD0010")
ADVECTION = os.path.join(TEST_DATA, "amrex-advection-amrcore3d", "plt00040")
FLAME = os.path.join(TEST_DATA, "amrex-pelelmex-flame3d_plt")


check = checker(failures)


def fresh(source, name):
    target = os.path.join(WORK, name)
    shutil.rmtree(target, ignore_errors=True)
    shutil.copytree(source, target, copy_function=shutil.copyfile)
    return target


def edit(path, old, new, count=1):
    with open(path, "rb") as f:
        text = f.read()
    if old not in text:
        raise SystemExit("test bug: %r not in %s" % (old, path))
    with open(path, "wb") as f:
        f.write(text.replace(old, new, count))


def cut(path, size):
    with open(path, "rb") as f:
        data = f.read()
    with open(path, "wb") as f:
        f.write(data[:size] if size >= 0 else data[:len(data) + size])


def expect_error(what, path, damaged_file, pattern):
    t0 = time.time()
    error = vtkAMRDualMeshFileCheck.Check(path)
    seconds = time.time() - t0
    ok = ("'%s'" % damaged_file) in error and re.search(pattern, error) and "\n" not in error
    check(bool(ok) and seconds < 1.0, "%s: %r (%.3f s)" % (what, error, seconds))


def expect_whole(path, blocks, cells):
    c = vtkAMRDualMeshFileCheck()
    t0 = time.time()
    fine = c.CheckFile(path)
    got = [c.GetNumberOfBlocks(level) for level in range(c.GetNumberOfLevels())]
    check(fine and got == blocks and c.GetNumberOfCells() == cells,
          "intact %s: %r, blocks per level %s, %d cells (%.3f s)" % (
              os.path.relpath(path, TEST_DATA) if path.startswith(TEST_DATA) else path,
              c.GetError(), got, c.GetNumberOfCells(), time.time() - t0))


def enzo_cases():
    expect_whole(os.path.join(ENZO, "moving7_0010.hierarchy"), [1, 3, 1, 1, 1, 1, 1, 1], 30360)
    expect_whole(os.path.join(ENZO, "moving7_0010.boundary"), [1, 3, 1, 1, 1, 1, 1, 1], 30360)
    # Cut after every Pointer line but the last: a hierarchy that describes fewer grids than its
    # pointers (vtkAMREnzoReader renders the grids before the cut and says nothing).
    with open(os.path.join(ENZO, "moving7_0010.hierarchy"), "rb") as f:
        text = f.read()
    ends = [m.end() for m in re.finditer(rb"Pointer: [^\n]*\n", text)][:-1]
    bad = 0
    for end in ends:
        d = fresh(ENZO, "enzo-cut")
        h = os.path.join(d, "moving7_0010.hierarchy")
        cut(h, end)
        error = vtkAMRDualMeshFileCheck.Check(h)
        bad += 0 if ("'%s'" % h) in error and ("grid" in error) else 1
    check(bad == 0 and len(ends) == 19,
          "a .hierarchy cut after each of its %d inner Pointer lines: %d accepted" % (len(ends), bad))
    d = fresh(ENZO, "enzo")
    h = os.path.join(d, "moving7_0010.hierarchy")
    cases = [
        ("grids out of order", h, b"Grid = 3\n", b"Grid = 4\n", h, r"numbered in order"),
        ("a pointer to a grid the file lacks", h, b"NextGridThisLevel = 4", b"NextGridThisLevel = 99",
         h, r"points to grid 99"),
        ("a grid without GridLeftEdge", h, b"GridLeftEdge      = 0.5625", b"GridLeftXdge      = 0.5625",
         h, r"grid 3 has no 'GridLeftEdge"),
        ("a huge GridEndIndex", h, b"GridEndIndex      = 18 18 18", b"GridEndIndex      = 18 9999999999 18",
         h, r"integers in \[0, 2\^20\]"),
        ("no TopGridRank", os.path.join(d, "moving7_0010"), b"TopGridRank ", b"TopGridRonk ",
         os.path.join(d, "moving7_0010"), r"no 'TopGridRank"),
        ("a BaryonFileName that does not exist", h, b"moving7_0010.cpu0000\nCourant",
         b"moving7_0010.cpu9999\nCourant", os.path.join(d, "moving7_0010.cpu9999"), r"missing"),
    ]
    for what, target, old, new, named, pattern in cases:
        d = fresh(ENZO, "enzo")
        edit(os.path.join(d, os.path.basename(target)), old, new)
        expect_error(what, os.path.join(d, "moving7_0010.hierarchy"),
                     os.path.join(d, os.path.basename(named)), pattern)
    grid = lambda d: os.path.join(d, "moving7_0010.cpu0000")  # noqa: E731
    d = fresh(ENZO, "enzo")
    cut(grid(d), 704198)
    expect_error("the grid file cut in half", os.path.join(d, "moving7_0010.hierarchy"), grid(d),
                 r"has 704198 bytes, but its HDF5 superblock says 1408396: truncated")
    d = fresh(ENZO, "enzo")
    with open(grid(d), "wb") as f:
        f.write(b"not HDF5\n" * 100)
    expect_error("a grid file that is not HDF5", os.path.join(d, "moving7_0010.hierarchy"), grid(d),
                 r"not an HDF5 file")
    # A superblock that agrees with a file too small for the grids' cells (10 grids, 5 fields).
    d = fresh(ENZO, "enzo")
    with open(grid(d), "rb") as f:
        head = bytearray(f.read(4096))
    head[40:48] = (4096).to_bytes(8, "little")
    with open(grid(d), "wb") as f:
        f.write(head)
    expect_error("an HDF5 grid file too small for its grids", os.path.join(d, "moving7_0010.hierarchy"),
                 grid(d), r"fewer than the \d+ that its grids up to grid 1 need")
    d = fresh(ENZO, "enzo")
    edit(grid(d), b"Grid00000003", b"Grid00000013")  # a name in the root group's local heap
    expect_error("a grid group renamed in the HDF5 file", os.path.join(d, "moving7_0010.hierarchy"),
                 grid(d), r"no root group 'Grid00000003' for grid 3")
    d = fresh(ENZO, "enzo")
    with open(grid(d), "r+b") as f:  # the root heap's data address (superblock v0, 8-byte offsets)
        f.seek(0x78)
        f.write((1 << 40).to_bytes(8, "little"))
    expect_error("the HDF5 root heap's data address past the end", os.path.join(d, "moving7_0010.hierarchy"),
                 grid(d), r"name heap .* does not fit the file")
    d = fresh(ENZO, "enzo")
    edit(os.path.join(d, "moving7_0010.procmap"), b"      10  /rmount", b"      99  /rmount")
    expect_error("a .procmap naming grid 99", os.path.join(d, "moving7_0010.hierarchy"),
                 os.path.join(d, "moving7_0010.procmap"), r"grid number in \[1, 10\]")


def amrex_cases():
    expect_whole(ADVECTION, [16, 50, 160], 786432)
    expect_whole(FLAME, [1, 8, 64], 37376)
    header = lambda d: os.path.join(d, "Header")  # noqa: E731
    cell_h = lambda d: os.path.join(d, "Level_1", "Cell_H")  # noqa: E731
    data = lambda d: os.path.join(d, "Level_1", "Cell_D_00000")  # noqa: E731
    cases = [
        ("2^40 variables", header, b"HyperCLaw-V1.1\n1\n", b"HyperCLaw-V1.1\n1099511627776\n", header,
         r"expected a version and a number of variables"),
        ("a finest level of 10^6", header, b"0.48068850047028266\n2\n", b"0.48068850047028266\n1000000\n",
         header, r"finest level \(0-63\)"),
        ("10^9 boxes in a Cell_H", cell_h, b"(50 0", b"(1000000000 0", cell_h, r"expected '\(50 0'"),
        ("a Cell_H box with hi < lo", cell_h, b"((80,0,0) (95,7,15)", b"((80,0,0) (95,7,-15)", cell_h,
         r"lo <= hi"),
        ("a FabOnDisk offset past the end", cell_h, b"Cell_D_00000 0\n", b"Cell_D_00000 99999999999\n",
         data, r"truncated"),
        ("a FabOnDisk file that does not exist", cell_h, b"Cell_D_00000 0\n", b"Cell_D_00077 0\n",
         lambda d: os.path.join(d, "Level_1", "Cell_D_00077"), r"missing"),
        ("a Cell_H of version 2", cell_h, b"1\n1\n1\n0\n(50", b"2\n1\n1\n0\n(50", cell_h, r"version 2"),
        ("a FAB header whose box differs", data, b"((80,0,0) (95,7,15) (0,0,0)) 1\n",
         b"((80,0,0) (95,7,14) (0,0,0)) 1\n", data, r"another box"),
    ]
    for what, target, old, new, named, pattern in cases:
        d = fresh(ADVECTION, "amrex")
        edit(target(d), old, new)
        expect_error(what, d, named(d), pattern)
    d = fresh(ADVECTION, "amrex")
    size = os.path.getsize(data(d))
    cut(data(d), -1)
    expect_error("a data file one byte short", d, data(d),
                 r"has %d bytes; the FAB at offset \d+ needs %d: truncated" % (size - 1, size))
    d = fresh(ADVECTION, "amrex")
    cut(header(d), 4185)
    expect_error("a Header cut in half", d, header(d), r"line \d+: expected")
    d = fresh(ADVECTION, "amrex")
    os.remove(header(d))
    expect_error("a folder without Header", d, d, r"without a Header")


def vthb_cases():
    def write(name, compressed=True):
        folder = os.path.join(WORK, name)
        shutil.rmtree(folder, ignore_errors=True)
        os.makedirs(folder)
        write_enzo_vthb(os.path.join(folder, "enzo.vthb"), compressed)
        return os.path.join(folder, "enzo.vthb"), os.path.join(folder, "enzo", "enzo_1.vti")
    for compressed in (True, False):
        kind = "zlib" if compressed else "raw"
        vthb, block = write("vthb")
        vthb, block = write("vthb", compressed)
        expect_whole(vthb, [1, 3, 1, 1, 1, 1, 1, 1], 30360)
        cut(vthb, -40)
        expect_error(kind + ": a .vthb cut 40 bytes short", vthb, vthb, r"not well-formed XML")
        vthb, block = write("vthb", compressed)
        os.remove(block)
        expect_error(kind + ": a missing block file", vthb, block, r"missing")
        vthb, block = write("vthb", compressed)
        with open(block, "rb") as f:
            end = f.read().rfind(b"</AppendedData>")
        cut(block, end - 4)  # "\n  </AppendedData>" and the last data byte
        expect_error(kind + ": a block file one data byte short", vthb, block, r"truncated")
        vthb, block = write("vthb", compressed)
        edit(block, b'offset="0"', b'offset="99999999"')
        expect_error(kind + ": an array offset past the end", vthb, block, r"past the end")
        vthb, block = write("vthb", compressed)
        edit(vthb, b'amr_box="', b'amr_bax="')
        expect_error(kind + ": a DataSet without amr_box", vthb, vthb, r"amr_box")
        vthb, block = write("vthb", compressed)
        edit(vthb, b'amr_box="6 15 6 15 6 15"', b'amr_box="6 15 6 15 6 16"')
        expect_error(kind + ": an amr_box one cell longer than its block's extent", vthb, block,
                     r"its extent has 10 cells on axis 2, its amr_box in the .vthb 11")
        vthb, block = write("vthb", compressed)
        edit(block, b'DataArray type="Float32"', b'DataArray typd="Float32"')
        expect_error(kind + ": a DataArray without a type", vthb, block, r"a known type")
        vthb, block = write("vthb", compressed)
        edit(vthb, b' file="enzo/enzo_2.vti"', b' fime="enzo/enzo_2.vti"')
        c = vtkAMRDualMeshFileCheck()
        fine = c.CheckFile(vthb)
        reader = vtkXMLUniformGridAMRReader()
        reader.SetFileName(vthb)
        reader.SetMaximumLevelsToReadByDefault(0)
        reader.Update()
        error = c.CheckOutput(reader.GetOutput())
        check(fine and error == "" and "1 of 10 blocks (1440 of 30360 cells) have no file" in
              c.GetWarning(), kind + ": a DataSet without a file is an empty block, with a warning: "
              "%r" % c.GetWarning())
        vthb, block = write("vthb", compressed)
        edit(vthb, b'index="1"', b'index="7"')
        expect_error(kind + ": a DataSet index out of order", vthb, vthb, r'index="1"')


def output_cases():
    c = vtkAMRDualMeshFileCheck()
    path = os.path.join(ENZO, "moving7_0010.hierarchy")
    c.CheckFile(path)
    check(c.CheckOutput(read_enzo()) == "", "the whole Enzo output passes CheckOutput")
    reader = all_levels(vtkAMREnzoReader(), path, max_level=3)
    reader.Update()
    error = c.CheckOutput(reader.GetOutput())
    check("returned 6 of the 10 blocks" in error and "level 4: 0 of 1 blocks" in error,
          "levels 0-3 only: %r" % error)
    amr = read_enzo()
    amr.GetDataSet(2, 0).GetCellData().RemoveArray("Density")
    error = c.CheckOutput(amr)
    counts = re.search(r"block 0 of level 2 has (\d+) cell arrays, others (\d+)", error)
    check(counts and int(counts.group(1)) + 1 == int(counts.group(2)),
          "a missing array: %r" % error)
    os.environ["AMRDM_READ_TIMEOUT"] = "2.5"
    check(c.GetReadTimeoutSeconds() == 2.5, "AMRDM_READ_TIMEOUT=2.5 gives 2.5 s")
    del os.environ["AMRDM_READ_TIMEOUT"]
    expected = 10 + c.GetDataBytes() / 5e6
    check(abs(c.GetReadTimeoutSeconds() - expected) < 1e-9 and c.GetDataBytes() == 1408396,
          "default read timeout 10 s + 1 s per 5 MB: %.3f s" % c.GetReadTimeoutSeconds())


try:
    enzo_cases()
    amrex_cases()
    vthb_cases()
    output_cases()
finally:
    shutil.rmtree(WORK, ignore_errors=True)
if failures:
    print("%d failure(s)" % len(failures))
    sys.exit(1)
print("all checks passed")
