"""Helpers shared by the Python tests: data paths, readers, small hand-made AMR sets, an
observer that records VTK errors instead of printing them, and the pieces of a volume scene
(property, mapper, window, camera, grabbed pixels) that the mapper tests build alike."""
import os
import sys

from vtkmodules.util.misc import calldata_type
from vtkmodules.vtkCommonCore import VTK_STRING, vtkCommand, vtkDoubleArray
from vtkmodules.vtkCommonDataModel import vtkAMRBox, vtkOverlappingAMR, vtkUniformGrid

TEST_DATA = os.environ.get("AMRDM_TEST_DATA", os.path.join(os.path.dirname(__file__), "..", "Data"))
ADVECTION = os.path.join(TEST_DATA, "amrex-advection-amrcore3d", "plt00040")
# The advection set's colour map (phi runs from 1 to 2): Cool to Warm's ends and middle.
COOL_WARM = ((1.0, 0.23, 0.30, 0.75), (1.5, 0.87, 0.87, 0.87), (2.0, 0.71, 0.02, 0.15))


def check_file(path):
    """vtkAMRDualMeshFileCheck before a VTK reader sees `path` (issue 33): raises RuntimeError with
    its one-line message (the file and the problem) when the file is damaged or incomplete."""
    from amrdualmesh import vtkAMRDualMeshFileCheck
    problem = vtkAMRDualMeshFileCheck.Check(path)
    if isinstance(problem, bytes):  # a damaged name that is not UTF-8
        problem = problem.decode("utf-8", "replace")
    if problem:
        raise RuntimeError(problem)


def all_levels(reader, path, max_level=99):
    """`reader` on `path` with every level up to max_level (readers load level 0 only by default)
    and every cell array on; not updated, so a mapper can take its output port."""
    reader.SetFileName(path)
    reader.UpdateInformation()
    reader.SetMaxLevel(max_level)
    reader.GetCellDataArraySelection().EnableAllArrays()
    return reader


def read_enzo():
    from vtkmodules.vtkIOAMR import vtkAMREnzoReader
    path = os.path.join(TEST_DATA, "enzo-moving7_DD0010", "moving7_0010.hierarchy")
    check_file(path)
    reader = all_levels(vtkAMREnzoReader(), path)
    reader.Update()
    return reader.GetOutput()


def write_enzo_vthb(path, compressed=True):
    """The Enzo set written by VTK's XML AMR writer (appended, not encoded; zlib or raw) to
    `path` (a .vthb, its blocks in a folder beside it). False when the writer failed."""
    from vtkmodules.vtkIOXML import vtkXMLUniformGridAMRWriter
    writer = vtkXMLUniformGridAMRWriter()
    writer.SetInputData(read_enzo())
    writer.SetDataModeToAppended()
    writer.EncodeAppendedDataOff()
    if not compressed:
        writer.SetCompressorTypeToNone()
    writer.SetFileName(path)
    return bool(writer.Write())


def amrex_reader(path=ADVECTION):
    from vtkmodules.vtkIOAMR import vtkAMReXGridReader
    return all_levels(vtkAMReXGridReader(), path)


def read_amrex(path=ADVECTION):
    """The vtkOverlappingAMR of an AMReX plotfile (default: the advection set), all levels."""
    reader = amrex_reader(path)
    reader.Update()
    return reader.GetOutputDataObject(0)


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


def checker(failures, passed="ok:   ", failed="FAIL: "):
    """check(condition, message): prints the message after `passed` or `failed`, and appends it
    to the list `failures` when the condition is false."""
    def check(condition, message):
        print((passed if condition else failed) + message)
        if not condition:
            failures.append(message)
    return check


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


