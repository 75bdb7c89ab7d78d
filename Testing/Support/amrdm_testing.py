"""Helpers shared by the Python tests: data paths, readers, small hand-made AMR sets, and an
observer that records VTK errors instead of printing them."""
import os

from vtkmodules.util.misc import calldata_type
from vtkmodules.vtkCommonCore import VTK_STRING, vtkCommand, vtkDoubleArray
from vtkmodules.vtkCommonDataModel import vtkAMRBox, vtkOverlappingAMR, vtkUniformGrid
from vtkmodules.vtkIOAMR import vtkAMREnzoReader

TEST_DATA = os.environ.get("AMRDM_TEST_DATA", os.path.join(os.path.dirname(__file__), "..", "Data"))


def check_file(path):
    """vtkAMRDualMeshFileCheck before a VTK reader sees `path` (issue 33): raises RuntimeError with
    its one-line message (the file and the problem) when the file is damaged or incomplete."""
    from amrdualmesh import vtkAMRDualMeshFileCheck
    problem = vtkAMRDualMeshFileCheck.Check(path)
    if isinstance(problem, bytes):  # a damaged name that is not UTF-8
        problem = problem.decode("utf-8", "replace")
    if problem:
        raise RuntimeError(problem)


def read_enzo():
    path = os.path.join(TEST_DATA, "enzo-moving7_DD0010", "moving7_0010.hierarchy")
    check_file(path)
    reader = vtkAMREnzoReader()
    reader.SetFileName(path)
    reader.UpdateInformation()
    reader.SetMaxLevel(99)
    reader.GetCellDataArraySelection().EnableAllArrays()
    reader.Update()
    return reader.GetOutput()


def make_amr(levels, origin=(0.0, 0.0, 0.0), spacing0=(1.0, 1.0, 1.0), ratio=2, field=None,
             grid_spacing_override=None):
    """levels: list of lists of (lo, hi) inclusive cell boxes per level. Cell array 'f'."""
    amr = vtkOverlappingAMR()
    amr.Initialize(len(levels), [len(boxes) for boxes in levels])
    amr.SetOrigin(origin)
    for level, boxes in enumerate(levels):
        h = [s / (ratio ** level) for s in spacing0]
        amr.SetSpacing(level, h)
        amr.SetRefinementRatio(level, 2)
        for i, (lo, hi) in enumerate(boxes):
            box = vtkAMRBox(lo, hi)
            amr.SetAMRBox(level, i, box)
            grid = vtkUniformGrid()
            dims = [hi[d] - lo[d] + 2 for d in range(3)]
            grid.SetDimensions(dims)
            gh = grid_spacing_override if grid_spacing_override else h
            grid.SetSpacing(gh)
            grid.SetOrigin([origin[d] + lo[d] * h[d] for d in range(3)])
            values = vtkDoubleArray()
            values.SetName("f")
            n = grid.GetNumberOfCells()
            values.SetNumberOfTuples(n)
            for c in range(n):
                center = [0.0, 0.0, 0.0]
                # cell centres, x fastest
                ix = c % (dims[0] - 1)
                iy = (c // (dims[0] - 1)) % (dims[1] - 1)
                iz = c // ((dims[0] - 1) * (dims[1] - 1))
                center = [origin[0] + (lo[0] + ix + 0.5) * h[0], origin[1] + (lo[1] + iy + 0.5) * h[1],
                          origin[2] + (lo[2] + iz + 0.5) * h[2]]
                values.SetValue(c, field(center) if field else 1.0)
            grid.GetCellData().AddArray(values)
            amr.SetDataSet(level, i, grid)
    return amr


class ErrorRecorder:
    """Attach to a vtkObject: records ErrorEvent and WarningEvent messages."""

    def __init__(self, obj):
        self.errors = []
        self.warnings = []
        obj.AddObserver(vtkCommand.ErrorEvent, self._error)
        obj.AddObserver(vtkCommand.WarningEvent, self._warning)

    @calldata_type(VTK_STRING)
    def _error(self, obj, event, data=None):
        self.errors.append(data)

    @calldata_type(VTK_STRING)
    def _warning(self, obj, event, data=None):
        self.warnings.append(data)
