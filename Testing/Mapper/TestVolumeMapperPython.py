"""Baseline image of vtkAMRDualMeshVolumeMapper driven from Python (vtkmodules.test.Testing):
the AMReX advection set (phi), single scattering lit by a positional scene light plus the
headlight, a parallel camera, an opaque sphere half inside the volume and two clipping planes.
Fixed seed and sample count. Run: TestVolumeMapperPython.py -B <Baseline dir> -T <temp dir>."""
import os
import sys

from vtkmodules.test import Testing
from vtkmodules.vtkCommonDataModel import vtkPiecewiseFunction, vtkPlane, vtkPlaneCollection
from vtkmodules.vtkFiltersSources import vtkSphereSource
from vtkmodules.vtkIOAMR import vtkAMReXGridReader
from vtkmodules.vtkRenderingCore import (vtkActor, vtkColorTransferFunction, vtkLight,
                                         vtkPolyDataMapper, vtkRenderer, vtkRenderWindow,
                                         vtkVolume, vtkVolumeProperty)
import vtkmodules.vtkInteractionStyle  # noqa: F401
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401

from amrdualmesh import vtkAMRDualMeshVolumeMapper

DATA = os.environ.get("AMRDM_TEST_DATA", os.path.join(os.path.dirname(__file__), "..", "Data"))


class TestVolumeMapperPython(Testing.vtkTest):
    def testImage(self):
        path = os.path.join(DATA, "amrex-advection-amrcore3d", "plt00040")
        reader = vtkAMReXGridReader()
        reader.SetFileName(path)
        reader.UpdateInformation()
        reader.SetMaxLevel(99)  # readers load level 0 only by default
        reader.GetCellDataArraySelection().EnableAllArrays()

        mapper = vtkAMRDualMeshVolumeMapper()
        mapper.SetInputConnection(reader.GetOutputPort())
        mapper.SelectScalarArray("phi")
        mapper.SetIntegrator(vtkAMRDualMeshVolumeMapper.SINGLE_SCATTER)
        mapper.SetSeed(3)
        mapper.SetMaximumSamples(16)
        mapper.SetEnvironmentRadiance(0.3, 0.3, 0.3)
        planes = vtkPlaneCollection()
        for origin, normal in (((0.76, 0.5, 0.5), (-1, 0, 0)), ((0.5, 0.42, 0.5), (0, 1, 0))):
            plane = vtkPlane()
            plane.SetOrigin(origin)
            plane.SetNormal(normal)
            planes.AddItem(plane)
        mapper.SetClippingPlanes(planes)

        color = vtkColorTransferFunction()
        color.AddRGBPoint(1.0, 0.27, 0.0, 0.33)
        color.AddRGBPoint(1.5, 0.13, 0.57, 0.55)
        color.AddRGBPoint(2.0, 0.99, 0.91, 0.14)
        opacity = vtkPiecewiseFunction()
        opacity.AddPoint(1.0, 0.0)
        opacity.AddPoint(1.02, 0.02)
        opacity.AddPoint(1.3, 0.4)
        opacity.AddPoint(2.0, 0.95)
        prop = vtkVolumeProperty()
        prop.SetColor(color)
        prop.SetScalarOpacity(opacity)
        prop.SetScalarOpacityUnitDistance(0.02)
        volume = vtkVolume()
        volume.SetMapper(mapper)
        volume.SetProperty(prop)

        sphere = vtkSphereSource()
        sphere.SetCenter(0.64, 0.52, 0.25)  # on the slab's top face: half inside
        sphere.SetRadius(0.1)
        sphere.SetThetaResolution(32)
        sphere.SetPhiResolution(32)
        sphere_mapper = vtkPolyDataMapper()
        sphere_mapper.SetInputConnection(sphere.GetOutputPort())
        actor = vtkActor()
        actor.SetMapper(sphere_mapper)
        actor.GetProperty().SetColor(0.9, 0.6, 0.3)

        ren = vtkRenderer()
        ren.SetBackground(0.1, 0.1, 0.12)
        ren.AddActor(actor)
        ren.AddVolume(volume)
        light = vtkLight()  # a positional scene light above the blob
        light.SetLightTypeToSceneLight()
        light.SetPositional(True)
        light.SetPosition(0.4, 0.9, 1.0)
        light.SetFocalPoint(0.68, 0.56, 0.12)
        light.SetConeAngle(90)
        light.SetIntensity(4.0)
        ren.AddLight(light)
        window = vtkRenderWindow()
        window.SetSize(200, 200)
        window.AddRenderer(ren)
        cam = ren.GetActiveCamera()
        cam.ParallelProjectionOn()
        cam.SetFocalPoint(0.68, 0.56, 0.12)
        cam.SetPosition(0.98, -0.24, 0.82)
        cam.SetViewUp(0, 0, 1)
        cam.SetParallelScale(0.32)
        ren.ResetCameraClippingRange()

        reached = mapper.RenderUntil(window, 16)
        self.assertEqual(reached, 16)
        self.assertEqual(mapper.GetDualMesh().GetBuildCount(), 1)
        print("16 samples; last render %.1f ms" % (1e3 * mapper.GetLastRenderSeconds()))
        Testing.compareImage(window, Testing.getAbsImagePath("TestVolumeMapperPython.png"),
                             threshold=0.05)


if __name__ == "__main__":
    if not os.path.isdir(os.path.join(DATA, "amrex-advection-amrcore3d")):
        print("SKIP: the AMReX advection set is missing")
        sys.exit(125)
    Testing.main([(TestVolumeMapperPython, "test")])