def volume_property(colors, opacities, unit_distance=None, shade=None):
    """A vtkVolumeProperty of the colour points (value, r, g, b) and opacity points (value, a)."""
    from vtkmodules.vtkCommonDataModel import vtkPiecewiseFunction
    from vtkmodules.vtkRenderingCore import vtkColorTransferFunction, vtkVolumeProperty
    color = vtkColorTransferFunction()
    for point in colors:
        color.AddRGBPoint(*point)
    opacity = vtkPiecewiseFunction()
    for point in opacities:
        opacity.AddPoint(*point)
    prop = vtkVolumeProperty()
    prop.SetColor(color)
    prop.SetScalarOpacity(opacity)
    if unit_distance is not None:
        prop.SetScalarOpacityUnitDistance(unit_distance)
    if shade is not None:
        prop.SetShade(shade)
    return prop


def dual_mesh_volume(data, array, prop, **settings):
    """(vtkAMRDualMeshVolumeMapper, vtkVolume): the mapper on `data` (an AMR, or a reader whose
    output port it takes) colouring by `array`, in a volume with `prop`. Each setting Name=value
    calls mapper.SetName(value) (a tuple is spread over the arguments), in the order given."""
    from amrdualmesh import vtkAMRDualMeshVolumeMapper
    from vtkmodules.vtkRenderingCore import vtkVolume
    mapper = vtkAMRDualMeshVolumeMapper()
    if hasattr(data, "GetOutputPort"):
        mapper.SetInputConnection(data.GetOutputPort())
    else:
        mapper.SetInputDataObject(data)
    mapper.SelectScalarArray(array)
    for name, value in settings.items():
        getattr(mapper, "Set" + name)(*(value if isinstance(value, tuple) else (value,)))
    volume = vtkVolume()
    volume.SetMapper(mapper)
    volume.SetProperty(prop)
    return mapper, volume


def render_window(size, background=(0.0, 0.0, 0.0), offscreen=False, multisamples=None):
    """(vtkRenderWindow of `size`, its one vtkRenderer). multisamples None keeps VTK's default."""
    import vtkmodules.vtkRenderingOpenGL2  # noqa: F401
    from vtkmodules.vtkRenderingCore import vtkRenderer, vtkRenderWindow
    window = vtkRenderWindow()
    window.SetSize(*size)
    if multisamples is not None:
        window.SetMultiSamples(multisamples)
    if offscreen:
        window.SetOffScreenRendering(1)
    ren = vtkRenderer()
    ren.SetBackground(*background)
    window.AddRenderer(ren)
    return window, ren


def aim(camera, position, focal_point, view_up=(0.0, 0.0, 1.0)):
    camera.SetPosition(position)
    camera.SetFocalPoint(focal_point)
    camera.SetViewUp(view_up)
    return camera


def sphere_actor(center, radius, color, resolution=32):
    """An opaque vtkActor of a sphere (a test's "geometry in the volume")."""
    from vtkmodules.vtkFiltersSources import vtkSphereSource
    from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper
    sphere = vtkSphereSource()
    sphere.SetCenter(*center)
    sphere.SetRadius(radius)
    sphere.SetThetaResolution(resolution)
    sphere.SetPhiResolution(resolution)
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(sphere.GetOutputPort())
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetColor(*color)
    return actor


def grab(window, rerender=False):
    """The window's back buffer as a vtkImageData; rerender=False reads what the last Render()
    drew (vtkWindowToImageFilter's ShouldRerender off)."""
    from vtkmodules.vtkRenderingCore import vtkWindowToImageFilter
    grabber = vtkWindowToImageFilter()
    grabber.SetInput(window)
    if not rerender:
        grabber.ShouldRerenderOff()
    grabber.ReadFrontBufferOff()
    grabber.Update()
    return grabber.GetOutput()


def rgb(image, unit=255.0):
    """An image's RGB as floats divided by `unit`, shape (rows from the bottom, columns, 3)."""
    from vtkmodules.util.numpy_support import vtk_to_numpy
    dims = image.GetDimensions()
    a = vtk_to_numpy(image.GetPointData().GetScalars()).reshape(dims[1], dims[0], -1)
    return a[:, :, :3].astype(float) / unit


