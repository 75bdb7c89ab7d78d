"""Baseline image of vtkAMRDualMeshVolumeMapper driven from Python (vtkmodules.test.Testing):
the AMReX advection set (phi), single scattering lit by a positional scene light plus the
headlight, a parallel camera, an opaque sphere half inside the volume and two clipping planes.
Fixed seed and sample count. Run: TestVolumeMapperPython.py -B <Baseline dir> -T <temp dir>."""
import os
import sys

from vtkmodules.test import Testing
from vtkmodules.vtkCommonDataModel import vtkPlane, vtkPlaneCollection
from vtkmodules.vtkRenderingCore import vtkLight
import vtkmodules.vtkInteractionStyle  # noqa: F401

from amrdualmesh import vtkAMRDualMeshVolumeMapper

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "Support"))
from amrdm_testing import (ADVECTION, aim, amrex_reader, dual_mesh_volume,  # noqa: E402
                           render_window, sphere_actor, volume_property)


class TestVolumeMapperPython(Testing.vtkTest):
    def testImage(self):
        planes = vtkPlaneCollection()
        for origin, normal in (((0.76, 0.5, 0.5), (-1, 0, 0)), ((0.5, 0.42, 0.5), (0, 1, 0))):
            plane = vtkPlane()
            plane.SetOrigin(origin)
            plane.SetNormal(normal)
            planes.AddItem(plane)
        prop = volume_property(((1.0, 0.27, 0.0, 0.33), (1.5, 0.13, 0.57, 0.55),
                                (2.0, 0.99, 0.91, 0.14)),
                               ((1.0, 0.0), (1.02, 0.02), (1.3, 0.4), (2.0, 0.95)), 0.02)
        mapper, volume = dual_mesh_volume(
            amrex_reader(), "phi", prop, Integrator=vtkAMRDualMeshVolumeMapper.SINGLE_SCATTER,
            Seed=3, MaximumSamples=16, EnvironmentRadiance=(0.3, 0.3, 0.3), ClippingPlanes=planes)

        window, ren = render_window((200, 200), (0.1, 0.1, 0.12))
        # the sphere on the slab's top face: half inside
        ren.AddActor(sphere_actor((0.64, 0.52, 0.25), 0.1, (0.9, 0.6, 0.3)))
        ren.AddVolume(volume)
        light = vtkLight()  # a positional scene light above the blob
        light.SetLightTypeToSceneLight()
        light.SetPositional(True)
        light.SetPosition(0.4, 0.9, 1.0)
        light.SetFocalPoint(0.68, 0.56, 0.12)
        light.SetConeAngle(90)
        light.SetIntensity(4.0)
        ren.AddLight(light)
        cam = aim(ren.GetActiveCamera(), (0.98, -0.24, 0.82), (0.68, 0.56, 0.12))
        cam.ParallelProjectionOn()
        cam.SetParallelScale(0.32)
        ren.ResetCameraClippingRange()

        reached = mapper.RenderUntil(window, 16)
        self.assertEqual(reached, 16)
        self.assertEqual(mapper.GetDualMesh().GetBuildCount(), 1)
        print("16 samples; last render %.1f ms" % (1e3 * mapper.GetLastRenderSeconds()))
        Testing.compareImage(window, Testing.getAbsImagePath("TestVolumeMapperPython.png"),
                             threshold=0.05)


if __name__ == "__main__":
    if not os.path.isdir(ADVECTION):
        print("SKIP: the AMReX advection set is missing")
        sys.exit(125)
    Testing.main([(TestVolumeMapperPython, "test")])