def mean_luminance(pixels):
    """The mean Rec. 709 luminance of RGB pixels (last axis), in their unit."""
    return float((0.2126 * pixels[..., 0] + 0.7152 * pixels[..., 1] +
                  0.0722 * pixels[..., 2]).mean())


def write_png(image, path):
    from vtkmodules.vtkIOImage import vtkPNGWriter
    writer = vtkPNGWriter()
    writer.SetInputData(image)
    writer.SetFileName(path)
    writer.Write()


def temp_dir():
    """The folder given with -T on the command line, or None."""
    argv = sys.argv
    return argv[argv.index("-T") + 1] if "-T" in argv[:-1] else None


def blend_mode_scene(size, centre, iso_value, top, slice_z, unit_distance=None):
    """The blend-mode tests' scene: a 2-level AMR of f = |p - centre| over the unit cube (16^3
    root cells, the middle half refined), ray-marched (step 1/256, one sample) with an opaque
    grey ramp 0 .. 1 over [0, top], the isosurface value `iso_value` and the slice plane
    z = slice_z, seen along -z by a parallel camera in a size x size offscreen window. Returns
    a namespace: amr, mapper, recorder (its ErrorRecorder), prop, plane, volume, ren, window,
    camera (the clipping range is the test's)."""
    import math
    from types import SimpleNamespace
    from amrdualmesh import vtkAMRDualMeshVolumeMapper
    from vtkmodules.vtkCommonDataModel import vtkPlane
    s = SimpleNamespace()
    s.amr = make_amr([[((0, 0, 0), (15, 15, 15))], [((8, 8, 8), (23, 23, 23))]],
                     spacing0=(1.0 / 16,) * 3,
                     field=lambda p: math.sqrt(sum((p[d] - centre[d]) ** 2 for d in range(3))))
    s.prop = volume_property(((0.0, 0.0, 0.0, 0.0), (top, 1.0, 1.0, 1.0)),
                             ((0.0, 1.0), (top, 1.0)), unit_distance)
    s.prop.GetIsoSurfaceValues().SetValue(0, iso_value)
    s.plane = vtkPlane()
    s.plane.SetOrigin(0.5, 0.5, slice_z)
    s.plane.SetNormal(0.0, 0.0, 1.0)
    s.prop.SetSliceFunction(s.plane)
    s.mapper, s.volume = dual_mesh_volume(s.amr, "f", s.prop,
                                          Integrator=vtkAMRDualMeshVolumeMapper.RAY_MARCH,
                                          StepSize=1.0 / 256, MaximumSamples=1)
    s.recorder = ErrorRecorder(s.mapper)
    s.window, s.ren = render_window((size, size), offscreen=True)
    s.ren.AddVolume(s.volume)
    s.camera = aim(s.ren.GetActiveCamera(), (0.5, 0.5, 3.0), (0.5, 0.5, 0.5), (0.0, 1.0, 0.0))
    s.camera.ParallelProjectionOn()
    s.camera.SetParallelScale(0.5)
    return s


def halton(i, base):
    """The i-th point of the van der Corput sequence in `base` (one Halton coordinate)."""
    f, r = 1.0, 0.0
    while i > 0:
        f /= base
        r += f * (i % base)
        i //= base
    return r


def probe_points(points, source, array):
    """vtkAMRDualMeshProbeFilter of `source`'s `array` at `points` (a vtkPoints), updated.
    Returns (values, vtkValidPointMask, the probe's ErrorRecorder); values or the mask is None
    when the probe made no output."""
    from amrdualmesh import vtkAMRDualMeshProbeFilter
    from vtkmodules.vtkCommonDataModel import vtkPolyData
    poly = vtkPolyData()
    poly.SetPoints(points)
    probe = vtkAMRDualMeshProbeFilter()
    recorder = ErrorRecorder(probe)
    probe.SetInputData(poly)
    probe.SetSourceData(source)
    probe.SetArrayName(array)
    probe.Update()
    data = probe.GetOutput().GetPointData()
    return data.GetArray(array), data.GetArray("vtkValidPointMask"), recorder
